// Mathematical fidelity in attractor-cli's output: the whole per-map analysis in analyse --json
// (S with exact fractions, M, A, b, eigenvalues of A), the distance to the exact curve, fixed
// points without an invertible lifting, the dragon's equivalent IFS, start points of the
// lifted space, closed figures drawn closed, and the polygon command (001's figures).

#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"

#include "CliRunner.h"

#include <cmath>

class TestFidelityCli : public QObject {
    Q_OBJECT
private slots:
    void wholeAnalysisOfFig2();
    void certifiedDistanceToExactCurve();
    void fixedPointsWithoutLifting();
    void dragonHasItsIfs();
    void liftedStartPoints();
    void polygonCommand();
    void closedFiguresDrawnClosed();
    void deepCurveIsVectorPathsInSvgAndPdf();
    void normalVectorStartSetInEdgeFrame();

private:
    QString example(const QString &name) const { return awb::test::examplePath(name); }
    int run(const QStringList &args, QByteArray *out = nullptr, QByteArray *err = nullptr)
    {
        return awb::test::runProgram(awb::test::cliPath(), args, out, err);
    }
    QJsonObject analyse(const QString &file, const QString &item)
    {
        QByteArray out, err;
        if (run({"analyse", file, "--item", item, "--json"}, &out, &err) != 0)
            qWarning("%s", err.constData());
        return QJsonDocument::fromJson(out).object()["items"].toArray().first().toObject();
    }
    QTemporaryDir m_dir;
};

void TestFidelityCli::wholeAnalysisOfFig2()
{
    const QJsonObject item = analyse(example("000-fig02-cubic-bspline-from-point.awb"),
                                     "000 Fig. 2: cubic B-spline from a point");
    const QJsonObject map1 = item["maps"].toArray()[0].toObject();
    // S_1 of 000 §2.1, exactly.
    const QJsonArray S = map1["S"].toObject()["exact"].toArray();
    const char *rows[5][5] = {{"1/2", "1/2", "0", "0", "0"}, {"1/8", "3/4", "1/8", "0", "0"},
                              {"0", "1/2", "1/2", "0", "0"}, {"0", "1/8", "3/4", "1/8", "0"},
                              {"0", "0", "1/2", "1/2", "0"}};
    QCOMPARE(S.size(), 5);
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 5; ++c)
            QCOMPARE(S[r].toArray()[c].toString(), QString(rows[r][c]));
    QCOMPARE(map1["S"].toObject()["values"].toArray()[1].toArray()[1].toDouble(), 0.75);
    // M_1 = P^-1 S_1 P = [[A_1, 0], [b_1, 1]]: 5 x 5, A_1 4 x 4, b_1 1 x 4; the spectrum of A_1
    // is that of S_1 without the eigenvalue 1: 1/2, 1/4, 1/8, 0.
    const QJsonArray M = map1["M"].toObject()["values"].toArray();
    QCOMPARE(M.size(), 5);
    QCOMPARE(M[4].toArray()[4].toDouble(), 1.0);
    QCOMPARE(map1["A"].toObject()["values"].toArray().size(), 4);
    QCOMPARE(map1["b"].toObject()["values"].toArray()[0].toArray().size(), 4);
    const QJsonArray evA = map1["eigenvalues_A"].toArray();
    const double want[4] = {0.5, 0.25, 0.125, 0.0};
    for (int k = 0; k < 4; ++k)
        QVERIFY(std::abs(evA[k].toArray()[0].toDouble() - want[k]) < 1e-9);
    // The distance to the exact B-spline at the item's depth, certified: value and one_sided
    // are the midpoints of their brackets.
    const QJsonObject h = item["hausdorff_to_exact"].toObject();
    QVERIFY(h["depth"].toInt() > 8);
    QVERIFY(h["value"].toDouble() > 0 && h["value"].toDouble() < 2e-3);
    QVERIFY(h["one_sided"].toDouble() <= h["value"].toDouble());
    const QJsonArray vb = h["value_bracket"].toArray(), ob = h["one_sided_bracket"].toArray();
    QCOMPARE(vb.size(), 2);
    QVERIFY(vb[0].toDouble() <= h["value"].toDouble() && h["value"].toDouble() <= vb[1].toDouble());
    QVERIFY(ob[0].toDouble() <= h["one_sided"].toDouble());
    QVERIFY(h["one_sided"].toDouble() <= ob[1].toDouble());
    QCOMPARE(h["curve_side_bracket"].toArray().size(), 2);
    QVERIFY(h["converged"].toBool() && h["width"].toDouble() <= 1e-3);
}

