// The flame item (issue 45, model/FlameItem.h) end to end through attractor-cli, judged by
// flam3-render (Debian flam3-utils): 30 real flames that flam3-genome wrote (random variations
// and parameters, symmetry, a final xform, mutations with post transforms, two with xaos rows;
// tests/cli/data/flames/README.md) are imported -- every one as a flame item, nothing dropped
// -- rendered by `attractor-cli render` and by flam3-render in the same frame, and the two
// pictures' block alpha must agree for at least 90 % of them (and disagree once ours is
// mirrored, for most, so that the comparison can fail). The item's exchange is exact: exported
// as a .flame and imported again it is the same item; `check`, `analyse`, and the refusals of
// what a flame is not (iterated points, a Fractint entry, deterministic depth) name the reason.

#include "TestPaths.h"
#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include "BlockCompare.h"
#include "CliRunner.h"
#include "Flam3Judge.h"
#include "TestMain.h"
#include "TestTime.h"

#include <algorithm>

using namespace awb::test;

namespace {

QString flamesDir()
{
    return awb::test::sourceDir()
           + "/tests/cli/data/flames";
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool put(const QString &path, const QByteArray &text)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(text) == text.size();
}

QJsonObject firstItem(const QString &project)
{
    return QJsonDocument::fromJson(readAll(project))["items"][0].toObject();
}

// The genome at `side` x `side` pixels (flam3-genome writes 100 x 100): the same frame, scaled.
QByteArray resized(QByteArray flame, int side)
{
    QString text = QString::fromUtf8(flame);
    const QRegularExpression sizeRe("(<flame [^>]*)size=\"100 100\"");
    const QRegularExpression scaleRe("(<flame [^>]*)scale=\"([^\"]+)\"");
    const double scale = scaleRe.match(text).captured(2).toDouble();
    text.replace(sizeRe, QStringLiteral("\\1size=\"%1 %1\"").arg(side));
    text.replace(scaleRe,
                 QStringLiteral("\\1scale=\"%1\"").arg(scale * side / 100.0, 0, 'g', 17));
    return text.toUtf8();
}

} // namespace

class TestFlameItem : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }
    void realFlamesRenderAsFlam3Renders();
    void exportImportIsExact();
    void whatAFlameIsNot();
    void paletteOfFlam3sPaletteFile();

private:
    int run(const QStringList &args, QByteArray *out = nullptr, QByteArray *err = nullptr)
    {
        return runProgram(cliPath(), args, out, err);
    }
    QTemporaryDir m_dir;
};

