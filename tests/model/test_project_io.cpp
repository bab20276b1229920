// Project files: the shapes of the issue load exactly as written, save -> load -> save is
// byte-identical, unknown fields survive, every bad-file case gives its own message naming the
// file, the item and the field and leaves the open project untouched, and every JSON example
// of docs/file-format.md loads.

#include "TestProjects.h"

#include "model/ProjectIO.h"

#include <QFileInfo>
#include <QJsonDocument>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QtTest>

#include "TestMain.h"

#include <cstring>

using namespace awb;

namespace {

QByteArray project(const QByteArray &items)
{
    return R"({"format": "attractor-workbench", "version": 1, "items": [)" + items + "]}";
}

// A valid curve item with one field replaced (or added).
QByteArray curveWith(const QByteArray &name, const QByteArray &field, const QByteArray &value)
{
    QJsonObject item{{"type", "subdivision-curve"},
                     {"name", QString::fromUtf8(name)},
                     {"scheme", QJsonObject{{"kind", "bspline"}, {"degree", 3}}},
                     {"control_points", QJsonArray{QJsonArray{0, 0}, QJsonArray{1, 2},
                                                   QJsonArray{3, 2}, QJsonArray{4, 0}}}};
    QByteArray json = QJsonDocument(item).toJson(QJsonDocument::Compact);
    if (!field.isEmpty()) {
        json.chop(1);
        json += ",\"" + field + "\":" + value + "}";
    }
    return json;
}

QByteArray read(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestProjectIO : public QObject {
    Q_OBJECT

private slots:
    void issueShapesLoadExactly()
    {
        const QByteArray json = project(R"(
            {"type": "subdivision-curve", "name": "a", "scheme": {"kind": "bspline", "degree": 3},
             "control_points": [[0, 0], [1, 2.5], [3, 2], [4, -0.125]]},
            {"type": "subdivision-curve", "name": "b",
             "scheme": {"kind": "bezier", "degree": 2, "t": [0.5, 0.25]},
             "control_points": [[0, 0], [1, 1], [2, 0]]},
            {"type": "subdivision-curve", "name": "c",
             "scheme": {"kind": "four-point", "omega": -0.1}, "control_points": []},
            {"type": "subdivision-curve", "name": "d", "scheme": {"kind": "chaikin"},
             "control_points": [[1e-300, 1e300]]},
            {"type": "subdivision-curve", "name": "e",
             "scheme": {"kind": "bspline-end-interpolating"}, "control_points": []},
            {"type": "subdivision-curve", "name": "f",
             "scheme": {"kind": "corner-cutting", "a": 0.125, "b": 0.875}, "control_points": []},
            {"type": "subdivision-curve", "name": "g",
             "scheme": {"kind": "matrices",
                        "matrices": [[[1, 0], [0.5, 0.5]], [[0.5, 0.5], [0, 1]]]},
             "control_points": [[0, 0], [1, 0]]},
            {"type": "subdivision-curve", "name": "h",
             "scheme": {"kind": "bezier", "degree": 3, "t": 0.25}, "control_points": []},
            {"type": "eigenvalue-plot", "name": "i", "source": "a", "matrices": "A"}
        )");
        ProjectData data;
        QString error;
        QVERIFY2(ProjectIO::parse(json, "shapes.awb", &data, &error), qPrintable(error));
        QCOMPARE(data.items.size(), size_t(9));
        auto c = [&](int i) { return dynamic_cast<SubdivisionCurveItem *>(data.items[i].get()); };
        using K = SchemeSpec::Kind;
        QCOMPARE(c(0)->name(), QString("a"));
        QCOMPARE(c(0)->scheme().kind, K::BSpline);
        QCOMPARE(c(0)->scheme().degree, 3);
        QVERIFY(c(0)->controlPoints() == (PointList{{0, 0}, {1, 2.5}, {3, 2}, {4, -0.125}}));
        QCOMPARE(c(1)->scheme().kind, K::Bezier);
        QCOMPARE(c(1)->scheme().degree, 2);
        QCOMPARE(c(1)->scheme().t, std::complex<double>(0.5, 0.25));
        QCOMPARE(c(2)->scheme().omega, -0.1);
        QVERIFY(c(2)->controlPoints().empty());
        QCOMPARE(c(3)->scheme().kind, K::Chaikin);
        QVERIFY(c(3)->controlPoints() == (PointList{{1e-300, 1e300}}));
        QCOMPARE(c(4)->scheme().kind, K::EndInterpolatingBSpline);
        QCOMPARE(c(4)->scheme().degree, 3); // the default
        QCOMPARE(c(5)->scheme().a, 0.125);
        QCOMPARE(c(5)->scheme().b, 0.875);
        QCOMPARE(c(6)->scheme().matrices.size(), size_t(2));
        QCOMPARE(c(6)->scheme().matrices[0](1, 0), 0.5);
        QCOMPARE(c(7)->scheme().t, std::complex<double>(0.25, 0.0));
        auto *plot = dynamic_cast<EigenvaluePlotItem *>(data.items[8].get());
        QVERIFY(plot);
        QCOMPARE(plot->source(), QString("a"));
        QCOMPARE(plot->matrixKind(), EigenvaluePlotItem::MatrixKind::A);
        // The defaults of the optional common fields.
        QVERIFY(c(0)->startSet() == StartSetSpec());
        QVERIFY(c(0)->algorithm() == AlgorithmSpec());
        QVERIFY(c(0)->style() == StyleSpec());
        QCOMPARE(c(0)->startSet().points.size(), size_t(1));
        QCOMPARE(c(0)->algorithm().depth, 8);
        QCOMPARE(c(0)->style().pointSize, 2.0);
    }

    void saveLoadSaveIsByteIdentical()
    {
        QTemporaryDir dir;
        Project p;
        test::fillSampleProject(p);
        // Doubles that need all 17 digits, and every common field away from its default.
        QRandomGenerator rng(42);
        auto *c = dynamic_cast<SubdivisionCurveItem *>(p.findItem("B-spline"));
        for (int i = 0; i < 5; ++i)
            c->moveControlPoint(i, {rng.generateDouble() * 1e3 - 500, rng.generateDouble() / 3});
        c->setStartSet({StartSetSpec::Kind::Polygon, {{0.1, 0.2}, {1.0 / 3, 0.5}, {2, 1e-17}}});
        c->setAlgorithm({AlgorithmSpec::Mode::Random, 11, 777, {0.1, 0.9}, 123456789012});
        c->setStyle({StyleSpec::ColorBy::Address, 2, 0.75, {"#010203", "#abcdef"}});
        const QString first = dir.filePath("first.awb");
        const QString second = dir.filePath("second.awb");
        QVERIFY(p.saveAs(first));
        Project q;
        QString error;
        QVERIFY2(q.open(first, &error), qPrintable(error));
        QVERIFY(!q.isModified());
        QCOMPARE(q.fileName(), first);
        QVERIFY(q.saveAs(second));
        QCOMPARE(read(second), read(first));
        QCOMPARE(q.serialize(), p.serialize());
        // The loaded values are the saved ones, bit for bit.
        auto *d = dynamic_cast<SubdivisionCurveItem *>(q.findItem("B-spline"));
        QVERIFY(d->controlPoints() == c->controlPoints());
        QVERIFY(d->startSet() == c->startSet());
        QVERIFY(d->algorithm() == c->algorithm());
        QVERIFY(d->style() == c->style());
        QCOMPARE(q.findItem("Chaikin")->parentItem(), q.findItem("End-interpolating"));
        const QByteArray text = read(first);
        QVERIFY(text.contains("\"format\": \"attractor-workbench\""));
        QVERIFY(text.contains("\"version\": 1"));
        QVERIFY(text.contains("\"t\": [\n")); // complex t as [re, im]
        QVERIFY(text.contains("Lévy-like")); // UTF-8, not escaped
    }

    void unknownFieldsAreKept()
    {
        const QByteArray json = R"({"format": "attractor-workbench", "version": 1,
            "comment": {"by": "a later version"},
            "items": [{"type": "subdivision-curve", "name": "a", "future_field": [1, 2, 3],
                       "scheme": {"kind": "chaikin", "future_scheme_field": true},
                       "control_points": [[0, 0], [1, 1], [2, 0]]}]})";
        ProjectData data;
        QString error;
        QVERIFY2(ProjectIO::parse(json, "u.awb", &data, &error), qPrintable(error));
        Project p;
        p.adopt(std::move(data), "u.awb", false);
        const QJsonObject root = QJsonDocument::fromJson(p.serialize()).object();
        QCOMPARE(root.value("comment").toObject().value("by").toString(),
                 QString("a later version"));
        const QJsonObject item = root.value("items").toArray().at(0).toObject();
        QCOMPARE(item.value("future_field").toArray().size(), 3);
        // Inside a nested object unknown fields are skipped.
        QVERIFY(!item.value("scheme").toObject().contains("future_scheme_field"));
    }

