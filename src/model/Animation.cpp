#include "model/Animation.h"

#include "model/AttractorItem.h"
#include "model/Item.h"
#include "model/ProjectIO.h"

#include <QJsonArray>
#include <QPointF>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace awb {

namespace {

// "points.<set>.<index>" -> set, index (false for any other target).
bool parsePointTarget(const QString &target, int *set, int *index)
{
    static const QRegularExpression re(QStringLiteral("^points\\.(\\d{1,6})\\.(\\d{1,7})$"));
    const auto m = re.match(target);
    if (!m.hasMatch())
        return false;
    *set = m.captured(1).toInt();
    *index = m.captured(2).toInt();
    return true;
}

const QString probabilitiesTarget = QStringLiteral("probabilities");

// lupdate takes the context of AnimationTr::tr() from the macro (a free tr() would get the
// enclosing namespace as its context).
struct AnimationTr {
    Q_DECLARE_TR_FUNCTIONS(awb::Animation)
};

std::optional<ParameterInfo> findParameter(const Item &item, const QString &key)
{
    for (const ParameterInfo &p : item.parameters())
        if (p.key == key)
            return p;
    return std::nullopt;
}

bool animatable(const ParameterInfo &p)
{
    using T = ParameterInfo::Type;
    return p.animatable && !p.readOnly
           && (p.type == T::Real || p.type == T::Integer || p.type == T::Complex);
}

QString timeText(double time) { return QString::number(time, 'g', 6); }

} // namespace

// ---- AnimationTrack / AnimationSpec --------------------------------------------------------------

std::vector<double> AnimationTrack::valueAt(double time, double duration) const
{
    if (keys.empty())
        return {};
    if (path == Path::Circle) {
        std::vector<double> v = keys.front().value;
        if (v.size() < 2 || center.size() < 2 || !(duration > 0))
            return v;
        const double angle = 2.0 * std::numbers::pi * turns * std::clamp(time / duration, 0.0, 1.0);
        const double c = std::cos(angle), s = std::sin(angle);
        const double dx = v[0] - center[0], dy = v[1] - center[1];
        v[0] = center[0] + c * dx - s * dy;
        v[1] = center[1] + s * dx + c * dy;
        return v;
    }
    if (time <= keys.front().time)
        return keys.front().value;
    if (time >= keys.back().time)
        return keys.back().value;
    const auto next = std::upper_bound(keys.begin(), keys.end(), time,
                                       [](double t, const AnimationKey &k) { return t < k.time; });
    const AnimationKey &b = *next;
    const AnimationKey &a = *(next - 1);
    double s = (time - a.time) / (b.time - a.time);
    if (easing == Easing::Smooth)
        s = s * s * (3.0 - 2.0 * s);
    std::vector<double> v(a.value.size());
    for (std::size_t i = 0; i < v.size(); ++i)
        v[i] = a.value[i] + s * (b.value[i] - a.value[i]);
    return v;
}

int AnimationSpec::frameCount() const
{
    if (!(duration >= 0) || !(fps > 0))
        return 1;
    return int(std::min(std::floor(duration * fps + 1e-9), double(maxFrames - 1))) + 1;
}

double AnimationSpec::frameTime(int frame) const
{
    return fps > 0 ? std::min(frame / fps, duration) : 0.0;
}

int AnimationSpec::trackIndex(const QString &target) const
{
    for (std::size_t i = 0; i < tracks.size(); ++i)
        if (tracks[i].target == target)
            return int(i);
    return -1;
}

const QStringList &AnimationSpec::pathNames()
{
    static const QStringList names{QStringLiteral("keys"), QStringLiteral("circle")};
    return names;
}

const QStringList &AnimationSpec::easingNames()
{
    static const QStringList names{QStringLiteral("linear"), QStringLiteral("smooth")};
    return names;
}

