#pragma once
// Running attractor-cli from the CLI tests: the executable (AWB_BIN_DIR), the bundled examples
// (AWB_SOURCE_DIR) and a run with captured output and exit code (-1 on a crash or time-out).

#include "TestPaths.h"
#include "TestTime.h"

#include <QCoreApplication>
#include <QProcess>
#include <QString>
#include <QStringList>

namespace awb::test {

inline QString cliPath()
{
    return qEnvironmentVariable("AWB_BIN_DIR", QCoreApplication::applicationDirPath() + "/../bin")
           + "/attractor-cli";
}

inline QString examplePath(const QString &name)
{
    return awb::test::sourceDir() + "/examples/"
           + name;
}

inline int runProgram(const QString &program, const QStringList &args, QByteArray *out = nullptr,
                      QByteArray *err = nullptr)
{
    QProcess p;
    p.start(program, args);
    if (!p.waitForFinished(awb::test::ms(300000)))
        return -1;
    if (out)
        *out = p.readAllStandardOutput();
    if (err)
        *err = p.readAllStandardError();
    return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
}

} // namespace awb::test
