#include "model/FlameFile.h"

#include "core/Messages.h"
#include "core/flame/FlameChaos.h"
#include "core/flame/FlameTone.h"
#include "core/flame/Variations.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QXmlStreamReader>

#include <algorithm>
#include <array>
#include <map>
#include <cmath>

namespace awb {

namespace {

struct FlameFileTr {
    Q_DECLARE_TR_FUNCTIONS(awb::FlameFile)
};

using flame::Affine2;
using flame::Flame;
using flame::FlameXform;

// Attributes of <flame> that change nothing of the still picture flam3 draws here: animation,
// interpolation, the file's own notes.
bool ignoredFlameAttribute(QStringView name)
{
    static const QStringList names{
        "version", "time", "interpolation", "interpolation_type", "interpolation_space",
        "palette_interpolation", "hsv_rgb_palette_blend", "temporal_filter_type",
        "temporal_filter_width", "temporal_filter_exp", "temporal_samples",
        "url", "nick", "notes", "contrast", "genome_index", "parent",
        "soloxform", "new_linear", "plugins"};
    return names.contains(name);
}

// flam3's palette file (flam3-palettes.xml, installed with flam3; the FLAM3_PALETTES variable
// names another, as for flam3-render): each entry's number and hex data, read once an import;
// or why it cannot be read.
struct Flam3Palettes {
    QString path, error;
    std::map<int, QString> data;

    Flam3Palettes()
    {
        const QByteArray env = qgetenv("FLAM3_PALETTES");
        path = env.isEmpty() ? QStringLiteral("/usr/share/flam3/flam3-palettes.xml")
                             : QString::fromLocal8Bit(env);
        QFile file(path);
        if (file.size() > (qint64(16) << 20)) {
            error = FlameFileTr::tr("%1 is larger than 16 MB").arg(path);
            return;
        }
        if (!file.open(QIODevice::ReadOnly)) {
            error = FlameFileTr::tr("%1 cannot be read").arg(path);
            return;
        }
        QXmlStreamReader xml(&file);
        while (xml.readNextStartElement()) {
            if (xml.name() == QLatin1String("palettes"))
                continue;  // into the root
            bool ok = false;
            const int number = xml.attributes().value(QLatin1String("number")).toInt(&ok);
            if (xml.name() == QLatin1String("palette") && ok) {
                QString hex = xml.attributes().value(QLatin1String("data")).toString();
                hex.remove(QRegularExpression(QStringLiteral("\\s")));
                data[number] = hex;
            }
            xml.skipCurrentElement();
        }
        if (xml.hasError())
            error = FlameFileTr::tr("%1: %2").arg(path, xml.errorString());
    }

    // Entry `number`, its hue turned by `hue` turns as flam3_get_palette does, into f.palette;
    // an empty string, or why not.
    QString get(int number, double hue, Flame &f) const
    {
        if (!error.isEmpty())
            return error;
        const auto it = data.find(number);
        if (it == data.end())
            return FlameFileTr::tr("%1 has no palette %2").arg(path).arg(number);
        const QString &hex = it->second;
        if (hex.size() != 256 * 8)
            return FlameFileTr::tr("its entry %1 has %2 hex digits, not 256 x 8")
                .arg(number)
                .arg(hex.size());
        for (int i = 0; i < 256; ++i) {
            bool ok = false;
            const uint v = QStringView(hex).mid(8 * i, 8).toUInt(&ok, 16);
            if (!ok)
                return FlameFileTr::tr("its entry %1 is not hexadecimal").arg(number);
            double rgb[3] = {((v >> 16) & 0xff) / 255.0, ((v >> 8) & 0xff) / 255.0,
                             (v & 0xff) / 255.0};
            if (hue != 0.0) {
                double hsv[3];
                flame::rgbToHsv(rgb, hsv);
                hsv[0] += hue * 6.0;
                flame::hsvToRgb(hsv, rgb);
            }
            f.palette[std::size_t(i)] = {rgb[0], rgb[1], rgb[2]};
        }
        return {};
    }
};

// A whole number in [lo, hi], or nullopt.
std::optional<long long> readWhole(QStringView text, long long lo, long long hi)
{
    bool ok = false;
    const long long v = text.trimmed().toLongLong(&ok);
    if (!ok || v < lo || v > hi)
        return std::nullopt;
    return v;
}

std::optional<double> readReal(QStringView text)
{
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return std::nullopt;
    return v;
}

// Exactly n finite numbers (n < 0: any count up to -n), or an empty vector.
std::vector<double> readReals(QStringView text, int n)
{
    std::vector<double> out;
    const auto parts = text.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    if ((n >= 0 && parts.size() != n) || (n < 0 && parts.size() > -n))
        return {};
    out.reserve(std::size_t(parts.size()));
    for (const QStringView part : parts) {
        const auto v = readReal(part);
        if (!v)
            return {};
        out.push_back(*v);
    }
    return out;
}

// flam3's c[3][2] order "a d b e c f".
Affine2 affineOf(const std::vector<double> &c)
{
    Affine2 m;
    m.a = c[0];
    m.d = c[1];
    m.b = c[2];
    m.e = c[3];
    m.c = c[4];
    m.f = c[5];
    return m;
}

// flam3's parameter names, with the old spellings it also reads.
int parameterIdOf(QStringView name)
{
    QString n = name.toString();
    if (n.startsWith(QLatin1String("oscope_")))
        n.replace(0, 7, QStringLiteral("oscilloscope_"));
    return flame::parameterId(n.toStdString());
}

class Reader {
public:
    Reader(const QByteArray &text, const QString &fileName)
        : m_xml(text), m_file(QFileInfo(fileName).fileName())
    {}