void TestFlameItem::realFlamesRenderAsFlam3Renders()
{
    const QStringList files = judgedFlames(flamesDir(), 3);
    QCOMPARE(files.size(), qEnvironmentVariableIntValue("AWB_TEST_TIME_SCALE") > 1 ? 10 : 30);
    const int side = 150, quality = 60;
    int agree = 0, discriminates = 0;
    QStringList report;
    for (const QString &name : files) {
        const QByteArray flame = withQuality(resized(readAll(flamesDir() + "/" + name), side),
                                             quality);
        const QString genome = m_dir.filePath(name);
        QVERIFY(put(genome, flame));
        QString why;
        const QString theirs = m_dir.filePath(name + ".flam3.png");
        QVERIFY2(flam3Render(genome, theirs, &why), qPrintable(name + ": " + why));

        // Imported as a flame item: nothing of what flam3 draws is dropped (the <edit>
        // history and the animation attributes are not drawing).
        const QString project = m_dir.filePath(name + ".awb");
        QByteArray err;
        QCOMPARE(run({"import", genome, "--out", project}, nullptr, &err), 0);
        QVERIFY2(!err.contains("dropped"), err.constData());
        QCOMPARE(firstItem(project)["type"].toString(), QString("flame"));

        int w = 0, h = 0;
        const QString bounds = boundsOfFlame(flame, &w, &h);
        const QString ours = m_dir.filePath(name + ".ours.png");
        QCOMPARE(run({"render", project, "--size", QStringLiteral("%1x%2").arg(w).arg(h),
                      "--bounds", bounds, "--samples", QString::number(side * side * quality),
                      "--bits", "16", "--out", ours},
                     nullptr, &err),
                 0);
        const QImage a(theirs), b(ours);
        QCOMPARE(a.size(), QSize(side, side));
        QCOMPARE(b.size(), QSize(side, side));
        const auto A = blockAlpha(a, 10), B = blockAlpha(b, 10), Bm = blockAlpha(b, 10, true);
        const double same = correlation(A, B), mirrored = correlation(A, Bm);
        report << QStringLiteral("%1 %2 (mirrored %3)")
                      .arg(name)
                      .arg(same, 0, 'f', 3)
                      .arg(mirrored, 0, 'f', 3);
        agree += same > 0.8;
        discriminates += same > mirrored + 0.1;
    }
    qInfo("correlation of 10 x 10 block alpha, ours and flam3-render's:\n  %s",
          qPrintable(report.join("\n  ")));
    qInfo("%d of %d flames agree (> 0.8); %d tell their mirror image apart", agree,
          int(files.size()), discriminates);
    QVERIFY2(agree >= int(std::ceil(0.9 * files.size())), qPrintable(report.join("; ")));
    QVERIFY2(discriminates >= int(files.size()) / 2, qPrintable(report.join("; ")));
}

void TestFlameItem::exportImportIsExact()
{
    AWB_SKIP_WITHOUT_THREADS();
    // A flame with xaos, post, a final xform and parametric variations: exported as flam3
    // writes it and imported again, the item is the same, number for number.
    const QString source = flamesDir() + "/xaos-2.flame";
    const QString project = m_dir.filePath("exact.awb");
    QCOMPARE(run({"import", source, "--out", project}), 0);
    const QJsonObject before = firstItem(project);
    QCOMPARE(before["type"].toString(), QString("flame"));
    QVERIFY(before["xforms"][0].toObject().contains("chaos"));
    const QString name = before["name"].toString();
    const QString out = m_dir.filePath("exact.flame");
    QCOMPARE(run({"export", project, "--item", name, "--format", "flame", "--out", out}), 0);
    const QString again = m_dir.filePath("exact-again.awb");
    QByteArray err;
    QCOMPARE(run({"import", out, "--out", again}, nullptr, &err), 0);
    const QJsonObject after = firstItem(again);
    for (const char *key : {"xforms", "palette", "camera", "tone", "final_xform"})
        QVERIFY2(after[key] == before[key], key);
    QCOMPARE(after["name"], before["name"]);
    // And the project itself is stored canonically: rewritten, byte for byte the same.
    const QString copy = m_dir.filePath("exact-copy.awb");
    QCOMPARE(run({"rewrite", project, "--out", copy}), 0);
    QCOMPARE(readAll(copy), readAll(project));
}

void TestFlameItem::whatAFlameIsNot()
{
    AWB_SKIP_WITHOUT_THREADS();
    const QString project = m_dir.filePath("not.awb");
    QCOMPARE(run({"import", flamesDir() + "/genome-07.flame", "--out", project}), 0);
    const QString name = firstItem(project)["name"].toString();
    QByteArray out, err;
    QCOMPARE(run({"check", project}, &out, &err), 0);
    // The analysis: the xforms' affine parts, each with its eigenvalues.
    QCOMPARE(run({"analyse", project, "--json"}, &out, &err), 0);
    const QJsonObject item = QJsonDocument::fromJson(out)["items"][0].toObject();
    QCOMPARE(item["type"].toString(), QString("flame"));
    QCOMPARE(item["maps"].toArray().size(), 4);
    QVERIFY(!item["maps"][0]["eigenvalues"].toArray().isEmpty());
    // No box-counting dimension of those affine parts' attractor, which is not the flame's.
    QVERIFY(item["box_dimension"].isNull());
    QVERIFY2(item["box_dimension_note"].toString().contains("not their affine parts"),
             qPrintable(item["box_dimension_note"].toString()));
    // Not points of iterated maps, not a Fractint entry, not a deterministic depth.
    QCOMPARE(run({"points", project, "--item", name, "--csv"}, &out, &err), 1);
    QVERIFY2(err.contains("fractal flame"), err.constData());
    QCOMPARE(run({"export", project, "--item", name, "--format", "ifs", "--out",
                  m_dir.filePath("not.ifs")},
                 &out, &err),
             1);
    QVERIFY2(err.contains("not affine maps"), err.constData());
    QCOMPARE(run({"render", project, "--item", name, "--depth", "6", "--out",
                  m_dir.filePath("not.png")},
                 &out, &err),
             1);
    QVERIFY2(err.contains("random iteration only"), err.constData());
}

