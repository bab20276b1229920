// attractor-bench-window: the application measured as a user sees it. Starts the real window
// (build/bin/attractor-workbench) on an X display (run it under xvfb-run), moves the pointer
// with XTest -- the X server's own input path, as a mouse would -- 60 times 3 px apart at 60 Hz
// while a handle is held, and reads back the frame log the application writes when
// AWB_FRAME_LOG is set (gui/views/FrameLog.h): which picture each presented frame showed, where
// the handle was drawn, and which pointer position the picture was made from. Both processes
// stamp with CLOCK_MONOTONIC, so the figures are the pointer's times against the frames' times:
//
//   fps       new attractor pictures presented per second between the first and last move
//   lag       pointer moved -> the handle drawn there (median and 90th percentile, ms)
//   picture   pointer moved -> a picture made from that position presented (median, ms)
//   final     last move -> the full-quality picture of the last position presented (ms)
//
//   xvfb-run -a -s "-screen 0 1600x1000x24" build/bin/attractor-bench-window [--case NAME]
//       [--rounds N] [--moves N] [--step PX] [--hz F] [--app PATH] [--env VAR=VALUE]
//       [--keep-logs DIR]
//
// Cases: sierpinski-d8, sierpinski-d11 (000 Fig. 11), bspline-d14 (000 Fig. 2), loop-drag-3d
// (000 Fig. 7, a net point: the start triangle's vertex 9), loop-drag-3d-p5 (net point 5, no
// vertex of the start), loop-orbit-3d (the camera), cube-drag-100k, cube-orbit-100k,
// cube-drag-1m, cube-orbit-1m (a Catmull-Clark mesh, issue 31), flame-drag (a corner of a
// flame's xform triangle, issue 45). The goals (issue 28): 2D drags
// >= 30 frames/s, lag <= 50 ms, final <= 150 ms (depth 11: 300 ms); 3D >= 20 frames/s, full
// quality <= 300 ms after the release. No timed test depends on this program.

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPoint>
#include <QProcess>
#include <QRect>
#include <QStringList>
#include <QTemporaryDir>
#include <QTextStream>

#include <X11/Xlib.h>
#include <X11/extensions/XTest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <optional>
#include <thread>
#include <vector>

namespace {

double now()
{
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) / 1e6;
}

void sleepUntil(double t)
{
    for (;;) {
        const double left = t - now();
        if (left <= 0)
            return;
        std::this_thread::sleep_for(std::chrono::microseconds(
            left > 2 ? std::int64_t((left - 1) * 1000) : std::int64_t(left * 1000)));
    }
}

struct Case {
    QString name;
    QString example;       // examples/*.awb
    QString item;          // the item to select
    int depth = 0;         // 0: the example's own
    QString view;          // "attractor" or "surface"
    int handle = -1;       // the handle to drag; -1: orbit from an empty corner of the view
    int dx = 3, dy = 0;    // pointer step per move
};

