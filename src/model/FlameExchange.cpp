#include "model/FlameExchange.h"

#include "core/Messages.h"
#include "core/analysis/Spectrum.h"
#include "core/ifs/Attractor.h"
#include "model/AttractorItem.h"
#include "model/Item.h"
#include "model/ProjectIO.h"

#include <QColor>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QXmlStreamReader>

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

namespace awb {

namespace {

struct FlameTr {
    Q_DECLARE_TR_FUNCTIONS(awb::FlameExchange)
};

// flam3 3.1.1's variations (variations.c, flam3_variation_names), in its order: the index of
// the old `var` and `var1` attributes.
const QStringList &variationNames()
{
    static const QStringList names = QStringLiteral(
        "linear sinusoidal spherical swirl horseshoe polar handkerchief heart disc spiral "
        "hyperbolic diamond ex julia bent waves fisheye popcorn exponential power cosine rings "
        "fan blob pdj fan2 rings2 eyefish bubble cylinder perspective noise julian juliascope "
        "blur gaussian_blur radial_blur pie ngon curl rectangles arch tangent square rays "
        "blade secant2 twintrian cross disc2 super_shape flower conic parabola bent2 bipolar "
        "boarders butterfly cell cpow curve edisc elliptic escher foci lazysusan loonie "
        "pre_blur modulus oscilloscope polar2 popcorn2 scry separation split splits stripes "
        "wedge wedge_julia wedge_sph whorl waves2 exp log sin cos tan sec csc cot sinh cosh "
        "tanh sech csch coth auger flux mobius").split(QLatin1Char(' '));
    return names;
}

// Attributes of an xform that do not change its map: colour, animation, the plot switch.
bool drawingAttribute(QStringView name)
{
    static const QStringList names{"color",  "color_speed", "symmetry",         "animate",
                                   "name",   "var_color",   "motion_frequency", "motion_function",
                                   "opacity", "plotmode"};
    return names.contains(name);
}

// Exactly `n` finite numbers separated by whitespace.
bool readNumbers(QStringView text, int n, double *out)
{
    const auto parts = text.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    if (parts.size() != n)
        return false;
    for (int i = 0; i < n; ++i) {
        bool ok = false;
        out[i] = parts[i].trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(out[i]))
            return false;
    }
    return true;
}

// Row convention (Ifs.h: x |-> x A + b) of flam3's c[3][2]: rows x, y, 1.
AffineMap affineOf(const double c[6])
{
    AffineMap f;
    f.A.resize(2, 2);
    f.A << c[0], c[1], c[2], c[3];
    f.b.resize(2);
    f.b << c[4], c[5];
    return f;
}

// g = R f R with R = diag(1, -1): the map in the other orientation of y.
AffineMap mirrored(const AffineMap &f)
{
    AffineMap g = f;
    g.A(0, 1) = -f.A(0, 1);
    g.A(1, 0) = -f.A(1, 0);
    g.b(1) = -f.b(1);
    return g;
}

// post(w pre(x)) in the row convention.
AffineMap composed(const AffineMap &pre, double w, const AffineMap &post)
{
    AffineMap f;
    f.A = w * pre.A * post.A;
    f.b = w * pre.b * post.A + post.b;
    return f;
}

struct Xform {
    AffineMap map;  // in the flame's orientation
    double weight = 0;
    double colour = 0;
    std::vector<double> chaos;
    qint64 line = 0, column = 0;
};

class FlameReader {
public:
    FlameReader(const QByteArray &text, const QString &fileName)
        : m_xml(text), m_file(QFileInfo(fileName).fileName())
    {}

    ImportedItems read()
    {
        int index = 0;
        while (!m_xml.atEnd()) {
            m_xml.readNext();
            if (m_xml.isStartElement() && m_xml.name() == QLatin1String("flame"))
                readFlame(++index);
        }
        if (m_xml.hasError())
            m_out.problems << place(m_xml.lineNumber(), m_xml.columnNumber())
                                  + FlameTr::tr("the XML is malformed: %1")
                                        .arg(m_xml.errorString());
        else if (index == 0)
            m_out.problems << FlameTr::tr("%1: the file holds no <flame> element").arg(m_file);
        return std::move(m_out);
    }

private:
    QString place(qint64 line, qint64 column) const
    {
        return FlameTr::tr("%1, line %2, column %3: ").arg(m_file).arg(line).arg(column);
    }
    QString here() const { return place(m_xml.lineNumber(), m_xml.columnNumber()); }

