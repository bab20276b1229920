#include "model/FigureMetadata.h"

#include "model/EigenvaluePlotItem.h"
#include "model/Item.h"
#include "model/Project.h"
#include "model/ProjectIO.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>

#include <algorithm>

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

bool isPngFile(const QString &fileName)
{
    QFile f(fileName);
    return f.open(QIODevice::ReadOnly) && f.read(8) == QByteArray("\x89PNG\r\n\x1a\n", 8);
}

namespace {

constexpr qint64 kMaxFigureFile = 512ll << 20;  // a figure larger than this is no figure
constexpr qsizetype kMaxProjectText = 64 << 20;  // decompressed project text

quint32 bigEndian32(const char *p)
{
    return (quint32(uchar(p[0])) << 24) | (quint32(uchar(p[1])) << 16) | (quint32(uchar(p[2])) << 8)
           | quint32(uchar(p[3]));
}

QByteArray inflate(const QByteArray &zlib)
{
    // qUncompress wants the length first; it grows its buffer when the hint is short.
    const quint32 hint = quint32(std::min<qsizetype>(kMaxProjectText, 16 * zlib.size() + 1024));
    QByteArray framed(4, '\0');
    framed[0] = char(hint >> 24), framed[1] = char(hint >> 16), framed[2] = char(hint >> 8),
    framed[3] = char(hint);
    const QByteArray out = qUncompress(framed + zlib);
    return out.size() <= kMaxProjectText ? out : QByteArray();
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

} // namespace

QByteArray embeddedProject(const QString &pngFile, QString *error)
{
    QFile file(pngFile);
    if (!file.open(QIODevice::ReadOnly) || file.size() > kMaxFigureFile) {
        if (error)
            *error = QCoreApplication::translate("awb::FigureMetadata",
                                                 "%1: cannot read the PNG: %2")
                         .arg(pngFile, file.isOpen()
                                           ? QCoreApplication::translate("awb::FigureMetadata",
                                                                         "larger than 512 MB")
                                           : file.errorString());
        return {};
    }
    const QByteArray text = pngText(file.readAll(), QByteArray(kFigureProjectKey));
    if (text.isEmpty()) {
        if (error)
            *error = QCoreApplication::translate(
                         "awb::FigureMetadata",
                         "%1: this PNG holds no Attractor Workbench item (only figures exported "
                         "by Attractor Workbench carry their parameters)")
                         .arg(pngFile);
        return {};
    }
    return text;
}

} // namespace awb
