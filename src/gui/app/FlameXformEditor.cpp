#include "gui/app/FlameXformEditor.h"

#include "core/Messages.h"
#include "core/flame/Variations.h"
#include "gui/app/CompactEditors.h"
#include "model/FlameItem.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHash>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace awb {

using flame::Flame;
using flame::FlameXform;

namespace {

QString nameOf(std::string_view s) { return QString::fromUtf8(s.data(), qsizetype(s.size())); }

QDoubleSpinBox *spin(double lo, double hi, double step)
{
    auto *s = new ExactSpinBox;  // short decimals as they are, fractions typed
    s->setRange(lo, hi);
    s->setSingleStep(step);
    s->setMinimumWidth(90);
    return s;
}

QString shortest(double v) { return QString::fromStdString(shortestNumber(v)); }

QTableWidget *table(const QStringList &headers)
{
    auto *t = new QTableWidget(0, 2);
    t->setHorizontalHeaderLabels(headers);
    t->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    t->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    t->verticalHeader()->setVisible(false);
    t->setSelectionBehavior(QAbstractItemView::SelectRows);
    t->setMinimumHeight(90);
    return t;
}

// A flam3 xform that draws its points where they are (linear 1).
FlameXform plainXform()
{
    FlameXform x;
    x.weight = 1;
    return x;
}

} // namespace

FlameXformEditor::FlameXformEditor(FlameItem *item, std::function<void(const QString &)> report,
                                   QWidget *parent)
    : QWidget(parent), m_item(item), m_report(std::move(report))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *top = new QHBoxLayout;
    m_which = new QComboBox;
    m_which->setToolTip(tr("The xform to edit; its pre map is its triangle in the attractor "
                           "view (drag a corner) and in the point table below"));
    top->addWidget(m_which, 1);
    m_add = new QPushButton(tr("Add"));
    m_add->setToolTip(tr("A new xform (linear, weight 1) after the others"));
    m_duplicate = new QPushButton(tr("Duplicate"));
    m_delete = new QPushButton(tr("Delete"));
    for (QPushButton *b : {m_add, m_duplicate, m_delete})
        top->addWidget(b);
    layout->addLayout(top);

    auto *form = new QFormLayout;
    m_weight = spin(0, 1e6, 0.1);
    m_colour = spin(0, 1, 0.05);
    m_speed = spin(-1, 1, 0.05);
    m_opacity = spin(0, 1, 0.1);
    form->addRow(tr("Weight:"), m_weight);
    form->addRow(tr("Colour:"), m_colour);
    form->addRow(tr("Colour speed:"), m_speed);
    form->addRow(tr("Opacity:"), m_opacity);
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    layout->addLayout(form);

    m_variations = table({tr("Variation"), tr("Weight")});
    m_variations->setToolTip(tr("The xform's variations; a weight of 0 removes one"));
    layout->addWidget(m_variations);
    m_addVariation = new QComboBox;
    m_addVariation->addItem(tr("Add a variation…"));
    for (int id = 0; id < flame::kVariationCount; ++id)
        m_addVariation->addItem(nameOf(flame::variationName(id)), id);
    layout->addWidget(m_addVariation);
    m_parameters = table({tr("Parameter"), tr("Value")});
    m_parameters->setToolTip(tr("The parameters of the xform's variations"));
    layout->addWidget(m_parameters);

    connect(m_which, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_updating)
            refresh();
    });
    connect(m_add, &QPushButton::clicked, this, [this] { append(plainXform()); });
    connect(m_duplicate, &QPushButton::clicked, this, [this] {
        if (!m_item)
            return;
        Flame f = m_item->flame();
        if (const FlameXform *x = xformOf(f)) {
            FlameXform copy = *x;
            copy.xaos.clear();
            append(copy);
        }
    });
    connect(m_delete, &QPushButton::clicked, this, [this] {
        if (!m_item)
            return;
        Flame f = m_item->flame();
        const int i = current();
        if (i >= int(f.xforms.size())) {
            f.finalXform.reset();
        } else {
            if (f.xforms.size() == 1) {
                m_report(tr("A flame needs at least one xform."));
                return;
            }
            f.xforms.erase(f.xforms.begin() + i);
            // The xaos rows lose the deleted xform's column.
            for (FlameXform &x : f.xforms)
                if (std::size_t(i) < x.xaos.size())
                    x.xaos.erase(x.xaos.begin() + i);
        }
        commit(f);
    });
    auto field = [this](QDoubleSpinBox *box, double FlameXform::*member) {
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, member](double v) {
            if (!m_updating)
                edit([&](Flame &, FlameXform &x) { x.*member = v; });
        });
    };
    field(m_weight, &FlameXform::weight);
    field(m_colour, &FlameXform::colour);
    field(m_speed, &FlameXform::colourSpeed);
    field(m_opacity, &FlameXform::opacity);
    connect(m_variations, &QTableWidget::cellChanged, this, [this](int row, int column) {
        if (m_updating || column != 1)
            return;
        const int id = m_variations->item(row, 0)->data(Qt::UserRole).toInt();
        bool ok = false;
        const double w = m_variations->item(row, 1)->text().toDouble(&ok);
        if (!ok || !std::isfinite(w)) {
            m_report(tr("%1: '%2' is not a number")
                         .arg(nameOf(flame::variationName(id)), m_variations->item(row, 1)->text()));
            refresh();
            return;
        }
        edit([&](Flame &, FlameXform &x) {
            auto it = std::find_if(x.variations.begin(), x.variations.end(),
                                   [&](const flame::VariationTerm &t) { return t.id == id; });
            if (it == x.variations.end())
                return;
            if (w == 0)
                x.variations.erase(it);
            else
                it->weight = w;
        });
    });
    connect(m_addVariation, &QComboBox::activated, this, [this](int index) {
        if (index <= 0)
            return;
        const int id = m_addVariation->itemData(index).toInt();
        m_addVariation->setCurrentIndex(0);
        edit([&](Flame &, FlameXform &x) {
            for (const flame::VariationTerm &t : x.variations)
                if (t.id == id)
                    return;
            x.variations.push_back({id, 1.0});
            std::sort(x.variations.begin(), x.variations.end(),
                      [](const auto &a, const auto &b) { return a.id < b.id; });
        });
    });
    connect(m_parameters, &QTableWidget::cellChanged, this, [this](int row, int column) {
        if (m_updating || column != 1)
            return;
        const int p = m_parameters->item(row, 0)->data(Qt::UserRole).toInt();
        bool ok = false;
        const double v = m_parameters->item(row, 1)->text().toDouble(&ok);
        if (!ok || !std::isfinite(v)) {
            m_report(tr("%1: '%2' is not a number")
                         .arg(nameOf(flame::parameterName(p)), m_parameters->item(row, 1)->text()));
            refresh();
            return;
        }
        edit([&](Flame &, FlameXform &x) { x.parameters[std::size_t(p)] = v; });
    });
    if (m_item)
        connect(m_item, &FlameItem::flameChanged, this, &FlameXformEditor::refresh);
    refresh();
}

