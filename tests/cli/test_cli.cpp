// attractor-cli end to end: the bundled figures render to real, non-empty images; bad use gives
// the exit codes and messages a command-line user expects.

#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "TestTime.h"

class TestCli : public QObject {
    Q_OBJECT
private slots:
    void examplesRenderToPng();
    void usageErrors();

private:
    QString cli() const
    {
        // CTest sets AWB_BIN_DIR; run by hand, the binary is in ../bin beside tests/.
        const QString dir = qEnvironmentVariable("AWB_BIN_DIR",
                                                 QCoreApplication::applicationDirPath() + "/../bin");
        return dir + "/attractor-cli";
    }
    int run(const QStringList &args, QString *out = nullptr, QString *err = nullptr)
    {
        QProcess p;
        p.start(cli(), args);
        if (!p.waitForFinished(awb::test::ms(120000)))
            return -1;
        if (out)
            *out = QString::fromUtf8(p.readAllStandardOutput());
        if (err)
            *err = QString::fromUtf8(p.readAllStandardError());
        return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    }
};

void TestCli::examplesRenderToPng()
{
    QTemporaryDir dir;
    QString out;
    QCOMPARE(run({"examples", "--out", dir.path()}, &out), 0);
    const QStringList ids = {"000-fig02-cubic-bspline-from-point",
                             "000-fig03-end-interpolating-cubic-from-triangle",
                             "000-fig05-four-point-from-segment"};
    for (const QString &id : ids) {
        const QString file = dir.filePath(id + ".png");
        QVERIFY2(out.contains(file), qPrintable(out));
        const QImage img(file);
        QVERIFY2(!img.isNull(), qPrintable(file));
        // Five panels of 420 x 360 plus title and captions.
        QCOMPARE(img.width(), 5 * 420);
        // Count coloured (non-grey) pixels: the attractor and the control polygon are drawn.
        int coloured = 0;
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x) {
                const QColor c = img.pixelColor(x, y);
                if (std::max({c.red(), c.green(), c.blue()}) - std::min({c.red(), c.green(), c.blue()}) > 60)
                    ++coloured;
            }
        QVERIFY2(coloured > 3000, qPrintable(QString("%1: %2 coloured pixels").arg(id).arg(coloured)));
    }
}

void TestCli::usageErrors()
{
    QString out, err;
    QCOMPARE(run({}, &out), 2);
    QVERIFY(out.contains("Usage: attractor-cli"));
    QCOMPARE(run({"frobnicate"}, &out, &err), 2);
    QVERIFY(err.contains("unknown command 'frobnicate'"));
    QCOMPARE(run({"examples", "--help"}, &out), 0);
    QVERIFY(out.contains("--out"));
    QCOMPARE(run({"examples", "--list"}, &out), 0);
    QCOMPARE(out.count('\n'), 3);
}

QTEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
