#pragma once
// flam3-render as the judge of the flame tests (Debian flam3-utils, installed by
// scripts/setup.sh): a genome rendered by flam3 and by attractor-cli in the same frame, the two
// pictures compared by block means of alpha (BlockCompare.h).

#include <QDir>
#include <QImage>
#include <QProcess>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QString>

#include "TestTime.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace awb::test {

// A flame's frame as attractor-cli's --bounds: the world rectangle before render's 6% padding,
// so that the padded frame is the flame's (centre, size / scale; y mirrored).
inline QString boundsOfFlame(const QByteArray &flame, int *width, int *height)
{
    auto attribute = [&](const char *name) {
        const QRegularExpression re(QStringLiteral("<flame [^>]*\\b%1=\"([^\"]+)\"").arg(name));
        return re.match(QString::fromUtf8(flame)).captured(1).split(' ');
    };
    const QStringList size = attribute("size"), centre = attribute("center");
    const double scale = attribute("scale").value(0).toDouble();
    *width = size.value(0).toInt();
    *height = size.value(1).toInt();
    const double W = *width / scale, H = *height / scale;
    const double cx = centre.value(0).toDouble(), cy = -centre.value(1).toDouble();
    // Padding adds 0.06 of the larger side on each side.
    const double w0 = W >= H ? W / 1.12 : W - 0.12 * H / 1.12;
    const double h0 = W >= H ? H - 0.12 * w0 : H / 1.12;
    return QStringLiteral("%1,%2,%3,%4")
        .arg(cx - w0 / 2, 0, 'g', 17)
        .arg(cy - h0 / 2, 0, 'g', 17)
        .arg(cx + w0 / 2, 0, 'g', 17)
        .arg(cy + h0 / 2, 0, 'g', 17);
}

// The picture's alpha in blocks of b x b pixels (their means), row by row; `mirror` flips it
// upside down first.
inline std::vector<double> blockAlpha(const QImage &image, int b, bool mirror = false)
{
    const QImage a = image.convertToFormat(QImage::Format_RGBA64);
    const int nx = a.width() / b, ny = a.height() / b;
    std::vector<double> out(std::size_t(nx) * ny, 0.0);
    for (int y = 0; y < ny * b; ++y) {
        const auto *row =
            reinterpret_cast<const QRgba64 *>(a.constScanLine(mirror ? a.height() - 1 - y : y));
        for (int x = 0; x < nx * b; ++x)
            out[std::size_t(y / b) * nx + x / b] += row[x].alpha() / 65535.0 / (b * b);
    }
    return out;
}

// The mean colour of each b x b block, as chromaticity (r, g, b) / (r + g + b), and its lit
// weight (the sum of r + g + b): brightness, gamma and alpha differ between two renderers, the
// hue of what is drawn must not.
struct BlockChroma {
    std::vector<std::array<double, 3>> chroma;
    std::vector<double> weight;
};
inline BlockChroma blockChroma(const QImage &image, int b)
{
    const QImage a = image.convertToFormat(QImage::Format_RGBA64);
    const int nx = a.width() / b, ny = a.height() / b;
    BlockChroma out;
    out.chroma.assign(std::size_t(nx) * ny, {0.0, 0.0, 0.0});
    out.weight.assign(std::size_t(nx) * ny, 0.0);
    for (int y = 0; y < ny * b; ++y) {
        const auto *row = reinterpret_cast<const QRgba64 *>(a.constScanLine(y));
        for (int x = 0; x < nx * b; ++x) {
            auto &c = out.chroma[std::size_t(y / b) * nx + x / b];
            c[0] += row[x].red();
            c[1] += row[x].green();
            c[2] += row[x].blue();
        }
    }
    for (std::size_t k = 0; k < out.chroma.size(); ++k) {
        auto &c = out.chroma[k];
        const double sum = c[0] + c[1] + c[2];
        out.weight[k] = sum;
        if (sum > 0)
            for (double &v : c)
                v /= sum;
    }
    return out;
}

// The mean L1 distance of the chromaticities of the blocks lit in both (each more than
// `lit` of the brightest block's weight).
inline double chromaDistance(const BlockChroma &a, const BlockChroma &b, double lit = 0.05)
{
    const double ma = *std::max_element(a.weight.begin(), a.weight.end());
    const double mb = *std::max_element(b.weight.begin(), b.weight.end());
    double sum = 0;
    int n = 0;
    for (std::size_t k = 0; k < a.weight.size() && k < b.weight.size(); ++k) {
        if (a.weight[k] <= lit * ma || b.weight[k] <= lit * mb)
            continue;
        for (int c = 0; c < 3; ++c)
            sum += std::abs(a.chroma[k][c] - b.chroma[k][c]);
        ++n;
    }
    return n ? sum / n : 2.0;
}

// flam3-render of a genome into `png` (with alpha: transparency=1; `more` sets other
// variables of flam3-render, e.g. transparency=0 for the picture on its background, or
// isaac_seed for other random numbers).
inline bool flam3Render(const QString &flame, const QString &png, QString *why,
                        const QList<std::pair<QString, QString>> &more = {})
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("format", "png");
    env.insert("transparency", "1");
    env.insert("out", png);
    for (const auto &[k, v] : more)
        env.insert(k, v);
    env.insert("nthreads", "2");
    p.setProcessEnvironment(env);
    p.setStandardInputFile(flame);
    p.start("flam3-render", {});
    if (!p.waitForFinished(awb::test::ms(300000)) || p.exitCode() != 0) {
        *why = QString::fromUtf8(p.readAllStandardError());
        return false;
    }
    return true;
}

// The genomes of tests/cli/data/flames (30 files written by flam3-genome), by name; in the
// instrumented builds (scripts/sanitize.sh: AWB_TEST_TIME_SCALE), which look for memory
// errors and races rather than at pictures, every `step`-th of them.
inline QStringList judgedFlames(const QString &dir, int step)
{
    QStringList files = QDir(dir).entryList({"*.flame"}, QDir::Files, QDir::Name);
    if (qEnvironmentVariableIntValue("AWB_TEST_TIME_SCALE") <= 1)
        return files;
    QStringList some;
    for (qsizetype i = 0; i < files.size(); i += step)
        some << files[i];
    return some;
}

// A genome with its quality (samples per pixel) raised, as flam3-render should draw it.
inline QByteArray withQuality(QByteArray flame, int quality)
{
    return QString::fromUtf8(flame)
        .replace(QRegularExpression("quality=\"[^\"]*\""), QStringLiteral("quality=\"%1\"").arg(quality))
        .toUtf8();
}

} // namespace awb::test
