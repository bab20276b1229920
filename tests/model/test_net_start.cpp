// The start set of net points (StartSetSpec::Kind::Net, file kind "net"): control points by
// index, taken as the lifted space has them -- the rows of the lifted P of 000 §2 -- so that the
// set follows the net when a point moves. 000 Fig. 7 starts "with a single triangle" whose
// corners are net points 0, 9 and 18: as a triangle of coordinates it stayed behind when net
// point 9 was dragged and iterated to scattered pieces; as net points it moves with the net.

#include "TestPaths.h"
#include "ItemKindTests.h"

#include "core/ifs/Attractor.h"
#include "core/ifs/SurfaceIfs.h"
#include "model/Project.h"
#include "model/StartSetText.h"
#include "model/SubdivisionCurveItem.h"
#include "model/SubdivisionSurfaceItem.h"
#include "TestMain.h"

#include <Eigen/Geometry>
#include <QJsonArray>
#include <QJsonDocument>

using namespace awb;

namespace {

const QString kFig7 = QStringLiteral("000 Fig. 7: box-spline hexagon from a triangle");

bool openExample(Project &p, const QString &file, QString *error)
{
    ProjectData data;
    if (!ProjectIO::readFile(test::sourceDir() + "/examples/" + file, &data, error))
        return false;
    p.adopt(std::move(data), {}, false);
    return true;
}

// F^depth(X0) drawn (the item's first view), one row per vertex, in the iteration's order.
Mat drawnImages(const AttractorItem &item, const StartSet &start, int depth)
{
    const auto d = item.derivedIfs();
    PointCollector points(d->ifs.views.front());
    iterate(d->ifs, start, depth, points);
    return points.points();
}

} // namespace

class TestNetStart : public QObject {
    Q_OBJECT
private slots:
    void fig7StartsFromItsNetPoints();
    void theStartFollowsADraggedPoint();
    void curvesAndTheBarycentricForm();
    void fileFormatAndRefusals_data();
    void fileFormatAndRefusals();
    void typedIndicesAreOneUndoStep();
    void theStartFollowsTheNetsCount();
    void aNewNetRefitsTheStart();
    void startTextReadsNetPoints();
};

// The examples of 000 Figs. 6-9 start from triangles of net points, drawn at depth 0 as those
// points. Where the corners are rows of the lifting without identity entries (Figs. 6, 7, 9),
// whose lifted points are the plane points with zero extra coordinates, they draw the very
// images the triangles of the same coordinates drew; Fig. 8's free rows are others (0, 18 and
// 36 are not the largest simplex of its net), so its lifted corners differ from the plane
// points' and its finite levels with them (the same attractor).
void TestNetStart::fig7StartsFromItsNetPoints()
{
    const std::vector<std::tuple<QString, std::vector<int>, bool>> examples = {
        {"000-fig06-bicubic-patch.awb", {0, 3, 15}, true},
        {"000-fig07-box-spline-hexagon.awb", {0, 9, 18}, true},
        {"000-fig08-sqrt3-surface.awb", {0, 18, 36}, false},
        {"000-fig09-box-spline-subset.awb", {0, 9, 18}, true}};
    for (const auto &[file, net, freeRows] : examples) {
        Project p;
        QString error;
        QVERIFY2(openExample(p, file, &error), qPrintable(error));
        for (Item *any : p.items()) {
            auto *item = qobject_cast<SubdivisionSurfaceItem *>(any);
            QVERIFY(item);
            QCOMPARE(item->startSet().kind, StartSetSpec::Kind::Net);
            QCOMPARE(item->startSet().net, net);
            const auto d = item->derivedIfs();
            QVERIFY2(d, qPrintable(item->derivedError()));
            const StartSet start = item->coreStartSet(*d);
            QVERIFY(start.kind == StartSet::Kind::Polygon);
            // The same triangle as the plane points of the net, lifted.
            Mat corners(3, 3);
            for (int k = 0; k < 3; ++k) {
                const Point c = item->controlPoints()[std::size_t(net[std::size_t(k)])];
                corners.row(k) << c.x, c.y, c.z;
            }
            const Mat drawn = drawnImages(*item, start, 0);
            QVERIFY2((drawn - corners).cwiseAbs().maxCoeff() < 1e-12, qPrintable(file));
            const std::vector<int> &free = d->surface->ifs.lifting.freeRows;
            QCOMPARE(std::all_of(net.begin(), net.end(),
                                 [&](int r) {
                                     return std::find(free.begin(), free.end(), r) != free.end();
                                 }),
                     freeRows);
            if (!freeRows)
                continue;
            const Mat lifted = d->toIfsSpace(corners);
            QVERIFY2((start.vertices - lifted).cwiseAbs().maxCoeff() < 1e-12,
                     qPrintable(file));
            const Mat a = drawnImages(*item, start, 3);
            const Mat b = drawnImages(*item, StartSet::polygon(lifted), 3);
            QCOMPARE(a.rows(), b.rows());
            QVERIFY2((a - b).cwiseAbs().maxCoeff() < 1e-12, qPrintable(file));
        }
    }
}