std::vector<Case> cases()
{
    const QString fig11 = QStringLiteral("000-fig11-sierpinski-with-control-points.awb");
    const QString gasket = QStringLiteral("000 Fig. 11 (top): Sierpinski gasket from its "
                                          "control points");
    const QString fig7 = QStringLiteral("000-fig07-box-spline-hexagon.awb");
    const QString hexagon = QStringLiteral("000 Fig. 7: box-spline hexagon from a triangle");
    const QString cube = QStringLiteral("mesh-cube-catmull-clark.awb");
    const QString cubeItem = QStringLiteral("Cube (Catmull–Clark)");
    return {
        {QStringLiteral("sierpinski-d8"), fig11, gasket, 8, QStringLiteral("attractor"), 4, -3, 0},
        {QStringLiteral("sierpinski-d11"), fig11, gasket, 11, QStringLiteral("attractor"), 4, -3, 0},
        {QStringLiteral("bspline-d14"), QStringLiteral("000-fig02-cubic-bspline-from-point.awb"),
         QStringLiteral("000 Fig. 2: cubic B-spline from a point"), 14,
         QStringLiteral("attractor"), 2, 0, 3},
        {QStringLiteral("loop-drag-3d"), fig7, hexagon, 0, QStringLiteral("surface"), 9, 3, 0},
        {QStringLiteral("loop-orbit-3d"), fig7, hexagon, 0, QStringLiteral("surface"), -1, 3, 0},
        // A net point that is no vertex of the start triangle: the full mesh of the press,
        // moved, is F^k(X0) at the release (docs/mathematics.md, "Dragging a net point").
        {QStringLiteral("loop-drag-3d-p5"), fig7, hexagon, 0, QStringLiteral("surface"), 5, 3, 0},
        // A mesh of any topology (issue 31): the Catmull-Clark cube at about 100 k and 1.5 M
        // faces of its limit surface (depth 5 and 7: 96 quads after isolation, 4^k each).
        {QStringLiteral("cube-drag-100k"), cube, cubeItem, 5, QStringLiteral("surface"), 6, 3, 0},
        {QStringLiteral("cube-orbit-100k"), cube, cubeItem, 5, QStringLiteral("surface"), -1, 3, 0},
        {QStringLiteral("cube-drag-1m"), cube, cubeItem, 7, QStringLiteral("surface"), 6, 3, 0},
        {QStringLiteral("cube-orbit-1m"), cube, cubeItem, 7, QStringLiteral("surface"), -1, 3, 0},
        // A flame (issue 45): a corner of its first xform's triangle, drawn by flam3's tone
        // (the density estimator and filters on every frame).
        {QStringLiteral("flame-drag"), QStringLiteral("flam3-genome-final-xform.awb"),
         QStringLiteral("flam3-genome 20: julian, pie, rings and a final xform"), 0,
         QStringLiteral("attractor"), 1, 3, 0},
    };
}

struct Frame {
    double t = 0;
    QString view;
    qint64 image = 0;
    bool final = false;
    std::optional<QPoint> handle, shows;
};

struct Log {
    std::vector<Frame> frames;
    std::map<QString, std::map<int, QPoint>> handles;  // view -> index -> global
    std::map<QString, QRect> areas;
    QStringList notes;
};

std::optional<QPoint> parsePoint(const QString &s)
{
    const QStringList xy = s.split(QLatin1Char(','));
    if (xy.size() != 2)
        return std::nullopt;
    return QPoint(xy[0].toInt(), xy[1].toInt());
}

Log readLog(const QString &path)
{
    Log log;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return log;
    for (const QByteArray &raw : f.readAll().split('\n')) {
        const QStringList w = QString::fromUtf8(raw).split(QLatin1Char(' '), Qt::SkipEmptyParts);
        if (w.size() < 3)
            continue;
        const QString &kind = w[0];
        const double t = w[1].toDouble();
        if (kind == QLatin1String("frame")) {
            Frame fr;
            fr.t = t;
            fr.view = w[2];
            for (const QString &field : w.mid(3)) {
                const QString key = field.section(QLatin1Char('='), 0, 0);
                const QString value = field.section(QLatin1Char('='), 1);
                if (key == QLatin1String("image"))
                    fr.image = value.toLongLong();
                else if (key == QLatin1String("final"))
                    fr.final = value == QLatin1String("1");
                else if (key == QLatin1String("handle"))
                    fr.handle = parsePoint(value);
                else if (key == QLatin1String("shows"))
                    fr.shows = parsePoint(value);
            }
            log.frames.push_back(fr);
        } else if (kind == QLatin1String("handle") && w.size() >= 6) {
            log.handles[w[2]][w[3].toInt()] = QPoint(w[4].toInt(), w[5].toInt());
        } else if (kind == QLatin1String("area") && w.size() >= 7) {
            log.areas[w[2]] = QRect(w[3].toInt(), w[4].toInt(), w[5].toInt(), w[6].toInt());
        } else if (kind == QLatin1String("note")) {
            log.notes << w.mid(2).join(QLatin1Char(' '));
        }
    }
    return log;
}

