#include "render/FigureFile.h"

#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>
#include <QSvgGenerator>

namespace awb {

void addPngText(QImage &image, const FigureMetadata &metadata)
{
    for (const auto &[key, text] : metadata.pngText)
        image.setText(key, text);
}

bool addSvgMetadata(const QString &svgFile, const FigureMetadata &metadata, QString *error)
{
    if (metadata.svgElement.isEmpty())
        return true;
    QFile in(svgFile);
    if (!in.open(QIODevice::ReadOnly)) {
        *error = QString("cannot read %1: %2").arg(svgFile, in.errorString());
        return false;
    }
    QByteArray svg = in.readAll();
    in.close();
    const qsizetype open = svg.indexOf("<svg");
    const qsizetype end = open < 0 ? -1 : svg.indexOf('>', open);
    if (end < 0) {
        *error = QString("%1 is not an SVG file").arg(svgFile);
        return false;
    }
    svg.insert(end + 1, "\n" + metadata.svgElement);
    QSaveFile out(svgFile);
    if (!out.open(QIODevice::WriteOnly) || out.write(svg) != svg.size() || !out.commit()) {
        *error = QString("cannot write %1: %2").arg(svgFile, out.errorString());
        return false;
    }
    return true;
}

bool writePaintedFigure(const QString &fileName, QSize size, const QString &title,
                        const std::function<void(QPainter &)> &paint, QString *error,
                        const FigureMetadata &metadata)
{
    const QString suffix = QFileInfo(fileName).suffix().toLower();
    const auto cannot = [&] {
        *error = QString("cannot write %1").arg(fileName);
        return false;
    };
    QPainter p;
    if (suffix == "png") {
        QImage image(size, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::white);
        if (!p.begin(&image))
            return cannot();
        paint(p);
        p.end();
        addPngText(image, metadata);
        return image.save(fileName, "PNG") || cannot();
    }
    if (suffix == "svg") {
        QSvgGenerator svg;
        svg.setFileName(fileName);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setTitle(title);
        svg.setDescription("Attractor Workbench figure");
        if (!p.begin(&svg))
            return cannot();
        paint(p);
        if (!p.end())
            return cannot();
        return addSvgMetadata(fileName, metadata, error);
    }
    if (suffix == "pdf") {
        QPdfWriter pdf(fileName);
        pdf.setTitle(title);
        pdf.setCreator("Attractor Workbench");
        pdf.setResolution(300);
        // A page of the figure's own proportions: width 180 mm (a journal column pair).
        const double mm = 180.0;
        pdf.setPageSize(QPageSize(QSizeF(mm, mm * size.height() / size.width()),
                                  QPageSize::Millimeter));
        pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
        if (!p.begin(&pdf))
            return cannot();
        // Scale figure pixels to the page: fonts given in pixels scale with it. Rasters stay
        // lossless (Qt's PDF engine would store them as JPEG).
        const double s = pdf.width() / double(size.width());
        p.scale(s, s);
        p.setRenderHint(QPainter::LosslessImageRendering);
        paint(p);
        return p.end() || cannot();
    }
    *error = QString("unknown output format '.%1' (use .png, .svg or .pdf)").arg(suffix);
    return false;
}

} // namespace awb