MaybeProblem AnimationSpec::check() const
{
    if (!std::isfinite(duration) || duration <= 0 || duration > maxDuration)
        return Problem{QStringLiteral("duration"),
                       AnimationTr::tr("expected a duration in seconds above 0 and at most %1")
                           .arg(maxDuration)};
    if (!std::isfinite(fps) || fps < 1 || fps > maxFps)
        return Problem{QStringLiteral("fps"),
                       AnimationTr::tr("expected between 1 and %1 frames per second").arg(maxFps)};
    if (duration * fps >= maxFrames)
        return Problem{QStringLiteral("duration"),
                       AnimationTr::tr("%1 s at %2 frames per second makes more than %3 frames")
                           .arg(duration).arg(fps).arg(maxFrames)};
    for (std::size_t t = 0; t < tracks.size(); ++t) {
        const AnimationTrack &track = tracks[t];
        const QString at = QStringLiteral("tracks[%1]").arg(t + 1);
        if (track.target.isEmpty())
            return Problem{at + QStringLiteral(".target"), AnimationTr::tr("names no parameter")};
        if (trackIndex(track.target) != int(t))
            return Problem{at + QStringLiteral(".target"),
                           AnimationTr::tr("%1 is driven by an earlier track already").arg(track.target)};
        if (track.keys.empty())
            return Problem{at + QStringLiteral(".keys"), AnimationTr::tr("needs at least one key")};
        const std::size_t size = track.keys.front().value.size();
        for (std::size_t k = 0; k < track.keys.size(); ++k) {
            const AnimationKey &key = track.keys[k];
            const QString where = at + QStringLiteral(".keys[%1]").arg(k + 1);
            if (!std::isfinite(key.time) || key.time < 0 || key.time > duration)
                return Problem{where + QStringLiteral(".time"),
                               AnimationTr::tr("expected a time between 0 and the duration, %1 s")
                                   .arg(duration)};
            if (k > 0 && key.time <= track.keys[k - 1].time)
                return Problem{where + QStringLiteral(".time"),
                               AnimationTr::tr("key times must increase (%1 s follows %2 s)")
                                   .arg(timeText(key.time), timeText(track.keys[k - 1].time))};
            if (key.value.empty() || key.value.size() != size)
                return Problem{where + QStringLiteral(".value"),
                               AnimationTr::tr("expected %1 numbers, as the first key").arg(size)};
            for (double x : key.value)
                if (!std::isfinite(x))
                    return Problem{where + QStringLiteral(".value"), AnimationTr::tr("not a finite number")};
        }
        if (track.path == AnimationTrack::Path::Circle) {
            if (size < 2)
                return Problem{at + QStringLiteral(".path"),
                               AnimationTr::tr("a circle turns a point or a complex value, not one number")};
            if (track.center.size() != 2 || !std::isfinite(track.center[0])
                || !std::isfinite(track.center[1]))
                return Problem{at + QStringLiteral(".center"), AnimationTr::tr("expected [x, y]")};
            if (!std::isfinite(track.turns) || std::abs(track.turns) > 1000)
                return Problem{at + QStringLiteral(".turns"),
                               AnimationTr::tr("expected a number of turns between -1000 and 1000")};
        }
    }
    return std::nullopt;
}

// ---- targets ------------------------------------------------------------------------------------

QList<AnimationTarget> animationTargets(const Item &item)
{
    QList<AnimationTarget> list;
    for (const ParameterInfo &p : item.parameters()) {
        if (!animatable(p))
            continue;
        const bool complex = p.type == ParameterInfo::Type::Complex;
        QString label = p.label;
        if (!p.group.isEmpty() && p.group != label)
            label = QStringLiteral("%1: %2").arg(p.group, p.label);
        list.append({p.key, label, complex ? 2 : 1, complex, false});
    }
    const auto *attractor = qobject_cast<const AttractorItem *>(&item);
    if (!attractor)
        return list;
    if (attractor->algorithm().mode == AlgorithmSpec::Mode::Random && attractor->mapCount() > 1)
        list.append({probabilitiesTarget, AnimationTr::tr("Probabilities"), attractor->mapCount(), false,
                     false});
    const int sets = attractor->controlPointSetCount();
    for (int s = 0; s < sets; ++s) {
        const PointList &points = attractor->controlPoints(s);
        for (std::size_t i = 0; i < points.size(); ++i) {
            const QString label = sets > 1 ? AnimationTr::tr("Points %1, point %2").arg(s + 1).arg(i + 1)
                                           : AnimationTr::tr("Control point %1").arg(i + 1);
            list.append({QStringLiteral("points.%1.%2").arg(s).arg(i), label,
                         attractor->pointDimension(), false, true});
        }
    }
    return list;
}

