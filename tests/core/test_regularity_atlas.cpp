// The regularity atlas (issue 48): a family of schemes over a grid, refined where the verdict
// "C^k" changes, every point under a budget of work so the rows are the same wherever they are
// computed. Checked against the literature: the four-point scheme is C^1 exactly for
// 0 < omega < omega*, omega* = 0.19273 the real root of 32 w^3 + 4 w - 1 (Hechler, Mößner &
// Reif 2009); the six-point scheme of Dubuc & Deslauriers (3/256, -25/256, 150/256) is C^2
// (Hölder 2.83, Rioul 1992); on the line v = 0 the six-point family is the four-point scheme.

#include "core/Types.h"
#include "core/analysis/RegularityAtlas.h"
#include "core/schemes/Scheme.h"

#include <QtTest>

#include "TestMain.h"
#include "TestTime.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <set>
#include <thread>

using namespace awb;

namespace {

// The real root of 32 w^3 + 4 w - 1 (Newton from 0.2).
double omegaStar()
{
    double w = 0.2;
    for (int i = 0; i < 50; ++i)
        w -= (32 * w * w * w + 4 * w - 1) / (96 * w * w + 4);
    return w;
}

Regularity fourPoint(const std::vector<double> &p, const RegularityOptions &o)
{
    return schemeRegularity(fourPointScheme(p[0]), 8, o);
}

// v, 0, w, 0, 1/2 - w - v, 1, 1/2 - w - v, 0, w, 0, v: the interpolatory six-point family
// (v = 0, w = -omega: the four-point scheme).
Regularity sixPoint(const std::vector<double> &p, const RegularityOptions &o)
{
    const double w = p[0], v = p[1], a = 0.5 - w - v;
    return maskRegularity({v, 0, w, 0, a, 1, a, 0, w, 0, v}, 2, o);
}

// Runs a plan to the end, each batch evaluated in `order` (a permutation of the batch) by
// `threads` threads: how and where the points run must not matter.
std::vector<AtlasRow> run(AtlasPlan &plan, const AtlasMember &member, bool shuffle = false,
                          int threads = 1)
{
    std::mt19937 rng(7);
    for (auto batch = plan.nextBatch(); !batch.empty(); batch = plan.nextBatch()) {
        std::vector<size_t> order(batch.size());
        std::iota(order.begin(), order.end(), 0);
        if (shuffle)
            std::shuffle(order.begin(), order.end(), rng);
        std::vector<AtlasRow> rows(batch.size());
        std::atomic<size_t> next{0};
        const auto work = [&] {
            for (size_t n; (n = next++) < order.size();)
                rows[order[n]] = evaluateAtlasPoint(member, batch[order[n]], plan.options());
        };
        std::vector<std::thread> pool;
        for (int t = 1; t < threads; ++t)
            pool.emplace_back(work);
        work();
        for (auto &t : pool)
            t.join();
        plan.accept(rows);
    }
    return plan.rows();
}

bool sameRows(const std::vector<AtlasRow> &a, const std::vector<AtlasRow> &b)
{
    if (a.size() != b.size())
        return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].params != b[i].params || a[i].lower != b[i].lower ||
            a[i].upper != b[i].upper || a[i].exact != b[i].exact ||
            a[i].verdict != b[i].verdict)
            return false;
    return true;
}

} // namespace

class TestRegularityAtlas : public QObject {
    Q_OBJECT
private slots:
    void fourPointC1Region()
    {
        AWB_SKIP_WITHOUT_THREADS();
        AtlasOptions o;
        o.smoothness = 1;
        o.tolerance = 1e-6;
        AtlasPlan plan({{"omega", 0.0, 0.25, 26}}, o);
        const std::vector<AtlasRow> rows = run(plan, fourPoint);
        QVERIFY(plan.finished());
        const std::vector<AtlasRun> runs = plan.runs();
        QCOMPARE(runs.size(), size_t(1));
        // omega = 0 is piecewise linear: r = 1 exactly, so C^1 is not certified there (the
        // bounds touch k), and every positive grid value up to omega* is.
        QCOMPARE(runs[0].from.outer, 0.0);
        QVERIFY(runs[0].from.inner > 0.0 && runs[0].from.inner <= 1e-6 + 1e-12);
        const double star = omegaStar();
        QVERIFY(std::abs(star - 0.19273) < 5e-6);
        const AtlasBoundary &to = runs[0].to;
        QVERIFY2(to.inner < star + 1e-9 && std::abs(to.outer - to.inner) <= 2e-6,
                 qPrintable(QString("[%1, %2]")
                                .arg(to.inner, 0, 'g', 12)
                                .arg(to.outer, 0, 'g', 12)));
        QVERIFY2(std::abs(to.inner - star) < 1e-5,
                 qPrintable(QString("%1 vs %2").arg(to.inner, 0, 'g', 12).arg(star, 0, 'g', 12)));
        // The grid rows first: every omega in (0, omega*) certified C^1, beyond it not.
        for (const AtlasRow &r : rows) {
            if (r.params[0] > 0 && r.params[0] < star - 1e-4)
                QCOMPARE(r.verdict, 1);
            if (r.params[0] > star + 1e-4)
                QVERIFY(r.verdict <= 0);
        }
    }