// Net point 9 of 000 Fig. 7 dragged: the start's corner moves with it (the drawn start is the
// new net's points 0, 9, 18), and F^k(X0) still tiles the patch -- its level-k triangles cover
// the same area as those of the moved net's own corner-limit start (within the few per cent by
// which a start triangle's images overlap), where the triangle left behind covers far less or
// far more.
void TestNetStart::theStartFollowsADraggedPoint()
{
    Project p;
    QString error;
    QVERIFY2(openExample(p, "000-fig07-box-spline-hexagon.awb", &error), qPrintable(error));
    auto *item = qobject_cast<SubdivisionSurfaceItem *>(p.findItem(kFig7));
    QVERIFY(item);
    const auto before = item->derivedIfs();
    const StartSet oldStart = item->coreStartSet(*before);
    PointList net = item->controlPoints();
    net[9] = {net[9].x + 0.3, net[9].y - 0.2, net[9].z + 0.5};
    QVERIFY(item->setControlPoints(0, net));
    const auto d = item->derivedIfs();
    QVERIFY2(d, qPrintable(item->derivedError()));
    const StartSet start = item->coreStartSet(*d);
    // Depth 0: the start drawn is the moved net's points.
    const Mat drawn = drawnImages(*item, start, 0);
    QCOMPARE(drawn.rows(), Eigen::Index(3));
    for (int k = 0; k < 3; ++k) {
        const Point c = net[std::size_t(item->startSet().net[std::size_t(k)])];
        QVERIFY((drawn.row(k) - RowVec((RowVec(3) << c.x, c.y, c.z).finished())).norm() < 1e-12);
    }
    // Its coefficients on the net are unit vectors: the weights of the 3D view's drags.
    const Projection c = d->surface->ifs.netCoordinates();
    const Mat coefficients = (start.vertices * c.V).rowwise() + c.c;
    for (int k = 0; k < 3; ++k)
        QVERIFY((coefficients.row(k)
                 - RowVec(RowVec::Unit(coefficients.cols(), item->startSet().net[std::size_t(k)])))
                    .cwiseAbs()
                    .maxCoeff()
                < 1e-12);
    // The level-3 triangles' total area against the tiling start's (the patch itself).
    const auto area = [&](const StartSet &s) {
        const Mat v = drawnImages(*item, s, 3);
        double total = 0;
        for (Eigen::Index t = 0; t + 2 < v.rows(); t += 3) {
            const Eigen::Vector3d a = v.row(t).transpose(), b = v.row(t + 1).transpose(),
                                  e = v.row(t + 2).transpose();
            total += 0.5 * (b - a).cross(e - a).norm();
        }
        return total;
    };
    const double tiling = area(StartSet::polygon(d->surface->cornerLimitStart));
    const double following = area(start);
    QVERIFY2(std::abs(following / tiling - 1) < 0.5,
             qPrintable(QString("%1 %2").arg(following).arg(tiling)));
    // The same coordinates as before the move, lifted by the new net (what a "triangle" start
    // set would iterate): not the net's triangle any more.
    Mat oldCorners = project(before->ifs.views.front(), oldStart.vertices);
    const Mat leftBehind = d->toIfsSpace(oldCorners);
    QVERIFY((leftBehind - start.vertices).cwiseAbs().maxCoeff() > 0.1);
}

