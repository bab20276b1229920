#include "model/ItemRegistry.h"

#include "model/BcifsJunctionItem.h"
#include "model/BezierUnionItem.h"
#include "model/CifsItem.h"
#include "model/ComplexBezierItem.h"
#include "model/EigenvaluePlotItem.h"
#include "model/FlameItem.h"
#include "model/FractalItem.h"
#include "model/NormalVectorItem.h"
#include "model/SubdivisionCurveItem.h"
#include "model/SubdivisionMeshItem.h"
#include "model/SubdivisionSurfaceItem.h"

namespace awb {

ItemRegistry::ItemRegistry()
{
    // One line per item kind.
    add<SubdivisionCurveItem>();
    add<EigenvaluePlotItem>();
    add<FractalItem>();
    add<BezierUnionItem>();
    add<NormalVectorItem>();
    add<ComplexBezierItem>();
    add<FlameItem>();
    add<CifsItem>();
    add<BcifsJunctionItem>();
    add<SubdivisionSurfaceItem>();
    add<SubdivisionMeshItem>();
}

const ItemRegistry &ItemRegistry::instance()
{
    static const ItemRegistry registry;
    return registry;
}

const ItemRegistry::Kind *ItemRegistry::find(const QString &type) const
{
    for (const Kind &k : m_kinds)
        if (k.type == type)
            return &k;
    return nullptr;
}

std::unique_ptr<Item> ItemRegistry::create(const QString &type) const
{
    const Kind *k = find(type);
    return k ? k->create() : nullptr;
}

QStringList ItemRegistry::types() const
{
    QStringList out;
    for (const Kind &k : m_kinds)
        out << k.type;
    return out;
}

} // namespace awb
