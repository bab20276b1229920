// A linear flame with xaos rows is a controlled IFS (issue 46): `attractor-cli import` makes it a
// "cifs" item -- one state per xform, an arc j -> i carrying f_j wherever xform i may precede
// xform j -- and flam3-render (Debian flam3-utils) is the judge of the picture: the same frame
// drawn by both must agree block by block, and must not agree with the same flame without its
// xaos (which imports as an ordinary IFS), so that the comparison can fail. A final xform and a
// post transform are kept, as flam3 applies them.

#include "TestPaths.h"
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include "BlockCompare.h"
#include "CliRunner.h"
#include "Flam3Judge.h"
#include "TestMain.h"

using namespace awb::test;

namespace {

// The flames (tests/cli/data/xaos): Sierpinski's three halvings, none twice in a row (the
// gasket's "no repeat" variant); four corners of a square, never the opposite corner next, one
// xform with a post transform (a quarter turn about its corner) and a final xform that shears
// the whole picture.
QByteArray flameFile(const QString &name)
{
    QFile f(awb::test::sourceDir() + "/tests/cli/data/xaos/" + name);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool put(const QString &path, const QByteArray &text)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(text) == text.size();
}

QJsonObject firstItem(const QString &project)
{
    QFile f(project);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll())["items"][0].toObject();
}

QByteArray withoutXaos(QByteArray flame)
{
    return QString::fromUtf8(flame)
        .remove(QRegularExpression(QStringLiteral(" chaos=\"[^\"]*\"")))
        .toUtf8();
}

} // namespace

class TestFlameXaos : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }
    void xaosFlamesRenderAsFlam3Renders_data();
    void xaosFlamesRenderAsFlam3Renders();

private:
    int run(const QStringList &args, QByteArray *out = nullptr, QByteArray *err = nullptr)
    {
        return runProgram(cliPath(), args, out, err);
    }
    // Ours, rendered in the flame's frame: the alpha of 10 x 10 blocks.
    std::vector<double> ours(const QByteArray &flame, const QString &name, QString *type)
    {
        const QString genome = m_dir.filePath(name + ".flame");
        const QString project = m_dir.filePath(name + ".awb");
        const QString png = m_dir.filePath(name + ".ours.png");
        QByteArray err;
        if (!put(genome, flame) || run({"import", genome, "--out", project}, nullptr, &err) != 0)
            return {};
        *type = firstItem(project)["type"].toString();
        int w = 0, h = 0;
        const QString bounds = boundsOfFlame(flame, &w, &h);
        if (run({"render", project, "--size", QStringLiteral("%1x%2").arg(w).arg(h), "--bounds",
                 bounds, "--samples", "3000000", "--bits", "16", "--out", png},
                nullptr, &err)
            != 0)
            return {};
        return blockAlpha(QImage(png), 10);
    }
    QTemporaryDir m_dir;
};

void TestFlameXaos::xaosFlamesRenderAsFlam3Renders_data()
{
    QTest::addColumn<QByteArray>("flame");
    QTest::addColumn<int>("states");
    QTest::addColumn<int>("arcs");
    QTest::newRow("xaos gasket") << flameFile("xaos-gasket.flame") << 3 << 6;
    QTest::newRow("xaos square, post and final") << flameFile("xaos-square.flame") << 4 << 12;
}

void TestFlameXaos::xaosFlamesRenderAsFlam3Renders()
{
    QFETCH(QByteArray, flame);
    QFETCH(int, states);
    QFETCH(int, arcs);
    QVERIFY(!flame.isEmpty());
    const QString name = QString::fromLatin1(QTest::currentDataTag()).replace(' ', '_');
    const QString genome = m_dir.filePath(name + ".judge.flame");
    QVERIFY(put(genome, flame));
    QString why;
    const QString theirs = m_dir.filePath(name + ".flam3.png");
    QVERIFY2(flam3Render(genome, theirs, &why), qPrintable(why));
    const auto A = blockAlpha(QImage(theirs), 10);

    QString type;
    const auto B = ours(flame, name, &type);
    QCOMPARE(type, QString("cifs"));
    QVERIFY(!B.empty());
    const QJsonObject item = firstItem(m_dir.filePath(name + ".awb"));
    QCOMPARE(item["states"].toArray().size(), states);
    QCOMPARE(item["arcs"].toArray().size(), arcs);
    QCOMPARE(item["state"].toString(), QString("all"));

    // The same flame without its xaos: an ordinary IFS, another picture.
    QString plainType;
    const auto C = ours(withoutXaos(flame), name + "_plain", &plainType);
    QCOMPARE(plainType, QString("fractal"));
    const double same = correlation(A, B), plain = correlation(A, C);
    qInfo("%s: correlation with flam3-render %.3f; without xaos %.3f", qPrintable(name), same,
          plain);
    QVERIFY2(same > 0.85, qPrintable(QString::number(same)));
    QVERIFY2(same > plain + 0.1, qPrintable(QStringLiteral("%1 against %2").arg(same).arg(plain)));
}

AWB_TEST_MAIN(TestFlameXaos)
#include "test_flame_xaos.moc"
