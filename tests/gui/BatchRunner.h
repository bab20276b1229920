#pragma once
// Runs attractor-workbench in batch mode (offscreen) with a scratch home, so that settings and
// autosave copies never touch the user's; shared by the batch-mode tests.
#include "TestPaths.h"
#include <QCoreApplication>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

namespace awb::test {

class BatchRunner {
public:
    // Exit code of `attractor-workbench args` (-1 on a crash or a 3-minute hang); *err gets
    // its standard error.
    int run(const QStringList &args, QString *err = nullptr)
    {
        const QString dir = qEnvironmentVariable("AWB_BIN_DIR",
                                                 QCoreApplication::applicationDirPath() + "/../bin");
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("QT_QPA_PLATFORM", "offscreen");
        env.insert("HOME", m_home.path());
        env.insert("XDG_CONFIG_HOME", m_home.path() + "/config");
        env.insert("XDG_DATA_HOME", m_home.path() + "/data");
        env.insert("XDG_RUNTIME_DIR", m_home.path());
        p.setProcessEnvironment(env);
        p.start(dir + "/attractor-workbench", args);
        if (!p.waitForFinished(180000)) {
            p.kill();
            p.waitForFinished();
            return -1;
        }
        if (err)
            *err = QString::fromUtf8(p.readAllStandardError());
        return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    }
    static QString example(const QString &name)
    {
        return awb::test::sourceDir() + "/examples/" + name;
    }

private:
    QTemporaryDir m_home;
};

} // namespace awb::test
