// The flame engine (core/flame/FlameChaos.h) judged by flam3-render (Debian flam3-utils,
// installed by scripts/setup.sh): flames with non-linear variations (deterministic and
// random ones, pre_blur), post transforms, xaos, a final xform with its opacity, an xform of
// opacity 0.5 and the rotations flam3's <symmetry> adds, each written as a flam3 genome and
// drawn by flam3-render (density estimation off, alpha out) and by accumulateFlame in the same
// frame. The pictures' occupancy in 8 x 8 blocks must agree (correlation > 0.85, and clearly
// less once ours is mirrored, so that the comparison can fail), and flam3's lit blocks must be
// lit in ours. Also: checkFlame's refusals, and the same picture on 1 and 2 threads.

#include <QFile>
#include <QImage>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include "BlockCompare.h"
#include "TestMain.h"
#include "TestTime.h"

#include "core/Messages.h"
#include "core/flame/FlameChaos.h"
#include "core/flame/Variations.h"

#include <cmath>

using namespace awb;
using namespace awb::flame;

namespace {

QString num(double v) { return QString::fromStdString(shortestNumber(v)); }

FlameXform xform(double weight, Affine2 pre, std::vector<std::pair<const char *, double>> vars,
                 double colour = 0)
{
    FlameXform x;
    x.weight = weight;
    x.pre = pre;
    x.colour = colour;
    x.variations.clear();
    for (const auto &[name, w] : vars)
        x.variations.push_back({variationId(name), w});
    std::sort(x.variations.begin(), x.variations.end(),
              [](const VariationTerm &a, const VariationTerm &b) { return a.id < b.id; });
    return x;
}

void setParameter(FlameXform &x, const char *name, double value)
{
    x.parameters[std::size_t(parameterId(name))] = value;
}

// One xform as flam3's XML (coefs="a d b e c f").
QString xformXml(const FlameXform &x, const char *tag, int count)
{
    auto coefs = [](const Affine2 &m) {
        return QStringLiteral("%1 %2 %3 %4 %5 %6")
            .arg(num(m.a), num(m.d), num(m.b), num(m.e), num(m.c), num(m.f));
    };
    QString out = QStringLiteral("<%1 weight=\"%2\" color=\"%3\" color_speed=\"%4\" "
                                 "opacity=\"%5\" coefs=\"%6\"")
                      .arg(QString::fromLatin1(tag), num(x.weight), num(x.colour),
                           num(x.colourSpeed), num(x.opacity), coefs(x.pre));
    if (!x.post.isIdentity())
        out += QStringLiteral(" post=\"%1\"").arg(coefs(x.post));
    for (const VariationTerm &v : x.variations) {
        out += QStringLiteral(" %1=\"%2\"")
                   .arg(QString::fromUtf8(variationName(v.id).data(),
                                          qsizetype(variationName(v.id).size())),
                        num(v.weight));
        for (int p : variationParameters(v.id)) {
            QString name = QString::fromUtf8(parameterName(p).data(),
                                             qsizetype(parameterName(p).size()));
            name.replace("oscilloscope_", "oscope_");
            out += QStringLiteral(" %1=\"%2\"").arg(name, num(x.parameters[std::size_t(p)]));
        }
    }
    if (!x.xaos.empty()) {
        QStringList row;
        for (int j = 0; j < count; ++j)
            row << num(x.xaosTo(std::size_t(j)));
        out += QStringLiteral(" chaos=\"%1\"").arg(row.join(' '));
    }
    return out + "/>\n";
}

QByteArray genomeXml(const Flame &f)
{
    QString out = QStringLiteral("<flame name=\"t\" size=\"%1 %2\" center=\"%3 %4\" scale=\"%5\" "
                                 "rotate=\"%6\" quality=\"%7\" supersample=\"1\" "
                                 "filter=\"0.5\" oversample=\"1\" background=\"0 0 0\" "
                                 "brightness=\"4\" gamma=\"4\" vibrancy=\"1\" "
                                 "estimator_radius=\"0\">\n")
                      .arg(f.width)
                      .arg(f.height)
                      .arg(num(f.centre[0]), num(f.centre[1]), num(f.scale), num(f.rotate),
                           num(f.quality));
    for (const FlameXform &x : f.xforms)
        out += xformXml(x, "xform", int(f.xforms.size()));
    if (f.finalXform)
        out += xformXml(*f.finalXform, "finalxform", int(f.xforms.size()));
    for (int i = 0; i < 256; ++i)
        out += QStringLiteral("<color index=\"%1\" rgb=\"255 255 255\"/>\n").arg(i);
    return (out + "</flame>\n").toUtf8();
}

// The picture's alpha (flam3) or occupancy (ours) in blocks of b x b pixels.
std::vector<double> blocks(const QImage &alpha, int b)
{
    const QImage a = alpha.convertToFormat(QImage::Format_RGBA64);
    const int nx = a.width() / b, ny = a.height() / b;
    std::vector<double> out(std::size_t(nx) * ny, 0.0);
    for (int y = 0; y < ny * b; ++y) {
        const auto *row = reinterpret_cast<const QRgba64 *>(a.constScanLine(y));
        for (int x = 0; x < nx * b; ++x)
            out[std::size_t(y / b) * nx + x / b] += (row[x].alpha() > 0) / double(b * b);
    }
    return out;
}

std::vector<double> blocks(const DensityImage &image, int b, bool mirror)
{
    const int w = image.cellsX(), h = image.cellsY();
    const int nx = w / b, ny = h / b;
    std::vector<double> out(std::size_t(nx) * ny, 0.0);
    for (int y = 0; y < ny * b; ++y)
        for (int x = 0; x < nx * b; ++x) {
            const int row = mirror ? h - 1 - y : y;
            out[std::size_t(y / b) * nx + x / b] +=
                (image.count(std::size_t(row) * w + x) > 0) / double(b * b);
        }
    return out;
}

Flame frameOf(double cx, double cy, double scale, double quality)
{
    Flame f;
    f.width = f.height = 256;
    f.centre[0] = cx;
    f.centre[1] = cy;
    f.scale = scale;
    f.quality = quality;
    return f;
}

// Non-linear deterministic variations with a post transform: a spherical / swirl flame.
Flame sphericalSwirl()
{
    Flame f = frameOf(0, 0, 60, 60);
    f.xforms.push_back(xform(1, {0.6, 0.3, 0.2, -0.3, 0.6, 0.1}, {{"spherical", 0.8},
                                                                  {"linear", 0.2}}));
    f.xforms.push_back(xform(1, {0.5, 0, -0.5, 0, 0.5, 0.5}, {{"swirl", 1}}, 0.5));
    f.xforms.back().post = {0.9, -0.2, 0.1, 0.2, 0.9, 0};
    f.xforms.push_back(xform(0.5, {0.4, -0.4, 0.4, 0.4, 0.4, -0.3}, {{"sinusoidal", 1}}, 1));
    return f;
}

// Random variations (julian's branches, gaussian_blur, pre_blur) and xaos.
Flame julianXaos()
{
    Flame f = frameOf(0, 0, 50, 60);
    f.xforms.push_back(xform(1, {0.7, 0.2, 0.1, -0.2, 0.7, 0}, {{"julian", 1}}));
    setParameter(f.xforms.back(), "julian_power", 3);
    setParameter(f.xforms.back(), "julian_dist", 1);
    f.xforms.push_back(xform(1, {0.3, 0, 1, 0, 0.3, 0.5}, {{"gaussian_blur", 0.1},
                                                          {"linear", 1}}, 1));
    f.xforms.push_back(xform(0.5, {0.5, 0.5, -0.5, -0.5, 0.5, 0}, {{"pre_blur", 0.05},
                                                                  {"bubble", 1}}, 0.5));
    // After xform 1 never xform 3, after 3 twice as likely 2.
    f.xforms[0].xaos = {1, 1, 0};
    f.xforms[2].xaos = {1, 2, 1};
    return f;
}

// A final xform drawn on half the points, an xform of opacity 0.5, and flam3's symmetry
// kind 3 written out (the rotations by 120 and 240 degrees).
Flame finalAndSymmetry()
{
    Flame f = frameOf(0.1, -0.1, 70, 60);
    f.xforms.push_back(xform(1, {0.5, 0.1, 0.5, 0.1, 0.5, 0}, {{"cylinder", 0.5},
                                                              {"linear", 0.5}}));
    f.xforms.push_back(xform(1, {0.4, -0.3, -0.4, 0.3, 0.4, 0.2}, {{"hyperbolic", 0.3},
                                                                  {"linear", 0.7}}, 1));
    f.xforms.back().opacity = 0.5;
    for (double deg : {120.0, 240.0}) {
        const double c = std::round(1e6 * std::cos(deg * M_PI / 180)) / 1e6;
        const double s = std::round(1e6 * std::sin(deg * M_PI / 180)) / 1e6;
        f.xforms.push_back(xform(1, {c, -s, 0, s, c, 0}, {{"linear", 1}}));
        f.xforms.back().colourSpeed = 0;
        f.xforms.back().animate = 0;
    }
    FlameXform fin = xform(0, {1, 0, 0, 0, 1, 0}, {{"eyefish", 1}});
    fin.opacity = 0.5;
    f.finalXform = fin;
    return f;
}

} // namespace

