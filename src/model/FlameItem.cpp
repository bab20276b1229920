#include "model/FlameItem.h"

#include "core/Messages.h"
#include "core/flame/FlameChaos.h"
#include "core/flame/FlameTone.h"
#include "core/flame/Variations.h"
#include "model/Commands.h"
#include "model/ProjectIO.h"
#include "model/PropertyDeclaration.h"

#include <QJsonArray>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

struct FlameItemTr {
    Q_DECLARE_TR_FUNCTIONS(awb::FlameItem)
};

using flame::Affine2;
using flame::Flame;
using flame::FlameXform;

// flam3's order "a d b e c f" (its c[3][2]: rows x, y, 1).
QJsonArray affineToJson(const Affine2 &m) { return {m.a, m.d, m.b, m.e, m.c, m.f}; }

Affine2 affineFromJson(const QJsonValue &v, const QString &where)
{
    const QJsonArray a = v.toArray();
    if (!v.isArray() || a.size() != 6)
        throw LoadError{where, FlameItemTr::tr("expected 6 numbers in flam3's order [a, d, b, e, "
                                               "c, f]: x' = a x + b y + c, y' = d x + e y + f")};
    double c[6];
    for (int k = 0; k < 6; ++k)
        c[k] = FieldReader::toNumber(a[k], where + QStringLiteral("[%1]").arg(k + 1));
    return Affine2{c[0], c[2], c[4], c[1], c[3], c[5]};
}

// Parameters of variations the xform does not use are never drawn: at their defaults, so that
// equal pictures are equal values (and a file keeps only what flam3 writes).
void normalizeParameters(FlameXform &x)
{
    std::vector<double> p = flame::defaultParameters();
    for (const flame::VariationTerm &v : x.variations)
        for (int k : flame::variationParameters(v.id))
            p[std::size_t(k)] = x.parameters[std::size_t(k)];
    x.parameters = std::move(p);
}

QJsonValue xformsToJson(const Flame &f)
{
    QJsonArray out;
    for (const FlameXform &x : f.xforms)
        out.append(flameXformToJson(x, f.xforms.size()));
    return out;
}

std::vector<FlameXform> xformsFromJson(const QJsonValue &v, const QString &where)
{
    const QJsonArray a = v.toArray();
    if (!v.isArray() || a.isEmpty())
        throw LoadError{where, FlameItemTr::tr("expected a non-empty array of xforms")};
    if (a.size() > flame::kMaxXforms)
        throw LoadError{where, FlameItemTr::tr("%1 xforms: at most %2 are drawn")
                                   .arg(a.size())
                                   .arg(flame::kMaxXforms)};
    std::vector<FlameXform> out;
    out.reserve(std::size_t(a.size()));
    for (qsizetype k = 0; k < a.size(); ++k)
        out.push_back(flameXformFromJson(a[k], where + QStringLiteral("[%1]").arg(k + 1)));
    return out;
}

bool wholeBytes(const Flame &f)
{
    for (const flame::FlameColour &c : f.palette)
        for (double v : {c.r, c.g, c.b})
            if (!(v >= 0 && v <= 1) || std::round(v * 255.0) / 255.0 != v)
                return false;
    return true;
}

// 256 colours: "rrggbb..." (1536 hex digits) when every channel is a whole byte, as flam3's
// <palette> holds them; otherwise [[r, g, b], ...] with channels from 0 to 1, as the flame
// holds them (exact: a file read and written again is the same, bit for bit).
QJsonValue paletteToJson(const Flame &f)
{
    if (wholeBytes(f)) {
        QString hex;
        hex.reserve(256 * 6);
        for (const flame::FlameColour &c : f.palette)
            for (double v : {c.r, c.g, c.b})
                hex += QStringLiteral("%1").arg(int(std::round(v * 255.0)), 2, 16, QLatin1Char('0'));
        return hex;
    }
    QJsonArray out;
    for (const flame::FlameColour &c : f.palette)
        out.append(QJsonArray{c.r, c.g, c.b});
    return out;
}

