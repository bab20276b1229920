// A flame item's picture (core/flame/FlameTone.h through `attractor-cli render`) judged pixel
// by pixel by flam3-render's (Debian flam3-utils): the 30 real genomes of tests/cli/data/flames
// and one genome under every tone setting flam3 has (palette mode, filter shape, supersample,
// highlight power, vibrancy, gamma threshold, background, the density estimator on and off,
// zoom, rotation). Two renders of flam3 with different seeds differ by their noise; ours must
// differ from flam3's by no more than that (the mean absolute difference of the RGB channels,
// within 1.25 x + 0.004), and clearly more from flam3's picture of the flame made brighter, so
// that the comparison can fail. flam3's passes, which only change the grain, are judged by the
// grain; the picture's limits by their message.

#include "TestPaths.h"
#include <QDir>
#include <QFile>
#include <QImage>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include "CliRunner.h"
#include "Flam3Judge.h"
#include "TestMain.h"

#include <cmath>

using namespace awb::test;

namespace {

QString flamesDir() { return awb::test::sourceDir() + "/tests/cli/data/flames"; }

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

// The genome with these attributes of <flame> set (replaced or added).
QByteArray withAttributes(const QByteArray &flame, const QList<std::pair<QString, QString>> &set)
{
    QString text = QString::fromUtf8(flame);
    for (const auto &[key, value] : set) {
        const QRegularExpression re(QStringLiteral("(<flame [^>]*\\b)%1=\"[^\"]*\"").arg(key));
        if (text.contains(re))
            text.replace(re, QStringLiteral("\\1%1=\"%2\"").arg(key, value));
        else
            text.replace(QStringLiteral("<flame "), QStringLiteral("<flame %1=\"%2\" ").arg(key, value));
    }
    return text.toUtf8();
}

// The mean absolute difference of the RGB channels, 0..1.
double meanDifference(const QImage &a, const QImage &b)
{
    if (a.size() != b.size())
        return 1.0;
    const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
    double sum = 0;
    for (int r = 0; r < x.height(); ++r) {
        const auto *p = reinterpret_cast<const QRgb *>(x.constScanLine(r));
        const auto *q = reinterpret_cast<const QRgb *>(y.constScanLine(r));
        for (int c = 0; c < x.width(); ++c)
            sum += std::abs(qRed(p[c]) - qRed(q[c])) + std::abs(qGreen(p[c]) - qGreen(q[c]))
                   + std::abs(qBlue(p[c]) - qBlue(q[c]));
    }
    return sum / (3.0 * 255.0 * x.width() * x.height());
}

// How grainy a picture is: the mean absolute difference of the RGB channels from the mean of
// each pixel's 3 x 3 neighbourhood (inner pixels), 0..1.
double roughness(const QImage &image)
{
    const QImage x = image.convertToFormat(QImage::Format_RGB32);
    double sum = 0;
    long long count = 0;
    for (int r = 1; r + 1 < x.height(); ++r)
        for (int c = 1; c + 1 < x.width(); ++c) {
            int mean[3] = {0, 0, 0};
            for (int dr = -1; dr <= 1; ++dr)
                for (int dc = -1; dc <= 1; ++dc) {
                    const QRgb q = x.pixel(c + dc, r + dr);
                    mean[0] += qRed(q);
                    mean[1] += qGreen(q);
                    mean[2] += qBlue(q);
                }
            const QRgb p = x.pixel(c, r);
            sum += std::abs(qRed(p) - mean[0] / 9.0) + std::abs(qGreen(p) - mean[1] / 9.0)
                   + std::abs(qBlue(p) - mean[2] / 9.0);
            ++count;
        }
    return count ? sum / (3.0 * 255.0 * double(count)) : 0.0;
}

struct Judgement {
    double ours = 0, noise = 0, brighter = 0;
    bool same() const { return ours <= 1.25 * noise + 0.004; }
    bool tellsApart() const { return brighter > 1.5 * ours; }
};

} // namespace

class TestFlameTone : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }
    void realFlamesLookAsFlam3DrawsThem();
    void everyToneSettingAsFlam3();
    void passesAsFlam3();
    void pictureLimitsNameTheItem();

