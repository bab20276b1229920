#pragma once
// Document item "normal-vector" (layer 2, model): the non-linear normal-vector subdivision
// scheme of 001 (new points moved along the edge normals), a preset of 001 §3 or own α_j, β_j.
// Its figure is the polygon after `steps` steps (DerivedIfs::polygon). Where the rules are the
// same on every edge the scheme also has an equivalent IFS of similarities (001 §4), drawn with
// one view per edge; the other schemes have no IFS and only the polygon is drawn.

#include "model/AttractorItem.h"

namespace awb {

class NormalVectorScheme;

struct NormalVectorSpec {
    Q_DECLARE_TR_FUNCTIONS(awb::NormalVectorSpec)
public:
    enum class Normal { Positive, Negative };
    enum class Sign { Constant, EdgeAlternating, LevelEdgeAlternating, LevelAlternating };
    QString preset = QStringLiteral("koch");  // a core preset key, or "custom"
    // Custom only (kept while a preset is chosen).
    std::vector<double> alpha, beta;          // p values each, p >= 2
    Normal normal = Normal::Positive;
    std::vector<Sign> signs;                  // empty (constant), 1 or p
    bool closed = false;                      // the control polygon is closed
    int steps = 4;                            // subdivision steps shown

    static constexpr int maxSteps = 30;

    bool operator==(const NormalVectorSpec &) const = default;
    // Known preset; custom: equal lengths >= 2, finite, 1 or p signs (the core's judgement);
    // steps in 0..maxSteps. The field is the JSON key.
    MaybeProblem check() const;
    bool isCustom() const { return preset == QLatin1String("custom"); }
    // The core scheme (the preset's, or the custom one). Throws InputError.
    NormalVectorScheme makeScheme() const;
    int arity() const;
    // Core preset keys, then "custom".
    static const QStringList &presetNames();
    static const QStringList &normalNames();
    static const QStringList &signNames();
};

class NormalVectorItem : public AttractorItem {
    Q_OBJECT
public:
    NormalVectorItem();

    static QString staticType() { return QStringLiteral("normal-vector"); }
    static QString staticTypeName() { return tr("Normal-vector curve"); }
    QString type() const override { return staticType(); }
    QString typeName() const override { return staticTypeName(); }

    const NormalVectorSpec &spec() const { return m_spec; }
    MaybeProblem checkSpec(const NormalVectorSpec &spec) const;
    // Undoable; refused when checkSpec() complains. A nonzero gesture merges a slider drag.
    bool setSpec(const NormalVectorSpec &spec, int gesture = 0);

    // Declared: "preset", "steps", "normal", "closed", the rules "alpha.<j>", "beta.<j>"
    // (j = 0 .. p-1; saved as the lists "alpha", "beta" with "signs" for own rules),
    // "control_points". Editing normal, α or β of a preset turns it into own rules starting
    // from the preset's values.
    static const PropertyTable &declaration();
    const PropertyTable &properties() const override { return declaration(); }

    int mapCount() const override { return m_spec.arity(); }
    int controlPointSetCount() const override { return 1; }
    bool controlPointSetClosed(int) const override { return m_spec.closed; }

signals:
    void specChanged();

protected:
    DerivedIfs computeIfs() const override;
    PointList &pointStorage(int) override { return m_points; }

private:
    NormalVectorSpec m_spec;
    PointList m_points;
};

} // namespace awb
