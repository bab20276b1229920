#include "model/ItemAddress.h"

#include "model/AttractorItem.h"
#include "model/SubdivisionCurveItem.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace awb {

namespace {

// lupdate takes the context of ItemAddressTr::tr() from the macro (a free tr() would get the
// enclosing namespace as its context).
struct ItemAddressTr {
    Q_DECLARE_TR_FUNCTIONS(awb::ItemAddress)
};

} // namespace

std::vector<ParameterInterval> parameterPieces(const AttractorItem &item)
{
    const auto *curve = qobject_cast<const SubdivisionCurveItem *>(&item);
    if (!curve || curve->scheme().isComplex())
        return {};
    const SchemeSpec &s = curve->scheme();
    if (s.kind == SchemeSpec::Kind::Bezier)
        return {{0.0, s.t.real()}, {s.t.real(), 1.0}};
    return uniformPieces(s.arity());
}

QString parameterMeaning(const AttractorItem &item)
{
    const auto *curve = qobject_cast<const SubdivisionCurveItem *>(&item);
    if (!curve || curve->scheme().isComplex())
        return {};
    switch (curve->scheme().kind) {
    case SchemeSpec::Kind::BSpline:
    case SchemeSpec::Kind::Chaikin:
        return ItemAddressTr::tr("t: the B-spline's knot parameter scaled to [0, 1] (the address in base 2)");
    case SchemeSpec::Kind::EndInterpolatingBSpline:
        return ItemAddressTr::tr("t: the knot parameter scaled to [0, 1] (the address in base 2)");
    case SchemeSpec::Kind::Bezier:
        return curve->scheme().t.real() == 0.5
                   ? ItemAddressTr::tr("t: the Bernstein parameter (the address in base 2)")
                   : ItemAddressTr::tr("t: the Bernstein parameter (pieces [0, t], [t, 1] of the split)");
    default:
        return ItemAddressTr::tr("t: the scheme's own parameter, the address read in base %1")
            .arg(curve->scheme().arity());
    }
}

Address parseItemAddress(const QString &text, const DerivedIfs &d)
{
    if (d.iterate && !d.iterateDrawsIfs)
        throw InputError(ItemAddressTr::tr("this item is drawn by an automaton: its words are not addresses "
                            "of one IFS").toStdString());
    return parseAddress(text.toStdString(), d.ifs.size());
}

std::optional<Mat> addressControlPoints(const DerivedIfs &d, const Address &w)
{
    if (!d.subdivision || (d.iterate && !d.iterateDrawsIfs) || d.S.real.empty())
        return std::nullopt;
    Address analysis;
    for (int symbol : w)
        analysis.push_back(d.analysisIndex(symbol));
    const Mat &P = d.subdivision->controlPoints;
    const Mat S = addressMatrix(d.S.real, analysis);
    if (S.cols() != P.rows())
        return std::nullopt;
    return Mat(S * P);
}

std::optional<ParameterInterval> parseParameterInterval(const QString &text)
{
    static const QRegularExpression form(
        QStringLiteral("^\\s*\\[\\s*([^,\\]]+)\\s*,\\s*([^,\\]]+)\\s*\\]\\s*$"));
    const auto match = form.match(text);
    if (!match.hasMatch())
        return std::nullopt;
    bool ok0 = false, ok1 = false;
    const double t0 = match.captured(1).trimmed().toDouble(&ok0);
    const double t1 = match.captured(2).trimmed().toDouble(&ok1);
    if (!ok0 || !ok1)
        throw InputError(ItemAddressTr::tr("a parameter interval is [t0, t1] with two numbers, e.g. "
                            "[0.25, 0.5]").toStdString());
    if (!(t0 >= 0.0 && t0 < t1 && t1 <= 1.0))
        throw InputError(ItemAddressTr::tr("the parameter interval [%1, %2] must satisfy 0 <= t0 < t1 <= 1")
                             .arg(t0)
                             .arg(t1)
                             .toStdString());
    return ParameterInterval{t0, t1};
}

} // namespace awb
