#pragma once
// Document item "bcifs-junction" (layer 2, model): the junction curve between a cubic and a
// quadratic B-spline built as a boundary controlled IFS (003 §3-§5). The "cubic-quadratic"
// variant has the free parameters a..n of 003 §4.1, the "refined" variant the eigenvalues j, r
// of 003 §5 with three handles at the interpolated vertex. The curve is drawn through the
// automaton (DerivedIfs::iterate); the junction matrices go to DerivedIfs::S so that an
// eigenvalue plot shows the paper's spectrum, and the spectral verdict goes to the note.

#include "core/ifs/Bcifs.h"
#include "model/AttractorItem.h"

#include <array>

namespace awb {

struct JunctionSpec {
    Q_DECLARE_TR_FUNCTIONS(awb::JunctionSpec)
public:
    enum class Variant { CubicQuadratic, Refined };
    Variant variant = Variant::CubicQuadratic;
    JunctionParameters free;    // cubic-quadratic: a, b, c, d, k, l, m, n (Fig. 16 defaults)
    RefinedParameters refined;  // refined: j, r

    bool operator==(const JunctionSpec &other) const;
    // Finite a..n; j in (0.5, 1) and r in (0.25, 1) (the core's computed ranges). The field
    // is the parameter's key.
    MaybeProblem check() const;
    static const QStringList &variantNames();
    // "a".."n" in the order of JunctionParameters.
    static const QStringList &freeKeys();
    double *freeSlot(int index);  // nullptr outside 0..7
    double freeValue(int index) const { return *const_cast<JunctionSpec *>(this)->freeSlot(index); }
};

class BcifsJunctionItem : public AttractorItem {
    Q_OBJECT
public:
    BcifsJunctionItem();

    static QString staticType() { return QStringLiteral("bcifs-junction"); }
    static QString staticTypeName() { return tr("BCIFS junction curve"); }
    QString type() const override { return staticType(); }
    QString typeName() const override { return staticTypeName(); }

    const JunctionSpec &spec() const { return m_spec; }
    MaybeProblem checkSpec(const JunctionSpec &spec) const { return spec.check(); }
    // Undoable; refused when checkSpec() complains. A nonzero gesture merges a slider drag.
    bool setSpec(const JunctionSpec &spec, int gesture = 0);

    // Declared: "variant"; then "a", "b", "c", "d", "k", "l", "m", "n" (cubic-quadratic) or
    // "j", "r" (refined, with sliders over their admissible ranges); the point sets
    // "left_points", "right_points" and (refined) "handles".
    static const PropertyTable &declaration();
    const PropertyTable &properties() const override { return declaration(); }

    // The most arcs leaving one state (the junction state: T^l, T^r, T^i): bounds the depth.
    int mapCount() const override { return 3; }
    // 0: the left cubic (4 points), 1: the right quadratic (3 points), 2 (refined only): the
    // left tangent handle, the interpolated vertex and the right tangent handle.
    int controlPointSetCount() const override;
    // The cubic (4 points), the quadratic (3) and the handles (3) are fixed by 003 §4-5.
    bool pointCountEditable(int) const override { return false; }

signals:
    void specChanged();

protected:
    DerivedIfs computeIfs() const override;
    PointList &pointStorage(int set) override { return m_points[size_t(set)]; }

private:
    JunctionSpec m_spec;
    std::array<PointList, 3> m_points;
};

} // namespace awb