void paletteFromJson(Flame &f, const QJsonValue &v, const QString &where)
{
    if (v.isString()) {
        const QString hex = v.toString();
        if (hex.size() != 256 * 6)
            throw LoadError{where, FlameItemTr::tr("expected 1536 hexadecimal digits (256 colours "
                                                   "rrggbb), got %1")
                                       .arg(hex.size())};
        for (int i = 0; i < 256; ++i) {
            bool ok = false;
            const uint rgb = QStringView(hex).mid(i * 6, 6).toUInt(&ok, 16);
            if (!ok)
                throw LoadError{where, FlameItemTr::tr("colour %1 is not hexadecimal").arg(i)};
            f.palette[std::size_t(i)] = {((rgb >> 16) & 255) / 255.0, ((rgb >> 8) & 255) / 255.0,
                                         (rgb & 255) / 255.0};
        }
        return;
    }
    const QJsonArray a = v.toArray();
    if (!v.isArray() || a.size() != 256)
        throw LoadError{where, FlameItemTr::tr("expected 256 colours: a string of hexadecimal "
                                               "rrggbb, or [[r, g, b], ...] from 0 to 1")};
    for (int i = 0; i < 256; ++i) {
        const QString at = where + QStringLiteral("[%1]").arg(i + 1);
        const QJsonArray c = a[i].toArray();
        if (!a[i].isArray() || c.size() != 3)
            throw LoadError{at, FlameItemTr::tr("expected [r, g, b]")};
        double rgb[3];
        for (int k = 0; k < 3; ++k) {
            rgb[k] = FieldReader::toNumber(c[k], at);
            if (rgb[k] < 0 || rgb[k] > 1)
                throw LoadError{at, FlameItemTr::tr("a channel must be from 0 to 1")};
        }
        f.palette[std::size_t(i)] = {rgb[0], rgb[1], rgb[2]};
    }
}

// The default flame: three halving maps of the Sierpinski gasket, the third bent by the
// spherical variation, in a gradient from deep blue to gold.
Flame defaultFlame()
{
    Flame f;
    auto xform = [](double e, double f_, double colour, double spherical) {
        FlameXform x;
        x.pre = Affine2{0.5, 0, e, 0, 0.5, f_};
        x.weight = 1;
        x.colour = colour;
        if (spherical > 0)
            x.variations = {{0, 1 - spherical}, {flame::variationId("spherical"), spherical}};
        return x;
    };
    f.xforms = {xform(0, 0, 0, 0), xform(0.5, 0, 0.5, 0), xform(0, 0.5, 1, 0.5)};
    for (int i = 0; i < 256; ++i) {
        const double t = i / 255.0;
        auto byte = [t](int from, int to) { return std::round(from + t * (to - from)) / 255.0; };
        f.palette[std::size_t(i)] = {byte(20, 255), byte(40, 200), byte(140, 60)};
    }
    f.centre[0] = 0.5;
    f.centre[1] = 0.5;
    f.scale = 300;
    f.width = 400;
    f.height = 400;
    f.quality = 50;
    return f;
}

} // namespace

Flame canonicalFlame(Flame f)
{
    f.name.clear();
    const std::size_t n = f.xforms.size();
    for (FlameXform &x : f.xforms) {
        normalizeParameters(x);
        // A xaos row is one entry per xform, or none when every entry is 1.
        bool plain = true;
        for (std::size_t j = 0; j < n; ++j)
            plain = plain && x.xaosTo(j) == 1.0;
        if (plain) {
            x.xaos.clear();
        } else {
            x.xaos.resize(n, 1.0);
        }
    }
    if (f.finalXform) {
        // What a final xform does not have: a weight, a xaos row, an animation.
        normalizeParameters(*f.finalXform);
        f.finalXform->weight = 0;
        f.finalXform->xaos.clear();
        f.finalXform->animate = 1;
    }
    return f;
}

AffineMap planeMapOf(const Affine2 &m)
{
    // Row convention [x' y'] = [x y] A + b with A = [[a, d], [b, e]]; then R A R, b R.
    AffineMap f{Mat(2, 2), RowVec(2)};
    f.A << m.a, -m.d, -m.b, m.e;
    f.b << m.c, -m.f;
    return f;
}