QWidget *FlameXformEditor::editor(const QString &name) const
{
    const QHash<QString, QWidget *> editors{
        {"xform", m_which},         {"add", m_add},         {"duplicate", m_duplicate},
        {"delete", m_delete},       {"weight", m_weight},   {"color", m_colour},
        {"color_speed", m_speed},   {"opacity", m_opacity}, {"variations", m_variations},
        {"add_variation", m_addVariation}, {"parameters", m_parameters}};
    return editors.value(name);
}

int FlameXformEditor::current() const { return std::max(0, m_which->currentIndex()); }

void FlameXformEditor::append(const FlameXform &x)
{
    if (!m_item)
        return;
    Flame f = m_item->flame();
    f.xforms.push_back(x);
    if (commit(f))
        m_which->setCurrentIndex(int(f.xforms.size()) - 1);
}

bool FlameXformEditor::commit(const Flame &f)
{
    // One undo step; the item's flameChanged brings the editors up to date. A refusal is
    // reported and the editors show the model again.
    QString error;
    if (m_item->setFlame(f, 0, &error))
        return true;
    m_report(error);
    refresh();
    return false;
}

FlameXform *FlameXformEditor::xformOf(Flame &f) const
{
    const int i = current();
    if (i < int(f.xforms.size()))
        return &f.xforms[std::size_t(i)];
    return f.finalXform ? &*f.finalXform : nullptr;
}

bool FlameXformEditor::edit(const std::function<void(Flame &, FlameXform &)> &change)
{
    if (!m_item)
        return false;
    Flame f = m_item->flame();
    FlameXform *x = xformOf(f);
    if (!x)
        return false;
    change(f, *x);
    return f == m_item->flame() || commit(f);
}

void FlameXformEditor::refresh()
{
    if (!m_item)
        return;
    ++m_updating;
    const Flame &f = m_item->flame();
    const int n = int(f.xforms.size()) + (f.finalXform ? 1 : 0);
    const int keep = std::min(m_which->currentIndex(), n - 1);
    m_which->clear();
    for (std::size_t i = 0; i < f.xforms.size(); ++i)
        m_which->addItem(f.xforms[i].name.empty()
                             ? tr("Xform %1").arg(i + 1)
                             : tr("Xform %1: %2").arg(i + 1).arg(QString::fromStdString(f.xforms[i].name)));
    if (f.finalXform)
        m_which->addItem(tr("Final xform"));
    m_which->setCurrentIndex(std::max(0, keep));
    Flame copy = f;
    const FlameXform *x = xformOf(copy);
    const bool isFinal = current() >= int(f.xforms.size());
    m_weight->setEnabled(!isFinal);
    m_duplicate->setEnabled(!isFinal);
    m_delete->setEnabled(isFinal || f.xforms.size() > 1);
    if (x) {
        m_weight->setValue(x->weight);
        m_colour->setValue(x->colour);
        m_speed->setValue(x->colourSpeed);
        m_opacity->setValue(x->opacity);
        m_variations->setRowCount(int(x->variations.size()));
        std::vector<int> params;
        for (int r = 0; r < int(x->variations.size()); ++r) {
            const flame::VariationTerm &t = x->variations[std::size_t(r)];
            auto *name = new QTableWidgetItem(nameOf(flame::variationName(t.id)));
            name->setFlags(name->flags() & ~Qt::ItemIsEditable);
            name->setData(Qt::UserRole, t.id);
            m_variations->setItem(r, 0, name);
            m_variations->setItem(r, 1, new QTableWidgetItem(shortest(t.weight)));
            for (int p : flame::variationParameters(t.id))
                params.push_back(p);
        }
        m_parameters->setRowCount(int(params.size()));
        for (int r = 0; r < int(params.size()); ++r) {
            const int p = params[std::size_t(r)];
            auto *name = new QTableWidgetItem(nameOf(flame::parameterName(p)));
            name->setFlags(name->flags() & ~Qt::ItemIsEditable);
            name->setData(Qt::UserRole, p);
            m_parameters->setItem(r, 0, name);
            m_parameters->setItem(r, 1,
                                  new QTableWidgetItem(shortest(x->parameters[std::size_t(p)])));
        }
    }
    --m_updating;
}

} // namespace awb