    FlameFileRead read()
    {
        int index = 0;
        while (!m_xml.atEnd()) {
            m_xml.readNext();
            if (m_xml.isStartElement() && m_xml.name() == QLatin1String("flame"))
                readFlame(++index);
        }
        if (m_xml.hasError())
            m_out.problems << place(m_xml.lineNumber(), m_xml.columnNumber())
                                  + FlameFileTr::tr("the XML is malformed: %1")
                                        .arg(m_xml.errorString());
        else if (index == 0)
            m_out.problems << FlameFileTr::tr("%1: the file holds no <flame> element").arg(m_file);
        return std::move(m_out);
    }

private:
    QString place(qint64 line, qint64 column) const
    {
        return FlameFileTr::tr("%1, line %2, column %3: ").arg(m_file).arg(line).arg(column);
    }
    QString here() const { return place(m_xml.lineNumber(), m_xml.columnNumber()); }

    // Reads one <flame> to its end; a malformed part leaves the whole flame out.
    void readFlame(int index)
    {
        FlameRead r;
        r.line = m_xml.lineNumber();
        r.column = m_xml.columnNumber();
        Flame &f = r.flame;
        f.name = m_xml.attributes().value(QLatin1String("name")).toString().toStdString();
        m_flame = f.name.empty() ? FlameFileTr::tr("flame %1").arg(index)
                                 : QString::fromStdString(f.name);
        m_problem.clear();
        m_warnings.clear();
        std::array<bool, 256> given{};
        m_paletteNumber.reset();
        m_hue = 0;
        readFlameAttributes(f);
        // palette="N": flam3's palette file's entry N (hue-turned); <color>s below override it.
        if (m_paletteNumber) {
            if (!m_palettes)
                m_palettes.emplace();
            const QString why = m_palettes->get(*m_paletteNumber, m_hue, f);
            if (why.isEmpty())
                given.fill(true);
            else
                warn(here(), FlameFileTr::tr("palette %1 of flam3's palette file is not kept: %2")
                                 .arg(*m_paletteNumber)
                                 .arg(why));
        }
        int written = 0;  // <xform> elements so far
        while (m_problem.isEmpty() && m_xml.readNextStartElement()) {
            const QStringView tag = m_xml.name();
            if (tag == QLatin1String("xform") || tag == QLatin1String("finalxform")) {
                const bool isFinal = tag == QLatin1String("finalxform");
                if (isFinal && f.finalXform) {
                    fail(FlameFileTr::tr("a second <finalxform> (flam3 allows one)"));
                    break;
                }
                if (!isFinal && f.xforms.size() >= std::size_t(flame::kMaxXforms)) {
                    fail(FlameFileTr::tr("more than %1 xforms").arg(flame::kMaxXforms));
                    break;
                }
                const QString where =
                    isFinal ? FlameFileTr::tr("final xform")
                            : FlameFileTr::tr("xform %1").arg(++written);
                // flam3's new xform: colour by its place (initialize_xforms), no variation.
                FlameXform x;
                x.colour = double((f.xforms.size() + (f.finalXform ? 1 : 0)) & 1);
                x.variations.clear();
                readXform(x, where, isFinal);
                if (isFinal)
                    f.finalXform = std::move(x);
                else
                    f.xforms.push_back(std::move(x));
            } else if (tag == QLatin1String("color")) {
                readColour(f, given);
                m_xml.skipCurrentElement();
            } else if (tag == QLatin1String("palette") || tag == QLatin1String("colors")) {
                readPalette(f, given);
            } else if (tag == QLatin1String("symmetry")) {
                readSymmetry(f, r.symmetry);
                m_xml.skipCurrentElement();
            } else if (tag == QLatin1String("edit")) {
                m_xml.skipCurrentElement();  // the genome's history: no picture
            } else {
                warn(here(), FlameFileTr::tr("element <%1> ignored").arg(tag.toString()));
                m_xml.skipCurrentElement();
            }
        }
        if (m_xml.hasError())
            return;  // read() names it
        if (!m_problem.isEmpty()) {
            m_out.problems << m_problem;
            // The rest of the flame is skipped: its end tag closes it.
            while (!m_xml.atEnd()
                   && !(m_xml.isEndElement() && m_xml.name() == QLatin1String("flame")))
                m_xml.readNext();
            return;
        }
        fillPalette(f, given);
        for (std::size_t i = 0; i < f.xforms.size(); ++i)
            if (f.xforms[i].xaos.size() > f.xforms.size()) {
                warn(place(r.line, r.column),
                     FlameFileTr::tr("xform %1: its xaos row has %2 entries for %3 xforms; the "
                                     "extra ones are ignored, as flam3 does")
                         .arg(i + 1)
                         .arg(f.xforms[i].xaos.size())
                         .arg(f.xforms.size()));
                f.xforms[i].xaos.resize(f.xforms.size());
            }
        try {
            flame::checkFlame(f);
        } catch (const std::exception &e) {
            m_out.problems << place(r.line, r.column)
                                  + FlameFileTr::tr("flame '%1': %2")
                                        .arg(m_flame, QString::fromUtf8(e.what()));
            return;
        }
        m_out.warnings << m_warnings;
        m_out.flames.push_back(std::move(r));
    }

