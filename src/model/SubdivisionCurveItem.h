#pragma once
// Document item "subdivision-curve" (layer 2, model): a stationary subdivision scheme with its
// parameters and the control points; its attractor is the limit curve (000 §2). The derived IFS
// comes from the core's buildSubdivisionIfs() (lifted M_i = P^-1 S_i P, or barycentric when P
// is singular). A Bézier scheme may have a complex parameter t (004 §3.7): the control points
// are then complex numbers x + iy and the IFS acts on complex coordinates.

#include "model/AttractorItem.h"
#include "model/SchemeSpec.h"

namespace awb {

class SubdivisionCurveItem : public AttractorItem {
    Q_OBJECT
public:
    SubdivisionCurveItem();

    static QString staticType() { return QStringLiteral("subdivision-curve"); }
    static QString staticTypeName() { return tr("Subdivision curve"); }
    QString type() const override { return staticType(); }
    QString typeName() const override { return staticTypeName(); }

    const SchemeSpec &scheme() const { return m_scheme; }
    // The scheme's own check, plus the depth bound with the new number of maps.
    MaybeProblem checkScheme(const SchemeSpec &scheme) const;
    // Undoable (kind, degree, t, omega, a, b, matrices: any of them); refused when
    // checkScheme() complains. A nonzero gesture merges the edits of one slider drag.
    bool setScheme(const SchemeSpec &scheme, int gesture = 0);

    // Declared: "scheme.kind" always; "scheme.degree", "scheme.t", "scheme.omega",
    // "scheme.a", "scheme.b", "scheme.matrices", "scheme.arity", "scheme.mask",
    // "scheme.offset" (and the read-only "scheme.symbol") while the kind uses them;
    // "control_points". Switching to "mask" or "matrices" starts from the current scheme's
    // mask or matrices.
    static const PropertyTable &declaration();
    const PropertyTable &properties() const override { return declaration(); }

    int mapCount() const override { return m_scheme.arity(); }
    int controlPointSetCount() const override { return 1; }
    bool startsAtNetPoints() const override { return true; }
    // The user's own m x m matrices S_i fix m (points can be added or removed only while
    // their number is not m yet); a Bézier curve takes degree + 1 points (the GUI raises the
    // degree with an inserted point).
    bool pointCountEditable(int) const override
    {
        return m_scheme.kind != SchemeSpec::Kind::Matrices || m_scheme.matrices.empty()
               || Eigen::Index(controlPoints(0).size()) != m_scheme.matrices.front().rows();
    }

signals:
    void schemeChanged();

protected:
    DerivedIfs computeIfs() const override;
    PointList &pointStorage(int) override { return m_points; }

private:
    // S_i of the current scheme for the current points (or the cubic B-spline's): where own
    // matrices start.
    std::vector<Mat> startingMatrices() const;

    SchemeSpec m_scheme;
    PointList m_points;
};

} // namespace awb
