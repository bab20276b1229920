// attractor-cli animate (issue 16 part 2): frame k of an animation is the render of the item
// with its parameters at time k / fps; PNG frames, movies through ffmpeg, clear refusals.
#include "CliRunner.h"
#include "TestTime.h"
#include "TestMain.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace awb::test;

namespace {

const QString animated = QStringLiteral("animation-four-point-omega-and-complex-t.awb");
const QString fourPoint = QStringLiteral("Four-point scheme, tension ω from 0 to 1/4");

QString boundsOf(const QByteArray &out)
{
    const auto m = QRegularExpression("bounds: (\\S+)").match(QString::fromUtf8(out));
    return m.hasMatch() ? m.captured(1) : QString();
}

bool samePixels(const QString &a, const QString &b)
{
    const QImage x(a), y(b);
    return !x.isNull() && x.convertToFormat(QImage::Format_ARGB32)
                              == y.convertToFormat(QImage::Format_ARGB32);
}

} // namespace

class TestAnimateCli : public QObject {
    Q_OBJECT
private slots:
    // 17 frames at 4 frames/s over 4 s; frame 6 is t = 1.5 s, half-way between the keys
    // omega(1) = 1/16 and omega(4) = 1/4: omega = 1/16 + (3/16)(0.5/3) = 3/32, the render of the
    // item at omega = 3/32 in the same framing, pixel for pixel.
    void frameIsTheRenderAtItsParameter()
    {
        QTemporaryDir dir;
        QByteArray out, err;
        const QStringList common{"--item", fourPoint, "--size", "480x360"};
        QCOMPARE(runProgram(cliPath(), QStringList{"animate", examplePath(animated), "--out",
                                                   dir.filePath("frames"), "--fps", "4",
                                                   "--no-caption-values"} + common,
                            &out, &err),
                 0);
        QVERIFY2(out.contains("17 frames of 480x360"), out.constData());
        const QStringList frames = QDir(dir.filePath("frames")).entryList({"frame-*.png"});
        QCOMPARE(frames.size(), 17);
        QCOMPARE(frames.first(), QStringLiteral("frame-0000.png"));
        QCOMPARE(frames.last(), QStringLiteral("frame-0016.png"));
        const QString bounds = boundsOf(out);
        QVERIFY2(!bounds.isEmpty() && bounds.count(',') == 3, out.constData());

        // The same project with omega = 3/32 and no animation.
        QFile f(examplePath(animated));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QJsonObject root = QJsonDocument::fromJson(f.readAll()).object();
        QJsonArray items = root["items"].toArray();
        bool found = false;
        for (int i = 0; i < items.size(); ++i) {
            QJsonObject item = items[i].toObject();
            if (item["name"].toString() != fourPoint)
                continue;
            QJsonObject scheme = item["scheme"].toObject();
            scheme["omega"] = 3.0 / 32.0;
            item["scheme"] = scheme;
            item.remove("animation");
            items[i] = item;
            found = true;
        }
        QVERIFY(found);
        root["items"] = items;
        QFile still(dir.filePath("still.awb"));
        QVERIFY(still.open(QIODevice::WriteOnly));
        still.write(QJsonDocument(root).toJson());
        still.close();
        QCOMPARE(runProgram(cliPath(), QStringList{"render", still.fileName(), "--out",
                                                   dir.filePath("still.png"), "--bounds", bounds}
                                           + common),
                 0);
        QVERIFY(samePixels(dir.filePath("frames/frame-0006.png"), dir.filePath("still.png")));
        // ... and not the render of another frame: the curve moves with omega.
        QVERIFY(!samePixels(dir.filePath("frames/frame-0005.png"), dir.filePath("still.png")));
        QVERIFY(!samePixels(dir.filePath("frames/frame-0000.png"), dir.filePath("still.png")));

        // --frame K alone gives the same picture as the K-th file of the sequence.
        QCOMPARE(runProgram(cliPath(), QStringList{"animate", examplePath(animated), "--out",
                                                   dir.filePath("one.png"), "--fps", "4",
                                                   "--frame", "6", "--no-caption-values"} + common,
                            &out),
                 0);
        QCOMPARE(boundsOf(out), bounds);
        QVERIFY(samePixels(dir.filePath("one.png"), dir.filePath("frames/frame-0006.png")));
    }

    // A complex t on a circle (004 §3.7): every frame drawn, captions with t.
    void movieThroughFfmpeg()
    {
        QTemporaryDir dir;
        QByteArray out, err;
        const QString movie = dir.filePath("levy.mp4");
        QCOMPARE(runProgram(cliPath(),
                            {"animate", examplePath(animated), "--item",
                             "Complex de Casteljau t on a circle through the Lévy t = 1/2 + i/2",
                             "--out", movie, "--fps", "5", "--size", "320x240"},
                            &out, &err),
                 0);
        QVERIFY2(out.contains("31 frames of 320x240"), out.constData());
        QFile f(movie);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray head = f.read(12);
        QCOMPARE(head.mid(4, 4), QByteArray("ftyp")); // an MP4 (ISO base media) file
        QVERIFY(f.size() > 10000);
    }

    void refusalsAreClear()
    {
        QTemporaryDir dir;
        QByteArray err;
        // No ffmpeg: said before any frame is drawn.
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("AWB_FFMPEG", "/nonexistent/ffmpeg");
        p.setProcessEnvironment(env);
        p.start(cliPath(), {"animate", examplePath(animated), "--out", dir.filePath("a.gif")});
        QVERIFY(p.waitForFinished(awb::test::ms(60000)));
        QCOMPARE(p.exitCode(), 1);
        QVERIFY2(p.readAllStandardError().contains("needs ffmpeg"), "no ffmpeg message");
        QVERIFY(!QFile::exists(dir.filePath("a.gif")));

        // An item without an animation.
        QCOMPARE(runProgram(cliPath(),
                            {"animate", examplePath("000-fig05-four-point-from-segment.awb"),
                             "--out", dir.filePath("x")},
                            nullptr, &err),
                 1);
        QVERIFY2(err.contains("no animated item"), err.constData());
        QCOMPARE(runProgram(cliPath(),
                            {"animate", examplePath("000-fig05-four-point-from-segment.awb"),
                             "--item", "000 Fig. 5: four-point scheme from a segment", "--out",
                             dir.filePath("x")},
                            nullptr, &err),
                 1);
        QVERIFY2(err.contains("has no animation"), err.constData());
        // A frame past the end, a folder that is a file, bad bounds.
        QCOMPARE(runProgram(cliPath(), {"animate", examplePath(animated), "--frame", "101",
                                        "--out", dir.filePath("f.png")},
                            nullptr, &err),
                 1);
        QVERIFY2(err.contains("--frame must be a whole number from 0 to 100"), err.constData());
        QFile file(dir.filePath("plain"));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.close();
        QCOMPARE(runProgram(cliPath(), {"animate", examplePath(animated), "--out", file.fileName()},
                            nullptr, &err),
                 1);
        QVERIFY2(err.contains("is a file, not a folder"), err.constData());
        QCOMPARE(runProgram(cliPath(), {"render", examplePath(animated), "--bounds", "1,1,0,2",
                                        "--out", dir.filePath("r.png")},
                            nullptr, &err),
                 1);
        QVERIFY2(err.contains("--bounds must be"), err.constData());
    }
};

AWB_TEST_GUILESS_MAIN(TestAnimateCli)
#include "test_animate_cli.moc"