QJsonObject flameXformToJson(const FlameXform &x, std::size_t xforms)
{
    QJsonObject o;
    o["weight"] = x.weight;
    o["color"] = x.colour;
    o["color_speed"] = x.colourSpeed;
    if (x.opacity != 1)
        o["opacity"] = x.opacity;
    if (x.animate != 1)
        o["animate"] = x.animate;
    if (!x.name.empty())
        o["name"] = QString::fromStdString(x.name);
    o["coefs"] = affineToJson(x.pre);
    if (!x.post.isIdentity())
        o["post"] = affineToJson(x.post);
    QJsonObject variations, parameters;
    for (const flame::VariationTerm &v : x.variations) {
        variations[QString::fromUtf8(flame::variationName(v.id))] = v.weight;
        for (int p : flame::variationParameters(v.id))
            parameters[QString::fromUtf8(flame::parameterName(p))] =
                x.parameters[std::size_t(p)];
    }
    o["variations"] = variations;
    if (!parameters.isEmpty())
        o["parameters"] = parameters;
    bool xaos = false;
    for (std::size_t j = 0; j < xforms; ++j)
        xaos = xaos || x.xaosTo(j) != 1.0;
    if (xaos) {
        QJsonArray row;
        for (std::size_t j = 0; j < xforms; ++j)
            row.append(x.xaosTo(j));
        o["chaos"] = row;
    }
    return o;
}

FlameXform flameXformFromJson(const QJsonValue &v, const QString &where)
{
    if (!v.isObject())
        throw LoadError{where, FlameItemTr::tr("expected an xform {\"coefs\": [...], "
                                               "\"variations\": {...}, \"weight\": w, ...}")};
    const FieldReader r(v.toObject(), where + QLatin1Char('.'));
    FlameXform x;
    x.variations.clear();
    x.weight = r.number("weight", 0.0);
    if (x.weight < 0)
        r.fail("weight", FlameItemTr::tr("a weight must not be negative"));
    x.colour = r.number("color", 0.0);
    x.colourSpeed = r.number("color_speed", 0.5);
    x.opacity = r.number("opacity", 1.0);
    x.animate = r.number("animate", 1.0);
    x.name = r.string("name", QString()).toStdString();
    x.pre = affineFromJson(r.value("coefs"), r.path("coefs"));
    if (r.has("post"))
        x.post = affineFromJson(r.value("post"), r.path("post"));
    if (const auto vars = r.object("variations", true)) {
        for (auto it = vars->object().begin(); it != vars->object().end(); ++it) {
            const int id = flame::variationId(it.key().toStdString());
            if (id < 0)
                vars->fail(it.key(), FlameItemTr::tr("flam3 has no variation of this name"));
            const double w = vars->number(it.key());
            if (w == 0)
                continue;
            auto at = std::find_if(x.variations.begin(), x.variations.end(),
                                   [id](const flame::VariationTerm &t) { return t.id > id; });
            x.variations.insert(at, {id, w});
        }
    }
    if (const auto params = r.object("parameters")) {
        for (auto it = params->object().begin(); it != params->object().end(); ++it) {
            const int p = flame::parameterId(it.key().toStdString());
            if (p < 0)
                params->fail(it.key(), FlameItemTr::tr("no variation of flam3 has this "
                                                       "parameter"));
            x.parameters[std::size_t(p)] = params->number(it.key());
        }
    }
    normalizeParameters(x);
    if (r.has("chaos")) {
        x.xaos = r.numbers("chaos");
        for (double c : x.xaos)
            if (c < 0)
                r.fail("chaos", FlameItemTr::tr("a xaos entry must not be negative"));
    }
    const QJsonObject unknown = r.unread();
    if (!unknown.isEmpty())
        r.fail(unknown.begin().key(), FlameItemTr::tr("not a field of an xform (coefs, post, "
                                                      "variations, parameters, weight, color, "
                                                      "color_speed, opacity, animate, chaos, "
                                                      "name)"));
    return x;
}

FlameItem::FlameItem() : AttractorItem(tr("Flame")), m_flame(defaultFlame())
{
    AlgorithmSpec algorithm;
    algorithm.mode = AlgorithmSpec::Mode::Random;
    algorithm.samples = 2000000;
    setAlgorithm(algorithm);
}