// A curve: one index is a point, two a segment; the drawn start is the control points. A net
// in a line (singular P, the barycentric form) starts from unit vectors, drawn as the points.
void TestNetStart::curvesAndTheBarycentricForm()
{
    for (const bool collinear : {false, true}) {
        Project p;
        QString error;
        const QByteArray points = collinear ? "[[0,0],[1,0],[2,0],[3,0],[4,0]]"
                                            : "[[0,0],[1,2],[3,2],[4,0],[5,1]]";
        QVERIFY2(test::load(p,
                            R"({"type": "subdivision-curve", "name": "C",
                                "scheme": {"kind": "bspline", "degree": 3},
                                "control_points": )" + points + R"(,
                                "start_set": {"kind": "net", "points": [1, 4]}})",
                            &error),
                 qPrintable(error));
        auto *item = qobject_cast<AttractorItem *>(p.findItem("C"));
        const auto d = item->derivedIfs();
        QVERIFY2(d, qPrintable(item->derivedError()));
        QCOMPARE(d->subdivision->barycentric(), collinear);
        const StartSet start = item->coreStartSet(*d);
        QVERIFY(start.kind == StartSet::Kind::Polyline);
        if (collinear)
            QCOMPARE(start.vertices.row(1), RowVec(RowVec::Unit(5, 4)));
        const Mat drawn = drawnImages(*item, start, 0);
        const PointList &P = item->controlPoints(0);
        QCOMPARE(drawn.rows(), Eigen::Index(2));
        QVERIFY(std::abs(drawn(0, 0) - P[1].x) < 1e-12 && std::abs(drawn(0, 1) - P[1].y) < 1e-12);
        QVERIFY(std::abs(drawn(1, 0) - P[4].x) < 1e-12 && std::abs(drawn(1, 1) - P[4].y) < 1e-12);
        // Saved as indices, read back the same.
        QVERIFY(p.serialize().contains(R"("start_set":{"kind":"net","points":[1,4]})")
                || QJsonDocument::fromJson(p.serialize())
                           .object()["items"]
                           .toArray()[0]
                           .toObject()["start_set"]
                       == QJsonObject({{"kind", "net"}, {"points", QJsonArray{1, 4}}}));
        QVERIFY(test::reloadsIdentically(p));
    }
}

void TestNetStart::fileFormatAndRefusals_data()
{
    QTest::addColumn<QByteArray>("item");
    QTest::addColumn<QString>("expected");
    const QByteArray curve = R"({"type": "subdivision-curve", "name": "C",
        "scheme": {"kind": "bspline", "degree": 3},
        "control_points": [[0,0],[1,2],[3,2],[4,0],[5,1]], "start_set": )";
    QTest::newRow("past the net") << curve + R"({"kind": "net", "points": [0, 5]}})"
                                  << "net point 2 of the start set has the index 5; this item has "
                                     "5 control points (indices 0 to 4)";
    QTest::newRow("negative") << curve + R"({"kind": "net", "points": [-1]}})"
                              << "expected a net point index (an integer from 0)";
    QTest::newRow("fraction") << curve + R"({"kind": "net", "points": [1.5]}})"
                              << "expected a net point index (an integer from 0)";
    QTest::newRow("empty") << curve + R"({"kind": "net", "points": []}})"
                           << "a start set of net points needs at least one index";
    QTest::newRow("points, not indices")
        << curve + R"({"kind": "net", "points": [[0, 0]]}})" << "expected a number";
    QTest::newRow("no net")
        << QByteArray(R"({"type": "normal-vector", "name": "N", "preset": "levy",
                          "control_points": [[0, 0], [1, 0]],
                          "start_set": {"kind": "net", "points": [0]}})")
        << "is for items whose IFS is built from one control net";
}