    void fail(const QString &why)
    {
        if (m_problem.isEmpty())
            m_problem = here() + FlameFileTr::tr("flame '%1': %2").arg(m_flame, why);
    }
    void warn(const QString &at, const QString &what)
    {
        m_warnings << at + FlameFileTr::tr("flame '%1': %2").arg(m_flame, what);
    }

    void readFlameAttributes(Flame &f)
    {
        QStringList ignored;
        for (const QXmlStreamAttribute &a : m_xml.attributes()) {
            const QStringView key = a.name();
            const QString value = a.value().toString().simplified();
            auto real = [&](double *out) {
                if (const auto v = readReal(value))
                    *out = *v;
                else
                    fail(FlameFileTr::tr("%1=\"%2\" is not a finite number")
                             .arg(key.toString(), value));
            };
            auto reals = [&](double *out, int n) {
                const auto v = readReals(value, n);
                if (v.empty())
                    fail(FlameFileTr::tr("%1=\"%2\" must be %3 finite numbers")
                             .arg(key.toString(), value)
                             .arg(n));
                else
                    std::copy(v.begin(), v.end(), out);
            };
            if (key == QLatin1String("name")) {
            } else if (key == QLatin1String("size")) {
                const auto parts = value.split(QLatin1Char(' '));
                const auto w = readWhole(parts.value(0), 1, 32768);
                const auto h = readWhole(parts.value(1), 1, 32768);
                if (parts.size() != 2 || !w || !h)
                    fail(FlameFileTr::tr("size=\"%1\" must be two whole numbers from 1 to 32768")
                             .arg(value));
                else
                    f.width = int(*w), f.height = int(*h);
            } else if (key == QLatin1String("center")) {
                reals(f.centre, 2);
            } else if (key == QLatin1String("scale")) {
                real(&f.scale);
                if (!(f.scale > 0))
                    fail(FlameFileTr::tr("scale=\"%1\" must be positive").arg(value));
            } else if (key == QLatin1String("rotate")) {
                real(&f.rotate);
            } else if (key == QLatin1String("zoom")) {
                real(&f.zoom);
                if (std::abs(f.zoom) > 50)
                    fail(FlameFileTr::tr("zoom=\"%1\" is beyond +-50 (a factor 2^zoom)").arg(value));
            } else if (key == QLatin1String("quality")) {
                real(&f.quality);
                if (!(f.quality > 0))
                    fail(FlameFileTr::tr("quality=\"%1\" must be positive").arg(value));
            } else if (key == QLatin1String("passes")) {
                const auto v = readWhole(value, 1, flame::kMaxFlamePasses);
                if (!v)
                    fail(FlameFileTr::tr("passes=\"%1\" must be a whole number from 1 to %2")
                             .arg(value)
                             .arg(flame::kMaxFlamePasses));
                else
                    f.passes = int(*v);
            } else if (key == QLatin1String("brightness")) {
                real(&f.brightness);
            } else if (key == QLatin1String("gamma")) {
                real(&f.gamma);
            } else if (key == QLatin1String("gamma_threshold")) {
                real(&f.gammaThreshold);
            } else if (key == QLatin1String("vibrancy")) {
                real(&f.vibrancy);
            } else if (key == QLatin1String("highlight_power")) {
                real(&f.highlightPower);
            } else if (key == QLatin1String("background")) {
                double b[3] = {0, 0, 0};
                reals(b, 3);
                f.background = {b[0], b[1], b[2]};
            } else if (key == QLatin1String("oversample") || key == QLatin1String("supersample")) {
                const auto v = readWhole(value, 1, 64);
                if (!v)
                    fail(FlameFileTr::tr("%1=\"%2\" must be a whole number from 1 to 64")
                             .arg(key.toString(), value));
                else
                    f.supersample = int(*v);
            } else if (key == QLatin1String("filter")) {
                real(&f.filter);
            } else if (key == QLatin1String("filter_shape")) {
                // flam3 draws an unknown shape with the Gaussian, after a warning.
                const int id = flame::filterShapeId(value.toStdString());
                if (id < 0)
                    ignored << QStringLiteral("filter_shape=\"%1\" (not one of flam3's: the "
                                              "Gaussian is used)")
                                   .arg(value);
                f.filterShape = flame::FilterShape(std::max(id, 0));
            } else if (key == QLatin1String("palette_mode")) {
                if (value == QLatin1String("linear"))
                    f.paletteMode = flame::PaletteMode::Linear;
                else if (value == QLatin1String("step"))
                    f.paletteMode = flame::PaletteMode::Step;
                else
                    ignored << QStringLiteral("palette_mode=\"%1\" (flam3's are step and "
                                              "linear: step is used)")
                                   .arg(value);
            } else if (key == QLatin1String("estimator_radius")) {
                real(&f.estimatorRadius);
            } else if (key == QLatin1String("estimator_minimum")) {
                real(&f.estimatorMinimum);
            } else if (key == QLatin1String("estimator_curve")) {
                real(&f.estimatorCurve);
            } else if (key == QLatin1String("palette")) {
                if (const auto v = readWhole(value, 0, 100000))
                    m_paletteNumber = int(*v);
                else
                    ignored << QStringLiteral("palette=\"%1\" (not a palette's number)")
                                   .arg(value);
            } else if (key == QLatin1String("hue")) {
                real(&m_hue);
            } else if (!ignoredFlameAttribute(key)) {
                ignored << QStringLiteral("%1=\"%2\"").arg(key.toString(), value);
            }
        }
        if (!ignored.isEmpty())
            warn(here(), FlameFileTr::tr("attributes not kept: %1")
                             .arg(ignored.join(QStringLiteral(", "))));
    }

