#include "render/DensityFile.h"

#include <QCoreApplication>
#include <QImage>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {
struct DensityTr {
    Q_DECLARE_TR_FUNCTIONS(awb::DensityFile)
};
} // namespace

bool writeDensityPng16(const QString &fileName, const AttractorDensity &d,
                       const DensityFileInfo &info, QString *error)
{
    const int W = d.frame.width, H = d.frame.height;
    if (d.rgba.size() != 4 * std::size_t(W) * std::size_t(H)) {
        if (error)
            *error = DensityTr::tr("cannot write %1: the picture is empty").arg(fileName);
        return false;
    }
    double maxCount = 0;
    for (std::size_t i = 3; i < d.rgba.size(); i += 4)
        maxCount = std::max(maxCount, double(d.rgba[i]));
    QImage image(W, H, QImage::Format_RGBA64);
    if (image.isNull()) {
        if (error)
            *error = DensityTr::tr("cannot write %1: not enough memory").arg(fileName);
        return false;
    }
    const double norm = maxCount > 0 ? 1.0 / std::log1p(maxCount) : 0.0;
    auto q16 = [](double v) { return quint16(std::lround(std::clamp(v, 0.0, 1.0) * 65535.0)); };
    for (int y = 0; y < H; ++y) {
        auto *row = reinterpret_cast<QRgba64 *>(image.scanLine(y));
        for (int x = 0; x < W; ++x) {
            const float *p = &d.rgba[4 * (std::size_t(y) * W + x)];
            const double n = p[3];
            if (n <= 0) {
                row[x] = QRgba64::fromRgba64(0, 0, 0, 0);
                continue;
            }
            row[x] = QRgba64::fromRgba64(q16(p[0] / n), q16(p[1] / n), q16(p[2] / n),
                                         q16(std::log1p(n) * norm));
        }
    }
    addPngText(image, info.metadata);
    image.setText(QString::fromLatin1(kDensityMaxCountKey), QString::number(maxCount, 'g', 17));
    image.setText(QStringLiteral("Description"),
                  DensityTr::tr("%1; alpha = log(1 + hits) / log(1 + %2); world %3 %4 %5 %6")
                      .arg(info.what)
                      .arg(maxCount, 0, 'g', 17)
                      .arg(info.world.left(), 0, 'g', 17)
                      .arg(info.world.top(), 0, 'g', 17)
                      .arg(info.world.right(), 0, 'g', 17)
                      .arg(info.world.bottom(), 0, 'g', 17));
    return writeFigureFile(
        fileName, [&](QIODevice &out, QString *) { return writePng(image, out); }, error);
}

} // namespace awb