MaybeProblem FlameItem::checkFlame(const Flame &f) const
{
    try {
        flame::checkFlame(f);
    } catch (const std::exception &e) {
        return Problem{"xforms", QString::fromUtf8(e.what())};
    }
    if (!(f.scale > 0) || !std::isfinite(f.scale))
        return Problem{"camera.scale", tr("the scale (pixels per unit) must be positive")};
    return std::nullopt;
}

PointList flameTriangle(const Affine2 &m)
{
    return {{m.c, -m.f}, {m.a + m.c, -(m.d + m.f)}, {m.b + m.c, -(m.e + m.f)}};
}

Affine2 flameMapOfTriangle(const PointList &t)
{
    Affine2 m;
    m.c = t[0][0];
    m.f = -t[0][1];
    m.a = t[1][0] - m.c;
    m.d = -t[1][1] - m.f;
    m.b = t[2][0] - m.c;
    m.e = -t[2][1] - m.f;
    return m;
}

namespace {
constexpr std::size_t kExactTriangles = 64;

void remember(std::vector<std::pair<PointList, Affine2>> &list, const PointList &t,
              const Affine2 &m)
{
    for (auto &e : list)
        if (e.first == t) {
            e.second = m;
            return;
        }
    if (list.size() >= kExactTriangles)
        list.erase(list.begin());
    list.emplace_back(t, m);
}
} // namespace

void FlameItem::syncTriangles() const
{
    std::vector<Affine2> pres;
    for (const FlameXform &x : m_flame.xforms)
        pres.push_back(x.pre);
    if (m_flame.finalXform)
        pres.push_back(m_flame.finalXform->pre);
    if (pres == m_trianglesOf && m_triangles.size() == pres.size())
        return;
    m_triangles.resize(pres.size());
    m_exact.resize(pres.size());
    for (std::size_t i = 0; i < pres.size(); ++i) {
        if (i < m_trianglesOf.size() && m_trianglesOf[i] == pres[i])
            continue;
        // The triangle this map was last drawn as, if it came from one (an undo).
        const auto known = std::find_if(m_exact[i].begin(), m_exact[i].end(),
                                        [&](const auto &e) { return e.second == pres[i]; });
        m_triangles[i] = known != m_exact[i].end() ? known->first : flameTriangle(pres[i]);
        remember(m_exact[i], m_triangles[i], pres[i]);
    }
    m_trianglesOf = pres;
}

int FlameItem::controlPointSetCount() const
{
    syncTriangles();
    return int(m_triangles.size());
}

PointList &FlameItem::pointStorage(int set)
{
    syncTriangles();
    return m_triangles[std::size_t(set)];
}

Affine2 &FlameItem::preOf(int set)
{
    return std::size_t(set) < m_flame.xforms.size() ? m_flame.xforms[std::size_t(set)].pre
                                                    : m_flame.finalXform->pre;
}

void FlameItem::pointsStored(int set)
{
    const PointList &t = m_triangles[std::size_t(set)];
    auto &exact = m_exact[std::size_t(set)];
    const auto known = std::find_if(exact.begin(), exact.end(),
                                    [&](const auto &e) { return e.first == t; });
    const Affine2 m = known != exact.end() ? known->second : flameMapOfTriangle(t);
    remember(exact, t, m);
    preOf(set) = m;
    m_trianglesOf[std::size_t(set)] = m;
    emit flameChanged();
}

bool FlameItem::setFlame(const Flame &f, int gesture, QString *error)
{
    return setDeclared(*this, f, gesture, error);
}

Flame FlameItem::namedFlame() const
{
    Flame f = m_flame;
    f.name = name().toStdString();
    return f;
}