class TestFlameChaos : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void drawsAsFlam3Renders_data();
    void drawsAsFlam3Renders();
    void sameOnAnyThreads();
    void refusals();

private:
    QTemporaryDir m_dir;
};

void TestFlameChaos::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QVERIFY2(!QStandardPaths::findExecutable("flam3-render").isEmpty(),
             "flam3-render (Debian flam3-utils) is missing: run scripts/setup.sh");
}

void TestFlameChaos::drawsAsFlam3Renders_data()
{
    QTest::addColumn<int>("which");
    QTest::newRow("spherical, swirl, post") << 0;
    QTest::newRow("julian, gaussian_blur, pre_blur, xaos") << 1;
    QTest::newRow("final xform, opacity, symmetry") << 2;
}

void TestFlameChaos::drawsAsFlam3Renders()
{
    QFETCH(int, which);
    const Flame f = which == 0 ? sphericalSwirl() : which == 1 ? julianXaos() : finalAndSymmetry();
    QVERIFY_THROWS_NO_EXCEPTION(checkFlame(f));
    const QString genome = m_dir.filePath(QStringLiteral("g%1.flame").arg(which));
    QFile out(genome);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(genomeXml(f));
    out.close();
    const QString png = m_dir.filePath(QStringLiteral("g%1.png").arg(which));
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("format", "png");
    env.insert("transparency", "1");
    env.insert("out", png);
    env.insert("nthreads", "1");
    p.setProcessEnvironment(env);
    p.setStandardInputFile(genome);
    p.start("flam3-render", {});
    QVERIFY(p.waitForFinished(awb::test::ms(300000)));
    QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
    const QImage theirs(png);
    QCOMPARE(theirs.size(), QSize(256, 256));

    DensityImage image;
    FlameRaster job;
    job.flame = &f;
    job.frame = flameFrame(f);
    job.accumulation = Accumulation::Hits;
    job.samples = std::uint64_t(flameSamples(f));
    job.threads = 2;
    const FlameStats stats = accumulateFlame(job, image);
    QCOMPARE(stats.samples, job.samples);
    const auto A = blocks(theirs, 8), B = blocks(image, 8, false), Bm = blocks(image, 8, true);
    const double same = awb::test::correlation(A, B), mirrored = awb::test::correlation(A, Bm);
    qInfo("correlation of 8 x 8 block occupancy %.3f (ours mirrored %.3f); flam3's lit blocks "
          "lit in ours %.3f; bad values %llu",
          same, mirrored, awb::test::litCovered(A, B, 0.2, 0), static_cast<unsigned long long>(stats.badValues));
    QVERIFY2(same > 0.85, qPrintable(QString::number(same)));
    QVERIFY2(same > mirrored + 0.1, qPrintable(QString::number(mirrored)));
    QVERIFY(awb::test::litCovered(A, B, 0.2, 0) > 0.95);
}

