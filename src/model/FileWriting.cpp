#include "model/FileWriting.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

#include <cerrno>
#include <cstring>

namespace awb {

namespace {

// The translation context of the messages below.
struct FileWriting {
    Q_DECLARE_TR_FUNCTIONS(awb::FileWriting)
};

} // namespace

// The device writers write into: every byte reaches the file, or the first failure is kept
// (with the system's reason) and every later write fails. The file is unbuffered: a buffered
// QFileDevice reports a write as done and may lose its short tail at commit() without a word.
// Writers bring their own buffering (QBuffer, the writers' chunks).
class WholeFileWriter::Guard : public QIODevice {
public:
    explicit Guard(QFileDevice *file) : m_file(file) { open(QIODevice::WriteOnly); }
    const QString &failure() const { return m_failure; }

protected:
    qint64 readData(char *, qint64) override { return -1; }
    qint64 writeData(const char *data, qint64 len) override
    {
        if (!m_failure.isEmpty())
            return -1;
        qint64 done = 0;
        while (done < len) {
            errno = 0;
            const qint64 n = m_file->write(data + done, len - done);
            if (n <= 0) {
                const int code = errno;
                m_failure = code != 0 ? QString::fromLocal8Bit(std::strerror(code))
                                      : m_file->errorString();
                setErrorString(m_failure);
                return -1;
            }
            done += n;
        }
        return len;
    }

private:
    QFileDevice *m_file;
    QString m_failure;
};

WholeFileWriter::WholeFileWriter() = default;

WholeFileWriter::~WholeFileWriter()
{
    m_guard.reset();
    if (auto *save = qobject_cast<QSaveFile *>(m_file.get()))
        save->cancelWriting();
}

QIODevice *WholeFileWriter::device() const
{
    return m_guard.get();
}

bool WholeFileWriter::open(const QString &fileName, QString *reason)
{
    QString ignored;
    if (!reason)
        reason = &ignored;
    m_file.reset();
    const QFileInfo info(fileName);
    const QFileInfo folder(info.absolutePath());
    if (!folder.exists()) {
        *reason = FileWriting::tr("the folder %1 does not exist").arg(info.path());
        return false;
    }
    if (!folder.isDir()) {
        *reason = FileWriting::tr("%1 is not a folder").arg(folder.filePath());
        return false;
    }
    if (info.isDir()) {
        *reason = FileWriting::tr("it is a folder");
        return false;
    }
    if (info.exists() && !info.isFile()) {
        // A device or a FIFO: in place (replacing it would put a file where /dev/full was).
        auto file = std::make_unique<QFile>(fileName);
        if (!file->open(QIODevice::WriteOnly | QIODevice::Unbuffered)) {
            *reason = file->errorString();
            return false;
        }
        m_file = std::move(file);
        m_guard = std::make_unique<Guard>(m_file.get());
        return true;
    }
    if (info.exists() && !info.isWritable()) {
        *reason = FileWriting::tr("the file is read-only");
        return false;
    }
    auto file = std::make_unique<QSaveFile>(fileName);
    if (!file->open(QIODevice::WriteOnly | QIODevice::Unbuffered)) {
        *reason = folder.isWritable()
                      ? FileWriting::tr("cannot create a file in the folder %1: %2")
                            .arg(folder.filePath(), file->errorString())
                      : FileWriting::tr("the folder %1 is read-only").arg(folder.filePath());
        return false;
    }
    m_file = std::move(file);
    m_guard = std::make_unique<Guard>(m_file.get());
    return true;
}

bool WholeFileWriter::commit(QString *reason)
{
    QString ignored;
    if (!reason)
        reason = &ignored;
    if (!m_file) {
        *reason = FileWriting::tr("the file is not open");
        return false;
    }
    if (!m_guard->failure().isEmpty()) {
        *reason = m_guard->failure();
        m_guard.reset();
        if (auto *save = qobject_cast<QSaveFile *>(m_file.get()))
            save->cancelWriting();
        m_file.reset();
        return false;
    }
    m_guard.reset();
    bool ok = m_file->error() == QFileDevice::NoError;
    errno = 0;
    if (auto *save = qobject_cast<QSaveFile *>(m_file.get())) {
        ok = ok && save->commit();
    } else {
        ok = ok && m_file->flush();
        m_file->close();
        ok = ok && m_file->error() == QFileDevice::NoError;
    }
    if (!ok)
        *reason = errno != 0 ? QString::fromLocal8Bit(std::strerror(errno)) : m_file->errorString();
    m_file.reset();
    return ok;
}

bool writeWholeFile(const QString &fileName, const QByteArray &bytes, QString *reason)
{
    WholeFileWriter writer;
    if (!writer.open(fileName, reason))
        return false;
    writer.device()->write(bytes);
    return writer.commit(reason);
}

} // namespace awb
