#include "render/FigureFile.h"

#include <QFileInfo>
#include <QImage>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QSvgGenerator>

namespace awb {

bool writePaintedFigure(const QString &fileName, QSize size, const QString &title,
                        const std::function<void(QPainter &)> &paint, QString *error)
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
        return p.end() || cannot();
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
