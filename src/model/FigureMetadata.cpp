#include "model/FigureMetadata.h"

#include "model/EigenvaluePlotItem.h"
#include "model/Item.h"
#include "model/Project.h"
#include "model/ProjectIO.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QXmlStreamReader>

#include <zlib.h>

#include <algorithm>
#include <limits>

namespace awb {

QByteArray figureProjectBytes(const Project &project, const Item &item)
{
    QJsonObject root = ProjectIO::toJson(project);
    // The item, and the item an eigenvalue plot analyses (its source) so that it reopens.
    QString source;
    if (const auto *plot = qobject_cast<const EigenvaluePlotItem *>(&item))
        source = plot->source();
    QJsonArray kept;
    for (const Item *i : project.items())
        if (i == &item || (!source.isEmpty() && i->name() == source))
            kept.append(ProjectIO::itemToJson(*i));
    if (item.project() != &project) // a copy (an animation frame): itself
        kept.prepend(ProjectIO::itemToJson(item));
    root.insert(QStringLiteral("items"), kept);
    return ProjectIO::toBytes(root);
}

QList<QPair<QString, QString>> figurePngTexts(const QByteArray &projectBytes)
{
    return {{QString::fromLatin1(kFigureSoftwareKey),
             QStringLiteral("Attractor Workbench %1").arg(QStringLiteral(AWB_VERSION))},
            {QString::fromLatin1(kFigureProjectKey), QString::fromUtf8(projectBytes)}};
}

QByteArray svgMetadataElement(const QByteArray &projectBytes)
{
    QByteArray cdata = projectBytes;
    cdata.replace("]]>", "]]]]><![CDATA[>"); // cannot end the section early
    return "<metadata id=\"attractor-workbench-project\">\n<awb:project "
           "xmlns:awb=\"https://attractor-workbench.invalid/project\" version=\""
           + QByteArray(AWB_VERSION) + "\"><![CDATA[" + cdata
           + "]]></awb:project>\n</metadata>\n";
}

namespace {

constexpr qint64 kMaxFigureFile = 512ll << 20;  // a figure larger than this is no figure
constexpr qsizetype kMaxProjectText = 64 << 20;  // decompressed project text
const QByteArray kPngSignature("\x89PNG\r\n\x1a\n", 8);

QString tr(const char *text)
{
    return QCoreApplication::translate("awb::FigureMetadata", text);
}

quint32 bigEndian32(const char *p)
{
    return (quint32(uchar(p[0])) << 24) | (quint32(uchar(p[1])) << 16) | (quint32(uchar(p[2])) << 8)
           | quint32(uchar(p[3]));
}

// A zlib stream inflated to at most kMaxProjectText bytes: empty when it is malformed or
// larger (qUncompress doubles its buffer until the data fits: a 1 MB chunk of zeros asked it
// for 1 GB).
QByteArray inflate(const QByteArray &zlib)
{
    z_stream z{};
    if (inflateInit(&z) != Z_OK)
        return {};
    QByteArray out;
    char buffer[1 << 16];
    z.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(zlib.constData()));
    z.avail_in = uInt(std::min<qsizetype>(zlib.size(), std::numeric_limits<uInt>::max()));
    int status = Z_OK;
    while (status == Z_OK) {
        z.next_out = reinterpret_cast<Bytef *>(buffer);
        z.avail_out = sizeof buffer;
        status = ::inflate(&z, Z_NO_FLUSH);
        if (status != Z_OK && status != Z_STREAM_END)
            break;
        out.append(buffer, qsizetype(sizeof buffer - z.avail_out));
        if (out.size() > kMaxProjectText || (status == Z_OK && z.avail_in == 0
                                             && z.avail_out != 0)) {
            status = Z_DATA_ERROR;  // too large, or the stream ends before its end
            break;
        }
    }
    inflateEnd(&z);
    return status == Z_STREAM_END ? out : QByteArray();
}

// The text of `key` in a PNG's tEXt, zTXt or iTXt chunks, byte for byte (QImageReader::text
// folds line breaks and may miss compressed chunks). Empty when there is none.
QByteArray pngText(const QByteArray &png, const QByteArray &key)
{
    qsizetype i = 8;
    while (i + 12 <= png.size()) {
        const quint32 length = bigEndian32(png.constData() + i);
        const QByteArray type = png.mid(i + 4, 4);
        if (length > quint32(png.size() - i - 12))
            return {};  // truncated
        const QByteArray body = png.mid(i + 8, qsizetype(length));
        i += 12 + qsizetype(length);
        if (type == "IEND")
            break;
        const qsizetype zero = body.indexOf('\0');
        if (zero < 0 || body.left(zero) != key)
            continue;
        // tEXt and zTXt are Latin-1 (PNG standard); iTXt is UTF-8. The result is UTF-8.
        if (type == "tEXt")
            return QString::fromLatin1(body.mid(zero + 1)).toUtf8();
        if (type == "zTXt")
            return zero + 2 <= body.size() ? QString::fromLatin1(inflate(body.mid(zero + 2))).toUtf8()
                                           : QByteArray();
        if (type == "iTXt") {
            // key \0 compressed method language \0 translated \0 text
            if (zero + 3 > body.size())
                return {};
            const bool compressed = body[zero + 1] != 0;
            const qsizetype language = body.indexOf('\0', zero + 3);
            const qsizetype translated = language < 0 ? -1 : body.indexOf('\0', language + 1);
            if (translated < 0)
                return {};
            const QByteArray text = body.mid(translated + 1);
            return compressed ? inflate(text) : text;
        }
    }
    return {};
}

// The text of the SVG's <awb:project> element (svgMetadataElement), CDATA sections joined.
// Empty with *problem set when the XML does not parse before it; empty alone when there is
// none. QXmlStreamReader reads no external entity and bounds the expansion of internal ones.
QByteArray svgProject(const QByteArray &svg, QString *problem)
{
    static const QString ns = QStringLiteral("https://attractor-workbench.invalid/project");
    QXmlStreamReader xml(svg);
    while (!xml.atEnd()) {
        if (xml.readNext() == QXmlStreamReader::StartElement && xml.name() == u"project"
            && xml.namespaceUri() == ns) {
            const QString text = xml.readElementText(QXmlStreamReader::ErrorOnUnexpectedElement);
            if (xml.hasError())
                break;
            return text.toUtf8().left(kMaxProjectText + 1);
        }
    }
    if (xml.hasError())
        *problem = tr("the SVG does not parse: %1 (line %2, column %3)")
                       .arg(xml.errorString())
                       .arg(xml.lineNumber())
                       .arg(xml.columnNumber());
    return {};
}

} // namespace