    void readXform(FlameXform &x, const QString &where, bool isFinal)
    {
        const QString at = here();
        auto xfail = [&](const QString &why) { fail(where + QStringLiteral(": ") + why); };
        bool weighted = false, anyVariation = false;
        QStringList ignored, animation;
        for (const QXmlStreamAttribute &a : m_xml.attributes()) {
            const QStringView key = a.name();
            const QString value = a.value().toString().simplified();
            auto real = [&](double *out) {
                if (const auto v = readReal(value))
                    *out = *v;
                else
                    xfail(FlameFileTr::tr("%1=\"%2\" is not a finite number")
                              .arg(key.toString(), value));
            };
            int id = -1;
            if (key == QLatin1String("weight")) {
                weighted = true;
                real(&x.weight);
                if (x.weight < 0)
                    xfail(FlameFileTr::tr("weight=\"%1\" is negative").arg(value));
            } else if (key == QLatin1String("color")) {
                const auto v = readReals(value, -2);
                if (v.empty())
                    xfail(FlameFileTr::tr("color=\"%1\" must be one or two finite numbers")
                              .arg(value));
                else
                    x.colour = v[0];
            } else if (key == QLatin1String("color_speed")) {
                real(&x.colourSpeed);
            } else if (key == QLatin1String("symmetry")) {
                // flam3 2.7's name: colour speed (1 - s) / 2.
                double s = 0;
                real(&s);
                x.colourSpeed = (1.0 - s) / 2.0;
                x.animate = s > 0 ? 0 : 1;
            } else if (key == QLatin1String("animate")) {
                real(&x.animate);
            } else if (key == QLatin1String("opacity")) {
                real(&x.opacity);
            } else if (key == QLatin1String("plotmode")) {
                if (value == QLatin1String("off"))
                    x.opacity = 0;
            } else if (key == QLatin1String("name")) {
                x.name = value.toStdString();
            } else if (key == QLatin1String("chaos")) {
                x.xaos = readReals(value, -flame::kMaxXforms);
                if (x.xaos.empty() && !value.isEmpty())
                    xfail(FlameFileTr::tr("chaos=\"%1\" must be at most %2 finite numbers")
                              .arg(value.left(80))
                              .arg(flame::kMaxXforms));
                for (double v : x.xaos)
                    if (v < 0)
                        xfail(FlameFileTr::tr("chaos=\"%1\" has a negative entry").arg(value.left(80)));
            } else if (key == QLatin1String("coefs") || key == QLatin1String("post")) {
                const auto c = readReals(value, 6);
                if (c.empty())
                    xfail(FlameFileTr::tr("%1=\"%2\" must be 6 finite numbers")
                              .arg(key.toString(), value));
                else
                    (key == QLatin1String("coefs") ? x.pre : x.post) = affineOf(c);
            } else if (key == QLatin1String("var1")) {
                const auto j = readWhole(value, 0, flame::kVariationCount - 1);
                if (!j) {
                    xfail(FlameFileTr::tr("var1=\"%1\" names no variation").arg(value));
                } else {
                    x.variations = {{int(*j), 1.0}};
                    anyVariation = true;
                }
            } else if (key == QLatin1String("var")) {
                const auto v = readReals(value, flame::kVariationCount);
                if (v.empty())
                    xfail(FlameFileTr::tr("var=\"...\" must be %1 finite numbers, one per variation")
                              .arg(flame::kVariationCount));
                x.variations.clear();
                for (std::size_t j = 0; j < v.size(); ++j)
                    if (v[j] != 0)
                        x.variations.push_back({int(j), v[j]});
                anyVariation = true;
            } else if ((id = flame::variationId(key.toString().toStdString())) >= 0
                       || key == QLatin1String("linear3D")) {
                if (id < 0)
                    id = 0;  // JWildfire's linear3D: flam3's linear in the plane
                double w = 0;
                real(&w);
                anyVariation = true;
                setVariation(x, id, w);
            } else if (const int p = parameterIdOf(key); p >= 0) {
                real(&x.parameters[std::size_t(p)]);
            } else if (key == QLatin1String("motion_frequency")
                       || key == QLatin1String("motion_function")) {
                animation << key.toString();
            } else {
                ignored << key.toString();
            }
        }
        if (isFinal && weighted && x.weight != 0)
            warn(at, where + FlameFileTr::tr(": a final xform has no weight; weight=\"%1\" "
                                             "ignored")
                                 .arg(x.weight));
        if (isFinal)
            x.weight = 0;
        if (!weighted && !isFinal)
            warn(at, where + FlameFileTr::tr(": no weight given; taken as 0, as flam3 does (the "
                                             "xform is never chosen)"));
        if (!anyVariation)
            warn(at, where + FlameFileTr::tr(": no variation given: as in flam3, every point "
                                             "goes to post(0)"));
        if (!ignored.isEmpty())
            warn(at, where + FlameFileTr::tr(": attributes flam3 does not draw, ignored: %1")
                                 .arg(ignored.join(QStringLiteral(", "))));
        if (!animation.isEmpty())
            warn(at, where + FlameFileTr::tr(": animation attributes not kept: %1")
                                 .arg(animation.join(QStringLiteral(", "))));
        // Child elements (<motion>: an animation's change of the xform) are not kept.
        while (m_xml.readNextStartElement()) {
            warn(here(), where + FlameFileTr::tr(": element <%1> ignored (animation)")
                                     .arg(m_xml.name().toString()));
            m_xml.skipCurrentElement();
        }
    }

