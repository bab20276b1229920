// Crash safety, with real processes killed by SIGKILL. This test re-executes itself as a child:
//  * --recovery-child DIR FILE: opens FILE, makes the scripted edits, autosaves into DIR and
//    waits to be killed; the parent then finds the orphaned recovery file and recovers it.
//  * --save-loop FILE: saves two large projects alternately into FILE until killed; the parent
//    watches the file meanwhile and after the kill: it must always be one of them, whole (a
//    save that wrote in place would show a truncated file).
// Also in-process: the recovery file appears with unsaved edits and goes away with a save, an
// undo back to the saved state and a clean shutdown; a live process's file is no orphan.

#include "TestProjects.h"

#include "model/ProjectIO.h"
#include "model/Recovery.h"
#include "TestMain.h"

#include <QDeadlineTimer>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QProcess>
#include <QtTest>

#include <cstdio>

using namespace awb;

namespace {

// A project of about 2 MB, different for each variant.
void fillLargeProject(Project &p, int variant)
{
    for (int k = 0; k < 160; ++k) {
        PointList points; // at most AttractorItem::maxControlPoints
        for (int i = 0; i < 250; ++i)
            points.push_back({std::sin(i * 0.37 + k + variant) * 1.0e3 / 7.0,
                              std::cos(i * 0.11 * (variant + 1) + k) / 3.0});
        p.addItem(test::curve(QString("c%1").arg(k), test::scheme(SchemeSpec::Kind::Chaikin),
                              points));
    }
}

int runRecoveryChild(const QString &directory, const QString &file)
{
    Project project;
    if (!project.open(file))
        return 2;
    test::applyScriptedEdits(project);
    Recovery recovery(&project, directory);
    recovery.setInterval(20);
    QObject::connect(&recovery, &Recovery::autosaved, [](const QString &path) {
        std::printf("autosaved %s\n", qPrintable(path));
        std::fflush(stdout);
    });
    return QCoreApplication::exec(); // until killed
}

int runSaveLoop(const QString &file)
{
    Project a, b;
    fillLargeProject(a, 0);
    fillLargeProject(b, 1);
    for (bool first = true;; first = false) {
        if (!a.saveAs(file) || !b.saveAs(file))
            return 3;
        if (first) {
            std::printf("saved\n");
            std::fflush(stdout);
        }
    }
}

// Reads the child's stdout until `marker` shows (or 60 s pass).
QByteArray waitFor(QProcess &child, const QByteArray &marker)
{
    QByteArray out;
    const QDeadlineTimer deadline(60000);
    while (!out.contains(marker) && !deadline.hasExpired()
           && child.state() == QProcess::Running) {
        child.waitForReadyRead(100);
        out += child.readAllStandardOutput();
    }
    return out;
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestRecovery : public QObject {
    Q_OBJECT

private slots:
    void crashThenRecover()
    {
        QTemporaryDir dir;
        const QString original = dir.filePath("work.awb");
        const QString recoveryDir = dir.filePath("recovery");
        {
            Project p;
            test::fillSampleProject(p);
            QVERIFY(p.saveAs(original));
        }
        QProcess child;
        child.start(QCoreApplication::applicationFilePath(),
                    test::childArguments({"--recovery-child", recoveryDir, original}));
        QVERIFY(child.waitForStarted());
        const QByteArray out = waitFor(child, "autosaved");
        QVERIFY2(out.contains("autosaved"), (out + child.readAllStandardError()).constData());
        QVERIFY(Recovery::orphans(recoveryDir).isEmpty()); // its owner is alive

        child.kill(); // SIGKILL: no destructor runs, the recovery file stays
        QVERIFY(child.waitForFinished());
        QCOMPARE(child.exitStatus(), QProcess::CrashExit);

        // The next start.
        const QList<RecoveryFile> orphans = Recovery::orphans(recoveryDir);
        QCOMPARE(orphans.size(), 1);
        QCOMPARE(orphans[0].originalFile, original);
        QVERIFY(orphans[0].savedAt.isValid());
        QVERIFY(out.contains(orphans[0].path.toUtf8()));

        Project recovered;
        QString error;
        QVERIFY2(Recovery::recover(orphans[0], &recovered, &error), qPrintable(error));
        Project edited; // the same edits, made here
        QVERIFY(edited.open(original));
        test::applyScriptedEdits(edited);
        QCOMPARE(recovered.serialize(), edited.serialize());
        Project saved;
        QVERIFY(saved.open(original));
        QVERIFY(saved.serialize() != edited.serialize()); // the edits are what was recovered
        QVERIFY(recovered.isModified());
        QCOMPARE(recovered.fileName(), original);
        QVERIFY(!recovered.undoStack()->canUndo());

        QVERIFY(Recovery::discard(orphans[0]));
        QVERIFY(Recovery::orphans(recoveryDir).isEmpty());
        QVERIFY(QDir(recoveryDir).entryList(QDir::Files).isEmpty()); // no stale lock either
    }

    void killedDuringSaveLeavesAWholeFile()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath("big.awb");
        Project a, b;
        fillLargeProject(a, 0);
        fillLargeProject(b, 1);
        const QByteArray aBytes = a.serialize(), bBytes = b.serialize();
        QVERIFY(aBytes.size() > 1000000 && aBytes != bBytes);
        int sawA = 0, sawB = 0;
        for (int round = 0; round < 8; ++round) {
            QProcess child;
            child.start(QCoreApplication::applicationFilePath(),
                        test::childArguments({"--save-loop", file}));
            QVERIFY(child.waitForStarted());
            QVERIFY(waitFor(child, "saved").contains("saved"));
            // Watch the file while the child saves over it, then kill the child at once: a
            // file of another size (one being written in place) is the failure.
            qint64 odd = -1;
            const QDeadlineTimer until(100 + 30 * round);
            while (odd < 0 && !until.hasExpired()) {
                const qint64 size = QFileInfo(file).size();
                if (size != aBytes.size() && size != bBytes.size())
                    odd = size;
            }
            child.kill();
            QVERIFY(child.waitForFinished());
            QCOMPARE(child.exitStatus(), QProcess::CrashExit);
            QVERIFY2(odd < 0, qPrintable(QString("round %1: the file had %2 bytes while being "
                                                 "saved").arg(round).arg(odd)));
            const QByteArray bytes = readAll(file);
            QVERIFY2(bytes == aBytes || bytes == bBytes,
                     qPrintable(QString("round %1: a file of %2 bytes that is neither")
                                    .arg(round).arg(bytes.size())));
            (bytes == aBytes ? sawA : sawB)++;
            Project p;
            QString error;
            QVERIFY2(p.open(file, &error), qPrintable(error));
        }
        qInfo("the file held project A %d times, B %d times", sawA, sawB);
    }

    void lifecycleOfTheRecoveryFile()
    {
        QTemporaryDir dir;
        const QString recoveryDir = dir.filePath("recovery");
        Project p;
        test::fillSampleProject(p);
        QVERIFY(p.saveAs(dir.filePath("p.awb")));
        auto recovery = std::make_unique<Recovery>(&p, recoveryDir);
        QCOMPARE(recovery->interval(), Recovery::defaultIntervalMs);
        recovery->setInterval(10);
        const QString path = recovery->filePath();
        QVERIFY(path.startsWith(recoveryDir));
        QVERIFY(path.endsWith(".awb-recovery"));

        QVERIFY(recovery->autosave()); // clean: nothing to write
        QVERIFY(!QFile::exists(path));

        auto *c = static_cast<SubdivisionCurveItem *>(p.findItem("B-spline"));
        c->moveControlPoint(0, {5, 5});
        QTRY_VERIFY(QFile::exists(path)); // by the timer
        QVERIFY(Recovery::orphans(recoveryDir).isEmpty()); // this process is alive

        // The file follows later edits.
        c->moveControlPoint(1, {6, 6});
        QSignalSpy autosaved(recovery.get(), &Recovery::autosaved);
        QTRY_COMPARE(autosaved.count(), 1);
        Project copy;
        QVERIFY(Recovery::recover({path, {}, {}}, &copy));
        QCOMPARE(copy.serialize(), p.serialize());
        QCOMPARE(copy.fileName(), p.fileName());

        QVERIFY(p.save()); // saved: nothing to recover
        QVERIFY(!QFile::exists(path));
        c->moveControlPoint(2, {7, 7});
        QVERIFY(recovery->autosave());
        QVERIFY(QFile::exists(path));
        p.undoStack()->undo(); // back to the saved state
        QVERIFY(!p.isModified());
        QVERIFY(!QFile::exists(path));

        c->moveControlPoint(2, {8, 8});
        QVERIFY(recovery->autosave());
        QVERIFY(QFile::exists(path));
        recovery.reset(); // a clean shutdown
        QVERIFY(!QFile::exists(path));
        QVERIFY(Recovery::orphans(recoveryDir).isEmpty());
        QVERIFY(QDir(recoveryDir).entryList(QDir::Files).isEmpty());
    }

    void unsavedProjectRecoversWithoutFileName()
    {
        QTemporaryDir dir;
        Project p;
        Recovery recovery(&p, dir.path());
        test::fillSampleProject(p);
        QVERIFY(p.isModified());
        QVERIFY(recovery.autosave());
        const QJsonDocument doc = QJsonDocument::fromJson(readAll(recovery.filePath()));
        QCOMPARE(doc.object().value("format").toString(),
                 QString("attractor-workbench-recovery"));
        QCOMPARE(doc.object().value("original_file").toString(), QString());
        Project q;
        QVERIFY(Recovery::recover({recovery.filePath(), {}, {}}, &q));
        QCOMPARE(q.serialize(), p.serialize());
        QVERIFY(q.fileName().isEmpty());
        QVERIFY(q.isModified());
    }

    void damagedRecoveryFileIsKeptAside()
    {
        // A crashed session left a recovery file that is itself damaged (cut off mid-write
        // by a full disk, say): it is refused, moved to recovery/damaged, never deleted, and
        // not offered again.
        QTemporaryDir dir;
        const QString recoveryDir = dir.filePath("recovery");
        QVERIFY(QDir().mkpath(recoveryDir));
        const QString path = QDir(recoveryDir).filePath("0f0e-dead.awb-recovery");
        // Not a raw string: moc miscounts the braces of an unbalanced one.
        const QByteArray damaged = "{\"format\": \"attractor-workbench-recovery\", \"version\": 1, "
                                   "\"original_file\": \"/home/u/work.awb\", \"project\": "
                                   "{\"format\": \"attract";
        QVERIFY(test::writeBytes(path, damaged));
        const QList<RecoveryFile> orphans = Recovery::orphans(recoveryDir);
        QCOMPARE(orphans.size(), 1);
        Project p;
        QString error;
        QVERIFY(!Recovery::recover(orphans[0], &p, &error));
        QVERIFY2(error.contains("not valid JSON"), qPrintable(error));
        const QString kept = Recovery::setAside(orphans[0]);
        QVERIFY(!kept.isEmpty());
        QVERIFY(!QFile::exists(path));
        QCOMPARE(QFileInfo(kept).dir().dirName(), QString("damaged"));
        QCOMPARE(readAll(kept), damaged);                  // kept byte for byte
        QVERIFY(Recovery::orphans(recoveryDir).isEmpty()); // not offered again
    }

    void badRecoveryFileLeavesTheProjectAlone()
    {
        QTemporaryDir dir;
        Project p;
        test::fillSampleProject(p);
        const QByteArray before = p.serialize();
        const QString path = dir.filePath("x.awb-recovery");
        const struct {
            QByteArray content;
            QString message;
        } cases[] = {
            {"{", "not valid JSON"},
            {R"({"format": "attractor-workbench"})", "not an Attractor Workbench recovery file"},
            {R"({"format": "attractor-workbench-recovery", "version": 1, "project": 3})",
             "field \"project\": expected an object"},
            {R"({"format": "attractor-workbench-recovery", "version": 1, "project":
                 {"format": "attractor-workbench", "version": 1, "items": [{"name": "a"}]}})",
             "item 1 (\"a\"): field \"type\": missing"},
        };
        for (const auto &c : cases) {
            QVERIFY(test::writeBytes(path, c.content));
            QString error;
            QVERIFY(!Recovery::recover({path, {}, {}}, &p, &error));
            QVERIFY2(error.startsWith(path + ": ") && error.contains(c.message),
                     qPrintable(error));
            QCOMPARE(p.serialize(), before);
        }
    }
};

namespace {

int runRecoveryTest(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() == 4 && args[1] == "--recovery-child")
        return runRecoveryChild(args[2], args[3]);
    if (args.size() == 3 && args[1] == "--save-loop")
        return runSaveLoop(args[2]);
    TestRecovery test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

} // namespace

AWB_TEST_CUSTOM_MAIN(runRecoveryTest)

#include "test_recovery.moc"
