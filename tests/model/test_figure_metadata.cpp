// The projects carried by figures (model/FigureMetadata.h), read from their bytes: a PNG's
// tEXt, zTXt and iTXt chunks and an SVG's <metadata>, round trip with the writers; and what a
// hostile or broken figure gets: a message naming the file and the problem, within bounded
// memory (a compressed chunk that inflates past 64 MB, nested entities), never a crash.

#include "model/FigureMetadata.h"

#include <QBuffer>
#include <QImage>
#include <QtTest>

#include "TestMain.h"

#include <zlib.h>

using namespace awb;

namespace {

const QByteArray kProject = R"({"format": "attractor-workbench", "version": 1, "items": []})";

QByteArray bigEndian(quint32 v)
{
    QByteArray b(4, '\0');
    b[0] = char(v >> 24), b[1] = char(v >> 16), b[2] = char(v >> 8), b[3] = char(v);
    return b;
}

QByteArray chunk(const QByteArray &type, const QByteArray &body)
{
    const QByteArray typed = type + body;
    const uLong crc = crc32(0, reinterpret_cast<const Bytef *>(typed.constData()), uInt(typed.size()));
    return bigEndian(quint32(body.size())) + typed + bigEndian(quint32(crc));
}

QByteArray zlib(const QByteArray &raw)
{
    return qUncompress(qCompress(raw)).isNull() ? QByteArray() : qCompress(raw).mid(4);
}

// A 1x1 PNG with the given text chunks before its image data.
QByteArray png(const QByteArray &textChunks)
{
    QByteArray ihdr = bigEndian(1) + bigEndian(1) + QByteArray("\x08\x02\x00\x00\x00", 5);
    const QByteArray idat = zlib(QByteArray("\x00\xff\xff\xff", 4));
    return QByteArray("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + textChunks
           + chunk("IDAT", idat) + chunk("IEND", {});
}

QByteArray key()
{
    return QByteArray(kFigureProjectKey) + '\0';
}

QByteArray svg(const QByteArray &metadata)
{
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- exported -->\n"
           "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\">\n"
           + metadata + "<rect width=\"10\" height=\"10\"/></svg>\n";
}

} // namespace

class TestFigureMetadata : public QObject {
    Q_OBJECT

private slots:
    void formatsByContentNotName()
    {
        QCOMPARE(figureFormat(png({})), FigureFormat::Png);
        QCOMPARE(figureFormat(svg({})), FigureFormat::Svg);
        QCOMPARE(figureFormat("\xEF\xBB\xBF  \n<svg/>"), FigureFormat::Svg);
        QCOMPARE(figureFormat(kProject), FigureFormat::None);
        QCOMPARE(figureFormat("<html><body/></html>"), FigureFormat::None);
        QCOMPARE(figureFormat({}), FigureFormat::None);
    }

    // Each chunk kind the PNG standard has for text, and the SVG writer's element (with a
    // "]]>" inside the project, which the writer splits across two CDATA sections).
    void everyCarrierRoundTrips()
    {
        // (Plain literals: moc misreads a raw string that ends in a quote.)
        const QByteArray latin = QByteArray("{\"name\": \"caf") + '\xe9' + "\"}";
        const QByteArray utf8 = "{\"name\": \"café ]]> 三\"}";
        QString error;
        QCOMPARE(embeddedProject(png(chunk("tEXt", key() + kProject)), "a.png", &error), kProject);
        QCOMPARE(embeddedProject(png(chunk("tEXt", key() + latin)), "a.png", &error),
                 QByteArray("{\"name\": \"café\"}"));
        QCOMPARE(embeddedProject(png(chunk("zTXt", key() + '\0' + zlib(kProject))), "a.png",
                                 &error),
                 kProject);
        QCOMPARE(embeddedProject(png(chunk("iTXt", key() + QByteArray("\0\0en\0\0", 6) + utf8)),
                                 "a.png", &error),
                 utf8);
        QCOMPARE(embeddedProject(png(chunk("iTXt", key() + QByteArray("\1\0\0\0", 4) + zlib(utf8))),
                                 "a.png", &error),
                 utf8);
        QCOMPARE(embeddedProject(svg(svgMetadataElement(utf8)), "a.svg", &error), utf8);
        // The writers' own chunks, through QImage.
        QImage image(4, 4, QImage::Format_RGB32);
        image.fill(Qt::white);
        for (const auto &[k, text] : figurePngTexts(utf8))
            image.setText(k, text);
        QByteArray written;
        QBuffer buffer(&written);
        QVERIFY(buffer.open(QIODevice::WriteOnly) && image.save(&buffer, "PNG"));
        QCOMPARE(embeddedProject(written, "w.png", &error), utf8);
    }