    void sameRowsWhereverTheyRun()
    {
        AtlasOptions o;
        o.tolerance = 1e-5;
        AtlasPlan a({{"omega", 0.05, 0.25, 9}}, o), b({{"omega", 0.05, 0.25, 9}}, o);
        const auto one = run(a, fourPoint);
        const auto other = run(b, fourPoint, true, 2);
        QVERIFY(sameRows(one, other));
        QCOMPARE(a.round(), b.round());
        QVERIFY(a.round() >= 4);   // the grid and sectioning rounds
    }

    void sixPointPlane()
    {
        AWB_SKIP_WITHOUT_THREADS();
        AtlasOptions o;
        o.smoothness = 1;
        o.refineLevels = 1;
        o.work = 20000;
        AtlasPlan plan({{"w", -0.5, 0.0, 3}, {"v", -0.02, 0.02, 3}}, o);
        const auto rows = run(plan, sixPoint);
        QVERIFY(plan.finished());
        QVERIFY(rows.size() > 9);    // refined somewhere
        QCOMPARE(plan.round(), 2);   // the grid, then one level
        // On v = 0 the family is the four-point scheme with omega = -w.
        for (const AtlasRow &r : rows) {
            if (r.params[1] != 0.0)
                continue;
            const Regularity f = schemeRegularity(fourPointScheme(-r.params[0]), 8,
                                                  atlasRegularityOptions(o));
            QCOMPARE(r.verdict, atlasVerdict(evaluateAtlasPoint(fourPoint, {-r.params[0]}, o), 1));
            QVERIFY(std::abs(r.lower - f.lower) < 1e-9 || f.infinite);
        }
        // Refined points sit only in cells whose corners disagree: every row at the finest
        // level has a neighbour grid cell with two verdicts.
        const auto cell = plan.cellSize(rows.front());
        QCOMPARE(cell.size(), size_t(2));
        QCOMPARE(cell[0], 0.25);
        QCOMPARE(cell[1], 0.02);
        // Refined rows lie only in grid cells whose corners' verdicts differ.
        const auto verdictAt = [&](int i, int j) {
            for (const AtlasRow &g : rows)
                if (std::abs(g.params[0] - (-0.5 + 0.25 * i)) < 1e-12 &&
                    std::abs(g.params[1] - (-0.02 + 0.02 * j)) < 1e-12)
                    return g.verdict;
            return 99;
        };
        int refined = 0;
        for (const AtlasRow &r : rows) {
            if (plan.cellSize(r)[0] == 0.25)
                continue;
            ++refined;
            QCOMPARE(plan.cellSize(r)[0], 0.125);
            bool inMixedCell = false;
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 2; ++j) {
                    const bool inside = r.params[0] >= -0.5 + 0.25 * i - 1e-12 &&
                                        r.params[0] <= -0.25 + 0.25 * i + 1e-12 &&
                                        r.params[1] >= -0.02 + 0.02 * j - 1e-12 &&
                                        r.params[1] <= 0.02 * j + 1e-12;
                    const std::set<int> v{verdictAt(i, j), verdictAt(i + 1, j),
                                          verdictAt(i, j + 1), verdictAt(i + 1, j + 1)};
                    inMixedCell |= inside && v.size() > 1 && !v.count(99);
                }
            QVERIFY(inMixedCell);
        }
        QCOMPARE(refined, int(rows.size()) - 9);
    }

    void dubucDeslauriersIsC2()
    {
        AWB_SKIP_WITHOUT_THREADS();
        AtlasOptions o;
        o.smoothness = 2;
        const AtlasRow r = evaluateAtlasPoint(sixPoint, {-25.0 / 256, 3.0 / 256}, o);
        QVERIFY(r.applies);
        QCOMPARE(r.smoothness, 2);
        QCOMPARE(r.verdict, 1);
        QVERIFY2(r.lower > 2.8 && r.upper < 2.84,
                 qPrintable(QString("[%1, %2]").arg(r.lower).arg(r.upper)));
    }

    void refusesBadGrids()
    {
        const auto refused = [](std::vector<AtlasAxis> axes, AtlasOptions o = {}) {
            try {
                AtlasPlan plan(std::move(axes), o);
            } catch (const InputError &e) {
                return QString(e.what());
            }
            return QString();
        };
        QVERIFY(refused({}).contains("one or two"));
        QVERIFY(refused({{"w", 1, 0, 5}}).contains("from < to"));
        QVERIFY(refused({{"w", 0, NAN, 5}}).contains("finite"));
        QVERIFY(refused({{"w", 0, 1, 1}}).contains("2 to"));
        QVERIFY(refused({{"w", 0, 1, 3000}, {"v", 0, 1, 3000}}).contains("2 to 2000"));
        QVERIFY(refused({{"w", 0, 1, 2000}, {"v", 0, 1, 2000}}).contains("1e6"));
        QVERIFY(refused({{"w", 0, 1, 5}, {"w", 0, 1, 5}}).contains("same name"));
        AtlasOptions deep;
        deep.refineLevels = 40;
        QVERIFY(refused({{"w", 0, 1, 5}, {"v", 0, 1, 5}}, deep).contains("refinement"));
        // Rows that are not the batch's are refused, not merged.
        AtlasPlan plan({{"w", 0, 1, 3}}, {});
        const auto batch = plan.nextBatch();
        QVERIFY_THROWS_EXCEPTION(InputError, plan.accept({}));
    }
};

AWB_TEST_APPLESS_MAIN(TestRegularityAtlas)
#include "test_regularity_atlas.moc"