double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return NAN;
    std::sort(v.begin(), v.end());
    const double k = p * double(v.size() - 1);
    const auto i = std::size_t(std::floor(k));
    const double f = k - double(i);
    return i + 1 < v.size() ? v[i] * (1 - f) + v[i + 1] * f : v[i];
}

struct Result {
    double fps = NAN, lagMedian = NAN, lagP90 = NAN, pictureMedian = NAN, final = NAN;
    int frames = 0, pictures = 0;
    QString problem;
};

// The move index a drawn position stands for: how many steps from where the press was.
int stepIndex(const QPoint &p, const QPoint &origin, const Case &c)
{
    const double along = c.dx != 0 ? double(p.x() - origin.x()) / c.dx
                                   : double(p.y() - origin.y()) / c.dy;
    return int(std::lround(along));
}

Result measure(const Case &c, const Log &log, const std::vector<double> &sent, double release,
               const QPoint &pressHandle, const QPoint &pressPointer)
{
    Result r;
    if (sent.empty())
        return r;
    const double t0 = sent.front(), t1 = sent.back();
    qint64 lastImage = -1;
    std::vector<double> pictureTimes;
    for (const Frame &f : log.frames) {
        if (f.view != c.view)
            continue;
        if (f.t >= t0 && f.t <= t1 + 1) {
            ++r.frames;
            if (f.image != lastImage)
                pictureTimes.push_back(f.t);
        }
        lastImage = f.image;
    }
    r.pictures = int(pictureTimes.size());
    r.fps = (t1 > t0) ? 1000.0 * double(r.pictures) / (t1 - t0) : NAN;
    std::vector<double> lags, pictureLags;
    for (std::size_t i = 0; i < sent.size(); ++i) {
        const int want = int(i) + 1; // move i puts the pointer i + 1 steps from the press
        for (const Frame &f : log.frames) {
            if (f.view != c.view || f.t < sent[i] || !f.handle)
                continue;
            if (c.handle >= 0 && stepIndex(*f.handle, pressHandle, c) >= want) {
                lags.push_back(f.t - sent[i]);
                break;
            }
        }
        for (const Frame &f : log.frames) {
            if (f.view != c.view || f.t < sent[i] || !f.shows)
                continue;
            if (stepIndex(*f.shows, pressPointer, c) >= want) {
                pictureLags.push_back(f.t - sent[i]);
                break;
            }
        }
    }
    r.lagMedian = percentile(lags, 0.5);
    r.lagP90 = percentile(lags, 0.9);
    r.pictureMedian = percentile(pictureLags, 0.5);
    for (const Frame &f : log.frames)
        if (f.view == c.view && f.t >= release && f.final) {
            r.final = f.t - t1;
            break;
        }
    return r;
}

class Pointer {
public:
    Pointer() : m_display(XOpenDisplay(nullptr)) {}
    ~Pointer()
    {
        if (m_display)
            XCloseDisplay(m_display);
    }
    bool ok() const
    {
        int event, error, major, minor;
        return m_display && XTestQueryExtension(m_display, &event, &error, &major, &minor);
    }
    void move(QPoint p)
    {
        XTestFakeMotionEvent(m_display, -1, p.x(), p.y(), CurrentTime);
        XFlush(m_display);
    }
    void button(bool down)
    {
        XTestFakeButtonEvent(m_display, 1, down ? True : False, CurrentTime);
        XFlush(m_display);
    }
    void sync() { XSync(m_display, False); }

private:
    Display *m_display;
};

QString prepareProject(const Case &c, const QString &sourceDir, const QString &dir)
{
    QFile f(sourceDir + QStringLiteral("/examples/") + c.example);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    QJsonObject root = QJsonDocument::fromJson(f.readAll()).object();
    QJsonArray items = root.value(QStringLiteral("items")).toArray();
    for (int i = 0; i < items.size(); ++i) {
        QJsonObject item = items[i].toObject();
        if (c.depth > 0) {
            QJsonObject alg = item.value(QStringLiteral("algorithm")).toObject();
            alg.insert(QStringLiteral("depth"), c.depth);
            item.insert(QStringLiteral("algorithm"), alg);
        }
        items[i] = item;
    }
    root.insert(QStringLiteral("items"), items);
    const QString path = dir + QLatin1Char('/') + c.name + QStringLiteral(".awb");
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly))
        return {};
    out.write(QJsonDocument(root).toJson());
    return path;
}