    static void setVariation(FlameXform &x, int id, double w)
    {
        auto it = std::find_if(x.variations.begin(), x.variations.end(),
                               [id](const flame::VariationTerm &t) { return t.id >= id; });
        if (it != x.variations.end() && it->id == id) {
            it->weight += w;
            if (it->weight == 0)
                x.variations.erase(it);
        } else if (w != 0) {
            x.variations.insert(it, {id, w});
        }
    }

    void readColour(Flame &f, std::array<bool, 256> &given)
    {
        const auto attributes = m_xml.attributes();
        const auto index = readWhole(attributes.value(QLatin1String("index")), 0, 255);
        QStringView rgb = attributes.value(QLatin1String("rgb"));
        int n = 3;
        if (rgb.isEmpty()) {
            rgb = attributes.value(QLatin1String("rgba"));
            n = 4;
        }
        const auto c = readReals(rgb.toString().simplified(), n);
        if (!index || c.empty()) {
            fail(FlameFileTr::tr("a <color> needs index=\"0..255\" and rgb=\"r g b\""));
            return;
        }
        f.palette[std::size_t(*index)] = {c[0] / 255.0, c[1] / 255.0, c[2] / 255.0};
        given[std::size_t(*index)] = true;
    }

    // <palette count format="RGB|RGBA"> hex </palette>, or the old <colors count data="00rrggbb...">.
    void readPalette(Flame &f, std::array<bool, 256> &given)
    {
        const bool old = m_xml.name() == QLatin1String("colors");
        const auto attributes = m_xml.attributes();
        int width = old ? 8 : 6;
        if (!old && attributes.value(QLatin1String("format")) == QLatin1String("RGBA"))
            width = 8;
        if (!old && attributes.hasAttribute(QLatin1String("index0"))) {
            warn(here(), FlameFileTr::tr("a palette of flam3's palette file (index0) is not "
                                         "kept"));
            m_xml.skipCurrentElement();
            return;
        }
        QString hex = old ? attributes.value(QLatin1String("data")).toString() : QString();
        const QString text = m_xml.readElementText(QXmlStreamReader::SkipChildElements);
        if (!old)
            hex = text;
        hex.remove(QLatin1Char(' '))
            .remove(QLatin1Char('\n'))
            .remove(QLatin1Char('\r'))
            .remove(QLatin1Char('\t'));
        if (hex.size() % width != 0 || hex.size() / width > 256) {
            fail(FlameFileTr::tr("the palette's hex digits are not at most 256 colours of %1 "
                                 "digits")
                     .arg(width));
            return;
        }
        for (int i = 0; i * width < hex.size(); ++i) {
            bool ok = false;
            // RGB: rrggbb; RGBA: rrggbbaa; the old data: 00rrggbb.
            const int skip = old ? 2 : 0;
            const uint v = QStringView(hex).mid(i * width + skip, 6).toUInt(&ok, 16);
            if (!ok) {
                fail(FlameFileTr::tr("palette entry %1 is not hexadecimal").arg(i));
                return;
            }
            f.palette[std::size_t(i)] = {((v >> 16) & 255) / 255.0, ((v >> 8) & 255) / 255.0,
                                         (v & 255) / 255.0};
            given[std::size_t(i)] = true;
        }
    }

