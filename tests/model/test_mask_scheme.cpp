// A curve scheme typed in by its mask (issue 32): {"kind": "mask", "arity": N, "mask": [a_k],
// "offset": k0}. The built-in uniform schemes given by their masks (written from their rules
// in 004: eq. (2.7) for B-splines, (2.10) for the four-point scheme, (3.27) for Chaikin) give
// the same subdivision matrices S_i bit for bit; exact fractions and expressions are kept as
// typed; every coset must sum to 1, and the message names the one that does not; the
// Properties dock's parameters edit it in one undo step each; switching the kind to "mask" or
// "own matrices" starts from the scheme the curve had (a valid one).

#include "ItemKindTests.h"
#include "TestMain.h"

#include "core/schemes/Scheme.h"
#include "model/ProjectIO.h"
#include "model/SchemeRegularity.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonObject>

using namespace awb;

Q_DECLARE_METATYPE(awb::SchemeSpec)

class TestMaskScheme : public QObject {
    Q_OBJECT
private slots:
    void builtInSchemesByTheirMasks_data();
    void builtInSchemesByTheirMasks();
    void exactEntriesAreKept();
    void cosetSumsAreChecked();
    void parametersEditTheMask();
    void switchingKindStartsFromTheCurve();
    void symbolCountsSumRules();
    void longMasksAreNotAnalysed();
};

namespace {

PointList points(int m)
{
    PointList p;
    for (int i = 0; i < m; ++i)
        p.push_back({double(i), (i % 3) * 0.7 - double(i % 2)});
    return p;
}

SchemeSpec maskSpec(int arity, const QString &line, int offset)
{
    SchemeSpec s;
    s.kind = SchemeSpec::Kind::Mask;
    s.maskArity = arity;
    s.maskOffset = offset;
    QString why;
    if (!s.setMaskLine(line, &why))
        qFatal("%s", qPrintable(why));
    return s;
}

double binomial(int n, int k)
{
    double r = 1;
    for (int i = 1; i <= k; ++i)
        r = r * (n - k + i) / i;
    return r;
}

} // namespace

void TestMaskScheme::builtInSchemesByTheirMasks_data()
{
    QTest::addColumn<SchemeSpec>("builtIn");
    QTest::addColumn<SchemeSpec>("mask");
    // B-spline of degree d (Lane-Riesenfeld, 004 eq. 2.7): a_k = C(d + 1, k + d - 1) / 2^d for
    // k = 1 - d .. 2.
    for (int d = 1; d <= 6; ++d) {
        QStringList line;
        for (int i = 0; i <= d + 1; ++i)
            line << QStringLiteral("%1/%2").arg(binomial(d + 1, i)).arg(1 << d);
        SchemeSpec b;
        b.degree = d;
        QTest::addRow("B-spline %d", d) << b << maskSpec(2, line.join(", "), 1 - d);
    }
    SchemeSpec chaikin;
    chaikin.kind = SchemeSpec::Kind::Chaikin;
    QTest::addRow("Chaikin") << chaikin << maskSpec(2, "1/4, 3/4, 3/4, 1/4", -1);
    SchemeSpec cut;
    cut.kind = SchemeSpec::Kind::CornerCutting;
    cut.a = 0.125;
    cut.b = 0.625;
    // even points at b on (p_(i-1), p_i), odd ones at a on (p_i, p_(i+1)): a, b, 1 - a, 1 - b
    QTest::addRow("corner cutting") << cut << maskSpec(2, "1/8, 5/8, 7/8, 3/8", -1);
    for (const double omega : {1.0 / 16, 0.1, -0.05}) {
        SchemeSpec four;
        four.kind = SchemeSpec::Kind::FourPoint;
        four.omega = omega;
        const QString w = QString::number(omega, 'g', 17);
        QTest::addRow("four-point %g", omega)
            << four
            << maskSpec(2, QStringLiteral("-%1, 0, 1/2 + %1, 1, 1/2 + %1, 0, -%1").arg(w), -3);
    }
}

