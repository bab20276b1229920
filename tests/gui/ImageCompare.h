#pragma once
// Tolerant comparison of rendered images with references in tests/gui/data/ (the 3D view's CPU
// picture, the characteristic map): rasterisation details, thread scheduling and GL drivers
// differ, the figure must not. AWB_REGENERATE_REFERENCES=1 writes the references anew.

#include "TestPaths.h"
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QString>

#include <cmath>

namespace awb::test {

// Fraction of pixels where the two images disagree about being background (white), and the
// mean colour difference where both are drawn: a tolerant comparison (rasterisation details,
// thread scheduling and GL drivers differ; the figure must not).
struct ImageDiff {
    double coverageMismatch = 1.0;
    double meanColour = 255.0;
};
inline ImageDiff compare(const QImage &a0, const QImage &b0)
{
    const QImage a = a0.convertToFormat(QImage::Format_RGB32);
    const QImage b = b0.convertToFormat(QImage::Format_RGB32).scaled(a.size());
    qint64 mismatch = 0, both = 0, drawn = 0;
    double colour = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            const bool inA = (p & 0xffffff) != 0xffffff, inB = (q & 0xffffff) != 0xffffff;
            drawn += inA || inB;
            mismatch += inA != inB;
            if (inA && inB) {
                ++both;
                colour += (std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q))
                           + std::abs(qBlue(p) - qBlue(q))) / 3.0;
            }
        }
    ImageDiff d;
    d.coverageMismatch = drawn ? double(mismatch) / double(drawn) : 0.0;
    d.meanColour = both ? colour / double(both) : 0.0;
    return d;
}

inline QImage reference(const QString &name, const QImage &actual)
{
    const QString file = (awb::test::sourceDir() + QStringLiteral("/tests/gui/data/")) + name;
    if (qEnvironmentVariableIntValue("AWB_REGENERATE_REFERENCES")) {
        QDir().mkpath(QFileInfo(file).path());
        actual.save(file);
    }
    return QImage(file);
}

inline qint64 drawnPixels(const QImage &image)
{
    qint64 n = 0;
    const QImage im = image.convertToFormat(QImage::Format_RGB32);
    for (int y = 0; y < im.height(); ++y)
        for (int x = 0; x < im.width(); ++x)
            n += (im.pixel(x, y) & 0xffffff) != 0xffffff;
    return n;
}

} // namespace awb::test