QString g_keepLogs; // --keep-logs DIR: each case's frame log is copied there

std::optional<Result> runCase(const Case &c, const QString &app, const QString &sourceDir,
                              const QStringList &extraEnv, int moves, double hz, int stepPx)
{
    QTemporaryDir dir;
    const QString project = prepareProject(c, sourceDir, dir.path());
    if (project.isEmpty()) {
        std::fprintf(stderr, "%s: cannot read the example %s\n", qPrintable(c.name),
                     qPrintable(c.example));
        return std::nullopt;
    }
    const QString logPath = dir.path() + QStringLiteral("/frames.log");
    QProcess proc;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("AWB_FRAME_LOG"), logPath);
    // A fresh configuration: no saved window layout or preferences of a user.
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.path() + QStringLiteral("/config"));
    env.insert(QStringLiteral("AWB_LANGUAGE"), QStringLiteral("en"));
    env.remove(QStringLiteral("QT_QPA_PLATFORM"));
    if (!env.contains(QStringLiteral("XDG_RUNTIME_DIR")))
        env.insert(QStringLiteral("XDG_RUNTIME_DIR"), dir.path());
    for (const QString &kv : extraEnv)
        env.insert(kv.section(QLatin1Char('='), 0, 0), kv.section(QLatin1Char('='), 1));
    proc.setProcessEnvironment(env);
    proc.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    proc.start(app, {project, QStringLiteral("--item"), c.item});
    if (!proc.waitForStarted(10000)) {
        std::fprintf(stderr, "%s: cannot start %s\n", qPrintable(c.name), qPrintable(app));
        return std::nullopt;
    }
    // Ready: the view drew its full picture and wrote its handles and area; then quiet.
    const double deadline = now() + 60000;
    Log log;
    for (;;) {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        log = readLog(logPath);
        const bool handles = c.handle < 0 || log.handles[c.view].count(c.handle);
        const bool final = std::any_of(log.frames.begin(), log.frames.end(),
                                       [&](const Frame &f) { return f.view == c.view && f.final; });
        if (handles && final && log.areas.count(c.view))
            break;
        if (now() > deadline || proc.state() != QProcess::Running) {
            std::fprintf(stderr, "%s: the window never showed a finished %s view\n",
                         qPrintable(c.name), qPrintable(c.view));
            proc.kill();
            proc.waitForFinished();
            return std::nullopt;
        }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    log = readLog(logPath);
    const QRect area = log.areas[c.view];
    const QPoint pressHandle = c.handle >= 0 ? log.handles[c.view][c.handle]
                                             : area.topLeft() + QPoint(40, 40);
    Pointer pointer;
    if (!pointer.ok()) {
        std::fprintf(stderr, "no X display with the XTest extension\n");
        proc.kill();
        proc.waitForFinished();
        return std::nullopt;
    }
    pointer.move(pressHandle);
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    pointer.button(true);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const double period = 1000.0 / hz;
    std::vector<double> sent;
    const double start = now();
    const int sx = c.dx > 0 ? stepPx : c.dx < 0 ? -stepPx : 0;
    const int sy = c.dy > 0 ? stepPx : c.dy < 0 ? -stepPx : 0;
    Case stepped = c;
    stepped.dx = sx;
    stepped.dy = sy;
    for (int i = 1; i <= moves; ++i) {
        sleepUntil(start + i * period);
        pointer.move(pressHandle + QPoint(sx * i, sy * i));
        sent.push_back(now());
    }
    sleepUntil(start + (moves + 1) * period);
    pointer.button(false);
    const double release = now();
    std::this_thread::sleep_for(std::chrono::milliseconds(3500));
    proc.terminate();
    if (!proc.waitForFinished(5000)) {
        proc.kill();
        proc.waitForFinished();
    }
    log = readLog(logPath);
    if (!g_keepLogs.isEmpty()) {
        QDir().mkpath(g_keepLogs);
        const QString kept = g_keepLogs + QLatin1Char('/') + c.name + QStringLiteral(".log");
        QFile::remove(kept);
        QFile::copy(logPath, kept);
        QFile sends(g_keepLogs + QLatin1Char('/') + c.name + QStringLiteral(".sent"));
        if (sends.open(QIODevice::WriteOnly)) {
            QTextStream out(&sends);
            out.setRealNumberPrecision(12);
            for (std::size_t i = 0; i < sent.size(); ++i)
                out << "sent " << sent[i] << ' ' << i << '\n';
            out << "release " << release << '\n';
        }
    }
    return measure(stepped, log, sent, release, pressHandle, pressHandle);
}