void TestMaskScheme::builtInSchemesByTheirMasks()
{
    QFETCH(SchemeSpec, builtIn);
    QFETCH(SchemeSpec, mask);
    QVERIFY(!mask.check());
    const auto a = builtIn.makeScheme(), b = mask.makeScheme();
    QCOMPARE(b->arity(), a->arity());
    QCOMPARE(b->minControlPoints(), a->minControlPoints());
    for (int m = a->minControlPoints(); m <= a->minControlPoints() + 4; ++m) {
        const SubdivisionMatrices x = a->matrices(m), y = b->matrices(m);
        QCOMPARE(y.overlap, x.overlap);
        QCOMPARE(y.S.size(), x.S.size());
        for (size_t i = 0; i < x.S.size(); ++i) {
            QCOMPARE(y.S[i].rows(), x.S[i].rows());
            QVERIFY2((y.S[i] - x.S[i]).cwiseAbs().maxCoeff() <= 1e-15,
                     qPrintable(QStringLiteral("S_%1 for m = %2").arg(i + 1).arg(m)));
        }
    }
    // The whole item: the same IFS, hence the same points.
    Project project;
    auto *p = project.addItem(test::curve("built-in", builtIn, points(8)));
    auto *q = project.addItem(test::curve("mask", mask, points(8)));
    const auto dp = static_cast<AttractorItem *>(p)->derivedIfs();
    const auto dq = static_cast<AttractorItem *>(q)->derivedIfs();
    QVERIFY(dp && dq);
    QCOMPARE(dq->ifs.size(), dp->ifs.size());
    for (int i = 0; i < dp->ifs.size(); ++i)
        QVERIFY((dq->ifs.maps[size_t(i)].A - dp->ifs.maps[size_t(i)].A).cwiseAbs().maxCoeff()
                <= 1e-12);
}

void TestMaskScheme::exactEntriesAreKept()
{
    // Daubechies' D4 (Daubechies & Lagarias 1992), typed as expressions: read, written back
    // as typed; plain numbers stay numbers.
    Project project;
    const SchemeSpec d4 = maskSpec(
        2, "(1 + sqrt(3))/4, (3 + sqrt(3))/4, (3 - sqrt(3))/4, (1 - sqrt(3))/4", 0);
    auto *item = static_cast<SubdivisionCurveItem *>(project.addItem(test::curve("D4", d4,
                                                                                 points(6))));
    QVERIFY(item->derivedIfs());
    QJsonObject json;
    item->write(json);
    const QJsonObject scheme = json["scheme"].toObject();
    const QJsonArray mask = scheme["mask"].toArray();
    QCOMPARE(mask.size(), 4);
    QCOMPARE(mask[0].toString(), QStringLiteral("(1 + sqrt(3))/4"));
    QCOMPARE(scheme["kind"].toString(), QStringLiteral("mask"));
    QCOMPARE(scheme["offset"].toInt(), 0);
    QCOMPARE(scheme["arity"].toInt(), 2);

    const QByteArray saved = project.serialize();
    ProjectData data;
    QString error;
    QVERIFY2(ProjectIO::parse(saved, "d4.awb", &data, &error), qPrintable(error));
    Project copy;
    copy.adopt(std::move(data), "d4.awb", false);
    const auto *back = static_cast<const SubdivisionCurveItem *>(copy.items().front());
    QCOMPARE(back->scheme().maskText, d4.maskText);
    QCOMPARE(back->scheme().mask, d4.mask);
    QCOMPARE(copy.serialize(), saved);

    QCOMPARE(maskSpec(2, "0.25, 0.75, 0.75, 0.25", -1).maskText,
             (QStringList{QString(), QString(), QString(), QString()}));
    QCOMPARE(maskSpec(2, "0,25; 0,75; 0,75; 0,25", -1).mask,
             (std::vector<double>{0.25, 0.75, 0.75, 0.25}));
    QCOMPARE(maskSpec(2, "1 3 3 1", -1).mask.size(), size_t(4));
}

