#pragma once
// Document item "fractal" (layer 2, model): a fractal with control points (000 §4). The
// fractal's IFS is turned into subdivision matrices S_i (S_i P = f_i(P) on reference points);
// moving the control points then deforms the fractal. Presets are the paper's Koch curve and
// Sierpinski triangle with their printed S_i; the custom form takes any plane IFS.

#include "model/AttractorItem.h"

namespace awb {

struct FractalSpec {
    Q_DECLARE_TR_FUNCTIONS(awb::FractalSpec)
public:
    enum class Preset { Koch, Sierpinski, Custom };
    enum class Weights { Nearest, LeastNorm };
    Preset preset = Preset::Koch;
    // Custom only (kept while a preset is chosen, so switching back restores them).
    // Row convention x |-> x A + b: A 2 x 2, b 1 x 2 in the plane; A 3 x 3, b 1 x 3 in space
    // (all maps of one dimension; the control and reference points have it too).
    std::vector<AffineMap> maps;
    Weights weights = Weights::Nearest;
    // The points the S_i are built for (S_i R = f_i(R)); empty: the control points themselves,
    // which reproduces the IFS's own attractor until a point is moved.
    PointList reference;

    bool operator==(const FractalSpec &other) const;
    // Custom: at least one map, each 2 x 2 and finite; reference points finite, none or >= 3.
    MaybeProblem check() const;
    int mapCount() const;
    // 2, or 3 for own maps of space.
    int dimension() const;
    static const QStringList &presetNames();
    static const QStringList &weightNames();
};

class FractalItem : public AttractorItem {
    Q_OBJECT
public:
    FractalItem();

    static QString staticType() { return QStringLiteral("fractal"); }
    static QString staticTypeName() { return tr("Fractal with control points"); }
    QString type() const override { return staticType(); }
    QString typeName() const override { return staticTypeName(); }

    const FractalSpec &fractal() const { return m_fractal; }
    // The spec's own check and the depth bound with the new number of maps.
    MaybeProblem checkFractal(const FractalSpec &spec) const;
    // Undoable; refused when checkFractal() complains.
    bool setFractal(const FractalSpec &spec, int gesture = 0);

    // Declared: "preset" always; "maps", "weights" and "reference_points" while the preset
    // is custom; "control_points". Choosing "custom" from a preset copies the preset's
    // classic maps and canonical points, so the picture stays the same.
    static const PropertyTable &declaration();
    const PropertyTable &properties() const override { return declaration(); }

    int mapCount() const override { return m_fractal.mapCount(); }
    int pointDimension() const override { return m_fractal.dimension(); }
    bool startsAtNetPoints() const override { return true; }
    int controlPointSetCount() const override { return 1; }
    // A preset's S_i fix the number of points, and so do custom reference points; a custom
    // IFS on its own control points takes any number (>= 3).
    bool pointCountEditable(int) const override
    {
        return m_fractal.preset == FractalSpec::Preset::Custom && m_fractal.reference.empty();
    }

signals:
    void fractalChanged();

protected:
    DerivedIfs computeIfs() const override;
    PointList &pointStorage(int) override { return m_points; }

private:
    FractalSpec m_fractal;
    PointList m_points;
};

} // namespace awb