    void badFiles_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("message"); // after "FILE: "
        QTest::newRow("not JSON") << QByteArray("{\"format\": \"attractor-workbench\",\n  ")
                                  << "not valid JSON: unterminated object at line 2, column 3";
        QTest::newRow("not an object") << QByteArray("[1, 2]")
                                       << "expected a JSON object at the top level";
        QTest::newRow("wrong format")
            << QByteArray(R"({"format": "svg", "version": 1, "items": []})")
            << "field \"format\": expected \"attractor-workbench\": this is not an Attractor "
               "Workbench project";
        QTest::newRow("newer version")
            << QByteArray(R"({"format": "attractor-workbench", "version": 2, "items": []})")
            << "the file has format version 2, written by a newer version of Attractor "
               "Workbench; this version reads format version 1 only. Please update the "
               "application.";
        QTest::newRow("version as string")
            << QByteArray(R"({"format": "attractor-workbench", "version": "1", "items": []})")
            << "field \"version\": expected an integer";
        QTest::newRow("missing items")
            << QByteArray(R"({"format": "attractor-workbench", "version": 1})")
            << "field \"items\": missing";
        QTest::newRow("item not an object") << project("3") << "item 1: expected an object";
        QTest::newRow("missing name")
            << project(R"({"type": "eigenvalue-plot", "source": ""})")
            << "item 1: field \"name\": missing";
        QTest::newRow("unknown type")
            << project(R"({"type": "teapot", "name": "t"})")
            << "item 1 (\"t\"): field \"type\": unknown item type \"teapot\"; this version "
               "knows subdivision-curve, eigenvalue-plot, fractal, bezier-union, normal-vector, "
               "complex-bezier, flame, cifs, bcifs-junction, subdivision-surface, "
               "subdivision-mesh";
        QTest::newRow("missing field")
            << project(R"({"type": "subdivision-curve", "name": "a",
                           "scheme": {"kind": "chaikin"}})")
            << "item 1 (\"a\"): field \"control_points\": missing";
        QTest::newRow("mistyped degree")
            << project(curveWith("ok", "", "") + ","
                       + R"({"type": "subdivision-curve", "name": "name",
                             "scheme": {"kind": "bspline", "degree": 3.5},
                             "control_points": []})")
            << "item 2 (\"name\"): field \"scheme.degree\": expected an integer";
        QTest::newRow("degree as string")
            << project(curveWith("a", "scheme", R"({"kind": "bezier", "degree": "3"})"))
            << "item 1 (\"a\"): field \"scheme.degree\": expected an integer";
        QTest::newRow("degree out of range")
            << project(curveWith("a", "scheme", R"({"kind": "bspline", "degree": 16})"))
            << "item 1 (\"a\"): field \"scheme.degree\": B-spline degree must be between 1 "
               "and 15, got 16";
        QTest::newRow("unknown scheme kind")
            << project(curveWith("a", "scheme", R"({"kind": "loop"})"))
            << "item 1 (\"a\"): field \"scheme.kind\": expected one of \"bspline\", "
               "\"bspline-end-interpolating\", \"chaikin\", \"corner-cutting\", "
               "\"four-point\", \"bezier\", \"matrices\", \"mask\", got \"loop\"";
        QTest::newRow("infinite number")
            << project(curveWith("a", "control_points", "[[0, 0], [1, 1e400]]"))
            << "item 1 (\"a\"): field \"control_points[2][2]\": 1e400 is not a finite number";
        QTest::newRow("NaN")
            << project(curveWith("a", "scheme", R"({"kind": "four-point", "omega": NaN})"))
            << "item 1 (\"a\"): field \"scheme.omega\": NaN is not a finite number";
        QTest::newRow("-Infinity")
            << project(curveWith("a", "start_set",
                                 R"({"kind": "point", "points": [[-Infinity, 0]]})"))
            << "item 1 (\"a\"): field \"start_set.points[1][1]\": -Infinity is not a finite "
               "number";
        // Unknown fields are kept and written back: an invalid number there is refused too
        // (it used to come back as the string "\u001fawb-not-finite:NaN").
        QTest::newRow("NaN in an unknown item field")
            << project(curveWith("a", "future_field", "NaN"))
            << "field \"items[1].future_field\": NaN is not a finite number";
        QTest::newRow("1e999 deep in an unknown field")
            << project(curveWith("a", "future", R"({"x": [1, {"y": 1e999}]})"))
            << "field \"items[1].future.x[2].y\": 1e999 is not a finite number";
        QTest::newRow("Infinity in an unknown root field")
            << QByteArray(R"({"format": "attractor-workbench", "version": 1, "items": [],
                              "extra": -Infinity})")
            << "field \"extra\": -Infinity is not a finite number";
        QTest::newRow("NaN in an ignored field of a known object")
            << project(curveWith("a", "scheme", R"({"kind": "chaikin", "unused": NaN})"))
            << "field \"items[1].scheme.unused\": NaN is not a finite number";
        QTest::newRow("point of one number")
            << project(curveWith("a", "control_points", "[[0, 0], [1]]"))
            << "item 1 (\"a\"): field \"control_points[2]\": expected a point [x, y]";
        QTest::newRow("matrix of the wrong size")
            << project(curveWith("a", "scheme", R"({"kind": "matrices", "matrices": [
                   [[1, 0, 0], [0.5, 0.5, 0], [0, 0.5, 0.5]], [[0.5, 0.5], [0, 1]]]})"))
            << "item 1 (\"a\"): field \"scheme.matrices\": user matrices: matrix S_2 is 2 x 2, "
               "expected 3 x 3 like S_1";
        QTest::newRow("ragged matrix")
            << project(curveWith("a", "scheme", R"({"kind": "matrices", "matrices": [
                   [[1, 0], [0.5, 0.5]], [[0.5, 0.5], [1]]]})"))
            << "item 1 (\"a\"): field \"scheme.matrices[2][2]\": row 2 has 1 numbers, row 1 "
               "has 2";
        QTest::newRow("row not summing to 1")
            << project(curveWith("a", "scheme", R"({"kind": "matrices", "matrices": [
                   [[1, 0, 0], [0.5, 0.5, 0], [0, 0.5, 0.5]],
                   [[0.5, 0.5, 0], [0, 1, 0], [0, 0.5, 0.4]]]})"))
            << "item 1 (\"a\"): field \"scheme.matrices\": user matrices: matrix S_2, row 3 "
               "sums to 0.9, not 1 (subdivision rows are affine combinations)";
        QTest::newRow("absurd depth")
            << project(curveWith("a", "algorithm", R"({"depth": 100})"))
            << "item 1 (\"a\"): field \"algorithm.depth\": depth 100 is absurd: at most 64 is "
               "allowed";
        QTest::newRow("too many images")
            << project(curveWith("a", "algorithm", R"({"depth": 40})"))
            << "item 1 (\"a\"): field \"algorithm.depth\": depth 40 with 2 maps makes 1.1e+12 "
               "images of the start set, more than 2^31: at most depth 31 for 2 maps";
        QTest::newRow("bad start set")
            << project(curveWith("a", "start_set",
                                 R"({"kind": "triangle", "points": [[0, 0], [1, 0]]})"))
            << "item 1 (\"a\"): field \"start_set.points\": a start set of kind \"triangle\" "
               "needs exactly 3 points, got 2";
        QTest::newRow("bad colour")
            // Not a raw string: moc misreads a '#' inside one.
            << project(curveWith("a", "style", "{\"colors\": [\"#00ff00\", \"red\"]}"))
            << "item 1 (\"a\"): field \"style.colors\": colour 2 is \"red\", expected "
               "\"#rrggbb\" (lower-case hexadecimal)";
        QTest::newRow("complex t outside the lens")
            << project(curveWith("a", "scheme", R"({"kind": "bezier", "t": [0.5, 0.9]})"))
            << "item 1 (\"a\"): field \"scheme.t\": the complex parameter t = 0.5 + 0.9i must "
               "satisfy |t| < 1 and |1 - t| < 1 (004 §3.7)";
        QTest::newRow("plot matrices")
            << project(R"({"type": "eigenvalue-plot", "name": "p", "source": "x",
                           "matrices": "B"})")
            << "item 1 (\"p\"): field \"matrices\": expected one of \"S\", \"A\", \"M\", "
               "got \"B\"";
        QTest::newRow("duplicate name")
            << project(curveWith("twin", "", "") + "," + curveWith("twin", "", ""))
            << "item 2 (\"twin\"): field \"name\": another item is already called \"twin\"";
        QTest::newRow("bad child")
            << project(curveWith("a", "children",
                                 "[" + curveWith("b", "", "") + ","
                                     + curveWith("c", "algorithm", R"({"mode": "chaos"})")
                                     + "]"))
            << "item 1.2 (\"c\"): field \"algorithm.mode\": expected one of \"deterministic\", "
               "\"random\", got \"chaos\"";
    }

    void badFiles()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, message);
        QTemporaryDir dir;
        // An open project with a file, unsaved edits and undo history.
        const QString good = dir.filePath("good.awb");
        {
            Project p;
            test::fillSampleProject(p);
            QVERIFY(p.saveAs(good));
        }
        Project p;
        QVERIFY(p.open(good));
        p.findItem("Chaikin")->setName("Chaikin (edited)");
        const QByteArray before = p.serialize();
        const int undoIndex = p.undoStack()->index();
        QVERIFY(p.isModified());

        const QString bad = dir.filePath("bad.awb");
        QVERIFY(test::writeBytes(bad, content));
        QString error;
        QVERIFY(!p.open(bad, &error));
        QCOMPARE(error, bad + ": " + message);

        QCOMPARE(p.serialize(), before);
        QCOMPARE(p.fileName(), good);
        QCOMPARE(p.undoStack()->index(), undoIndex);
        QVERIFY(p.isModified());
        QVERIFY(p.findItem("Chaikin (edited)"));
    }

    void missingFile()
    {
        Project p;
        QString error;
        QVERIFY(!p.open("/nonexistent/dir/x.awb", &error));
        QVERIFY2(error.startsWith("/nonexistent/dir/x.awb: cannot open: "), qPrintable(error));
    }

    void failedSaveKeepsTheProjectModified()
    {
        Project p;
        test::fillSampleProject(p);
        QTemporaryDir dir;
        QString error;
        const QString path = dir.filePath("missing-dir/x.awb");
        QVERIFY(!p.saveAs(path, &error));
        QVERIFY2(error.startsWith(path + ": cannot save: "), qPrintable(error));
        QVERIFY(p.isModified());
        QVERIFY(p.fileName().isEmpty());
        QVERIFY(!p.save(&error)); // no file name yet
    }

    void numbersRoundTripExactly()
    {
        QRandomGenerator rng(7);
        PointList points;
        // As many points as an item takes (AttractorItem::maxControlPoints).
        for (int i = 0; i < AttractorItem::maxControlPoints; ++i) {
            // Random bit patterns: every exponent and all 53 bits of mantissa.
            double x, y;
            do {
                const quint64 bits = rng.generate64();
                std::memcpy(&x, &bits, sizeof x);
            } while (!std::isfinite(x));
            y = (rng.generateDouble() - 0.5) * std::pow(10.0, rng.bounded(-300, 300));
            points.push_back({x, y});
        }
        Project p;
        p.addItem(test::curve("n", test::scheme(SchemeSpec::Kind::Chaikin), points));
        ProjectData data;
        QString error;
        QVERIFY2(ProjectIO::parse(p.serialize(), "n.awb", &data, &error), qPrintable(error));
        const auto *c = dynamic_cast<SubdivisionCurveItem *>(data.items[0].get());
        QCOMPARE(c->controlPoints().size(), points.size());
        for (size_t i = 0; i < points.size(); ++i) {
            // Bit-exact, -0.0 aside (JSON has one zero).
            QVERIFY(c->controlPoints()[i].x == points[i].x);
            QVERIFY(c->controlPoints()[i].y == points[i].y);
        }
    }

    void documentedExamplesLoad()
    {
        // CTest sets AWB_SOURCE_DIR; run by hand, the source tree is two levels above this file.
        const QString source = qEnvironmentVariable(
            "AWB_SOURCE_DIR", QFileInfo(QStringLiteral(__FILE__)).absoluteDir().filePath("../.."));
        const QByteArray doc = read(source + "/docs/file-format.md");
        QVERIFY(!doc.isEmpty());
        static const QRegularExpression block("```json\\n(.*?)```",
                                              QRegularExpression::DotMatchesEverythingOption);
        int examples = 0;
        for (auto it = block.globalMatch(QString::fromUtf8(doc)); it.hasNext();) {
            QByteArray json = it.next().captured(1).toUtf8();
            QJsonParseError pe;
            const QJsonObject object = QJsonDocument::fromJson(json, &pe).object();
            QVERIFY2(pe.error == QJsonParseError::NoError, json.constData());
            if (object.contains("type")) // an item on its own
                json = project(json);
            ProjectData data;
            QString error;
            QVERIFY2(ProjectIO::parse(json, "file-format.md", &data, &error),
                     qPrintable(error));
            for (const auto &item : data.items) // and each item computes, the plots aside
                if (auto *a = dynamic_cast<AttractorItem *>(item.get()))
                    QVERIFY2(a->derivedIfs(), qPrintable(a->derivedError()));
            ++examples;
        }
        QCOMPARE(examples, 16);
    }
};

AWB_TEST_GUILESS_MAIN(TestProjectIO)
#include "test_project_io.moc"