    void brokenFiguresAreRefusedWithTheirProblem()
    {
        auto refusal = [](const QByteArray &bytes, const QString &name) {
            QString error;
            const QByteArray text = embeddedProject(bytes, name, &error);
            return text.isEmpty() ? error : QStringLiteral("accepted: ") + QString::fromUtf8(text);
        };
        // No project: a picture from elsewhere.
        QVERIFY(refusal(png({}), "plain.png").contains("plain.png: this PNG holds no Attractor "
                                                       "Workbench item"));
        QVERIFY(refusal(svg({}), "plain.svg").contains("holds no Attractor Workbench item"));
        QVERIFY(refusal(kProject, "p.txt").contains("p.txt: neither a PNG nor an SVG"));
        // A chunk longer than the file; a corrupt and a truncated compressed chunk.
        QByteArray truncated = png(chunk("tEXt", key() + kProject));
        truncated.chop(30);
        QVERIFY(refusal(truncated.left(60), "t.png").contains("holds no"));
        QVERIFY(refusal(png(chunk("zTXt", key() + '\0' + QByteArray("garbage!"))), "z.png")
                    .contains("holds no"));
        QVERIFY(refusal(png(chunk("zTXt", key() + '\0' + zlib(kProject).chopped(6))), "z.png")
                    .contains("holds no"));
        // XML that does not parse names its line.
        const QString bad = refusal("<?xml version=\"1.0\"?>\n<svg>\n<metadata><awb:project "
                                    "xmlns:awb=\"https://attractor-workbench.invalid/project\">"
                                    "<b></awb:project>",
                                    "bad.svg");
        QVERIFY2(bad.startsWith("bad.svg: the SVG does not parse:") && bad.contains("line 3"),
                 qPrintable(bad));
    }

    // A compressed chunk of 200 MB of zeros (200 KB in the file) is refused without inflating
    // it whole: the reader stops at 64 MB.
    void compressedBombsStopAt64MB()
    {
        const QByteArray zeros(200 << 20, ' ');
        const QByteArray bomb = zlib(zeros);
        QVERIFY(bomb.size() < (1 << 20));
        QString error;
        QVERIFY(embeddedProject(png(chunk("zTXt", key() + '\0' + bomb)), "bomb.png", &error)
                    .isEmpty());
        QVERIFY(embeddedProject(png(chunk("iTXt", key() + QByteArray("\1\0\0\0", 4) + bomb)),
                                "bomb.png", &error)
                    .isEmpty());
    }

    // Entities: QXmlStreamReader expands internal ones within a bound and reads no external one.
    void entitiesDoNotExplode()
    {
        QByteArray laughs = "<?xml version=\"1.0\"?>\n<!DOCTYPE svg [\n<!ENTITY a \"aaaaaaaaaa\">\n";
        for (char c = 'b'; c <= 'k'; ++c)
            laughs += QByteArray("<!ENTITY ") + c + " \""
                      + (QByteArray("&") + char(c - 1) + ';').repeated(10) + "\">\n";
        laughs += "]>\n<svg xmlns=\"http://www.w3.org/2000/svg\"><metadata><awb:project "
                  "xmlns:awb=\"https://attractor-workbench.invalid/project\">&k;</awb:project>"
                  "</metadata></svg>";
        QString error;
        QVERIFY(embeddedProject(laughs, "laughs.svg", &error).isEmpty());
        QVERIFY2(error.contains("laughs.svg"), qPrintable(error));
        const QByteArray external =
            "<?xml version=\"1.0\"?>\n<!DOCTYPE svg [<!ENTITY x SYSTEM \"file:///etc/passwd\">]>\n"
            "<svg><metadata><awb:project xmlns:awb=\"https://attractor-workbench.invalid/project\">"
            "&x;</awb:project></metadata></svg>";
        QVERIFY(!embeddedProject(external, "x.svg", &error).contains("root:"));
    }
};

AWB_TEST_MAIN(TestFigureMetadata)
#include "test_figure_metadata.moc"