void TestNetStart::fileFormatAndRefusals()
{
    QFETCH(QByteArray, item);
    QFETCH(QString, expected);
    const QString error = test::loadError(item);
    QVERIFY2(error.contains(expected), qPrintable(error));
    QVERIFY2(error.contains("start_set"), qPrintable(error));
}

// The Properties dock's field (and Python's item.parameters, the CLI's `set`): typed indices
// make the start set one of net points, in one undo step; a word is refused with its reason.
void TestNetStart::typedIndicesAreOneUndoStep()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, R"({"type": "subdivision-curve", "name": "C",
                               "scheme": {"kind": "bspline", "degree": 3},
                               "control_points": [[0,0],[1,2],[3,2],[4,0],[5,1]]})",
                        &error),
             qPrintable(error));
    auto *item = qobject_cast<AttractorItem *>(p.findItem("C"));
    const StartSetSpec original = item->startSet();
    const int steps = p.undoStack()->index();
    QVERIFY2(item->setParameter("start_set.net", "0, 2 4", 0, &error), qPrintable(error));
    QCOMPARE(item->startSet().kind, StartSetSpec::Kind::Net);
    QCOMPARE(item->startSet().net, (std::vector<int>{0, 2, 4}));
    QCOMPARE(item->parameter("start_set.net").toString(), QString("0, 2, 4"));
    QCOMPARE(p.undoStack()->index(), steps + 1);
    QVERIFY(!item->setParameter("start_set.net", "0, two", 0, &error));
    QVERIFY2(error.contains("'two' is not a net point index"), qPrintable(error));
    QVERIFY(!item->setParameter("start_set.net", "0, 7", 0, &error));
    QVERIFY2(error.contains("has the index 7"), qPrintable(error));
    QCOMPARE(p.undoStack()->index(), steps + 1);
    // Choosing the kind starts from the largest triangle of the net.
    p.undoStack()->undo();
    QCOMPARE(item->startSet(), original);
    QVERIFY2(item->setParameter("start_set.kind", "net", 0, &error), qPrintable(error));
    QCOMPARE(item->startSet().net.size(), std::size_t(3));
    QVERIFY(item->derivedIfs());
    QVERIFY(item->coreStartSet(*item->derivedIfs()).kind == StartSet::Kind::Polygon);
}

// A point inserted or removed: the indices follow their points, in the edit's own undo step;
// a start set whose points are all removed becomes the centroid.
void TestNetStart::theStartFollowsTheNetsCount()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, R"({"type": "subdivision-curve", "name": "C",
                               "scheme": {"kind": "bspline", "degree": 3},
                               "control_points": [[0,0],[1,2],[3,2],[4,0],[5,1],[6,3]],
                               "start_set": {"kind": "net", "points": [0, 2, 4]}})",
                        &error),
             qPrintable(error));
    auto *item = qobject_cast<AttractorItem *>(p.findItem("C"));
    const int steps = p.undoStack()->index();
    QVERIFY(item->insertControlPoint(1, Point{0.5, 1.0}));
    QCOMPARE(item->startSet().net, (std::vector<int>{0, 3, 5}));
    QCOMPARE(p.undoStack()->index(), steps + 1);
    QVERIFY(item->removeControlPoints({3, 4}));
    QCOMPARE(item->startSet().net, (std::vector<int>{0, 3}));
    QCOMPARE(p.undoStack()->index(), steps + 2);
    p.undoStack()->undo();
    p.undoStack()->undo();
    QCOMPARE(item->startSet().net, (std::vector<int>{0, 2, 4}));
    QCOMPARE(item->controlPoints().size(), std::size_t(6));
    QVERIFY(item->removeControlPoints({0, 2, 4}));
    QCOMPARE(item->startSet().kind, StartSetSpec::Kind::Point);
    // Every state the edits reached saves a file that reads back.
    QVERIFY(test::reloadsIdentically(p));
}