// palette="N" names entry N of flam3's palette file (FLAM3_PALETTES, as for flam3-render; here
// a file of two entries written by the test), its hue turned by hue="h" turns as
// flam3_get_palette does: red, green and blue a sixth of a turn on are yellow, cyan and magenta
// (a sixth back, magenta, yellow, cyan); a
// <color> after it overrides its entry; an entry the file lacks is named in a warning.
void TestFlameItem::paletteOfFlam3sPaletteFile()
{
    const QString palettes = m_dir.filePath("palettes.xml");
    {
        QFile f(palettes);
        QVERIFY(f.open(QIODevice::WriteOnly));
        QByteArray data;
        for (int i = 0; i < 256; ++i)
            data += i % 3 == 0 ? "00ff0000" : i % 3 == 1 ? "0000ff00" : "000000ff";
        f.write("<palettes>\n<palette number=\"3\" name=\"other\" data=\"" + QByteArray(2048, '0')
                + "\"/>\n<palette number=\"7\" name=\"rgb\" data=\"" + data + "\"/>\n</palettes>\n");
    }
    const QString flame = m_dir.filePath("named.flam3");
    {
        QFile f(flame);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("<flames>\n<flame name=\"n\" palette=\"7\" hue=\"0.16666666666666666\" size=\"64 64\" scale=\"16\">\n"
                "<xform weight=\"1\" color=\"0\" spherical=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>\n"
                "<color index=\"5\" rgb=\"10 20 30\"/>\n</flame>\n"
                "<flame name=\"m\" palette=\"8\" size=\"64 64\" scale=\"16\">\n"
                "<xform weight=\"1\" color=\"0\" spherical=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>\n"
                "</flame>\n</flames>\n");
    }
    qputenv("FLAM3_PALETTES", palettes.toLocal8Bit());
    const QString project = m_dir.filePath("named.awb");
    QByteArray out, err;
    const int code = run({"import", flame, "--out", project}, &out, &err);
    qunsetenv("FLAM3_PALETTES");
    QCOMPARE(code, 0);
    QVERIFY2(err.contains("palette 8 of flam3's palette file is not kept")
                 && err.contains("has no palette 8"),
             err.constData());
    QFile f(project);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QJsonArray items = QJsonDocument::fromJson(f.readAll()).object()["items"].toArray();
    QCOMPARE(items.size(), 2);
    // The palette as hex where every entry is a whole byte (model/FlameItem's format).
    const QString hex = items[0].toObject()["palette"].toString();
    QCOMPARE(hex.size(), 256 * 6);
    QCOMPARE(hex.mid(0, 18), QStringLiteral("ffff0000ffffff00ff"));  // yellow, cyan, magenta
    QCOMPARE(hex.mid(5 * 6, 6), QStringLiteral("0a141e"));            // <color index="5">
    // No entry: black, as flam3's.
    QCOMPARE(items[1].toObject()["palette"].toString(), QString(256 * 6, QLatin1Char('0')));
}

AWB_TEST_MAIN(TestFlameItem)
#include "test_flame_item.moc"
