#pragma once
// Crash recovery (layer 2, model). While a project has unsaved edits, Recovery writes it every
// interval (atomically) to its own recovery file in a recovery directory; a clean project (saved,
// or undone back to the saved state) and a clean shutdown remove the file. Each running
// instance holds a QLockFile beside its recovery file, so on the next start orphans() finds
// exactly the files whose process died; the GUI asks the user and calls recover() or discard().
//
// Recovery file: {"format": "attractor-workbench-recovery", "version": 1,
//                 "original_file": "<path or empty>", "saved_at": "<ISO 8601 UTC>",
//                 "project": { ...the project file's root object... }}

#include <QDateTime>
#include <QLockFile>
#include <QObject>
#include <QTimer>

#include <memory>

namespace awb {

class Project;

struct RecoveryFile {
    QString path;          // the recovery file
    QString originalFile;  // the project's file when the process died ("" if never saved)
    QDateTime savedAt;     // when it was written (UTC)
};

class Recovery : public QObject {
    Q_OBJECT
public:
    static constexpr int defaultIntervalMs = 30000;

    // Watches `project`; writes into `directory` (created if needed).
    Recovery(Project *project, const QString &directory, QObject *parent = nullptr);
    // A clean shutdown: the recovery file is removed.
    ~Recovery() override;

    // The per-user default: <AppLocalDataLocation>/recovery.
    static QString defaultDirectory();

    int interval() const { return m_timer.interval(); }
    void setInterval(int ms) { m_timer.setInterval(ms); }
    QString filePath() const { return m_path; }
    // Writes now when there are unsaved edits not yet written; removes the file when the
    // project is clean. False (and autosaveFailed) when writing fails.
    bool autosave();

    // Recovery files left by processes that are no longer running, newest first.
    static QList<RecoveryFile> orphans(const QString &directory);
    // Loads a recovery file into `project` (replacing its content): the project gets the
    // original file name and is marked modified. On failure the project is untouched.
    static bool recover(const RecoveryFile &file, Project *project, QString *error = nullptr);
    // Deletes a recovery file (after recovering it, or when the user declines).
    static bool discard(const RecoveryFile &file);
    // A recovery file that cannot be read is never deleted: it moves to the folder "damaged"
    // beside it (out of orphans(), kept for the user or a bug report). The new path, or empty
    // when even the move failed (the file then stays where it was).
    static QString setAside(const RecoveryFile &file);

signals:
    void autosaved(const QString &path);
    void autosaveFailed(const QString &message);

private:
    static QString lockPathFor(const QString &path) { return path + QStringLiteral(".lock"); }
    void removeFile();

    Project *m_project;
    QString m_path;
    std::unique_ptr<QLockFile> m_lock;
    QTimer m_timer;
    bool m_pending = false; // edits since the last autosave
};

} // namespace awb