    // Reads one <flame> to its end; a malformed part leaves the whole flame out.
    void readFlame(int index)
    {
        const qint64 line = m_xml.lineNumber(), column = m_xml.columnNumber();
        QString name = m_xml.attributes().value(QLatin1String("name")).toString().trimmed();
        if (name.isEmpty())
            name = FlameTr::tr("flame %1").arg(index);
        m_flame = name;
        std::vector<Xform> xforms;
        std::optional<Xform> final;
        std::map<int, QColor> palette;
        QString problem;
        QStringList warnings;
        int written = 0;  // the <xform> elements so far (symmetry adds others)
        while (m_xml.readNextStartElement()) {
            const QStringView tag = m_xml.name();
            if (tag == QLatin1String("xform") || tag == QLatin1String("finalxform")) {
                const bool isFinal = tag == QLatin1String("finalxform");
                Xform x;
                const QString where =
                    isFinal ? FlameTr::tr("flame '%1', final xform").arg(name)
                            : FlameTr::tr("flame '%1', xform %2").arg(name).arg(++written);
                if (!readXform(x, where, isFinal, &problem, &warnings))
                    break;
                if (isFinal)
                    final = x;
                else
                    xforms.push_back(x);
                if (int(xforms.size()) > kMaxMaps) {
                    problem = here()
                              + FlameTr::tr("flame '%1': more than %2 xforms (at most %2 maps "
                                            "are supported)")
                                    .arg(name)
                                    .arg(kMaxMaps);
                    break;
                }
            } else if (tag == QLatin1String("color")) {
                if (!readColour(palette, &problem))
                    break;
                m_xml.skipCurrentElement();
            } else if (tag == QLatin1String("palette") || tag == QLatin1String("colors")) {
                if (!readPalette(palette, &problem))
                    break;
            } else if (tag == QLatin1String("symmetry")) {
                // flam3's parser adds the symmetry's xforms (flam3_add_symmetry), also to a
                // file flam3 wrote, which lists them already: its measure, twice the weight.
                bool ok = false;
                const int kind = m_xml.attributes().value(QLatin1String("kind")).toInt(&ok);
                // Range-checked before anything is added: at most |kind| xforms more, within
                // the engine's limit of maps.
                if (!ok || kind < -kMaxMaps || kind > kMaxMaps
                    || int(xforms.size()) + std::abs(kind) > kMaxMaps) {
                    problem = here()
                              + FlameTr::tr("flame '%1': <symmetry> needs kind=\"k\", a whole "
                                            "number from %2 to %3, got '%4'")
                                    .arg(name)
                                    .arg(-kMaxMaps)
                                    .arg(kMaxMaps)
                                    .arg(m_xml.attributes().value(QLatin1String("kind")));
                    break;
                }
                addSymmetry(xforms, kind, m_xml.lineNumber(), m_xml.columnNumber());
                m_xml.skipCurrentElement();
            } else if (tag == QLatin1String("edit")) {
                m_xml.skipCurrentElement();  // the genome's history: no geometry
            } else {
                warnings << here()
                                + FlameTr::tr("flame '%1': element <%2> ignored")
                                      .arg(name, tag.toString());
                m_xml.skipCurrentElement();
            }
        }
        if (m_xml.hasError())
            return;  // read() names it
        if (problem.isEmpty() && xforms.empty())
            problem = place(line, column) + FlameTr::tr("flame '%1' has no xform").arg(name);
        if (!problem.isEmpty()) {
            m_out.problems << problem;
            // The rest of the flame is skipped: its end tag closes it.
            while (!m_xml.atEnd()
                   && !(m_xml.isEndElement() && m_xml.name() == QLatin1String("flame")))
                m_xml.readNext();
            return;
        }
        buildItem(name, xforms, final, palette, warnings, line, column);
    }