std::vector<double> animationValue(const Item &item, const QString &target, QString *error)
{
    const auto fail = [&](const QString &message) {
        if (error)
            *error = message;
        return std::vector<double>{};
    };
    const auto *attractor = qobject_cast<const AttractorItem *>(&item);
    int set = 0, index = 0;
    if (target == probabilitiesTarget) {
        if (!attractor || attractor->mapCount() < 1)
            return fail(AnimationTr::tr("%1 has no probabilities").arg(item.name()));
        std::vector<double> p = attractor->algorithm().probabilities;
        if (p.empty())
            p.assign(std::size_t(attractor->mapCount()), 1.0 / attractor->mapCount());
        return p;
    }
    if (parsePointTarget(target, &set, &index)) {
        if (!attractor || set >= attractor->controlPointSetCount()
            || index >= int(attractor->controlPoints(set).size()))
            return fail(AnimationTr::tr("%1 has no control point %2 in point set %3")
                            .arg(item.name()).arg(index + 1).arg(set + 1));
        const Point &p = attractor->controlPoints(set)[std::size_t(index)];
        if (attractor->pointDimension() == 3)
            return {p.x, p.y, p.z};
        return {p.x, p.y};
    }
    const auto info = findParameter(item, target);
    if (!info || !animatable(*info))
        return fail(info ? AnimationTr::tr("%1 is not a number that can be animated").arg(target)
                         : AnimationTr::tr("%1 has no parameter %2 (now)").arg(item.name(), target));
    const QVariant v = item.parameter(target);
    if (info->type == ParameterInfo::Type::Complex) {
        const QPointF z = v.toPointF();
        return {z.x(), z.y()};
    }
    return {v.toDouble()};
}

// ---- frames -------------------------------------------------------------------------------------

namespace {

bool applyTrack(Item &item, const AnimationTrack &track, const std::vector<double> &value,
                QString *error)
{
    auto *attractor = qobject_cast<AttractorItem *>(&item);
    int set = 0, index = 0;
    if (track.target == probabilitiesTarget) {
        if (!attractor)
            return false;
        AlgorithmSpec a = attractor->algorithm();
        a.probabilities = value;
        if (const MaybeProblem p = attractor->checkAlgorithm(a)) {
            *error = p->message;
            return false;
        }
        return attractor->setAlgorithm(a);
    }
    if (parsePointTarget(track.target, &set, &index)) {
        if (!attractor || set >= attractor->controlPointSetCount()
            || index >= int(attractor->controlPoints(set).size())) {
            *error = AnimationTr::tr("no such control point");
            return false;
        }
        Point p = attractor->controlPoints(set)[std::size_t(index)];
        p.x = value.at(0);
        p.y = value.size() > 1 ? value[1] : p.y;
        if (value.size() > 2)
            p.z = value[2];
        if (!attractor->moveControlPoint(index, p, 0, set)) {
            *error = AnimationTr::tr("the point was refused");
            return false;
        }
        return true;
    }
    const auto info = findParameter(item, track.target);
    if (!info || !animatable(*info)) {
        *error = AnimationTr::tr("no such parameter now");
        return false;
    }
    QVariant v;
    switch (info->type) {
    case ParameterInfo::Type::Complex:
        if (value.size() != 2) {
            *error = AnimationTr::tr("a complex value needs 2 numbers");
            return false;
        }
        v = QPointF(value[0], value[1]);
        break;
    case ParameterInfo::Type::Integer: v = int(std::lround(value.at(0))); break;
    default: v = value.at(0); break;
    }
    return item.setParameter(track.target, v, 0, error);
}

} // namespace

