#pragma once
// Writing a file the way a document editor must: whole or not at all. The bytes go into a
// temporary file beside the target, which replaces it only once complete (QSaveFile), so a
// full disk, a killed process or a cancelled export never leaves a truncated file where the
// user's file was. A target that is not a regular file (/dev/full, a FIFO) is written in place,
// as a device cannot be replaced. Layer: model (QtCore).

#include <QByteArray>
#include <QString>

#include <memory>

class QFileDevice;
class QIODevice;

namespace awb {

// For writers that stream: open(), write into device(), commit(). A write that the system
// cuts short (a full disk, a file size limit: QSaveFile itself would commit the part written)
// fails the device and then commit(). Reasons are translated and name no file: "the folder …
// does not exist", "the file is read-only", "No space left on device", "File too large", …
class WholeFileWriter {
public:
    WholeFileWriter();
    ~WholeFileWriter();  // without commit(): the target is left as it was
    bool open(const QString &fileName, QString *reason);
    QIODevice *device() const;
    bool commit(QString *reason);

private:
    class Guard;
    std::unique_ptr<QFileDevice> m_file;
    std::unique_ptr<Guard> m_guard;
};

// The whole of `bytes` into `fileName`; false with *reason set.
bool writeWholeFile(const QString &fileName, const QByteArray &bytes, QString *reason);

} // namespace awb
