#include "model/Recovery.h"

#include "model/Project.h"
#include "model/ProjectIO.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QStandardPaths>
#include <QUuid>

#include <algorithm>

namespace awb {

namespace {
const QString recoveryFormat = QStringLiteral("attractor-workbench-recovery");
const QString recoverySuffix = QStringLiteral(".awb-recovery");
constexpr int recoveryVersion = 1;
} // namespace

Recovery::Recovery(Project *project, const QString &directory, QObject *parent)
    : QObject(parent), m_project(project)
{
    QDir().mkpath(directory);
    m_path = QDir(directory).filePath(QUuid::createUuid().toString(QUuid::WithoutBraces)
                                      + recoverySuffix);
    m_lock = std::make_unique<QLockFile>(lockPathFor(m_path));
    // Held for the whole session: only a dead owner makes it stale, never its age.
    m_lock->setStaleLockTime(0);
    m_lock->tryLock(0);

    connect(project, &QObject::destroyed, this, [this] {
        m_project = nullptr;
        m_timer.stop();
    });
    connect(project->undoStack(), &QUndoStack::indexChanged, this, [this] { m_pending = true; });
    connect(project, &Project::reset, this, [this] { m_pending = true; });
    connect(project, &Project::modifiedChanged, this, [this](bool modified) {
        m_pending = true;
        if (!modified) // saved, or undone back to the saved state: nothing to recover
            removeFile();
    });
    m_pending = project->isModified();
    connect(&m_timer, &QTimer::timeout, this, [this] { autosave(); });
    m_timer.setInterval(defaultIntervalMs);
    m_timer.start();
}

Recovery::~Recovery()
{
    removeFile();
}

QString Recovery::defaultDirectory()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
        .filePath(QStringLiteral("recovery"));
}

void Recovery::removeFile()
{
    QFile::remove(m_path);
}

bool Recovery::autosave()
{
    if (!m_project)
        return false;
    if (!m_project->isModified()) {
        removeFile();
        m_pending = false;
        return true;
    }
    if (!m_pending && QFile::exists(m_path))
        return true;
    const QJsonObject wrapper{
        {"format", recoveryFormat},
        {"version", recoveryVersion},
        {"original_file", m_project->fileName()},
        {"saved_at", QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs)},
        {"project", ProjectIO::toJson(*m_project)},
    };
    QString error;
    if (!ProjectIO::writeFile(m_path, ProjectIO::toBytes(wrapper), &error)) {
        emit autosaveFailed(error);
        return false;
    }
    m_pending = false;
    emit autosaved(m_path);
    return true;
}

QList<RecoveryFile> Recovery::orphans(const QString &directory)
{
    QList<RecoveryFile> out;
    const QFileInfoList files = QDir(directory).entryInfoList({"*" + recoverySuffix},
                                                              QDir::Files);
    for (const QFileInfo &info : files) {
        QLockFile lock(lockPathFor(info.filePath()));
        lock.setStaleLockTime(0);
        if (!lock.tryLock(0)) // its process is alive (this one included)
            continue;
        lock.unlock();
        RecoveryFile file{info.filePath(), {}, info.lastModified().toUTC()};
        QFile f(info.filePath());
        if (f.open(QIODevice::ReadOnly)) {
            const QJsonObject wrapper = QJsonDocument::fromJson(f.readAll()).object();
            file.originalFile = wrapper.value("original_file").toString();
            const QDateTime at = QDateTime::fromString(wrapper.value("saved_at").toString(),
                                                       Qt::ISODateWithMs);
            if (at.isValid())
                file.savedAt = at;
        }
        out << file;
    }
    // Locks of processes that died before writing anything: tidy them up.
    for (const QFileInfo &info : QDir(directory).entryInfoList({"*" + recoverySuffix + ".lock"},
                                                               QDir::Files)) {
        const QString path = info.filePath().chopped(5);
        QLockFile lock(info.filePath());
        lock.setStaleLockTime(0);
        if (!QFile::exists(path) && lock.tryLock(0))
            lock.unlock();
    }
    std::sort(out.begin(), out.end(), [](const RecoveryFile &a, const RecoveryFile &b) {
        return a.savedAt > b.savedAt;
    });
    return out;
}

bool Recovery::recover(const RecoveryFile &file, Project *project, QString *error)
{
    QString ignored;
    if (!error)
        error = &ignored;
    QFile f(file.path);
    if (!f.open(QIODevice::ReadOnly)) {
        *error = tr("%1: cannot open: %2").arg(file.path, f.errorString());
        return false;
    }
    QJsonObject wrapper;
    if (!ProjectIO::parseJson(f.readAll(), file.path, &wrapper, error))
        return false;
    if (wrapper.value("format").toString() != recoveryFormat) {
        *error = tr("%1: not an Attractor Workbench recovery file").arg(file.path);
        return false;
    }
    if (wrapper.value("version").toInt() > recoveryVersion) {
        *error = tr("%1: written by a newer version of Attractor Workbench").arg(file.path);
        return false;
    }
    if (!wrapper.value("project").isObject()) {
        *error = tr("%1: field \"project\": expected an object").arg(file.path);
        return false;
    }
    ProjectData data;
    if (!ProjectIO::parseRoot(wrapper.value("project").toObject(), file.path, &data, error))
        return false;
    project->adopt(std::move(data), wrapper.value("original_file").toString(), true);
    return true;
}

QString Recovery::setAside(const RecoveryFile &file)
{
    const QFileInfo info(file.path);
    QDir damaged(info.dir().filePath(QStringLiteral("damaged")));
    if (!damaged.mkpath(QStringLiteral(".")))
        return {};
    // A unique name: the file's own, stamped with the moment it was set aside.
    const QString stamp = QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmsszzz"));
    const QString target = damaged.filePath(info.completeBaseName() + "-" + stamp + recoverySuffix);
    if (!QFile::rename(file.path, target))
        return {};
    QFile::remove(lockPathFor(file.path));
    return target;
}

bool Recovery::discard(const RecoveryFile &file)
{
    QFile::remove(lockPathFor(file.path)); // a stale lock left by the dead process, if any
    return QFile::remove(file.path);
}

} // namespace awb