bool applyAnimation(Item &item, const AnimationSpec &spec, double time, QString *error)
{
    Q_ASSERT(!item.project());
    for (const AnimationTrack &track : spec.tracks) {
        QString why;
        if (animationValue(item, track.target).empty())
            continue; // inactive: the item has no such input now
        if (!applyTrack(item, track, track.valueAt(time, spec.duration), &why)) {
            if (error)
                *error = AnimationTr::tr("%1 at %2 s: %3")
                             .arg(track.target, timeText(time),
                                  why.isEmpty() ? AnimationTr::tr("the value was refused") : why);
            return false;
        }
    }
    return true;
}

std::unique_ptr<Item> animatedCopy(const Item &item, double time, QString *error)
{
    std::unique_ptr<Item> copy = ProjectIO::copyItem(item, error);
    if (!copy || !applyAnimation(*copy, item.animation(), time, error))
        return nullptr;
    return copy;
}

QStringList inactiveAnimationTargets(const Item &item)
{
    QStringList list;
    for (const AnimationTrack &track : item.animation().tracks)
        if (animationValue(item, track.target).empty())
            list << track.target;
    return list;
}

MaybeProblem animationProblem(const Item &item, const AnimationSpec &spec,
                              const AnimationSpec *previous)
{
    if (spec.isEmpty())
        return std::nullopt;
    if (MaybeProblem p = spec.check())
        return p;
    for (std::size_t t = 0; t < spec.tracks.size(); ++t) {
        const AnimationTrack &track = spec.tracks[t];
        QString why;
        const std::vector<double> now = animationValue(item, track.target, &why);
        const QString at = QStringLiteral("tracks[%1]").arg(t + 1);
        if (now.empty() && previous && previous->trackIndex(track.target) >= 0)
            continue; // inactive already
        if (now.empty())
            return Problem{at + QStringLiteral(".target"), why};
        if (int(now.size()) != track.size())
            return Problem{at + QStringLiteral(".keys"),
                           AnimationTr::tr("%1 has %2 coordinates, the keys %3")
                               .arg(track.target).arg(now.size()).arg(track.size())};
    }
    // The values themselves: at every key time, and around circles.
    std::vector<double> times;
    for (const AnimationTrack &track : spec.tracks) {
        for (const AnimationKey &k : track.keys)
            times.push_back(k.time);
        if (track.path == AnimationTrack::Path::Circle)
            for (int q = 0; q <= 4; ++q)
                times.push_back(spec.duration * q / 4.0);
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    QString error;
    std::unique_ptr<Item> copy = ProjectIO::copyItem(item, &error);
    if (!copy)
        return Problem{{}, error};
    for (double time : times)
        if (!applyAnimation(*copy, spec, time, &error))
            return Problem{{}, error};
    return std::nullopt;
}

QString animationCaption(const Item &item, double time)
{
    const AnimationSpec &spec = item.animation();
    QStringList values;
    for (const AnimationTrack &track : spec.tracks) {
        const std::vector<double> v = track.valueAt(time, spec.duration);
        const auto num = [](double x) { return QString::number(x, 'g', 4); };
        int set = 0, index = 0;
        QString text;
        if (track.target == probabilitiesTarget) {
            QStringList p;
            for (double x : v)
                p << num(x);
            text = AnimationTr::tr("p = (%1)").arg(p.join(QStringLiteral(", ")));
        } else if (parsePointTarget(track.target, &set, &index)) {
            QStringList p;
            for (double x : v)
                p << num(x);
            text = QStringLiteral("P%1 = (%2)").arg(index + 1).arg(p.join(QStringLiteral(", ")));
        } else {
            const auto info = findParameter(item, track.target);
            const QString label = info ? info->label : track.target;
            if (v.size() == 2)
                text = QStringLiteral("%1 = %2 %3 %4i")
                           .arg(label, num(v[0]), v[1] < 0 ? QStringLiteral("−") : QStringLiteral("+"),
                                num(std::abs(v[1])));
            else if (info && info->type == ParameterInfo::Type::Integer)
                text = QStringLiteral("%1 = %2").arg(label).arg(std::lround(v.at(0)));
            else
                text = QStringLiteral("%1 = %2").arg(label, num(v.at(0)));
        }
        values << text;
    }
    return AnimationTr::tr("t = %1 s: %2").arg(time, 0, 'f', 2).arg(values.join(QStringLiteral(", ")));
}

// ---- JSON ---------------------------------------------------------------------------------------

QJsonObject animationToJson(const AnimationSpec &spec)
{
    QJsonArray tracks;
    for (const AnimationTrack &track : spec.tracks) {
        QJsonObject t{{"target", track.target}};
        QJsonArray keys;
        for (const AnimationKey &k : track.keys) {
            QJsonValue value;
            if (k.value.size() == 1) {
                value = k.value.front();
            } else {
                QJsonArray a;
                for (double x : k.value)
                    a.append(x);
                value = a;
            }
            keys.append(QJsonObject{{"time", k.time}, {"value", value}});
        }
        t["keys"] = keys;
        if (track.easing != AnimationTrack::Easing::Linear)
            t["easing"] = AnimationSpec::easingNames().at(int(track.easing));
        if (track.path == AnimationTrack::Path::Circle) {
            t["path"] = AnimationSpec::pathNames().at(int(track.path));
            t["center"] = QJsonArray{track.center.at(0), track.center.at(1)};
            t["turns"] = track.turns;
        }
        tracks.append(t);
    }
    return QJsonObject{{"duration", spec.duration}, {"fps", spec.fps}, {"tracks", tracks}};
}

AnimationSpec readAnimation(const FieldReader &r)
{
    AnimationSpec spec;
    spec.duration = r.number("duration");
    spec.fps = r.number("fps", spec.fps);
    const QJsonValue tracks = r.value("tracks");
    if (!tracks.isArray())
        r.fail("tracks", tracks.isUndefined() ? AnimationTr::tr("missing")
                                              : AnimationTr::tr("expected an array of tracks"));
    const QJsonArray list = tracks.toArray();
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString at = r.path("tracks") + QStringLiteral("[%1].").arg(i + 1);
        if (!list[i].isObject())
            throw LoadError{at.chopped(1), AnimationTr::tr("expected an object")};
        const FieldReader t(list[i].toObject(), at);
        AnimationTrack track;
        track.target = t.string("target");
        track.path = AnimationTrack::Path(t.choice("path", AnimationSpec::pathNames(), 0));
        track.easing = AnimationTrack::Easing(t.choice("easing", AnimationSpec::easingNames(), 0));
        if (track.path == AnimationTrack::Path::Circle) {
            track.center = t.numbers("center");
            track.turns = t.number("turns", track.turns);
        }
        const QJsonValue keys = t.value("keys");
        if (!keys.isArray())
            t.fail("keys", keys.isUndefined() ? AnimationTr::tr("missing")
                                              : AnimationTr::tr("expected an array of keys"));
        const QJsonArray keyList = keys.toArray();
        for (qsizetype k = 0; k < keyList.size(); ++k) {
            const QString kat = t.path("keys") + QStringLiteral("[%1].").arg(k + 1);
            if (!keyList[k].isObject())
                throw LoadError{kat.chopped(1), AnimationTr::tr("expected an object {\"time\", \"value\"}")};
            const FieldReader key(keyList[k].toObject(), kat);
            AnimationKey ak;
            ak.time = key.number("time");
            const QJsonValue v = key.value("value");
            if (v.isArray())
                ak.value = key.numbers("value");
            else
                ak.value = {key.number("value")};
            if (!key.unread().isEmpty())
                key.fail(key.unread().keys().front(), AnimationTr::tr("unknown field of a key"));
            track.keys.push_back(std::move(ak));
        }
        if (!t.unread().isEmpty())
            t.fail(t.unread().keys().front(), AnimationTr::tr("unknown field of a track"));
        spec.tracks.push_back(std::move(track));
    }
    if (!r.unread().isEmpty())
        r.fail(r.unread().keys().front(), AnimationTr::tr("unknown field of an animation"));
    r.require(spec.check());
    return spec;
}

} // namespace awb