FigureFormat figureFormat(const QByteArray &head)
{
    if (head.startsWith(kPngSignature))
        return FigureFormat::Png;
    // XML: a byte order mark, then white space, a declaration or comments before the root.
    QByteArrayView text(head);
    if (text.startsWith("\xEF\xBB\xBF"))
        text = text.sliced(3);
    text = text.trimmed();
    if (!text.startsWith('<'))
        return FigureFormat::None;
    const qsizetype svg = text.first(std::min<qsizetype>(text.size(), 4096)).indexOf("<svg");
    return svg >= 0 ? FigureFormat::Svg : FigureFormat::None;
}

FigureFormat figureFileFormat(const QString &fileName)
{
    QFile f(fileName);
    return f.open(QIODevice::ReadOnly) ? figureFormat(f.read(4096)) : FigureFormat::None;
}

QByteArray embeddedProject(const QString &figureFile, QString *error)
{
    QFile file(figureFile);
    if (!file.open(QIODevice::ReadOnly) || file.size() > kMaxFigureFile) {
        if (error)
            *error = tr("%1: cannot read the figure: %2")
                         .arg(figureFile, file.isOpen() ? tr("larger than 512 MB")
                                                        : file.errorString());
        return {};
    }
    return embeddedProject(file.readAll(), figureFile, error);
}

QByteArray embeddedProject(const QByteArray &figure, const QString &fileName, QString *error)
{
    QString problem;
    QByteArray text;
    switch (figureFormat(figure.left(4096))) {
    case FigureFormat::Png:
        text = pngText(figure, QByteArray(kFigureProjectKey));
        break;
    case FigureFormat::Svg:
        text = svgProject(figure, &problem);
        break;
    case FigureFormat::None:
        problem = tr("neither a PNG nor an SVG");
        break;
    }
    if (text.size() > kMaxProjectText)
        problem = tr("its project is larger than 64 MB");
    if (!problem.isEmpty() || text.isEmpty()) {
        if (error)
            *error = problem.isEmpty()
                         ? tr("%1: this %2 holds no Attractor Workbench item (only figures "
                              "exported by Attractor Workbench carry their parameters)")
                               .arg(fileName, figureFormat(figure.left(4096)) == FigureFormat::Svg
                                                  ? QStringLiteral("SVG")
                                                  : QStringLiteral("PNG"))
                         : QStringLiteral("%1: %2").arg(fileName, problem);
        return {};
    }
    return text;
}

} // namespace awb