QString figure(double v, int decimals = 0)
{
    return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("-");
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication qapp(argc, argv);
    QStringList args = qapp.arguments().mid(1);
    QString app = QCoreApplication::applicationDirPath() + QStringLiteral("/attractor-workbench");
    QString only;
    QStringList extraEnv;
    int rounds = 1, moves = 60, step = 3;
    double hz = 60;
    for (int i = 0; i < args.size(); ++i) {
        const QString a = args[i];
        const QString v = i + 1 < args.size() ? args[i + 1] : QString();
        if (a == QLatin1String("--app")) { app = v; ++i; }
        else if (a == QLatin1String("--case")) { only = v; ++i; }
        else if (a == QLatin1String("--rounds")) { rounds = std::max(1, v.toInt()); ++i; }
        else if (a == QLatin1String("--moves")) { moves = std::max(2, v.toInt()); ++i; }
        else if (a == QLatin1String("--step")) { step = std::max(1, v.toInt()); ++i; }
        else if (a == QLatin1String("--hz")) { hz = std::clamp(v.toDouble(), 1.0, 500.0); ++i; }
        else if (a == QLatin1String("--env")) { extraEnv << v; ++i; }
        else if (a == QLatin1String("--keep-logs")) { g_keepLogs = v; ++i; }
        else {
            std::fprintf(stderr, "usage: attractor-bench-window [--case NAME] [--rounds N] "
                                 "[--moves N] [--step PX] [--hz F] [--app PATH] "
                                 "[--env VAR=VALUE] [--keep-logs DIR]\n");
            return 2;
        }
    }
    if (qEnvironmentVariableIsEmpty("DISPLAY")) {
        std::fprintf(stderr, "attractor-bench-window needs an X display: run it under "
                             "xvfb-run -a -s \"-screen 0 1600x1000x24\"\n");
        return 2;
    }
    const QString sourceDir = QStringLiteral(AWB_BENCH_SOURCE_DIR);
    std::printf("%-16s %5s %8s %8s %8s %8s %9s %8s\n", "case", "round", "frames", "fps",
                "lag", "lag p90", "picture", "final");
    std::printf("%-16s %5s %8s %8s %8s %8s %9s %8s\n", "", "", "drawn", "pictures", "ms", "ms",
                "lag ms", "ms");
    int failures = 0;
    for (const Case &c : cases()) {
        if (!only.isEmpty() && !only.split(QLatin1Char(',')).contains(c.name))
            continue;
        for (int round = 1; round <= rounds; ++round) {
            const auto r = runCase(c, app, sourceDir, extraEnv, moves, hz, step);
            if (!r) {
                ++failures;
                continue;
            }
            std::printf("%-16s %5d %8d %8s %8s %8s %9s %8s\n", qPrintable(c.name), round,
                        r->frames, qPrintable(figure(r->fps, 1)),
                        qPrintable(figure(r->lagMedian)), qPrintable(figure(r->lagP90)),
                        qPrintable(figure(r->pictureMedian)), qPrintable(figure(r->final)));
            std::fflush(stdout);
        }
    }
    return failures ? 1 : 0;
}
