#pragma once
// Document item "subdivision-curve" (layer 2, model): a stationary subdivision scheme with its
// parameters and the control points; its attractor is the limit curve (000 §2). The derived IFS
// comes from the core's buildSubdivisionIfs() (lifted M_i = P^-1 S_i P, or barycentric when P
// is singular). A Bézier scheme may have a complex parameter t (004 §3.7): the control points
// are then complex numbers x + iy and the IFS acts on complex coordinates.

#include "model/AttractorItem.h"

#include <complex>

namespace awb {

class CurveScheme;

// The scheme and all its parameters. Parameters of other kinds are kept (switching the kind
// back restores them) but only the current kind's are saved.
struct SchemeSpec {
    Q_DECLARE_TR_FUNCTIONS(awb::SchemeSpec)
public:
    enum class Kind {
        BSpline,
        EndInterpolatingBSpline,
        Chaikin,
        CornerCutting,
        FourPoint,
        Bezier,
        Matrices,
        Mask,
    };
    Kind kind = Kind::BSpline;
    int degree = 3;                       // bspline, bspline-end-interpolating, bezier
    std::complex<double> t{0.5, 0.0};     // bezier: de Casteljau split parameter
    double omega = 1.0 / 16.0;            // four-point tension
    double a = 0.25, b = 0.75;            // corner cutting
    std::vector<Mat> matrices;            // matrices: S_1..S_p, m x m, row-stochastic
    // mask: a_k for k = maskOffset .. maskOffset + size - 1, arity maskArity (core maskScheme).
    // maskText[i] is the entry as written when it is not a plain number ("3/8",
    // "(1 + sqrt(3))/8"): kept, so the file says what the user typed; empty otherwise.
    int maskArity = 2;
    int maskOffset = -2;
    std::vector<double> mask{0.125, 0.5, 0.75, 0.5, 0.125};
    QStringList maskText{"1/8", "1/2", "3/4", "1/2", "1/8"};

    bool operator==(const SchemeSpec &other) const;
    // The parameters the core refuses (degree out of range, t outside the lens |t| < 1,
    // |1 - t| < 1, a matrix of the wrong size or with a row not summing to 1, ...). The
    // field is the parameter's JSON key.
    MaybeProblem check() const;
    // Number of maps: 2, or the number of matrices.
    int arity() const;
    bool isComplex() const { return kind == Kind::Bezier && t.imag() != 0.0; }
    // The core scheme of a real kind. Throws InputError.
    std::unique_ptr<CurveScheme> makeScheme() const;
    // JSON spellings, in enum order.
    static const QStringList &kindNames();
    // The mask as one line of text, "1/8, 1/2, 3/4, 1/2, 1/8" (what the user typed where it
    // was not a plain number), and back: entries separated by commas, or by semicolons when
    // there is one (then a comma may be a decimal comma). False with `error` set when an
    // entry is no number.
    QString maskLine() const;
    bool setMaskLine(const QString &line, QString *error);
    // How many sum rules the mask satisfies and its symbol's factorisation, in one line.
    QString symbolText() const;
    // The mask of a uniform scheme (B-spline, Chaikin, corner cutting, four-point), as a mask
    // kind would hold it; false for Bézier and matrices.
    bool takeMaskOf(const SchemeSpec &other);
};

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

    // Parameters: "scheme.kind" always; "scheme.degree", "scheme.t", "scheme.omega",
    // "scheme.a", "scheme.b", "scheme.arity", "scheme.mask", "scheme.offset" (and the
    // read-only "scheme.symbol") while the kind uses them. Edits go through setScheme().
    // Switching to "mask" or "matrices" starts from the current scheme's mask or matrices.
    QList<ParameterInfo> parameters() const override;
    QVariant parameter(const QString &key) const override;
    bool setParameter(const QString &key, const QVariant &value, int gesture = 0,
                      QString *error = nullptr) override;

    int mapCount() const override { return m_scheme.arity(); }
    int controlPointSetCount() const override { return 1; }
    // The user's own m x m matrices S_i fix m (points can be added or removed only while
    // their number is not m yet); a Bézier curve takes degree + 1 points (the GUI raises the
    // degree with an inserted point).
    bool pointCountEditable(int) const override
    {
        return m_scheme.kind != SchemeSpec::Kind::Matrices || m_scheme.matrices.empty()
               || Eigen::Index(controlPoints(0).size()) != m_scheme.matrices.front().rows();
    }

    void write(QJsonObject &json) const override;
    void read(const FieldReader &fields) override;

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
