#pragma once
// The item kinds the document knows, keyed by their JSON "type" (layer 2, model). The loader
// creates items through it and the GUI lists it for "Add item". Adding a kind is one class
// (deriving from Item or AttractorItem, with staticType(), staticTypeName() and a default
// constructor) plus one add<Kind>() line in ItemRegistry.cpp. Registration is explicit, not by
// static initialisers: those are dropped when nothing else uses their object file of the
// static library.

#include "model/Item.h"

#include <functional>

namespace awb {

class ItemRegistry {
public:
    struct Kind {
        QString type;                              // JSON "type"
        std::function<QString()> displayName;      // translated
        std::function<std::unique_ptr<Item>()> create;
    };

    static const ItemRegistry &instance();

    // nullptr for an unknown type.
    std::unique_ptr<Item> create(const QString &type) const;
    const Kind *find(const QString &type) const;
    // In registration order.
    QStringList types() const;
    const std::vector<Kind> &kinds() const { return m_kinds; }

private:
    ItemRegistry();
    template <class T>
    void add()
    {
        m_kinds.push_back({T::staticType(), &T::staticTypeName,
                           [] { return std::unique_ptr<Item>(new T); }});
    }

    std::vector<Kind> m_kinds;
};

} // namespace awb
