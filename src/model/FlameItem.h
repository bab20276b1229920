#pragma once
// Document item "flame" (layer 2, model; issue 45): a fractal flame as flam3 3.1.1 draws it --
// xforms of non-linear variations between pre and post affine maps, with weights, colours,
// colour speeds, opacities and xaos rows, a final xform, a 256-colour palette, flam3's camera
// and tone (core/flame/Flame.h). It is drawn by random iteration only, by the core's flame
// chaos game (core/flame/FlameChaos.h) through the one raster path (render/AttractorImage.h),
// in the palette's colours, so the window, `attractor-cli render`, Python and the exports show
// the same picture, which flam3-render draws too (tests/cli/test_flame_item.cpp).
//
// What is linear about a flame is analysed: the spectra of the xforms' affine parts, in the
// picture's orientation (y up: flam3's y mirrored), and the Lyapunov exponent of the flame's
// own orbit (the average log of how much one step stretches a small displacement), whose sign
// says whether the chaos game contracts on average. A flame has no subdivision matrices.
//
// Its file form (docs/file-format.md) keeps flam3's names: "xforms" (coefs, post, variations,
// parameters, weight, color, color_speed, opacity, chaos, name), "final_xform", "palette",
// "camera" and "tone".

#include "core/flame/Flame.h"
#include "model/AttractorItem.h"

namespace awb {

class FlameItem : public AttractorItem {
    Q_OBJECT
public:
    FlameItem();

    static QString staticType() { return QStringLiteral("flame"); }
    static QString staticTypeName() { return tr("Fractal flame"); }
    QString type() const override { return staticType(); }
    QString typeName() const override { return staticTypeName(); }

    const flame::Flame &flame() const { return m_flame; }
    // The core's checkFlame, its message for the user ("xforms" names the field).
    MaybeProblem checkFlame(const flame::Flame &f) const;
    // Undoable, one step; refused (false, *error says why) when checkFlame() complains.
    bool setFlame(const flame::Flame &f, int gesture = 0, QString *error = nullptr);
    // The flame as flam3 writes it, named after the item.
    flame::Flame namedFlame() const;

    // Declared: "xforms", "final_xform", "palette", "camera.*", "tone.*".
    static const PropertyTable &declaration();
    const PropertyTable &properties() const override { return declaration(); }

    int mapCount() const override { return int(m_flame.xforms.size()); }
    bool hasStartSet() const override { return false; }

    // Each xform's pre map as the triangle Apophysis draws (and the final xform's last): the
    // images of (0, 0), (1, 0) and (0, 1), in the picture's orientation (y up). Dragging a
    // corner changes the map, one undo step a drag; undo gives the map back exactly.
    int controlPointSetCount() const override;
    bool controlPointSetClosed(int) const override { return true; }
    bool pointCountEditable(int) const override { return false; }
    int maxPointCount(int) const override { return 3; }

signals:
    void flameChanged();

protected:
    DerivedIfs computeIfs() const override;
    PointList &pointStorage(int set) override;
    void pointsStored(int set) override;

private:
    // The triangles of the maps they were drawn from (rebuilt when a map changes otherwise),
    // and per set the last triangles with their exact maps, so that a triangle restored by an
    // undo gives its map back to the last bit.
    void syncTriangles() const;
    flame::Affine2 &preOf(int set);
    flame::Flame m_flame;
    mutable std::vector<PointList> m_triangles;
    mutable std::vector<flame::Affine2> m_trianglesOf;
    mutable std::vector<std::vector<std::pair<PointList, flame::Affine2>>> m_exact;
};

// The triangle of a pre map (y up) and the map of a triangle.
PointList flameTriangle(const flame::Affine2 &m);
flame::Affine2 flameMapOfTriangle(const PointList &t);

// An xform's affine map in the application's row convention and orientation: x |-> x A + b
// with y up (flam3's y points down the picture, so the map is mirrored: R f R, R = diag(1, -1)).
AffineMap planeMapOf(const flame::Affine2 &m);

// The flame as the item keeps it: no name (the item's), and the parameters of the variations
// an xform does not use at their defaults (they draw nothing; a file holds only the others).
flame::Flame canonicalFlame(flame::Flame f);

// An xform as the file, Python and `attractor-cli set` hold it (flam3's attribute names), and
// back; fromJson throws LoadError naming the field below `where`.
QJsonObject flameXformToJson(const flame::FlameXform &x, std::size_t xforms);
flame::FlameXform flameXformFromJson(const QJsonValue &v, const QString &where);

} // namespace awb