void TestMaskScheme::cosetSumsAreChecked()
{
    const auto problem = maskSpec(2, "1/4, 3/4, 7/10, 1/4", -1).check();
    QVERIFY(problem);
    QCOMPARE(problem->field, QStringLiteral("mask"));
    QVERIFY2(problem->message.contains("k = 1 mod 2 sum to 0.95, not 1"),
             qPrintable(problem->message));
    // Ternary: three cosets.
    const auto ternary = maskSpec(3, "1/3, 2/3, 1, 2/3, 1/3", -2).check();
    QVERIFY2(!ternary, qPrintable(ternary ? ternary->message : QString()));
    const auto off = maskSpec(3, "1/3, 2/3, 1, 2/3, 1/2", -2).check();
    QVERIFY(off);
    QVERIFY2(off->message.contains("k = 2 mod 3 sum to 1.1666"), qPrintable(off->message));

    // In a file: the field's path and the coset; a non-number names its entry.
    ProjectData data;
    QString error;
    const QByteArray bad = R"({"format": "attractor-workbench", "version": 1, "items": [
        {"type": "subdivision-curve", "name": "m", "control_points": [[0,0],[1,1],[2,0],[3,1]],
         "scheme": {"kind": "mask", "arity": 2, "mask": ["1/4", "3/4", "three quarters", "1/4"],
                    "offset": -1}}]})";
    QVERIFY(!ProjectIO::parse(bad, "bad.awb", &data, &error));
    QVERIFY2(error.contains("scheme.mask[3]") && error.contains("\"three quarters\" is not a"),
             qPrintable(error));
}

void TestMaskScheme::parametersEditTheMask()
{
    Project project;
    auto *c = static_cast<SubdivisionCurveItem *>(
        project.addItem(test::curve("c", maskSpec(2, "1/8, 1/2, 3/4, 1/2, 1/8", -2), points(7))));
    QStringList keys;
    for (const ParameterInfo &p : test::ownParameters(*c))
        keys << p.key;
    QCOMPARE(keys, (QStringList{"scheme.kind", "scheme.arity", "scheme.mask", "scheme.offset",
                                "scheme.symbol"}));
    QVERIFY(test::ownParameters(*c).at(4).readOnly);
    QCOMPARE(c->parameter("scheme.mask").toString(), QStringLiteral("1/8, 1/2, 3/4, 1/2, 1/8"));

    const int steps = project.undoStack()->count();
    QVERIFY(c->setParameter("scheme.mask", QStringLiteral("1/4, 3/4, 3/4, 1/4")));
    QCOMPARE(project.undoStack()->count(), steps + 1);
    QCOMPARE(c->mapCount(), 2);
    QVERIFY(c->derivedIfs());
    project.undoStack()->undo();
    QCOMPARE(c->parameter("scheme.mask").toString(), QStringLiteral("1/8, 1/2, 3/4, 1/2, 1/8"));

    QString error;
    QVERIFY(!c->setParameter("scheme.mask", QStringLiteral("1/4, 3/4, 1, 1/4"), 0, &error));
    QVERIFY2(error.contains("sum to 1.25, not 1"), qPrintable(error));
    QVERIFY(!c->setParameter("scheme.mask", QStringLiteral("1/4, x, 1, 1/4"), 0, &error));
    QVERIFY2(error.contains("mask entry 2, \"x\""), qPrintable(error));
    QVERIFY(!c->setParameter("scheme.symbol", QStringLiteral("1"), 0, &error));
    QCOMPARE(project.undoStack()->count(), steps + 1);  // the undone edit is still there to redo

    // A new arity the mask does not fit starts from the N-ary piecewise linear mask.
    QVERIFY(c->setParameter("scheme.arity", 3));
    QCOMPARE(c->mapCount(), 3);
    QCOMPARE(c->parameter("scheme.mask").toString(), QStringLiteral("1/3, 2/3, 1, 2/3, 1/3"));
    QCOMPARE(c->parameter("scheme.offset").toInt(), -2);
    QVERIFY(c->derivedIfs());
    project.undoStack()->undo();
    QCOMPARE(c->mapCount(), 2);
}