void TestFidelityCli::certifiedDistanceToExactCurve()
{
    // The issue's cases, where 4000 samples of the curve measured the sampling: the
    // end-interpolating cubic of 000 Fig. 3 at depth 12 (one-sided 1.3019e-6, which the
    // polyline put at 8.2e-4), and the Takagi image at y = 2^-8, depth 15 from the point 0
    // (the polyline saw d_H = 2.9e-5; it is at least 3.05e-5 = 2^-15, the distance from the
    // curve's end 1 to the nearest point f_2^15(0), which the start {0} never reaches), and
    // from the segment [0, 1] (its ends in the set: half a spacing, 1.54e-5).
    const QString file = m_dir.filePath("certified.awb");
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "attractor-workbench", "version": 1, "items": [
        {"type": "subdivision-curve", "name": "E",
         "scheme": {"kind": "bspline-end-interpolating", "degree": 3},
         "control_points": [[0, 0], [5, 4.5], [5.5, -0.5], [0.5, 3.5], [5, 3]],
         "start_set": {"kind": "triangle", "points": [[1, -1.2], [3.5, -1.5], [2, 0.8]]},
         "algorithm": {"depth": 12, "mode": "deterministic"}},
        {"type": "complex-bezier", "name": "T", "t": [0.5, 0.00390625],
         "control_points": [[0, 0], [1, 0]],
         "start_set": {"kind": "point", "points": [[0, 0]]},
         "algorithm": {"depth": 15, "mode": "deterministic"}},
        {"type": "complex-bezier", "name": "S", "t": [0.5, 0.00390625],
         "control_points": [[0, 0], [1, 0]],
         "start_set": {"kind": "segment", "points": [[0, 0], [1, 0]]},
         "algorithm": {"depth": 15, "mode": "deterministic"}}]})");
    f.close();
    const QJsonObject e = analyse(file, "E")["hausdorff_to_exact"].toObject();
    QCOMPARE(e["depth"].toInt(), 12);
    const QJsonArray eb = e["one_sided_bracket"].toArray();
    QVERIFY2(eb[0].toDouble() > 1.3015e-6 && eb[1].toDouble() < 1.3022e-6,
             qPrintable(QString("%1 %2").arg(eb[0].toDouble()).arg(eb[1].toDouble())));
    QVERIFY(e["converged"].toBool());
    const QJsonObject t = analyse(file, "T")["hausdorff_to_exact"].toObject();
    QCOMPARE(t["depth"].toInt(), 15);
    QVERIFY(t["curve"].toString().contains("Takagi"));
    const QJsonArray tb = t["value_bracket"].toArray();
    QVERIFY2(tb[0].toDouble() >= 3.05e-5, qPrintable(QString::number(tb[0].toDouble())));
    QVERIFY(tb[1].toDouble() - tb[0].toDouble() <= 1e-3 * tb[1].toDouble());
    // The points' own side is far smaller: 2.23e-6 = 0.15 y^2.
    const QJsonArray to = t["one_sided_bracket"].toArray();
    QVERIFY(to[0].toDouble() > 2.2e-6 && to[1].toDouble() < 2.26e-6);
    const QJsonArray sb = analyse(file, "S")["hausdorff_to_exact"].toObject()["value_bracket"]
                              .toArray();
    QVERIFY2(sb[0].toDouble() > 1.53e-5 && sb[1].toDouble() < 1.55e-5,
             qPrintable(QString::number(sb[0].toDouble())));
}

