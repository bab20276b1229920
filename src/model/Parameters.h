#pragma once
// The parameter view of an item's declared properties (layer 2, model; PropertyTable.h): every
// scalar property an item kind has (ω, t, u, j, r, a..p, degree, scheme kind, the style's point
// size, the algorithm's depth, ...) as the GUI's properties dock, the CLI and scripts list, read
// and edit it without knowing the kind. Structured inputs (control points, matrices, faces)
// are declared too, with their own editors, and set through their file form.

#include <QCoreApplication>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <QVariant>

#include <cmath>
#include <limits>

namespace awb {

struct ParameterInfo {
    enum class Type {
        Real,     // QVariant double
        Integer,  // QVariant int
        Choice,   // QVariant int: index into `choices`
        Complex,  // QVariant QPointF(re, im)
        Bool,     // QVariant bool
        Text,     // QVariant QString: a list typed as text (a mask "1/8, 1/2, 3/4, 1/2, 1/8")
    };
    QString key;     // stable, e.g. "scheme.omega", "curves.2.u", "j"
    QString label;   // translated, for the user
    Type type = Type::Real;
    // Values outside [minimum, maximum] are refused (Real, Integer).
    double minimum = -std::numeric_limits<double>::infinity();
    double maximum = std::numeric_limits<double>::infinity();
    // Where a slider makes sense: its range (NaN when a spin box is the right editor).
    double sliderMinimum = std::numeric_limits<double>::quiet_NaN();
    double sliderMaximum = std::numeric_limits<double>::quiet_NaN();
    QStringList choices;  // Choice: translated texts in index order
    QString group;        // heading in the properties dock ("Scheme", "Curve 2", ...)
    QString toolTip;      // what it means, with the paper reference
    bool readOnly = false;  // shown, never edited (a derived fact: the symbol's factorisation)
    bool animatable = true;  // numbers an animation may key (not a depth, a seed, a count)

    bool hasSlider() const { return !std::isnan(sliderMinimum) && !std::isnan(sliderMaximum); }

    // Fluent construction: ParameterInfo::make("j", tr("j"), Type::Real).range(0.5, 1)...
    static ParameterInfo make(const QString &key, const QString &label, Type type)
    {
        ParameterInfo p;
        p.key = key;
        p.label = label;
        p.type = type;
        return p;
    }
    ParameterInfo &range(double lo, double hi) { minimum = lo; maximum = hi; return *this; }
    ParameterInfo &slider(double lo, double hi) { sliderMinimum = lo; sliderMaximum = hi; return *this; }
    ParameterInfo &options(const QStringList &texts) { choices = texts; return *this; }
    ParameterInfo &in(const QString &heading) { group = heading; return *this; }
    ParameterInfo &tip(const QString &text) { toolTip = text; return *this; }
    ParameterInfo &shownOnly() { readOnly = true; return *this; }
};

} // namespace awb
