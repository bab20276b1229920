#pragma once
// Parameter animation (layer 2, model; issue 16 part 2). An item may carry an AnimationSpec:
// keyframed tracks, each driving one numeric input of the item over time —
//   * a parameter of Item::parameters() of type Real, Integer (rounded) or Complex
//     ("scheme.omega", "scheme.t", "curves.2.u", "alpha.1", ...);
//   * "probabilities": the random iteration's probabilities, one value per map;
//   * "points.<set>.<index>": one control point (x, y, or x, y, z for surfaces).
// A track interpolates its keys piecewise linearly (or with smoothstep easing) and holds the
// first and last value outside them; a "circle" track turns its first key's value (a point, or
// a complex parameter) about a centre. The spec is an input of the item: saved in the project
// file, edited by one undo step (Item::setAnimation). The document itself never moves: a frame
// is a copy of the item with the values at that time (animatedCopy), drawn by the same renderers
// as the item, so frame k of `attractor-cli animate` equals a render of the item with its
// parameters set to the values at time k / fps.

#include "model/ItemValues.h"

#include <QJsonObject>
#include <QList>
#include <QString>

#include <memory>
#include <vector>

namespace awb {

class FieldReader;
class Item;

struct AnimationKey {
    double time = 0.0;           // seconds from the start
    std::vector<double> value;   // the target's coordinates (1 for a real parameter)
    bool operator==(const AnimationKey &) const = default;
};

struct AnimationTrack {
    enum class Path { Keys, Circle };
    enum class Easing { Linear, Smooth };
    QString target;              // parameter key, "probabilities" or "points.<set>.<index>"
    Path path = Path::Keys;
    Easing easing = Easing::Linear;
    std::vector<AnimationKey> keys;  // strictly increasing times; at least one
    // Path::Circle: keys[0].value's first two coordinates turn about `center` (2 numbers)
    // `turns` times (negative: clockwise) over the whole animation; other coordinates stay.
    std::vector<double> center;
    double turns = 1.0;

    bool operator==(const AnimationTrack &) const = default;
    // The value at `time` seconds of an animation `duration` seconds long.
    std::vector<double> valueAt(double time, double duration) const;
    int size() const { return keys.empty() ? 0 : int(keys.front().value.size()); }
};

struct AnimationSpec {
    Q_DECLARE_TR_FUNCTIONS(awb::AnimationSpec)
public:
    double duration = 4.0;  // seconds
    double fps = 25.0;      // frames per second of the exported animation and of playback
    std::vector<AnimationTrack> tracks;

    static constexpr double maxDuration = 3600.0;
    static constexpr double maxFps = 120.0;
    static constexpr int maxFrames = 100000;

    bool operator==(const AnimationSpec &) const = default;
    bool isEmpty() const { return tracks.empty(); }
    // Frames at 0, 1/fps, 2/fps, ... up to and including the duration.
    int frameCount() const;
    double frameTime(int frame) const;
    // Structure only (finite times in [0, duration] in increasing order, equal value sizes,
    // a circle's centre); whether the item accepts the values is animationProblem()'s job.
    MaybeProblem check() const;
    // The track driving `target` (-1: none).
    int trackIndex(const QString &target) const;
    static const QStringList &pathNames();
    static const QStringList &easingNames();
};

// A quantity of an item that a track can drive.
struct AnimationTarget {
    QString key;    // the track's target
    QString label;  // for the user ("Tension ω", "Control point 3", "Probabilities")
    int size = 1;   // coordinates of its value
    bool complex = false;  // a complex parameter (a circle path makes sense)
    bool point = false;    // a control point
};

// What `item` can animate in its present state.
QList<AnimationTarget> animationTargets(const Item &item);
// The item's present value of `target`; empty with *error when the item has no such target.
std::vector<double> animationValue(const Item &item, const QString &target,
                                   QString *error = nullptr);
// Sets the inputs of `item` — which must not be in a project: a copy — to the values of `spec`
// at `time` (inactive tracks skipped). False with *error naming the track and the time when the
// item refuses a value.
bool applyAnimation(Item &item, const AnimationSpec &spec, double time, QString *error);
// A copy of `item` (without children, in no project) whose inputs are those at `time` of the
// item's own animation; nullptr with *error when a value is refused.
std::unique_ptr<Item> animatedCopy(const Item &item, double time, QString *error);
// Whether `spec` fits `item`: every target exists with the right size and the item accepts the
// values at every key time (and, for circles, a quarter of a turn apart). A target the item
// does not have now (ω after the scheme became a B-spline, a removed control point) makes the
// track inactive, not wrong, when `previous` has a track on it already: an edit may not key
// what does not exist, but an edit elsewhere never makes the document refuse itself, and such
// a file loads (the loader passes the spec itself as `previous`).
MaybeProblem animationProblem(const Item &item, const AnimationSpec &spec,
                              const AnimationSpec *previous = nullptr);
// The targets of the item's tracks that it does not have now (their tracks are skipped).
QStringList inactiveAnimationTargets(const Item &item);

// The values of the animated inputs at `time`, for a caption or the status bar:
// "t = 1.20 s: ω = 0.0625, P3 = (1.5, 2)".
QString animationCaption(const Item &item, double time);

QJsonObject animationToJson(const AnimationSpec &spec);
AnimationSpec readAnimation(const FieldReader &fields);

} // namespace awb
