#include "gui/views/FrameLog.h"

#include <QByteArray>

#include <cstdio>
#include <ctime>
#include <mutex>

namespace awb::framelog {

namespace {

struct Log {
    std::FILE *file = nullptr;
    std::mutex mutex;
    Log()
    {
        const QByteArray path = qgetenv("AWB_FRAME_LOG");
        if (!path.isEmpty())
            file = std::fopen(path.constData(), "w");
        if (file)
            std::fprintf(file, "# awb frame log 1\n");
    }
    ~Log()
    {
        if (file)
            std::fclose(file);
    }
};

Log &log()
{
    static Log instance;
    return instance;
}

} // namespace

bool enabled() { return log().file != nullptr; }

double now()
{
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) / 1e6;
}

void write(const char *kind, const QString &rest)
{
    Log &l = log();
    if (!l.file)
        return;
    const double t = now();
    const QByteArray text = rest.toUtf8();
    std::lock_guard lock(l.mutex);
    std::fprintf(l.file, "%s %.3f %s\n", kind, t, text.constData());
    // The driver reads the log while the application runs and may end it with a signal.
    std::fflush(l.file);
}

QString point(const QPoint &global)
{
    return QStringLiteral("%1,%2").arg(global.x()).arg(global.y());
}

} // namespace awb::framelog
