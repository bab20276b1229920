// `attractor-cli points --address w` (issue 16, part 3): the points of the sub-copy f_w(A)
// only, as many as without the option, inside the control polygon S_w P of that piece (a
// B-spline lies in the convex hull of its control points), and clear errors for bad addresses.

#include "CliRunner.h"
#include "PointCsv.h"

#include "core/ifs/Address.h"
#include "core/schemes/Scheme.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include "TestMain.h"

#include <algorithm>

using namespace awb;
using namespace awb::test;

namespace {

const QString kProject = QStringLiteral("000-fig02-cubic-bspline-from-point.awb");
const QString kItem = QStringLiteral("000 Fig. 2: cubic B-spline from a point");

// The example's control points, read from the project file.
Mat controlPoints()
{
    QFile f(examplePath(kProject));
    if (!f.open(QIODevice::ReadOnly))
        return {};
    const QJsonArray items = QJsonDocument::fromJson(f.readAll())["items"].toArray();
    const QJsonArray points = items.first()["control_points"].toArray();
    Mat P(points.size(), 2);
    for (int i = 0; i < points.size(); ++i) {
        P(i, 0) = points[i].toArray()[0].toDouble();
        P(i, 1) = points[i].toArray()[1].toDouble();
    }
    return P;
}

int points(const QStringList &extra, QByteArray *out, QByteArray *err = nullptr)
{
    return runProgram(cliPath(),
                      QStringList{"points", examplePath(kProject), "--item", kItem, "--csv"}
                          + extra,
                      out, err);
}

} // namespace

class TestAddressCli : public QObject {
    Q_OBJECT
private slots:
    void subCopyLiesInItsControlPolygon_data();
    void subCopyLiesInItsControlPolygon();
    void refusesBadAddresses_data();
    void refusesBadAddresses();
};

void TestAddressCli::subCopyLiesInItsControlPolygon_data()
{
    QTest::addColumn<QString>("address");
    QTest::newRow("0") << "0";
    QTest::newRow("0,1,1") << "0,1,1";
    QTest::newRow("1,0,1,1,0") << "1,0,1,1,0";
    QTest::newRow("compact 110") << "110";
}

void TestAddressCli::subCopyLiesInItsControlPolygon()
{
    QFETCH(QString, address);
    const Mat P = controlPoints();
    QCOMPARE(P.rows(), Eigen::Index(5));
    QByteArray all, sub, err;
    QCOMPARE(points({"--depth", "10"}, &all), 0);
    QCOMPARE(points({"--depth", "10", "--address", address}, &sub, &err), 0);
    std::vector<int> maps;
    const Mat A = csvPoints(all), B = csvPoints(sub, &maps);
    QCOMPARE(B.rows(), A.rows());
    QCOMPARE(B.rows(), Eigen::Index(1024));
    const Address w = parseAddress(address.toStdString(), 2);
    QVERIFY(std::all_of(maps.begin(), maps.end(), [&](int m) { return m == w.front() + 1; }));
    // S_w P of the cubic B-spline: its convex hull holds the piece; F^10(X0) is within
    // 2^-10 |X0 - A| of the attractor (subdominant eigenvalue 1/2), well under the slack.
    const Mat Q = addressMatrix(bsplineScheme(3).matrices(5).S, w) * P;
    const double slack = 0.02;
    const RowVec lo = Q.colwise().minCoeff().array() - slack;
    const RowVec hi = Q.colwise().maxCoeff().array() + slack;
    for (Eigen::Index i = 0; i < B.rows(); ++i)
        QVERIFY2((B.row(i).array() >= lo.array()).all() && (B.row(i).array() <= hi.array()).all(),
                 qPrintable(QString("row %1 (%2, %3) is outside the hull of S_w P")
                                .arg(i)
                                .arg(B(i, 0))
                                .arg(B(i, 1))));
    // The piece is a small part of the whole curve: its extent shrinks with the address.
    const double full = (A.colwise().maxCoeff() - A.colwise().minCoeff()).norm();
    const double part = (B.colwise().maxCoeff() - B.colwise().minCoeff()).norm();
    QVERIFY(part < full * std::pow(0.75, double(w.size())));
}

void TestAddressCli::refusesBadAddresses_data()
{
    QTest::addColumn<QString>("address");
    QTest::addColumn<QString>("message");
    QTest::newRow("out of range") << "0,2" << "map 2, but the IFS has 2 maps (0..1)";
    QTest::newRow("empty") << "" << "the address is empty";
    QTest::newRow("not numeric") << "0,a" << "'a', is not a map number";
    QTest::newRow("too long") << QString(70, '1') << "70 symbols, more than 64";
}

void TestAddressCli::refusesBadAddresses()
{
    QFETCH(QString, address);
    QFETCH(QString, message);
    QByteArray out, err;
    QCOMPARE(points({"--depth", "3", "--address", address}, &out, &err), 2);
    QVERIFY2(QString::fromUtf8(err).contains(message), err.constData());
    QVERIFY(QString::fromUtf8(err).startsWith("attractor-cli: --address"));
    QVERIFY(out.isEmpty());
}

AWB_TEST_GUILESS_MAIN(TestAddressCli)
#include "test_address_cli.moc"
