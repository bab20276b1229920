#pragma once
// The declared property of an attractor item's point set (layer 2, model): point set `set`
// kept in the file under `key` ("control_points", "left_points"), points of the item's
// dimension. Read and written from the declaration like every property; edited point by
// point through the control-point commands (drags, inserts, removals), or as a whole (Python's
// assign, item.update, attractor-cli set) through AttractorItem::setControlPoints.

#include "model/AttractorItem.h"
#include "model/PropertyDeclaration.h"

namespace awb {

class PointSetPart : public PartBase {
public:
    int pointSet = 0;
    QString key;
    DeclaredTexts texts;
    // Whether the set exists now (a junction's third set only with handles).
    std::function<bool(const AttractorItem &)> present;
    // The points a file without the field gets; none: the field is required.
    std::function<PointList(const AttractorItem &)> fallback;

    void parameters(const Item &, QList<ParameterInfo> &) const override {}
    std::optional<QVariant> value(const Item &, const QString &) const override
    {
        return std::nullopt;
    }
    std::optional<bool> set(Item &, const QString &, const QVariant &, int,
                            QString *) const override
    {
        return std::nullopt;
    }
    std::optional<bool> setJson(Item &item, const QString &k, const QJsonValue &v,
                                QString *error) const override;
    void write(const Item &item, QJsonObject &json) const override;
    void read(Item &item, const FieldReader &fields) const override;
    bool transfer(const Item &from, Item &to, QString *error) const override;
    void describe(const Item &item, QList<PropertyDescription> &out) const override;
    QStringList jsonKeys() const override { return {key}; }
    bool enabled(const Item &, const QString &) const override { return false; }

private:
    bool applies(const Item &item) const;
};

// Declares point set `set` of kind T under `key`.
template <class T>
PointSetPart &declarePointSet(Declaration<T> &d, int set, const QString &key,
                              const char *label = nullptr)
{
    auto part = std::make_shared<PointSetPart>();
    part->pointSet = set;
    part->key = key;
    part->texts.context = T::staticMetaObject.className();
    part->texts.label = label;
    PointSetPart &ref = *part;
    d.add(part);
    return ref;
}

} // namespace awb