private:
    // flam3-render twice (two seeds), once brighter, and attractor-cli's render of the item
    // imported from the genome, all at its own size and quality.
    bool judge(const QString &name, const QByteArray &genome, Judgement *out, QString *why)
    {
        const QString path = m_dir.filePath(name + ".flame");
        const QString brighterPath = m_dir.filePath(name + ".brighter.flame");
        const double brightness = QRegularExpression("<flame [^>]*\\bbrightness=\"([^\"]+)\"")
                                      .match(QString::fromUtf8(genome))
                                      .captured(1)
                                      .toDouble();
        if (!put(path, genome)
            || !put(brighterPath,
                    withAttributes(genome, {{"brightness",
                                             QString::number(2.5 * (brightness > 0 ? brightness : 4))}})))
            return *why = "cannot write the genomes", false;
        const QString a = m_dir.filePath(name + ".a.png"), b = m_dir.filePath(name + ".b.png"),
                      bright = m_dir.filePath(name + ".bright.png"),
                      ours = m_dir.filePath(name + ".ours.png"),
                      project = m_dir.filePath(name + ".awb");
        if (!flam3Render(path, a, why, {{"transparency", "0"}, {"isaac_seed", "first"}})
            || !flam3Render(path, b, why, {{"transparency", "0"}, {"isaac_seed", "second"}})
            || !flam3Render(brighterPath, bright, why, {{"transparency", "0"}, {"isaac_seed", "first"}}))
            return false;
        QByteArray err;
        if (runProgram(cliPath(), {"import", path, "--out", project}, nullptr, &err) != 0
            || runProgram(cliPath(), {"render", project, "--out", ours}, nullptr, &err) != 0)
            return *why = QString::fromUtf8(err), false;
        const QImage A(a), B(b), Bright(bright), O(ours);
        if (O.size() != A.size())
            return *why = QStringLiteral("ours is %1 x %2, flam3's %3 x %4")
                              .arg(O.width()).arg(O.height()).arg(A.width()).arg(A.height()),
                   false;
        out->ours = meanDifference(O, A);
        out->noise = meanDifference(B, A);
        out->brighter = meanDifference(O, Bright);
        return true;
    }
    QTemporaryDir m_dir;
};

void TestFlameTone::realFlamesLookAsFlam3DrawsThem()
{
    const QStringList files = judgedFlames(flamesDir(), 5);
    QCOMPARE(files.size(), qEnvironmentVariableIntValue("AWB_TEST_TIME_SCALE") > 1 ? 6 : 30);
    QStringList report, failed;
    int apart = 0;
    for (const QString &name : files) {
        Judgement j;
        QString why;
        QVERIFY2(judge(name, withQuality(readAll(flamesDir() + "/" + name), 100), &j, &why),
                 qPrintable(name + ": " + why));
        report << QStringLiteral("%1: ours %2, flam3's own noise %3, brighter %4")
                      .arg(name)
                      .arg(j.ours, 0, 'f', 4)
                      .arg(j.noise, 0, 'f', 4)
                      .arg(j.brighter, 0, 'f', 4);
        if (!j.same())
            failed << report.back();
        apart += j.tellsApart();
    }
    qInfo("mean |RGB| difference from flam3-render's picture:\n  %s",
          qPrintable(report.join("\n  ")));
    QVERIFY2(failed.isEmpty(), qPrintable(failed.join("; ")));
    QVERIFY2(apart >= int(std::ceil(0.9 * files.size())), qPrintable(report.join("; ")));
}

void TestFlameTone::everyToneSettingAsFlam3()
{
    const QByteArray base = withQuality(readAll(flamesDir() + "/genome-12.flame"), 100);
    const QList<QList<std::pair<QString, QString>>> settings = {
        {{"palette_mode", "linear"}},
        {{"filter_shape", "lanczos3"}, {"filter", "1"}, {"supersample", "2"}},
        {{"filter_shape", "quadratic"}, {"filter", "0.8"}, {"supersample", "3"}},
        {{"highlight_power", "1"}, {"brightness", "30"}},
        {{"highlight_power", "0.2"}, {"brightness", "15"}, {"gamma", "2"}},
        {{"vibrancy", "0.3"}, {"gamma", "2.2"}, {"gamma_threshold", "0.1"}},
        {{"background", "0.2 0.1 0.35"}},
        {{"estimator_radius", "4"}, {"estimator_minimum", "1"}, {"estimator_curve", "0.6"}},
        {{"estimator_radius", "0"}},
        {{"zoom", "0.6"}, {"rotate", "30"}},
    };
    QStringList report, failed;
    int apart = 0, n = 0;
    for (const auto &set : settings) {
        QStringList what;
        for (const auto &[k, v] : set)
            what << QStringLiteral("%1=%2").arg(k, v);
        Judgement j;
        QString why;
        QVERIFY2(judge(QStringLiteral("setting%1").arg(n++), withAttributes(base, set), &j, &why),
                 qPrintable(what.join(' ') + ": " + why));
        report << QStringLiteral("%1: ours %2, flam3's own noise %3, brighter %4")
                      .arg(what.join(' '))
                      .arg(j.ours, 0, 'f', 4)
                      .arg(j.noise, 0, 'f', 4)
                      .arg(j.brighter, 0, 'f', 4);
        if (!j.same())
            failed << report.back();
        apart += j.tellsApart();
    }
    qInfo("genome-12 under flam3's tone settings:\n  %s", qPrintable(report.join("\n  ")));
    // The picture carries its project, as every figure: `check` opens the PNG as the project.
    QByteArray out;
    QCOMPARE(runProgram(cliPath(), {"check", m_dir.filePath("setting0.ours.png")}, &out), 0);
    QVERIFY2(out.contains("OK, 1 item"), out.constData());
    QVERIFY2(failed.isEmpty(), qPrintable(failed.join("; ")));
    QVERIFY2(apart >= int(settings.size()) - 1, qPrintable(report.join("; ")));
}

