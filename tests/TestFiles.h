#pragma once
// Writing a test's input files into its temporary folder (shared by the tests of every layer).

#include <QByteArray>
#include <QFile>
#include <QString>
#include <QTemporaryDir>

namespace awb::test {

// `text` as the file `name` in `dir`; its path (empty when it cannot be written).
inline QString writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &text)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(text) != text.size())
        return {};
    return path;
}

} // namespace awb::test