    // flam3 3.1.1's flam3_add_symmetry: kind < 0 adds the reflection x |-> -x first; |kind|
    // >= 2 the rotations by 2 pi j / |kind|, j = 1 .. |kind| - 1 (cosines and sines rounded
    // to 6 decimals as flam3 does), each with weight 1.
    static void addSymmetry(std::vector<Xform> &xforms, int kind, qint64 line, qint64 column)
    {
        auto add = [&](double c00, double c01, double colour) {
            Xform x;
            const double c[6] = {c00, c01, -c01, c00, 0, 0};
            x.map = affineOf(c);
            x.weight = 1;
            x.colour = colour;
            x.line = line;
            x.column = column;
            xforms.push_back(x);
        };
        if (kind == 0 || kind == 1)
            return;
        if (kind < 0) {
            Xform x;
            const double c[6] = {-1, 0, 0, 1, 0, 0};
            x.map = affineOf(c);
            x.weight = 1;
            x.colour = 1;
            x.line = line;
            x.column = column;
            xforms.push_back(x);
            kind = -kind;
        }
        auto round6 = [](double v) {
            v *= 1e6;
            if (v < 0)
                v -= 1.0;
            return 1e-6 * double(int(v + 0.5));
        };
        const double a = 2 * M_PI / kind;
        for (int j = 1; j < kind; ++j)
            add(round6(std::cos(j * a)), round6(std::sin(j * a)),
                kind < 3 ? 0.0 : (j - 1.0) / (kind - 2.0));
    }

    bool readXform(Xform &x, const QString &where, bool isFinal, QString *problem,
                   QStringList *warnings)
    {
        x.line = m_xml.lineNumber();
        x.column = m_xml.columnNumber();
        const QString at = here();
        double pre[6] = {1, 0, 0, 1, 0, 0}, post[6] = {1, 0, 0, 1, 0, 0};
        double linear = 0;
        bool anyVariation = false;
        QStringList dropped;
        std::vector<double> variations;  // the `var` attribute's list
        // flam3 gives an xform without a weight the weight 0 (initialize_xforms): it is never
        // chosen. So do we, and say so.
        x.weight = 0;
        bool weighted = false;
        for (const QXmlStreamAttribute &a : m_xml.attributes()) {
            const QStringView key = a.name();
            const QString value = a.value().toString().simplified();
            auto fail = [&](const QString &why) {
                *problem = at + where + QStringLiteral(": ") + why;
                return false;
            };
            if (key == QLatin1String("coefs") || key == QLatin1String("post")) {
                if (!readNumbers(value, 6, key == QLatin1String("coefs") ? pre : post))
                    return fail(FlameTr::tr("%1=\"%2\" must be 6 finite numbers")
                                    .arg(key.toString(), value));
            } else if (key == QLatin1String("weight")) {
                weighted = true;
                bool ok = false;
                x.weight = value.toDouble(&ok);
                if (!ok || !std::isfinite(x.weight) || x.weight < 0)
                    return fail(FlameTr::tr("weight=\"%1\" must be a finite number >= 0")
                                    .arg(value));
            } else if (key == QLatin1String("color")) {
                x.colour = value.section(QLatin1Char(' '), 0, 0).toDouble();
            } else if (key == QLatin1String("chaos")) {
                for (const QString &v : value.split(QLatin1Char(' '), Qt::SkipEmptyParts))
                    x.chaos.push_back(v.toDouble());
            } else if (key == QLatin1String("var1")) {
                const int j = value.toInt();
                variations.assign(std::size_t(variationNames().size()), 0.0);
                if (j < 0 || j >= variationNames().size())
                    return fail(FlameTr::tr("var1=\"%1\" names no variation").arg(value));
                variations[std::size_t(j)] = 1;
            } else if (key == QLatin1String("var")) {
                variations.clear();
                for (const QString &v : value.split(QLatin1Char(' '), Qt::SkipEmptyParts))
                    variations.push_back(v.toDouble());
            } else if (variationNames().contains(key)) {
                bool ok = false;
                const double w = value.toDouble(&ok);
                if (!ok || !std::isfinite(w))
                    return fail(FlameTr::tr("variation %1=\"%2\" is not a number")
                                    .arg(key.toString(), value));
                anyVariation = true;
                if (key == QLatin1String("linear"))
                    linear += w;
                else if (w != 0)
                    dropped << QStringLiteral("%1 (%2)").arg(key.toString(), value);
            } else if (drawingAttribute(key)) {
                if (key == QLatin1String("opacity") && value.toDouble() != 1.0)
                    *warnings << at + where
                                     + FlameTr::tr(": opacity %1 not kept (every map is drawn)")
                                           .arg(value);
            } else {
                // A variation's parameter (blob_low, julian_power, ...): part of a dropped
                // variation, or of none; anything else is named.
                const int cut = int(key.indexOf(QLatin1Char('_')));
                bool parameter = false;
                for (int k = cut; k > 0 && !parameter;
                     k = int(key.left(k).lastIndexOf(QLatin1Char('_'))))
                    parameter = variationNames().contains(key.left(k));
                if (!parameter)
                    *warnings << at + where
                                     + FlameTr::tr(": attribute %1=\"%2\" ignored")
                                           .arg(key.toString(), value);
            }
        }
        for (std::size_t j = 0; j < variations.size() && j < std::size_t(variationNames().size());
             ++j) {
            anyVariation = anyVariation || variations[j] != 0;
            if (j == 0)
                linear += variations[j];
            else if (variations[j] != 0)
                dropped << QStringLiteral("%1 (%2)")
                               .arg(variationNames()[int(j)])
                               .arg(variations[j]);
        }
        if (!weighted && !isFinal)
            *warnings << at + where
                             + FlameTr::tr(": no weight given; taken as 0, as flam3 does (the "
                                           "map is never chosen)");
        if (!dropped.isEmpty())
            *warnings << at + where
                             + FlameTr::tr(": variation %1 dropped (non-linear)", nullptr,
                                           int(dropped.size()))
                                   .arg(dropped.join(QStringLiteral(", ")))
                             + (linear == 0 ? FlameTr::tr("; its affine part kept as a linear map")
                                            : QString());
        else if (!anyVariation)
            *warnings << at + where + FlameTr::tr(": no variation given; taken as linear");
        if (linear == 0)
            linear = 1;
        x.map = composed(affineOf(pre), linear, affineOf(post));
        // Child elements (<motion>: an animation's change of the xform) are not kept.
        while (m_xml.readNextStartElement()) {
            *warnings << here()
                             + FlameTr::tr("%1: element <%2> ignored (animation)")
                                   .arg(where, m_xml.name().toString());
            m_xml.skipCurrentElement();
        }
        return true;
    }

