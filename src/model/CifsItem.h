#pragma once
// Document item "cifs" (layer 2, model): a controlled IFS (003 §2.2), an automaton whose states
// carry barycentric spaces. The one preset is 003 Fig. 4-5: Barnsley's fern with one arc
// redirected into a Sierpiński state, so the fern is built of gaskets. The item draws the
// attractor of one state through the core's CIFS iteration (DerivedIfs::iterate); its control
// points are the frame triangle both states are placed in.

#include "model/AttractorItem.h"

namespace awb {

struct CifsSpec {
    Q_DECLARE_TR_FUNCTIONS(awb::CifsSpec)
public:
    int redirected = 2;                  // the fern arc T0..T3 led into the Sierpiński state
    QString state = QStringLiteral("Fern");  // the state whose attractor is drawn

    bool operator==(const CifsSpec &) const = default;
    // redirected in 0..3, state one of stateNames().
    MaybeProblem check() const;
    static const QStringList &presetNames();
    // The preset's states, in the automaton's order.
    static const QStringList &stateNames();
};

class CifsItem : public AttractorItem {
    Q_OBJECT
public:
    CifsItem();

    static QString staticType() { return QStringLiteral("cifs"); }
    static QString staticTypeName() { return tr("Controlled IFS"); }
    QString type() const override { return staticType(); }
    QString typeName() const override { return staticTypeName(); }

    const CifsSpec &spec() const { return m_spec; }
    MaybeProblem checkSpec(const CifsSpec &spec) const { return spec.check(); }
    bool setSpec(const CifsSpec &spec, int gesture = 0);

    // Declared: "preset" (shown), "redirected" (0..3), "state" (one of stateNames()), the
    // frame "control_points".
    static const PropertyTable &declaration();
    const PropertyTable &properties() const override { return declaration(); }

    // The fern state's four arcs: the most leaving one state, it bounds the depth.
    int mapCount() const override { return 4; }
    // The frame triangle (3 points).
    int controlPointSetCount() const override { return 1; }
    bool pointCountEditable(int) const override { return false; } // the frame triangle

signals:
    void specChanged();

protected:
    DerivedIfs computeIfs() const override;
    PointList &pointStorage(int) override { return m_frame; }

private:
    CifsSpec m_spec;
    PointList m_frame;
};

} // namespace awb
