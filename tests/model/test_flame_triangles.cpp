// A flame's xforms edited as Apophysis edits them (model/FlameItem.h): each pre map is the
// triangle of the images of (0, 0), (1, 0) and (0, 1), y up, one point set per xform and the
// final xform's last. Dragging a corner is one undo step that changes only that xform's map,
// as the triangle says; undo gives the map back to the last bit (the file is the same); an
// edit of the map by value (the Properties dock, Python, `set`) moves the triangle; the
// triangles are handles, not data: the file holds the maps only.

#include "ItemKindTests.h"
#include "TestPaths.h"

#include "model/FlameItem.h"
#include "model/Project.h"
#include "model/ProjectIO.h"
#include "TestMain.h"

#include <QJsonDocument>
#include <QJsonObject>

using namespace awb;
using flame::Affine2;

namespace {

const char *kFlame = R"({"type": "flame", "name": "F",
    "xforms": [{"weight": 1, "color": 0, "coefs": [0.5, 0.1, -0.2, 0.4, 0.3, -0.7],
                "variations": {"spherical": 1}},
               {"weight": 2, "color": 1, "coefs": [0.6, 0, 0, 0.6, 0.1, 0.2],
                "variations": {"linear": 0.5, "swirl": 0.5}}],
    "final_xform": {"color": 0.5, "coefs": [0.9, 0.2, -0.2, 0.9, 0, 0], "variations": {"linear": 1}},
    "algorithm": {"mode": "random", "samples": 100000}})";

QByteArray itemJson(const Item &item)
{
    return QJsonDocument(ProjectIO::itemToJson(item)).toJson(QJsonDocument::Compact);
}

} // namespace

class TestFlameTriangles : public QObject {
    Q_OBJECT
private slots:
    void trianglesAreTheMaps();
    void dragIsOneExactUndoStep();
    void editByValueMovesTheTriangle();
};

void TestFlameTriangles::trianglesAreTheMaps()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, kFlame, &error), qPrintable(error));
    auto *item = qobject_cast<FlameItem *>(p.findItem("F"));
    QVERIFY(item);
    QCOMPARE(item->controlPointSetCount(), 3);  // two xforms and the final one
    for (int s = 0; s < 3; ++s) {
        QVERIFY(item->controlPointSetClosed(s));
        QVERIFY(!item->pointCountEditable(s));
        QCOMPARE(item->controlPoints(s).size(), std::size_t(3));
    }
    // coefs [a, d, b, e, c, f] = [0.5, 0.1, -0.2, 0.4, 0.3, -0.7]: the images of (0, 0),
    // (1, 0), (0, 1) in flam3's y-down plane are (c, f), (a + c, d + f), (b + c, e + f), drawn
    // with y up.
    const PointList t = item->controlPoints(0);
    const PointList expected{{0.3, 0.7}, {0.8, 0.6}, {0.1, 0.3}};
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 2; ++k)
            QVERIFY(std::abs(t[std::size_t(i)][std::size_t(k)] - expected[std::size_t(i)][std::size_t(k)]) < 1e-15);
    // A map from its triangle, to rounding (the exact map comes back from the undo's triangle).
    const Affine2 m = item->flame().xforms[1].pre, r = flameMapOfTriangle(flameTriangle(m));
    for (const auto &[x, y] : {std::pair{m.a, r.a}, {m.b, r.b}, {m.c, r.c}, {m.d, r.d},
                               {m.e, r.e}, {m.f, r.f}})
        QVERIFY(std::abs(x - y) < 1e-15);
    // Not in the file: the maps are.
    QVERIFY(!itemJson(*item).contains("control_points"));
}

void TestFlameTriangles::dragIsOneExactUndoStep()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, kFlame, &error), qPrintable(error));
    auto *item = qobject_cast<FlameItem *>(p.findItem("F"));
    const flame::Flame before = item->flame();
    const QByteArray fileBefore = itemJson(*item);
    const int steps = p.undoStack()->index();
    // A drag of xform 1's corner (1, 0) in three moves: one gesture, one undo step.
    const int gesture = p.beginGesture();
    for (double dx : {0.01, 0.05, 0.125})
        QVERIFY(item->moveControlPoint(1, Point{0.7 + dx, -0.2 - dx}, gesture, 0));
    p.endGesture(gesture);
    QCOMPARE(p.undoStack()->index(), steps + 1);
    const Affine2 moved = item->flame().xforms[0].pre;
    // Only a and d change (the corner (1, 0) is (a + c, -(d + f)), now (0.825, -0.325)):
    // a = 0.825 - 0.3, d = 0.325 + 0.7, up to rounding.
    QCOMPARE(moved.c, before.xforms[0].pre.c);
    QCOMPARE(moved.f, before.xforms[0].pre.f);
    QVERIFY(std::abs(moved.a - 0.525) < 1e-15);
    QVERIFY(std::abs(moved.d - 1.025) < 1e-15);
    QCOMPARE(moved.b, before.xforms[0].pre.b);
    QCOMPARE(moved.e, before.xforms[0].pre.e);
    QCOMPARE(item->flame().xforms[1], before.xforms[1]);
    QCOMPARE(*item->flame().finalXform, *before.finalXform);
    // Undo: the map to the last bit, the file byte for byte; redo: the dragged map again.
    p.undoStack()->undo();
    QCOMPARE(item->flame(), before);
    QCOMPARE(itemJson(*item), fileBefore);
    p.undoStack()->redo();
    QCOMPARE(item->flame().xforms[0].pre, moved);
    // The final xform's triangle is the last set.
    QVERIFY(item->moveControlPoint(0, Point{0.05, 0.02}, 0, 2));
    QCOMPARE(item->flame().finalXform->pre.c, 0.05);
    QCOMPARE(item->flame().finalXform->pre.f, -0.02);
    p.undoStack()->undo();
    p.undoStack()->undo();
    QCOMPARE(item->flame(), before);
}

void TestFlameTriangles::editByValueMovesTheTriangle()
{
    Project p;
    QString error;
    QVERIFY2(test::load(p, kFlame, &error), qPrintable(error));
    auto *item = qobject_cast<FlameItem *>(p.findItem("F"));
    flame::Flame f = item->flame();
    f.xforms[1].pre = {2, 0, 1, 0, 2, 3};  // a, b, c, d, e, f
    f.xforms.push_back(f.xforms[0]);
    QVERIFY2(item->setFlame(f, 0, &error), qPrintable(error));
    QCOMPARE(item->controlPointSetCount(), 4);  // three xforms, then the final one
    QCOMPARE(item->controlPoints(1), (PointList{{1, -3}, {3, -3}, {1, -5}}));
    QCOMPARE(item->controlPoints(2), item->controlPoints(0));
    QCOMPARE(item->controlPoints(3), flameTriangle(item->flame().finalXform->pre));
    p.undoStack()->undo();
    QCOMPARE(item->controlPointSetCount(), 3);
    QCOMPARE(item->controlPoints(1), flameTriangle(item->flame().xforms[1].pre));
}

AWB_TEST_MAIN(TestFlameTriangles)
#include "test_flame_triangles.moc"