    // flam3's flam3_interp_missing_colors: entries not given are linear between the given
    // ones around them (wrapping around the ends); no entry given: black, as flam3's.
    static void fillPalette(Flame &f, const std::array<bool, 256> &given)
    {
        int first = -1, last = -1;
        for (int i = 0; i < 256; ++i)
            if (given[std::size_t(i)]) {
                if (first < 0)
                    first = i;
                last = i;
            }
        if (first < 0)
            return;
        for (int i = 0; i < 256;) {
            if (given[std::size_t(i)]) {
                ++i;
                continue;
            }
            const int start = i;
            while (i < 256 && !given[std::size_t(i)])
                ++i;
            int left = start - 1, right = i;
            int leftColour = left, rightColour = right;
            if (left == -1) {
                left = last - 256;
                leftColour = last;
            }
            if (right == 256) {
                right = first + 256;
                rightColour = first;
            }
            const flame::FlameColour a = f.palette[std::size_t(leftColour)];
            const flame::FlameColour b = f.palette[std::size_t(rightColour)];
            for (int j = start; j < i; ++j) {
                const double t = (j - left) / double(right - left);
                f.palette[std::size_t(j)] = {a.r * (1 - t) + b.r * t, a.g * (1 - t) + b.g * t,
                                             a.b * (1 - t) + b.b * t};
            }
        }
    }