void TestFlameChaos::sameOnAnyThreads()
{
    const Flame f = julianXaos();
    FlameRaster job;
    job.flame = &f;
    job.frame = flameFrame(f);
    job.samples = 300000;
    DensityImage one, two;
    job.threads = 1;
    accumulateFlame(job, one);
    job.threads = 2;
    accumulateFlame(job, two);
    for (std::size_t i = 0; i < std::size_t(one.cellsX()) * one.cellsY(); ++i)
        QCOMPARE(one.count(i), two.count(i));
}

void TestFlameChaos::refusals()
{
    Flame f = sphericalSwirl();
    DensityImage image;
    FlameRaster job;
    job.flame = &f;
    job.frame = flameFrame(f);
    job.samples = 1000;
    auto refused = [&](const char *part) {
        try {
            accumulateFlame(job, image);
        } catch (const InputError &e) {
            return QString::fromUtf8(e.what()).contains(QLatin1String(part));
        }
        return false;
    };
    for (FlameXform &x : f.xforms)
        x.weight = 0;
    QVERIFY(refused("every xform of the flame has weight 0"));
    f = sphericalSwirl();
    f.xforms[1].pre.c = std::nan("");
    QVERIFY(refused("xform 2: a coefficient is not a finite number"));
    f = sphericalSwirl();
    f.xforms[0].xaos = {0, 0, 0};
    QVERIFY(refused("xform 1: its xaos row forbids every xform"));
    f = sphericalSwirl();
    f.xforms[0].variations.push_back({kVariationCount, 1});
    QVERIFY(refused("variation 99 does not exist"));
    f.xforms.clear();
    QVERIFY(refused("the flame has no xform"));
}

AWB_TEST_MAIN(TestFlameChaos)
#include "test_flame_chaos.moc"