// A new scheme or layout brings its own net (000 §3): a net start set that no longer fits
// starts again from the new net's largest triangle, and lifted points take the new lifting's
// coordinate count -- in the same undo step, so that no saved file is left unreadable.
void TestNetStart::aNewNetRefitsTheStart()
{
    Project p;
    QString error;
    QVERIFY2(openExample(p, "000-fig08-sqrt3-surface.awb", &error), qPrintable(error));
    auto *item = qobject_cast<AttractorItem *>(p.items().front());
    QCOMPARE(item->startSet().net, (std::vector<int>{0, 18, 36}));
    const int steps = p.undoStack()->index();
    QVERIFY2(item->setParameter("scheme.kind", "loop", 0, &error), qPrintable(error));
    const int count = int(item->controlPoints().size());
    QVERIFY(count < 37);
    QCOMPARE(item->startSet().kind, StartSetSpec::Kind::Net);
    QCOMPARE(item->startSet().net.size(), std::size_t(3));
    QVERIFY(!item->checkNetStart(item->startSet().net));
    QCOMPARE(p.undoStack()->index(), steps + 1);
    QVERIFY(test::reloadsIdentically(p));
    p.undoStack()->undo();
    QCOMPARE(item->startSet().net, (std::vector<int>{0, 18, 36}));
    QCOMPARE(item->controlPoints().size(), std::size_t(37));

    // Lifted points (the centroid, lifted): as many coordinates as the new lifting has.
    QVERIFY2(item->setParameter("start_set.kind", "lifted", 0, &error), qPrintable(error));
    QCOMPARE(item->startSet().lifted.front().size(), std::size_t(item->derivedIfs()->ifs.dim()));
    QVERIFY2(item->setParameter("scheme.kind", "loop", 0, &error), qPrintable(error));
    const auto d = item->derivedIfs();
    QVERIFY(d);
    QVERIFY(d->ifs.dim() != 37);
    QCOMPARE(item->startSet().lifted.front().size(), std::size_t(d->ifs.dim()));
    QVERIFY(test::reloadsIdentically(p));
}

// `attractor-cli points --start net:...` and Python's points(start=...) read the same text.
void TestNetStart::startTextReadsNetPoints()
{
    Project p;
    QString error;
    QVERIFY2(openExample(p, "000-fig07-box-spline-hexagon.awb", &error), qPrintable(error));
    auto *item = qobject_cast<AttractorItem *>(p.findItem(kFig7));
    const auto d = item->derivedIfs();
    const StartSet start = startSetFromText(*item, *d, "net:0,9,18");
    QVERIFY(start.kind == StartSet::Kind::Polygon);
    QVERIFY((start.vertices - item->coreStartSet(*d).vertices).cwiseAbs().maxCoeff() == 0);
    QVERIFY(startSetFromText(*item, *d, "net:4").kind == StartSet::Kind::Points);
    for (const auto &[text, message] :
         std::vector<std::pair<QString, QString>>{{"net:19", "has the index 19; the net has 19"},
                                                  {"net:", "net: needs at least one index"},
                                                  {"net:1,x", "'x' is not a net point index"}}) {
        try {
            startSetFromText(*item, *d, text);
            QFAIL(qPrintable(text));
        } catch (const StartSetTextError &e) {
            QVERIFY2(e.message.contains(message), qPrintable(e.message));
        }
    }
}

AWB_TEST_MAIN(TestNetStart)
#include "test_net_start.moc"