    // flam3_add_symmetry: kind < 0 adds the reflection x |-> -x first; |kind| >= 2 the
    // rotations by 2 pi j / |kind|, j = 1 .. |kind| - 1 (cosines and sines rounded to 6
    // decimals as flam3 does), each weight 1, colour speed 0, not animated.
    void readSymmetry(Flame &f, int &symmetry)
    {
        const auto kind = readWhole(m_xml.attributes().value(QLatin1String("kind")),
                                    -flame::kMaxXforms, flame::kMaxXforms);
        if (!kind) {
            fail(FlameFileTr::tr("<symmetry> needs kind=\"k\", a whole number from %1 to %2, "
                                 "got '%3'")
                     .arg(-flame::kMaxXforms)
                     .arg(flame::kMaxXforms)
                     .arg(m_xml.attributes().value(QLatin1String("kind")).left(40)));
            return;
        }
        int k = int(*kind);
        symmetry = k;
        if (k == 0 || k == 1)
            return;
        const std::size_t added = std::size_t(std::abs(k)) - (k > 0 ? 1 : 0);
        if (f.xforms.size() + added > std::size_t(flame::kMaxXforms)) {
            fail(FlameFileTr::tr("<symmetry kind=\"%1\"> makes more than %2 xforms")
                     .arg(k)
                     .arg(flame::kMaxXforms));
            return;
        }
        auto add = [&](double c00, double c01, double colour) {
            FlameXform x;
            // flam3's c[0] = (cos, sin), c[1] = (-sin, cos): x' = cos x - sin y.
            x.pre = affineOf({c00, c01, -c01, c00, 0, 0});
            x.weight = 1;
            x.colour = colour;
            x.colourSpeed = 0;
            x.animate = 0;
            f.xforms.push_back(std::move(x));
        };
        const std::size_t begin = f.xforms.size();
        if (k < 0) {
            add(-1, 0, 1);
            f.xforms.back().pre = affineOf({-1, 0, 0, 1, 0, 0});
            k = -k;
        }
        auto round6 = [](double v) {
            v *= 1e6;
            if (v < 0)
                v -= 1.0;
            return 1e-6 * double(int(v + 0.5));
        };
        const double a = 2 * M_PI / k;
        for (int j = 1; j < k; ++j)
            add(round6(std::cos(j * a)), round6(std::sin(j * a)),
                k < 3 ? 0.0 : (j - 1.0) / (k - 2.0));
        // flam3 sorts the added xforms by determinant (compare_xforms; its qsort is not stable,
        // and only xaos rows could tell the order).
        std::stable_sort(f.xforms.begin() + std::ptrdiff_t(begin), f.xforms.end(),
                         [](const FlameXform &l, const FlameXform &r) {
                             return l.pre.determinant() < r.pre.determinant();
                         });
    }