void TestFidelityCli::fixedPointsWithoutLifting()
{
    // A uniform cubic B-spline whose last three control points are collinear: P is singular
    // (NOTES.md), the attractor is drawn in barycentric form, and the fixed point of S_1 is
    // still the curve's start (P0 + 4 P1 + P2)/6, of S_2 its end (P2 + 4 P3 + P4)/6.
    const QString file = m_dir.filePath("singular.awb");
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "attractor-workbench", "version": 1, "items": [
        {"type": "subdivision-curve", "name": "C", "scheme": {"kind": "bspline", "degree": 3},
         "control_points": [[0, 0], [1, 2], [2, 1], [3, 1], [4, 1]]}]})");
    f.close();
    const QJsonObject item = analyse(file, "C");
    QCOMPARE(item["lifting_invertible"].toBool(), false);
    const QJsonArray maps = item["maps"].toArray();
    const QJsonArray p1 = maps[0].toObject()["fixed_point"].toArray();
    const QJsonArray p2 = maps[1].toObject()["fixed_point"].toArray();
    QCOMPARE(p1.size(), 2);
    QVERIFY(std::abs(p1[0].toDouble() - 1.0) < 1e-12);           // (0 + 4 + 2)/6
    QVERIFY(std::abs(p1[1].toDouble() - 9.0 / 6.0) < 1e-12);     // (0 + 8 + 1)/6
    QVERIFY(std::abs(p2[0].toDouble() - 3.0) < 1e-12);           // (2 + 12 + 4)/6
    QVERIFY(std::abs(p2[1].toDouble() - 1.0) < 1e-12);
    QVERIFY(maps[0].toObject()["contractive"].toBool());
    QVERIFY(!maps[0].toObject().contains("M"));  // M_i needs P^-1
}

void TestFidelityCli::dragonHasItsIfs()
{
    const QJsonObject item = analyse(example("001-fig03-dragon-curve.awb"),
                                     "001 Fig. 3(a): dragon curve, 10 steps");
    const QJsonArray maps = item["maps"].toArray();
    QCOMPARE(maps.size(), 2);
    // f1(z) = (1+i) z/2, f2(z) = 1 - (1-i) z/2 in the row form x |-> x A + b.
    const QJsonArray A1 = maps[0].toObject()["A"].toObject()["exact"].toArray();
    const QJsonArray A2 = maps[1].toObject()["A"].toObject()["exact"].toArray();
    const QJsonArray b2 = maps[1].toObject()["b"].toObject()["exact"].toArray()[0].toArray();
    QCOMPARE(A1[0].toArray()[0].toString(), QString("1/2"));
    QCOMPARE(A1[0].toArray()[1].toString(), QString("1/2"));
    QCOMPARE(A1[1].toArray()[0].toString(), QString("-1/2"));
    QCOMPARE(A2[0].toArray()[0].toString(), QString("-1/2"));
    QCOMPARE(A2[1].toArray()[1].toString(), QString("-1/2"));
    QCOMPARE(b2[0].toString(), QString("1"));
    QCOMPARE(b2[1].toString(), QString("0"));
    // |eigenvalues| of each A are 1/sqrt(2): the dragon's ratio.
    for (const QJsonValue &m : maps)
        for (const QJsonValue &z : m.toObject()["eigenvalues_A"].toArray())
            QVERIFY(std::abs(std::hypot(z.toArray()[0].toDouble(), z.toArray()[1].toDouble())
                             - std::sqrt(0.5))
                    < 1e-12);
    QVERIFY(!item["note"].toString().contains("No equivalent IFS"));
}