    bool readColour(std::map<int, QColor> &palette, QString *problem)
    {
        const QString at = here();
        const auto attributes = m_xml.attributes();
        bool ok = false;
        const int index = attributes.value(QLatin1String("index")).toInt(&ok);
        double rgb[3];
        if (!ok || index < 0 || index > 255
            || !readNumbers(attributes.value(QLatin1String("rgb")).toString().simplified(), 3,
                            rgb)) {
            *problem = at + FlameTr::tr("flame '%1': a <color> needs index=\"0..255\" and "
                                        "rgb=\"r g b\"")
                                .arg(m_flame);
            return false;
        }
        palette[index] = QColor(std::clamp(int(std::lround(rgb[0])), 0, 255),
                                std::clamp(int(std::lround(rgb[1])), 0, 255),
                                std::clamp(int(std::lround(rgb[2])), 0, 255));
        return true;
    }

    // <palette count="256" format="RGB"> hex </palette>, or the old <colors count
    // data="00rrggbb...">.
    bool readPalette(std::map<int, QColor> &palette, QString *problem)
    {
        const QString at = here();
        const bool old = m_xml.name() == QLatin1String("colors");
        QString hex = old ? m_xml.attributes().value(QLatin1String("data")).toString() : QString();
        const QString text = m_xml.readElementText(QXmlStreamReader::SkipChildElements);
        if (!old)
            hex = text;
        hex.remove(QRegularExpression(QStringLiteral("\\s")));
        const int width = old ? 8 : 6;
        if (hex.size() % width != 0) {
            *problem = at + FlameTr::tr("flame '%1': the palette's hex digits are not whole "
                                        "colours of %2 digits")
                                .arg(m_flame)
                                .arg(width);
            return false;
        }
        for (int i = 0; i * width < hex.size() && i < 256; ++i) {
            bool ok = false;
            const uint v = hex.mid(i * width + width - 6, 6).toUInt(&ok, 16);
            if (!ok) {
                *problem = at + FlameTr::tr("flame '%1': palette entry %2 is not hexadecimal")
                                    .arg(m_flame)
                                    .arg(i);
                return false;
            }
            palette[i] = QColor::fromRgb(QRgb(v));
        }
        return true;
    }