DerivedIfs FlameItem::computeIfs() const
{
    flame::checkFlame(m_flame);
    if (algorithm().mode != AlgorithmSpec::Mode::Random)
        throw InputError(tr("a flame is drawn by random iteration only (its maps are not "
                            "affine): choose random iteration")
                             .toStdString());
    if (!algorithm().probabilities.empty())
        throw InputError(tr("a flame's xforms carry their own weights (\"xforms\"): leave the "
                            "algorithm's probabilities empty")
                             .toStdString());
    DerivedIfs out;
    bool weighted = true;
    for (const FlameXform &x : m_flame.xforms) {
        const AffineMap f = planeMapOf(x.pre);
        out.ifs.maps.push_back(f);
        out.A.real.push_back(f.A);
        weighted = weighted && x.weight > 0;
    }
    if (weighted)
        for (const FlameXform &x : m_flame.xforms)
            out.ifs.probabilities.push_back(x.weight);
    out.ifs.views = {Projection{Mat::Identity(2, 2), RowVec::Zero(2)}};
    out.ifs.space = "flame (the xforms' affine parts)";
    out.A.unavailable = QString();
    out.S.unavailable = tr("a flame has no subdivision matrices: its maps are not affine");
    auto shared = std::make_shared<const Flame>(m_flame);
    const auto statsOf = [](const flame::FlameStats &s) {
        IterationStats stats;
        stats.images = s.samples;
        stats.cancelled = s.cancelled;
        return stats;
    };
    out.chaos.run = [shared, statsOf](const ChaosJob &job, DensityImage &image,
                                      const IterationControl &control) {
        flame::FlameRaster r;
        r.flame = shared.get();
        r.frame = job.frame;
        r.accumulation = job.accumulation;
        r.samples = job.samples;
        r.seed = job.seed;
        r.threads = job.threads;
        return statsOf(flame::accumulateFlame(r, image, control));
    };
    out.chaos.picture = [shared, statsOf](const ChaosJob &job,
                                          std::vector<std::uint32_t> &pixels,
                                          const IterationControl &control) {
        flame::FlameImageJob r;
        r.flame = shared.get();
        r.frame = job.frame;
        r.samples = job.samples;
        r.seed = job.seed;
        r.threads = job.threads;
        flame::FlameImage image = flame::renderFlameImage(r, control);
        pixels = std::move(image.argb);
        return statsOf(image.stats);
    };
    out.chaos.colours = flame::flamePaletteRgb(m_flame);
    // 20 000 steps: a few milliseconds, about 1 % of the exponent (one orbit, a fixed seed);
    // when first asked for (a render does not).
    out.chaos.lyapunov = Lazy<std::optional<double>>([shared]() -> std::optional<double> {
        try {
            if (const double l = flame::flameLyapunov(*shared).exponent; std::isfinite(l))
                return l;
        } catch (const std::exception &) {  // a flame its check refuses: no number
        }
        return std::nullopt;
    });
    const RasterFrame camera = flame::flameFrame(m_flame);
    out.chaos.frame = std::array<double, 4>{camera.x0, camera.y0, camera.x1, camera.y1};
    out.chaos.width = m_flame.width;
    out.chaos.height = m_flame.height;
    out.chaos.samplesPerPixel = flame::flameSamples(m_flame) / (double(m_flame.width) * m_flame.height);
    out.toIfsSpace = [](const Mat &X) { return X; };
    out.note = tr("a fractal flame, drawn by its own chaos game as flam3 draws it; the spectra "
                  "are those of the xforms' affine (pre) maps, y up");
    return out;
}

// ---- declared properties ----------------------------------------------------------------------