void TestFidelityCli::liftedStartPoints()
{
    // 000 Fig. 2 starts from a point of the lifted space (5 control points: x, y and 2 extra
    // coordinates, the homogeneous 1 implied).
    const QString fig2 = example("000-fig02-cubic-bspline-from-point.awb");
    const QString name = "000 Fig. 2: cubic B-spline from a point";
    QByteArray out, err;
    QCOMPARE(run({"points", fig2, "--item", name, "--depth", "1", "--start",
                  "lifted:0.3,0.2,0.1,0.4;1,1,0,0", "--csv"},
                 &out, &err),
             0);
    QCOMPARE(out.trimmed().split('\n').size(), 1 + 2 * 2);
    QCOMPARE(run({"points", fig2, "--item", name, "--start", "lifted:0.3,0.2,0.1", "--csv"},
                 &out, &err),
             1);
    QVERIFY2(err.contains("has 4 coordinates") && err.contains("point 1 has 3"), err.constData());
    // In a file: start_set kind "lifted"; a wrong count is refused when the file is read.
    const QString file = m_dir.filePath("lifted.awb");
    const auto write = [&](const QByteArray &points) {
        QFile f(file);
        f.open(QIODevice::WriteOnly);
        f.write(R"({"format": "attractor-workbench", "version": 1, "items": [
            {"type": "subdivision-curve", "name": "C", "scheme": {"kind": "bspline", "degree": 3},
             "control_points": [[0, 0], [1, 2], [3, 2], [4, 0], [5, 1]],
             "start_set": {"kind": "lifted", "points": )" + points + "}}]}");
    };
    write("[[0.5, 0.5, 0.25, 0.25]]");
    QCOMPARE(run({"check", file}, &out, &err), 0);
    QCOMPARE(run({"rewrite", file}, &out, &err), 0);
    QFile back(file);
    QVERIFY(back.open(QIODevice::ReadOnly));
    QVERIFY(back.readAll().contains("\"lifted\""));
    write("[[0.5, 0.5, 0.25]]");
    QCOMPARE(run({"check", file}, &out, &err), 1);
    QVERIFY2(err.contains("start_set") && err.contains("has 4 coordinates"), err.constData());
}

void TestFidelityCli::polygonCommand()
{
    QByteArray out, err;
    const QString file = example("001-fig07-koch-snowflake.awb");
    const QString name = "001 Fig. 7(b): Koch snowflake, negative normals, 5 steps";
    QCOMPARE(run({"polygon", file, "--item", name, "--level", "1", "--json"}, &out, &err), 0);
    const QJsonObject o = QJsonDocument::fromJson(out).object();
    QCOMPARE(o["closed"].toBool(), true);
    QCOMPARE(o["points"].toArray().size(), 12);  // 3 edges, 4 new edges each, closed
    QCOMPARE(run({"polygon", file, "--item", name, "--level", "3", "--json"}, &out, &err), 0);
    QCOMPARE(QJsonDocument::fromJson(out).object()["points"].toArray().size(), 3 * 64);
    // A subdivision curve: classic subdivision, open.
    QCOMPARE(run({"polygon", example("000-fig02-cubic-bspline-from-point.awb"), "--item",
                  "000 Fig. 2: cubic B-spline from a point", "--level", "2", "--json"},
                 &out, &err),
             0);
    QCOMPARE(QJsonDocument::fromJson(out).object()["closed"].toBool(), false);
    QVERIFY(QJsonDocument::fromJson(out).object()["points"].toArray().size() > 5);
}

