// attractor-workbench in batch mode (--item, --print-pdf, --screenshot): the figure sheet of a
// chosen example item is printed to a one-page PDF and the window saved as a PNG without a
// display; bad options name the problem and exit non-zero.

#include "BatchRunner.h"

#include <QFile>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"

using namespace awb;

class TestBatch : public QObject {
    Q_OBJECT
private slots:
    void printsSheetAndScreenshot();
    void badOptions();

private:
    test::BatchRunner m_runner;
    int run(const QStringList &args, QString *err = nullptr) { return m_runner.run(args, err); }
    static QString example(const QString &name) { return test::BatchRunner::example(name); }
};

void TestBatch::printsSheetAndScreenshot()
{
    QTemporaryDir out;
    const QString pdf = out.filePath("sheet.pdf"), png = out.filePath("window.png");
    QString err;
    const int code = run({example("004-fig3.7-takagi-y-quarter-and-eighth.awb"), "--item",
                          "004 Fig. 3.7 (right): A*(y), t = 1/2 + i/8", "--print-pdf", pdf,
                          "--screenshot", png, "--window-size", "1200x800"},
                         &err);
    QVERIFY2(code == 0, qPrintable(err));
    QFile f(pdf);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray bytes = f.readAll();
    QVERIFY(bytes.startsWith("%PDF"));
    QCOMPARE(bytes.count("/Type /Page\n") + bytes.count("/Type /Page\r")
                 + bytes.count("/Type /Page "), 1);
    QVERIFY(bytes.size() > 5000);
    const QImage shot(png);
    QCOMPARE(shot.size(), QSize(1200, 800));
}

void TestBatch::badOptions()
{
    QTemporaryDir out;
    QString err;
    QCOMPARE(run({example("001-fig02-levy-curve.awb"), "--item", "no such item", "--print-pdf",
                  out.filePath("x.pdf")},
                 &err),
             1);
    QVERIFY2(err.contains("no item named \"no such item\""), qPrintable(err));
    QVERIFY(!QFile::exists(out.filePath("x.pdf")));
    QCOMPARE(run({example("001-fig02-levy-curve.awb"), "--screenshot", out.filePath("x.png"),
                  "--window-size", "huge"},
                 &err),
             2);
    QVERIFY2(err.contains("--window-size huge"), qPrintable(err));
    // A malformed project: the loader's message on stderr and exit 1, no modal box waiting
    // for a user who is not there (run() gives -1 after its 120 s timeout).
    const QString bad = out.filePath("bad.awb");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "attractor-workbench", "version": 1, "items": [{"type": "fractal"}]})");
    f.close();
    QCOMPARE(run({bad, "--print-pdf", out.filePath("bad.pdf")}, &err), 1);
    QVERIFY2(err.contains("bad.awb") && err.contains("item 1"), qPrintable(err));
    QVERIFY(!QFile::exists(out.filePath("bad.pdf")));
}

AWB_TEST_GUILESS_MAIN(TestBatch)
#include "test_batch.moc"