    void buildItem(const QString &name, const std::vector<Xform> &xforms,
                   const std::optional<Xform> &final, const std::map<int, QColor> &palette,
                   QStringList warnings, qint64 line, qint64 column)
    {
        FractintEntry e;
        e.name = name.toStdString();
        e.dimension = 2;
        e.line = int(line);
        // The final xform F is drawn on every point: the picture is F(A), the attractor of
        // the conjugates F f_i F^-1 when F is invertible.
        std::optional<AffineMap> F, Finv;
        if (final) {
            const double det = final->map.A.determinant();
            if (std::abs(det) > 1e-12 * std::max(1.0, final->map.A.squaredNorm())) {
                F = final->map;
                Finv = AffineMap{};
                Finv->A = F->A.inverse();
                Finv->b = -F->b * Finv->A;
            } else {
                warnings << place(final->line, final->column)
                                + FlameTr::tr("flame '%1': the final xform is not invertible "
                                              "(determinant %2): dropped")
                                      .arg(name)
                                      .arg(det);
            }
        }
        bool forbids = false, reweights = false;
        QStringList colours;
        for (const Xform &x : xforms) {
            AffineMap f = x.map;
            if (F) {
                f.A = Finv->A * x.map.A * F->A;
                f.b = Finv->b * x.map.A * F->A + x.map.b * F->A + F->b;
            }
            e.maps.push_back(mirrored(f));
            e.probabilities.push_back(x.weight);
            for (std::size_t j = 0; j < x.chaos.size() && j < xforms.size(); ++j) {
                forbids = forbids || x.chaos[j] == 0;
                reweights = reweights || (x.chaos[j] != 0 && x.chaos[j] != 1);
            }
            if (!palette.empty()) {
                const int index = std::clamp(int(x.colour * 255.0 + 0.5), 0, 255);
                auto it = palette.lower_bound(index);
                if (it == palette.end())
                    it = std::prev(it);
                colours << it->second.name();
            }
        }
        if (forbids)
            warnings << place(line, column)
                            + FlameTr::tr("flame '%1': its xaos (chaos) rows forbid some "
                                          "transitions; imported as the plain IFS of its maps, "
                                          "whose attractor contains the flame's")
                                  .arg(name);
        else if (reweights)
            warnings << place(line, column)
                            + FlameTr::tr("flame '%1': its xaos (chaos) weights are dropped: "
                                          "the attractor is the same, its measure differs")
                                  .arg(name);
        double total = 0;
        for (double p : e.probabilities)
            total += p;
        if (!(total > 0)) {
            m_out.problems << place(line, column)
                                  + FlameTr::tr("flame '%1': every xform has weight 0").arg(name);
            return;
        }
        try {
            m_out.items.push_back(importedFractal(e, colours, 1000000));
        } catch (const LoadError &error) {
            m_out.problems << place(line, column)
                                  + FlameTr::tr("flame '%1': %2 (%3)")
                                        .arg(name, error.message, error.field);
            return;
        } catch (const std::exception &error) {
            m_out.problems << place(line, column)
                                  + FlameTr::tr("flame '%1': %2")
                                        .arg(name, QString::fromUtf8(error.what()));
            return;
        }
        // flam3 draws any genome, discarding the points that escape; an IFS that does not even
        // contract on average has no attractor, and the user hears it here, not at the render.
        if (const auto *item = dynamic_cast<const AttractorItem *>(m_out.items.back().get()))
            if (const auto d = item->derivedIfs(); d && d->ifs.size() > 0)
                if (const IfsCheck check = checkIfs(d->ifs); !check.contractsOnAverage())
                    warnings << place(line, column)
                                    + FlameTr::tr("flame '%1': its maps do not contract, not "
                                                  "even on average (the Lyapunov exponent of "
                                                  "their products, %2, is not clearly negative: "
                                                  "not below -0.001), so it may have no "
                                                  "attractor; flam3 draws it only by discarding "
                                                  "the points that escape")
                                          .arg(name)
                                          .arg(check.lyapunov ? *check.lyapunov : qQNaN(), 0,
                                               'g', 3);
        m_out.warnings << warnings;
    }