void TestFidelityCli::closedFiguresDrawnClosed()
{
    // The snowflake's control triangle and its polygon figure are closed: in the SVG every such
    // path returns to its first point; an open curve's control polygon does not.
    const auto paths = [&](const QString &file) {
        QByteArray out, err;
        const QString svg = m_dir.filePath(QFileInfo(file).baseName() + ".svg");
        if (run({"render", example(file), "--out", svg}, &out, &err) != 0)
            return QList<bool>();
        QFile f(svg);
        f.open(QIODevice::ReadOnly);
        const QString text = QString::fromUtf8(f.readAll());
        QList<bool> closed;
        const QRegularExpression re(" d=\"M([-0-9.]+,[-0-9.]+) ([^\"]*)\"");
        for (auto it = re.globalMatch(text); it.hasNext();) {
            const auto m = it.next();
            closed << m.captured(2).trimmed().endsWith("L" + m.captured(1));
        }
        return closed;
    };
    const QList<bool> snowflake = paths("001-fig07-koch-snowflake.awb");
    QVERIFY(snowflake.size() >= 2);
    QVERIFY(snowflake[0]);  // the control triangle
    QVERIFY(snowflake[1]);  // the polygon after 5 steps
    // Open figures are written as polylines, never as closed paths.
    QVERIFY(!paths("001-fig06-koch-curve.awb").contains(true));
    QFile koch(m_dir.filePath("001-fig06-koch-curve.svg"));
    QVERIFY(koch.open(QIODevice::ReadOnly));
    QVERIFY(koch.readAll().contains("<polyline"));
}

// 000 Fig. 5: the four-point curve from a segment at depth 12 (4 096 images, more than the
// per-image vector limit) goes to SVG and PDF as joined paths in address order, not as an
// embedded picture.
void TestFidelityCli::deepCurveIsVectorPathsInSvgAndPdf()
{
    QByteArray out, err;
    const QString svg = m_dir.filePath("four-point.svg"), pdf = m_dir.filePath("four-point.pdf");
    QCOMPARE(run({"render", example("000-fig05-four-point-from-segment.awb"), "--out", svg},
                 &out, &err),
             0);
    QCOMPARE(run({"render", example("000-fig05-four-point-from-segment.awb"), "--out", pdf},
                 &out, &err),
             0);
    QFile s(svg), p(pdf);
    QVERIFY(s.open(QIODevice::ReadOnly) && p.open(QIODevice::ReadOnly));
    const QByteArray svgBytes = s.readAll(), pdfBytes = p.readAll();
    QVERIFY(!svgBytes.contains("<image"));
    QVERIFY(svgBytes.contains("stroke-linecap=\"round\""));
    QVERIFY2(svgBytes.count("<path") < 50, QByteArray::number(svgBytes.count("<path")).constData());
    QVERIFY(!pdfBytes.contains("/Subtype /Image"));
}

// docs/file-format.md: a normal-vector item's start set is read in the unit-edge frame and
// drawn on every edge: depth 0 of the point (0, 0) is each edge's first point, (1, 0) its last.
void TestFidelityCli::normalVectorStartSetInEdgeFrame()
{
    const QString file = example("001-fig07-koch-snowflake.awb");
    const QString name = "001 Fig. 7(b): Koch snowflake, negative normals, 5 steps";
    const auto rows = [&](const QString &start) {
        QByteArray out, err;
        run({"points", file, "--item", name, "--depth", "0", "--start", start, "--csv"}, &out,
            &err);
        QList<QPointF> points;
        const QList<QByteArray> lines = out.trimmed().split('\n');
        for (int i = 1; i < lines.size(); ++i) {
            const QList<QByteArray> f = lines[i].split(',');
            points << QPointF(f[0].toDouble(), f[1].toDouble());
        }
        return points;
    };
    const QList<QPointF> triangle{{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}};
    const QList<QPointF> first = rows("point:0,0"), last = rows("point:1,0");
    QCOMPARE(first.size(), 3);  // one view per edge of the closed triangle
    QCOMPARE(last.size(), 3);
    for (int e = 0; e < 3; ++e) {
        QVERIFY(QLineF(first[e], triangle[e]).length() < 1e-12);
        QVERIFY(QLineF(last[e], triangle[(e + 1) % 3]).length() < 1e-12);
    }
}

AWB_TEST_MAIN(TestFidelityCli)
#include "test_fidelity_cli.moc"
