#pragma once
// Document item "complex-bezier" (layer 2, model): a Bézier curve split at a complex parameter t
// (004 §3.7). The control points are complex numbers x + iy; the core's complexBezierIfs()
// gives the realified lifted IFS, whose attractor is the fractal "complex Bézier curve" when t
// is hyperbolic (|t| < 1 and |1 - t| < 1).

#include "model/AttractorItem.h"

#include <complex>

namespace awb {

// The derived IFS of the complex Bézier curve with control points P (rows (x, y) = x + iy) split
// at t, by the core's complexBezierIfs() (004 §3.7): complex S_i = L(t), R(t), the complex
// lifted M_i and A_i, the realified maps, plane points placed as the first complex coordinate.
// Shared by this item and a subdivision curve with a complex Bézier parameter. Throws
// InputError (non-finite or coinciding points).
DerivedIfs complexBezierDerivedIfs(const Mat &P, std::complex<double> t);

class ComplexBezierItem : public AttractorItem {
    Q_OBJECT
public:
    ComplexBezierItem();

    static QString staticType() { return QStringLiteral("complex-bezier"); }
    static QString staticTypeName() { return tr("Complex Bézier curve"); }
    QString type() const override { return staticType(); }
    QString typeName() const override { return staticTypeName(); }

    std::complex<double> t() const { return m_t; }
    // Refused only when not finite: a t outside the discs is stored, and derivedError() says
    // why there is no attractor (the user may be dragging t across the boundary).
    MaybeProblem checkT(const std::complex<double> &t) const;
    bool setT(std::complex<double> t, int gesture = 0);

    // 004 eq. (3.40): drawn in the scaled coordinates g(z, 1/(2y)) = Re z + i Im z / (2y) of
    // Thm 3.7.3 and Figs. 3.6-3.8, where the curves of t = 1/2 + iy approach the Takagi graph.
    // Applies when Re t = 1/2, y != 0 and the control points lie on the real axis (they are
    // then drawn as they are); otherwise the note says why the picture is not scaled.
    bool scaled() const { return m_scaled; }
    bool scaledApplies() const;
    bool setScaled(bool scaled);
    MaybeProblem checkScaled(const bool &) const { return std::nullopt; }

    // Declared: "t" (complex), "scaled", "control_points".
    static const PropertyTable &declaration();
    const PropertyTable &properties() const override { return declaration(); }

    int mapCount() const override { return 2; }
    int controlPointSetCount() const override { return 1; }

signals:
    void tChanged();
    void scaledChanged();

protected:
    DerivedIfs computeIfs() const override;
    PointList &pointStorage(int) override { return m_points; }

private:
    std::complex<double> m_t{0.5, 0.5};
    bool m_scaled = false;
    PointList m_points;
};

} // namespace awb