    QXmlStreamReader m_xml;
    QString m_file;
    QString m_flame;
    ImportedItems m_out;
};

// The shortest text that reads back as exactly v: round trips keep every map.
QString number(double v)
{
    return QString::fromStdString(shortestNumber(v));
}

} // namespace

ImportedItems importFlameText(const QByteArray &text, const QString &fileName)
{
    return FlameReader(text, fileName).read();
}

ImportedItems importFlame(const QString &fileName)
{
    return importFlameText(readExchangeFile(fileName), fileName);
}

std::optional<FractintEntry> flameEntryOf(const AttractorItem &item, QString *why)
{
    auto entry = fractintEntryOf(item, why, FlameTr::tr("a flam3 flame"));
    if (entry && entry->dimension != 2) {
        if (why)
            *why = FlameTr::tr("%1 is an IFS of space: a flam3 flame holds maps of the plane "
                               "(export it as a Fractint .ifs entry)")
                       .arg(item.name());
        return std::nullopt;
    }
    return entry;
}

std::optional<QByteArray> flameOf(const AttractorItem &item, const QStringList &mapColours,
                                  const FlameFrame &frame, QString *why)
{
    const auto entry = flameEntryOf(item, why);
    if (!entry)
        return std::nullopt;
    const QRectF w = frame.world.normalized();
    if (!(w.width() > 0) || frame.size.isEmpty() || !std::isfinite(w.width())) {
        if (why)
            *why = FlameTr::tr("the flame's frame is empty");
        return std::nullopt;
    }
    const int n = int(entry->maps.size());
    // Map i takes palette entry c_i = 255 i / (n - 1); the palette holds each map's colour
    // from its entry to the next one's.
    std::vector<int> entryOf(std::size_t(n), 0);
    for (int i = 0; i < n; ++i)
        entryOf[std::size_t(i)] = n > 1 ? int(std::lround(255.0 * i / (n - 1))) : 0;
    QByteArray out;
    out += "<flames name=\"Attractor Workbench\">\n";
    const double scale = frame.size.width() / w.width();
    out += QStringLiteral("<flame name=\"%1\" version=\"Attractor Workbench\" size=\"%2 %3\" "
                          "center=\"%4 %5\" scale=\"%6\" rotate=\"0\" quality=\"50\" "
                          "supersample=\"1\" filter=\"0.5\" filter_shape=\"gaussian\" "
                          "oversample=\"1\" background=\"0 0 0\" brightness=\"4\" gamma=\"4\" "
                          "vibrancy=\"1\" estimator_radius=\"0\" palette_mode=\"step\">\n")
               .arg(item.name().toHtmlEscaped())
               .arg(frame.size.width())
               .arg(frame.size.height())
               .arg(number(w.center().x()), number(-w.center().y()), number(scale))
               .toUtf8();
    for (int i = 0; i < n; ++i) {
        const AffineMap f = mirrored(entry->maps[std::size_t(i)]);
        out += QStringLiteral("   <xform weight=\"%1\" color=\"%2\" color_speed=\"0.5\" "
                              "linear=\"1\" coefs=\"%3 %4 %5 %6 %7 %8\" opacity=\"1\"/>\n")
                   .arg(number(entry->probabilities[std::size_t(i)]),
                        number(entryOf[std::size_t(i)] / 255.0), number(f.A(0, 0)),
                        number(f.A(0, 1)), number(f.A(1, 0)), number(f.A(1, 1)), number(f.b(0)),
                        number(f.b(1)))
                   .toUtf8();
    }
    for (int k = 0, i = 0; k < 256; ++k) {
        while (i + 1 < n && k >= entryOf[std::size_t(i + 1)])
            ++i;
        QColor c(mapColours.value(i));
        if (!c.isValid())
            c = Qt::white;
        out += QStringLiteral("   <color index=\"%1\" rgb=\"%2 %3 %4\"/>\n")
                   .arg(k)
                   .arg(c.red())
                   .arg(c.green())
                   .arg(c.blue())
                   .toUtf8();
    }
    out += "</flame>\n</flames>\n";
    return out;
}

} // namespace awb