// flam3's passes: each pass's histogram log-scaled and density-estimated apart, then summed.
// At quality 20 ten passes are much smoother than one (each pass's estimator sees a tenth of
// the hits, so its kernels are wider); the mean difference cannot tell them apart (both are
// within flam3's own noise), the grain can: ours must be as grainy as flam3's picture within
// 25 % at one and at ten passes, and flam3's two must differ by more than that.
void TestFlameTone::passesAsFlam3()
{
    const QByteArray base = withQuality(readAll(flamesDir() + "/genome-12.flame"), 20);
    double theirs[2] = {0, 0}, ours[2] = {0, 0};
    QStringList report;
    for (int k = 0; k < 2; ++k) {
        const QString passes = k ? QStringLiteral("10") : QStringLiteral("1");
        const QString name = QStringLiteral("passes") + passes;
        const QString path = m_dir.filePath(name + ".flame"), flam3 = m_dir.filePath(name + ".png"),
                      mine = m_dir.filePath(name + ".ours.png"),
                      project = m_dir.filePath(name + ".awb");
        QVERIFY(put(path, withAttributes(base, {{"passes", passes}})));
        QString why;
        QVERIFY2(flam3Render(path, flam3, &why, {{"transparency", "0"}, {"isaac_seed", "first"}}),
                 qPrintable(why));
        QByteArray err;
        QVERIFY2(runProgram(cliPath(), {"import", path, "--out", project}, nullptr, &err) == 0,
                 err.constData());
        QVERIFY2(runProgram(cliPath(), {"render", project, "--out", mine}, nullptr, &err) == 0,
                 err.constData());
        theirs[k] = roughness(QImage(flam3));
        ours[k] = roughness(QImage(mine));
        report << QStringLiteral("passes %1: grain ours %2, flam3's %3, mean difference %4")
                      .arg(passes)
                      .arg(ours[k], 0, 'f', 4)
                      .arg(theirs[k], 0, 'f', 4)
                      .arg(meanDifference(QImage(mine), QImage(flam3)), 0, 'f', 4);
    }
    qInfo("genome-12 at quality 20:\n  %s", qPrintable(report.join("\n  ")));
    for (int k = 0; k < 2; ++k)
        QVERIFY2(std::abs(ours[k] - theirs[k]) <= 0.25 * theirs[k], qPrintable(report.join("; ")));
    QVERIFY2(theirs[1] < 0.7 * theirs[0], qPrintable(report.join("; ")));
    // The setting is kept in the project, and written back to a flame.
    QByteArray out;
    QCOMPARE(runProgram(cliPath(), {"export", m_dir.filePath("passes10.awb"), "--format", "flame", "--out",
                                    m_dir.filePath("passes10.back.flame")},
                        &out),
             0);
    QVERIFY(readAll(m_dir.filePath("passes10.back.flame")).contains("passes=\"10\""));
}

// A flame whose picture cannot be drawn (a spatial filter wider than 1025 cells, passes out of
// range) is refused with a message that names the item and the limit, exit 1.
void TestFlameTone::pictureLimitsNameTheItem()
{
    const QString flame = m_dir.filePath("wide.flame"), project = m_dir.filePath("wide.awb");
    QVERIFY(put(flame, "<flame name=\"wide\" size=\"64 64\" filter=\"900\">"
                       "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0 0\" swirl=\"1\"/></flame>\n"));
    QByteArray out, err;
    QCOMPARE(runProgram(cliPath(), {"import", flame, "--out", project}, &out, &err), 0);
    QCOMPARE(runProgram(cliPath(), {"render", project, "--out", m_dir.filePath("wide.png")}, &out,
                        &err),
             1);
    QCOMPARE(err.trimmed(), QByteArray("attractor-cli: item 'wide': the spatial filter of radius "
                                       "900 at supersample 1 would be 2700 cells wide; at most "
                                       "1025"));
    QVERIFY(!QFile::exists(m_dir.filePath("wide.png")));
    QVERIFY(put(flame, "<flame name=\"p\" passes=\"65\"><xform weight=\"1\" "
                       "coefs=\"0.5 0 0 0.5 0 0\"/></flame>\n"));
    QCOMPARE(runProgram(cliPath(), {"import", flame, "--out", project}, &out, &err), 1);
    QVERIFY2(err.contains("passes=\"65\" must be a whole number from 1 to 64"), err.constData());
}

AWB_TEST_MAIN(TestFlameTone)
#include "test_flame_tone.moc"