const PropertyTable &FlameItem::declaration()
{
    static const PropertyTable table = [] {
        using I = FlameItem;
        Declaration<I> d(&AttractorItem::attractorProperties());
        auto f = d.part(&I::m_flame, &I::checkFlame, &I::flameChanged,
                        QT_TR_NOOP("Change flame of %1"));
        f.checkedOnRead([](const I &item, const Flame &v) { return item.checkFlame(v); });
        // A file without a palette or camera takes the new item's (flam3's own default
        // palette is black: a flame without one would draw nothing).
        f.startsFrom([](const I &) {
            Flame start = defaultFlame();
            start.xforms.clear();
            return start;
        });
        f.structured(
             "xforms", QStringLiteral("xforms"),
             [](const I &, const Flame &v) { return xformsToJson(v); },
             [](const I &, Flame &v, const QJsonValue &j, const QString &where) {
                 v.xforms = xformsFromJson(j, where);
             })
            .label(QT_TR_NOOP("Xforms"))
            .group(QT_TR_NOOP("Flame"))
            .tip(QT_TR_NOOP("flam3's xforms: {\"coefs\": [a, d, b, e, c, f], \"variations\": "
                            "{\"linear\": 1, ...}, \"weight\": w, \"color\": c, ...} each"))
            .required();
        f.structured(
             "final_xform", QStringLiteral("xform"),
             [](const I &, const Flame &v) -> QJsonValue {
                 if (!v.finalXform)
                     return QJsonValue::Null;
                 return flameXformToJson(*v.finalXform, 0);
             },
             [](const I &, Flame &v, const QJsonValue &j, const QString &where) {
                 if (j.isNull()) {
                     v.finalXform.reset();
                     return;
                 }
                 v.finalXform = flameXformFromJson(j, where);
                 v.finalXform->weight = 0;
             })
            .label(QT_TR_NOOP("Final xform"))
            .tip(QT_TR_NOOP("Drawn on every point without moving the orbit; null: none"));
        f.structured(
             "palette", QStringLiteral("palette"),
             [](const I &, const Flame &v) { return paletteToJson(v); },
             [](const I &, Flame &v, const QJsonValue &j, const QString &where) {
                 paletteFromJson(v, j, where);
             })
            .label(QT_TR_NOOP("Palette"))
            .tip(QT_TR_NOOP("256 colours, indexed by the colour coordinate"));
        f.real("camera.centre_x", [](Flame &v) -> double & { return v.centre[0]; })
            .label(QT_TR_NOOP("Centre x"))
            .group(QT_TR_NOOP("Camera"));
        f.real("camera.centre_y", [](Flame &v) -> double & { return v.centre[1]; })
            .label(QT_TR_NOOP("Centre y"))
            .group(QT_TR_NOOP("Camera"))
            .tip(QT_TR_NOOP("flam3's: y grows down the picture"));
        f.real("camera.scale", &Flame::scale)
            .label(QT_TR_NOOP("Scale"))
            .group(QT_TR_NOOP("Camera"))
            .tip(QT_TR_NOOP("Pixels per unit (times 2^zoom)"))
            .range(1e-9, 1e12);
        f.real("camera.rotate", &Flame::rotate)
            .label(QT_TR_NOOP("Rotation (degrees)"))
            .group(QT_TR_NOOP("Camera"))
            .slider(-180, 180);
        f.real("camera.zoom", &Flame::zoom)
            .label(QT_TR_NOOP("Zoom"))
            .group(QT_TR_NOOP("Camera"))
            .range(-50, 50);
        f.integer("camera.width", &Flame::width)
            .label(QT_TR_NOOP("Width (pixels)"))
            .group(QT_TR_NOOP("Camera"))
            .range(1, 32768)
            .notAnimated();
        f.integer("camera.height", &Flame::height)
            .label(QT_TR_NOOP("Height (pixels)"))
            .group(QT_TR_NOOP("Camera"))
            .range(1, 32768)
            .notAnimated();
        f.real("tone.quality", &Flame::quality)
            .label(QT_TR_NOOP("Quality (samples per pixel)"))
            .group(QT_TR_NOOP("Tone"))
            .range(1e-6, 1e6)
            .notAnimated();
        f.real("tone.brightness", &Flame::brightness)
            .label(QT_TR_NOOP("Brightness"))
            .group(QT_TR_NOOP("Tone"))
            .range(0, 1e6);
        f.real("tone.gamma", &Flame::gamma)
            .label(QT_TR_NOOP("Gamma"))
            .group(QT_TR_NOOP("Tone"))
            .range(1e-3, 1e3);
        f.real("tone.gamma_threshold", &Flame::gammaThreshold)
            .label(QT_TR_NOOP("Gamma threshold"))
            .group(QT_TR_NOOP("Tone"))
            .range(0, 1);
        f.real("tone.vibrancy", &Flame::vibrancy)
            .label(QT_TR_NOOP("Vibrancy"))
            .group(QT_TR_NOOP("Tone"))
            .range(0, 1);
        f.real("tone.highlight_power", &Flame::highlightPower)
            .label(QT_TR_NOOP("Highlight power"))
            .group(QT_TR_NOOP("Tone"))
            .tip(QT_TR_NOOP("flam3's: -1 leaves the highlights as they are"))
            .range(-1, 1e3);
        f.structured(
             "tone.background", QStringLiteral("colour"),
             [](const I &, const Flame &v) -> QJsonValue {
                 return QJsonArray{v.background.r, v.background.g, v.background.b};
             },
             [](const I &, Flame &v, const QJsonValue &j, const QString &where) {
                 const std::vector<double> c = property::numbersFromJson(j, where);
                 if (c.size() != 3)
                     throw LoadError{where, FlameItemTr::tr("expected [r, g, b] from 0 to 1")};
                 v.background = {c[0], c[1], c[2]};
             })
            .label(QT_TR_NOOP("Background"))
            .tip(QT_TR_NOOP("[r, g, b] from 0 to 1"));
        f.integer("tone.passes", &Flame::passes)
            .label(QT_TR_NOOP("Passes"))
            .group(QT_TR_NOOP("Tone"))
            .tip(QT_TR_NOOP("flam3's passes: the samples drawn in that many histograms, each "
                            "log-scaled and density-estimated apart, then summed (a little "
                            "smoother than one)"))
            .range(1, flame::kMaxFlamePasses)
            .notAnimated();
        f.integer("tone.supersample", &Flame::supersample)
            .label(QT_TR_NOOP("Supersample"))
            .group(QT_TR_NOOP("Tone"))
            .range(1, 64)
            .notAnimated();
        f.real("tone.filter", &Flame::filter)
            .label(QT_TR_NOOP("Filter radius (pixels)"))
            .group(QT_TR_NOOP("Tone"))
            .range(0, 1e3);
        f.choice("tone.filter_shape", &Flame::filterShape,
                 {"gaussian", "hermite", "box", "triangle", "bell", "bspline", "lanczos3",
                  "lanczos2", "mitchell", "blackman", "catrom", "hamming", "hanning",
                  "quadratic"},
                 {QT_TR_NOOP("Gaussian"), QT_TR_NOOP("Hermite"), QT_TR_NOOP("Box"),
                  QT_TR_NOOP("Triangle"), QT_TR_NOOP("Bell"), QT_TR_NOOP("B-spline"),
                  QT_TR_NOOP("Lanczos 3 (flam3 draws Mitchell)"),
                  QT_TR_NOOP("Lanczos 2 (flam3 draws Blackman)"),
                  QT_TR_NOOP("Mitchell (flam3 draws Catmull-Rom)"),
                  QT_TR_NOOP("Blackman (flam3 draws Hanning)"),
                  QT_TR_NOOP("Catmull-Rom (flam3 draws Hamming)"),
                  QT_TR_NOOP("Hamming (flam3 draws Lanczos 3)"),
                  QT_TR_NOOP("Hanning (flam3 draws Lanczos 2)"), QT_TR_NOOP("Quadratic")})
            .label(QT_TR_NOOP("Filter shape"))
            .group(QT_TR_NOOP("Tone"))
            .tip(QT_TR_NOOP("flam3's filter_shape; from Lanczos 3 on, flam3 3.1.1 draws "
                            "another shape than the name says, and so do we"));
        f.choice("tone.palette_mode", &Flame::paletteMode, {"step", "linear"},
                 {QT_TR_NOOP("Step"), QT_TR_NOOP("Linear")})
            .label(QT_TR_NOOP("Palette mode"))
            .group(QT_TR_NOOP("Tone"))
            .tip(QT_TR_NOOP("flam3's palette_mode: a hit takes the palette entry at its colour "
                            "coordinate (step) or between the two entries around it (linear)"));
        f.real("tone.estimator_radius", &Flame::estimatorRadius)
            .label(QT_TR_NOOP("Estimator radius"))
            .group(QT_TR_NOOP("Tone"))
            .range(0, 1e3);
        f.real("tone.estimator_minimum", &Flame::estimatorMinimum)
            .label(QT_TR_NOOP("Estimator minimum"))
            .group(QT_TR_NOOP("Tone"))
            .range(0, 1e3);
        f.real("tone.estimator_curve", &Flame::estimatorCurve)
            .label(QT_TR_NOOP("Estimator curve"))
            .group(QT_TR_NOOP("Tone"))
            .range(0, 1e3);
        return d.table();
    }();
    return table;
}

} // namespace awb