    QXmlStreamReader m_xml;
    QString m_file;
    QString m_flame;
    QString m_problem;
    std::optional<int> m_paletteNumber;  // the <flame>'s palette="N", and its hue
    double m_hue = 0;
    std::optional<Flam3Palettes> m_palettes;  // read at the first palette="N"
    QStringList m_warnings;
    FlameFileRead m_out;
};

// ---- writing ----------------------------------------------------------------------------------

QByteArray num(double v) { return QByteArray::fromStdString(shortestNumber(v)); }

QByteArray affineText(const Affine2 &m)
{
    return num(m.a) + ' ' + num(m.d) + ' ' + num(m.b) + ' ' + num(m.e) + ' ' + num(m.c) + ' '
           + num(m.f);
}

QByteArray escaped(const std::string &s)
{
    return QString::fromStdString(s).toHtmlEscaped().toUtf8();
}

void writeXform(QByteArray &out, const FlameXform &x, bool isFinal, std::size_t xforms)
{
    out += isFinal ? "   <finalxform" : "   <xform weight=\"" + num(x.weight) + '"';
    if (!x.name.empty())
        out += " name=\"" + escaped(x.name) + '"';
    out += " color=\"" + num(x.colour) + "\" color_speed=\"" + num(x.colourSpeed) + '"';
    if (!isFinal)
        out += " animate=\"" + num(x.animate) + '"';
    if (x.opacity != 1)
        out += " opacity=\"" + num(x.opacity) + '"';
    for (const flame::VariationTerm &v : x.variations)
        out += ' ' + QByteArray(flame::variationName(v.id).data(),
                                qsizetype(flame::variationName(v.id).size()))
               + "=\"" + num(v.weight) + '"';
    // The parameters of the variations it uses (flam3 writes those only).
    for (const flame::VariationTerm &v : x.variations)
        for (int p : flame::variationParameters(v.id)) {
            const std::string_view name = flame::parameterName(p);
            out += ' ' + QByteArray(name.data(), qsizetype(name.size())) + "=\""
                   + num(x.parameters[std::size_t(p)]) + '"';
        }
    out += " coefs=\"" + affineText(x.pre) + '"';
    if (!x.post.isIdentity())
        out += " post=\"" + affineText(x.post) + '"';
    if (!isFinal) {
        bool xaos = false;
        for (std::size_t j = 0; j < xforms; ++j)
            xaos = xaos || x.xaosTo(j) != 1.0;
        if (xaos) {
            out += " chaos=\"";
            for (std::size_t j = 0; j < xforms; ++j)
                out += (j ? " " : "") + num(x.xaosTo(j));
            out += '"';
        }
    }
    out += "/>\n";
}

} // namespace

FlameFileRead readFlameText(const QByteArray &text, const QString &fileName)
{
    return Reader(text, fileName).read();
}

QByteArray flameElement(const Flame &f)
{
    QByteArray out = "<flame version=\"Attractor Workbench\"";
    if (!f.name.empty())
        out += " name=\"" + escaped(f.name) + '"';
    out += " size=\"" + QByteArray::number(f.width) + ' ' + QByteArray::number(f.height) + '"';
    out += " center=\"" + num(f.centre[0]) + ' ' + num(f.centre[1]) + '"';
    out += " scale=\"" + num(f.scale) + "\" rotate=\"" + num(f.rotate) + '"';
    if (f.zoom != 0)
        out += " zoom=\"" + num(f.zoom) + '"';
    out += " quality=\"" + num(f.quality) + "\" passes=\"" + QByteArray::number(f.passes)
           + "\" supersample=\"" + QByteArray::number(f.supersample)
           + "\" filter=\"" + num(f.filter) + "\" filter_shape=\""
           + QByteArray::fromStdString(std::string(flame::filterShapeName(f.filterShape)))
           + "\" palette_mode=\""
           + (f.paletteMode == flame::PaletteMode::Linear ? "linear" : "step") + '"';
    out += " background=\"" + num(f.background.r) + ' ' + num(f.background.g) + ' '
           + num(f.background.b) + '"';
    out += " brightness=\"" + num(f.brightness) + "\" gamma=\"" + num(f.gamma)
           + "\" gamma_threshold=\"" + num(f.gammaThreshold) + "\" vibrancy=\"" + num(f.vibrancy)
           + "\" highlight_power=\"" + num(f.highlightPower) + '"';
    out += " estimator_radius=\"" + num(f.estimatorRadius) + "\" estimator_minimum=\""
           + num(f.estimatorMinimum) + "\" estimator_curve=\"" + num(f.estimatorCurve) + '"';
    out += ">\n";
    for (const FlameXform &x : f.xforms)
        writeXform(out, x, false, f.xforms.size());
    if (f.finalXform)
        writeXform(out, *f.finalXform, true, f.xforms.size());
    for (std::size_t i = 0; i < 256; ++i) {
        const flame::FlameColour &c = f.palette[i];
        out += "   <color index=\"" + QByteArray::number(qulonglong(i)) + "\" rgb=\""
               + num(c.r * 255.0) + ' ' + num(c.g * 255.0) + ' ' + num(c.b * 255.0) + "\"/>\n";
    }
    out += "</flame>\n";
    return out;
}

QByteArray flameFileText(const std::vector<Flame> &flames)
{
    QByteArray out = "<flames name=\"Attractor Workbench\">\n";
    for (const Flame &f : flames)
        out += flameElement(f);
    out += "</flames>\n";
    return out;
}

} // namespace awb
