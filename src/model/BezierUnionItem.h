#pragma once
// Document item "bezier-union" (layer 2, model): several Bézier curves, each with its own control
// points and split parameter u, drawn as one attractor (002 §6, 000 §2.2). In block mode the
// IFS is the block-diagonal union, whose attractor is exactly the union of the curves; in
// combined mode all plane maps act together and give 002 §6's "dusty" fractal.

#include "model/AttractorItem.h"

namespace awb {

struct BezierUnionSpec {
    Q_DECLARE_TR_FUNCTIONS(awb::BezierUnionSpec)
public:
    enum class Mode { Block, Combined };
    Mode mode = Mode::Block;
    std::vector<double> u;  // one split parameter per curve, each in (0, 1)
    std::vector<PointList> points;  // each curve's control points (point set i is curve i)

    bool operator==(const BezierUnionSpec &) const = default;
    // At least one curve, one u per curve; every u finite and strictly between 0 and 1 (field
    // "curves[i].u", 1-based like the file's messages).
    MaybeProblem check() const;
    // Block: 2 (map i acts on every curve); combined: 2 per curve.
    int mapCount() const;
    static const QStringList &modeNames();
};

class BezierUnionItem : public AttractorItem {
    Q_OBJECT
public:
    BezierUnionItem();

    static QString staticType() { return QStringLiteral("bezier-union"); }
    static QString staticTypeName() { return tr("Union of Bézier curves"); }
    QString type() const override { return staticType(); }
    QString typeName() const override { return staticTypeName(); }

    const BezierUnionSpec &spec() const { return m_spec; }
    // The spec's own check, its number of curves, and the depth bound with its number of maps.
    MaybeProblem checkSpec(const BezierUnionSpec &spec) const;
    // Undoable (mode and the u's; the number of curves stays); refused when checkSpec()
    // complains. A nonzero gesture merges the steps of a slider drag.
    bool setSpec(const BezierUnionSpec &spec, int gesture = 0);

    // Declared: "mode", the curves (saved as "curves", each its control points and u), shown
    // as "curves.<i>.u" for i = 0 .. curves - 1 (0-based like the point sets).
    static const PropertyTable &declaration();
    const PropertyTable &properties() const override { return declaration(); }

    int mapCount() const override { return m_spec.mapCount(); }
    // Point set i is curve i's control points.
    int controlPointSetCount() const override { return int(m_spec.points.size()); }

signals:
    void specChanged();

protected:
    DerivedIfs computeIfs() const override;
    PointList &pointStorage(int set) override { return m_spec.points[size_t(set)]; }

private:
    BezierUnionSpec m_spec;
};

} // namespace awb
