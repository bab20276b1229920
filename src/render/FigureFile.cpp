#include "render/FigureFile.h"

#include "model/FigureMetadata.h"
#include "model/FileWriting.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QFileInfo>
#include <QImage>
#include <QImageWriter>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QSvgGenerator>

namespace awb {

namespace {

// The translation context of the messages below.
struct FigureFile {
    Q_DECLARE_TR_FUNCTIONS(awb::FigureFile)
};

} // namespace

FigureMetadata itemFigureMetadata(const Project &project, const Item &item)
{
    const QByteArray bytes = figureProjectBytes(project, item);
    return {figurePngTexts(bytes), svgMetadataElement(bytes)};
}

void addPngText(QImage &image, const FigureMetadata &metadata)
{
    for (const auto &[key, text] : metadata.pngText)
        image.setText(key, text);
}

bool addSvgMetadata(QByteArray &svg, const FigureMetadata &metadata)
{
    const qsizetype open = svg.indexOf("<svg");
    const qsizetype end = open < 0 ? -1 : svg.indexOf('>', open);
    if (end < 0)
        return false;
    if (!metadata.svgElement.isEmpty())
        svg.insert(end + 1, "\n" + metadata.svgElement);
    return true;
}

bool writePng(const QImage &image, QIODevice &out)
{
    QImageWriter writer(&out, "png");
    // zlib level 1 (Qt maps quality q to level (100 - q) * 9 / 91): a 1024 x 1024 figure is
    // written in 57 ms instead of 89 ms at the default level 6, and is 4 % larger.
    writer.setQuality(80);
    return writer.write(image);
}

bool writeFigureFile(const QString &fileName,
                     const std::function<bool(QIODevice &out, QString *error)> &write,
                     QString *error)
{
    QString ignored;
    if (!error)
        error = &ignored;
    const auto fail = [&](const QString &reason) {
        *error = reason.isEmpty() ? FigureFile::tr("cannot write %1").arg(fileName)
                                  : FigureFile::tr("cannot write %1: %2").arg(fileName, reason);
        return false;
    };
    // Refused before any work: a missing folder, a folder, a read-only file.
    const QFileInfo info(fileName);
    if (!QFileInfo(info.absolutePath()).isDir())
        return fail(FigureFile::tr("the folder %1 does not exist").arg(info.path()));
    if (info.isDir())
        return fail(FigureFile::tr("it is a folder"));
    if (info.isFile() && !info.isWritable())
        return fail(FigureFile::tr("the file is read-only"));
    QByteArray bytes;
    QString reason;
    {
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        if (!write(buffer, &reason))
            return fail(reason);
    }
    if (!writeWholeFile(fileName, bytes, &reason))
        return fail(reason);
    return true;
}

bool writePaintedFigure(const QString &fileName, QSize size,
                        const std::function<void(QPainter &)> &paint, QString *error,
                        const PaintedFigureOptions &o)
{
    if (QFileInfo(fileName).isDir()) {
        *error = FigureFile::tr("cannot write %1: it is a folder").arg(fileName);
        return false;
    }
    const QString kind = o.format.isEmpty() ? QFileInfo(fileName).suffix().toLower() : o.format;
    if (kind != "png" && kind != "svg" && kind != "pdf") {
        *error = kind.isEmpty()
                     ? FigureFile::tr("%1 has no suffix: name the format (.png, .svg or .pdf)")
                           .arg(fileName)
                     : FigureFile::tr("unknown output format '.%1' (use .png, .svg or .pdf)")
                           .arg(kind);
        return false;
    }
    const auto cancelled = [&] { return o.cancelled && o.cancelled(); };
    // Each painter is declared after its device: a paint() that throws ends the painter
    // before the device goes.
    return writeFigureFile(fileName, [&](QIODevice &out, QString *) {
        if (kind == "png") {
            QImage image(size, QImage::Format_ARGB32_Premultiplied);
            image.fill(Qt::white);
            if (o.dpi > 0) {
                const int dpm = int(std::lround(o.dpi / 0.0254));
                image.setDotsPerMeterX(dpm);
                image.setDotsPerMeterY(dpm);
            }
            QPainter p;
            if (!p.begin(&image))
                return false;
            if (o.antialias)
                p.setRenderHint(QPainter::Antialiasing);
            paint(p);
            p.end();
            addPngText(image, o.metadata);
            return !cancelled() && writePng(image, out);
        }
        if (kind == "svg") {
            QByteArray svgBytes;
            {
                QBuffer svgBuffer(&svgBytes);
                QSvgGenerator svg;
                svg.setOutputDevice(&svgBuffer);
                svg.setSize(size);
                svg.setViewBox(o.viewBox.isEmpty() ? QRectF(QPoint(0, 0), size) : o.viewBox);
                if (o.dpi > 0)
                    svg.setResolution(o.dpi);
                svg.setTitle(o.title);
                if (o.dpi <= 0)
                    svg.setDescription("Attractor Workbench figure");
                QPainter p;
                if (!p.begin(&svg))
                    return false;
                paint(p);
                if (!p.end())
                    return false;
            }
            return !cancelled() && addSvgMetadata(svgBytes, o.metadata)
                   && out.write(svgBytes) == svgBytes.size();
        }
        QPdfWriter pdf(&out);
        if (o.dpi > 0) {
            // A page of the figure's size at the print resolution.
            pdf.setResolution(o.dpi);
            pdf.setPageLayout(QPageLayout(
                QPageSize(QSizeF(size.width() * 72.0 / o.dpi, size.height() * 72.0 / o.dpi),
                          QPageSize::Point),
                QPageLayout::Portrait, QMarginsF()));
        } else {
            pdf.setTitle(o.title);
            pdf.setCreator("Attractor Workbench");
            pdf.setResolution(300);
            // A page of the figure's own proportions: width 180 mm (a journal column pair).
            const double mm = 180.0;
            pdf.setPageSize(QPageSize(QSizeF(mm, mm * size.height() / size.width()),
                                      QPageSize::Millimeter));
            pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
        }
        QPainter p;
        if (!p.begin(&pdf))
            return false;
        if (o.dpi <= 0) {
            // Scale figure pixels to the page: fonts given in pixels scale with it.
            const double s = pdf.width() / double(size.width());
            p.scale(s, s);
        }
        // Rasters stay lossless (Qt's PDF engine would store them as JPEG).
        p.setRenderHint(QPainter::LosslessImageRendering);
        paint(p);
        return p.end() && !cancelled();
    }, error);
}

} // namespace awb