void TestMaskScheme::switchingKindStartsFromTheCurve()
{
    Project project;
    SchemeSpec four;
    four.kind = SchemeSpec::Kind::FourPoint;
    auto *c = static_cast<SubdivisionCurveItem *>(
        project.addItem(test::curve("c", four, points(8))));
    const Mat before = c->derivedIfs()->ifs.maps[1].A;
    QVERIFY(c->setParameter("scheme.kind", int(SchemeSpec::Kind::Mask)));
    QCOMPARE(c->parameter("scheme.mask").toString(),
             QStringLiteral("-1/16, 0, 9/16, 1, 9/16, 0, -1/16"));
    QCOMPARE(c->parameter("scheme.offset").toInt(), -3);
    QVERIFY((c->derivedIfs()->ifs.maps[1].A - before).cwiseAbs().maxCoeff() <= 1e-15);

    // Own matrices: today's S_i for today's points, so the dock has something valid to edit
    // (before, this switch was refused: "an IFS needs at least two matrices, got 0").
    QString error;
    QVERIFY2(c->setParameter("scheme.kind", int(SchemeSpec::Kind::Matrices), 0, &error),
             qPrintable(error));
    QCOMPARE(c->scheme().matrices.size(), size_t(2));
    QCOMPARE(c->scheme().matrices[0].rows(), Eigen::Index(8));
    QVERIFY((c->derivedIfs()->ifs.maps[1].A - before).cwiseAbs().maxCoeff() <= 1e-12);

    // From a Bézier curve (no mask): the cubic B-spline's.
    SchemeSpec bezier;
    bezier.kind = SchemeSpec::Kind::Bezier;
    auto *b = static_cast<SubdivisionCurveItem *>(
        project.addItem(test::curve("b", bezier, points(4))));
    QVERIFY(b->setParameter("scheme.kind", int(SchemeSpec::Kind::Mask)));
    QCOMPARE(b->parameter("scheme.mask").toString(), QStringLiteral("1/8, 1/2, 3/4, 1/2, 1/8"));
    QVERIFY(b->setParameter("scheme.kind", int(SchemeSpec::Kind::Bezier)));
    QVERIFY(b->setParameter("scheme.kind", int(SchemeSpec::Kind::Matrices)));
    QCOMPARE(b->scheme().matrices.size(), size_t(2));
}

void TestMaskScheme::symbolCountsSumRules()
{
    QVERIFY2(maskSpec(2, "1/8, 1/2, 3/4, 1/2, 1/8", -2).symbolText().startsWith("4 sum rules"),
             qPrintable(maskSpec(2, "1/8, 1/2, 3/4, 1/2, 1/8", -2).symbolText()));
    // The four-point scheme: a(z) = (1 + z)^4 (-1 + 4z - z^2) / 16 z^-3 (typographic minus).
    const QString four = maskSpec(2, "-1/16, 0, 9/16, 1, 9/16, 0, -1/16", -3).symbolText();
    QVERIFY2(four.startsWith("4 sum rules") && four.contains(QStringLiteral("σ(z)⁴ b(z) / 2⁴")) && four.contains(QStringLiteral("b = (−1, 4, −1) from z⁻³")),
             qPrintable(four));
    QVERIFY(maskSpec(3, "1/3, 2/3, 1, 2/3, 1/3", -2).symbolText().startsWith("2 sum rules"));
    const QString d4 = maskSpec(
        2, "(1 + sqrt(3))/4, (3 + sqrt(3))/4, (3 - sqrt(3))/4, (1 - sqrt(3))/4", 0).symbolText();
    QVERIFY2(d4.startsWith("2 sum rules"), qPrintable(d4));
}

void TestMaskScheme::longMasksAreNotAnalysed()
{
    // 119 coefficients (transition matrices 118 x 118): a message, at once, not minutes.
    QStringList line(119, QStringLiteral("0"));
    line[0] = line[118] = QStringLiteral("1/2");
    line[1] = QStringLiteral("1");
    SchemeSpec s = maskSpec(2, line.join(", "), 0);
    QVERIFY2(!s.check(), qPrintable(s.check() ? s.check()->message : QString()));
    QElapsedTimer t;
    t.start();
    const Regularity r = specRegularity(s, 8);
    QVERIFY(!r.applies);
    QVERIFY2(QString::fromStdString(r.message).contains("the regularity analysis takes at most 49"),
             r.message.c_str());
    QVERIFY(t.elapsed() < 5000);
}

AWB_TEST_GUILESS_MAIN(TestMaskScheme)
#include "test_mask_scheme.moc"
