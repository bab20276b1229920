#include "gui/app/PropertiesDock.h"

#include "gui/app/CompactEditors.h"
#include "gui/app/FlameXformEditor.h"
#include "gui/app/FrameBudget.h"
#include "gui/app/Messages.h"
#include "gui/app/WheelGuard.h"
#include "gui/views/ComplexPlanePicker.h"
#include "model/AttractorItem.h"
#include "model/EigenvaluePlotItem.h"
#include "model/FlameItem.h"
#include "model/NumberFormat.h"
#include "model/Project.h"
#include "model/PropertyTable.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMap>
#include <QScrollArea>
#include <QScrollBar>
#include <QSlider>
#include <QSpinBox>
#include <QTableWidget>
#include <algorithm>
#include <cmath>
#include <utility>

namespace awb {

namespace {

constexpr int sliderSteps = 1000;
constexpr double spinLimit = 1e9;

// A combo box whose width does not follow its longest entry, its text elided (CompactEditors).
QComboBox *compactCombo() { return new ElidingComboBox; }

double finiteOr(double v, double fallback) { return std::isfinite(v) ? v : fallback; }

// Real values shown exactly where they can be (1/3, not 0.333333) and typed as expressions.
ExactSpinBox *realSpin(double lo, double hi)
{
    auto *spin = new ExactSpinBox;
    spin->setRange(finiteOr(lo, -spinLimit), finiteOr(hi, spinLimit));
    spin->setSingleStep(0.01);
    spin->setMinimumWidth(90);
    return spin;
}

CheckedSpinBox *wholeSpin(int lo, int hi)
{
    auto *spin = new CheckedSpinBox;
    spin->setMinimumWidth(70); // not the width of its largest value
    spin->setRange(lo, hi);
    return spin;
}

} // namespace

PropertiesWidget::PropertiesWidget(Messages *messages, QWidget *parent)
    : QWidget(parent), m_messages(messages)
{
    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto *scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    // Editors fit the dock's width; a horizontal scroll bar would hide half of a row.
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    outer->addWidget(scroll);
    auto *holder = new QWidget;
    m_layout = new QVBoxLayout(holder);
    scroll->setWidget(holder);
    rebuild();
}

void PropertiesWidget::setItem(Item *item)
{
    endGesture(m_gesture); // a slider held while the item changes
    for (const auto &c : std::as_const(m_connections))
        disconnect(c);
    m_connections.clear();
    m_item = item;
    m_pointSet = 0;
    if (item)
        m_connections << connect(item, &Item::changed, this, &PropertiesWidget::onItemChanged);
    // A plot lists the project's items as sources: follow additions, removals and renames.
    if (qobject_cast<EigenvaluePlotItem *>(item) && item->project()) {
        const auto update = [this] { onItemChanged(); };
        m_connections << connect(item->project(), &Project::itemInserted, this, update);
        m_connections << connect(item->project(), &Project::itemRemoved, this, update);
        m_connections << connect(item->project(), &Project::itemChanged, this, update);
    }
    rebuild();
}

QWidget *PropertiesWidget::editor(const QString &key) const
{
    if (key.startsWith(QLatin1String("xforms.")) && m_xforms)
        return m_xforms->editor(key.mid(7));
    return m_editors.value(key);
}
QWidget *PropertiesWidget::slider(const QString &key) const { return m_sliders.value(key); }

void PropertiesWidget::onItemChanged()
{
    QStringList keys;
    if (m_item)
        for (const auto &p : m_item->parameters())
            keys << p.key;
    // The parameter list depends on the state (ω only for the four-point scheme): rebuild
    // when it changed, otherwise only show the new values (keeps focus and slider grabs).
    if (keys != m_keys) {
        rebuild();
    } else if (m_budget && m_budget->inGesture()) {
        // During a gesture the editor under the user's hand follows at once, the rest of the
        // dock a few times a second (FrameBudget).
        ++m_updating;
        const Infos infos = currentInfos();
        for (const Binding &b : std::as_const(m_bindings))
            if (!m_gestureKey.isEmpty() && b.key == m_gestureKey)
                b.update(infos);
        --m_updating;
        m_budget->markDirty(m_budgetPanel);
    } else {
        updateValues();
    }
}

std::function<void(const QString &)> PropertiesWidget::refusal(const QString &label)
{
    return [this, label](const QString &why) {
        report(tr("%1: %2").arg(QString(label).remove(QLatin1Char('&')).remove(QLatin1Char(':')),
                                why));
    };
}

void PropertiesWidget::report(const QString &message)
{
    if (m_messages)
        m_messages->error(this, tr("Value refused"), message);
}

int PropertiesWidget::beginGesture(const QString &key)
{
    if (!m_item || !m_item->project())
        return 0;
    m_gestureProject = m_item->project();
    m_gestureKey = key;
    m_gesture = m_gestureProject->beginGesture();
    return m_gesture;
}

void PropertiesWidget::endGesture(int gesture)
{
    if (gesture == 0 || gesture != m_gesture)
        return;
    if (m_gestureProject)
        m_gestureProject->endGesture(gesture);
    m_gesture = 0;
    m_gestureKey.clear();
    m_gestureProject = nullptr;
}

void PropertiesWidget::setFrameBudget(FrameBudget *budget)
{
    m_budget = budget;
    m_budgetPanel = budget ? budget->addPanel(this, [this] { updateValues(); }) : -1;
}

bool PropertiesWidget::apply(const QString &key, const QVariant &value, int gesture)
{
    if (!m_item || m_updating)
        return false;
    QString error;
    if (!m_item->setParameter(key, value, gesture, &error)) {
        updateValues();
        report(error.isEmpty() ? tr("%1 cannot be set to %2.").arg(key, value.toString())
                               : error);
        return false;
    }
    return true;
}

PropertiesWidget::Infos PropertiesWidget::currentInfos() const
{
    Infos infos;
    if (m_item)
        for (const ParameterInfo &p : m_item->parameters())
            infos.insert(p.key, p);
    return infos;
}

void PropertiesWidget::updateValues()
{
    ++m_updating;
    const Infos infos = currentInfos();
    for (const Binding &b : std::as_const(m_bindings))
        b.update(infos);
    --m_updating;
}

void PropertiesWidget::rebuild()
{
    ++m_updating;
    m_bindings.clear();
    m_editors.clear();
    m_sliders.clear();
    m_keys.clear();
    m_points = nullptr;
    if (m_content) {
        m_layout->removeWidget(m_content);
        m_content->deleteLater();
    }
    m_content = new QWidget;
    auto *content = new QVBoxLayout(m_content);
    content->setContentsMargins(4, 4, 4, 4);
    m_layout->insertWidget(0, m_content);
    if (!m_item) {
        content->addWidget(new QLabel(tr("No item selected.")));
        content->addStretch();
        --m_updating;
        return;
    }

    // Every declared parameter, grouped by its heading (the name under the kind's), in the
    // declaration's order; then the editors of structured inputs beside their group.
    QMap<QString, QFormLayout *> groups;
    QFormLayout *plotForm = nullptr;
    for (const ParameterInfo &info : m_item->parameters()) {
        m_keys << info.key;
        QFormLayout *form = groups.value(info.group);
        if (!form) {
            auto *box = new QGroupBox(info.group.isEmpty() ? tr("Parameters") : info.group);
            form = new QFormLayout(box);
            groups.insert(info.group, form);
            content->addWidget(box);
        }
        addParameter(form, info);
        // The palette beside the point size; the plot's state under its source.
        if (info.key == QLatin1String("style.point_size")
            && !qobject_cast<FlameItem *>(m_item.data()))  // a flame has its own palette
            addPaletteEditor(form);
        if (info.key == QLatin1String("source")
            && qobject_cast<EigenvaluePlotItem *>(m_item.data()))
            plotForm = form;
    }
    if (plotForm)
        addEigenvaluePlotStatus(plotForm);
    m_xforms = nullptr;
    if (auto *flameItem = qobject_cast<FlameItem *>(m_item.data())) {
        // A flame's xforms, beside its camera and tone.
        auto *box = new QGroupBox(tr("Xforms"));
        auto *boxLayout = new QVBoxLayout(box);
        m_xforms = new FlameXformEditor(flameItem, [this](const QString &m) { report(m); });
        boxLayout->addWidget(m_xforms);
        content->addWidget(box);
    }
    if (qobject_cast<AttractorItem *>(m_item.data()))
        addPointEditors();
    content->addStretch();
    // Scrolling the dock over an editor scrolls; it does not change the value.
    WheelGuard::guardChildren(m_content);
    // In a narrow dock a label goes above its editor rather than clipping it; the dock is
    // never narrower than the editors need (the scroll area has no horizontal scroll bar).
    for (QFormLayout *form : m_content->findChildren<QFormLayout *>())
        form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    if (auto *scroll = findChild<QScrollArea *>()) {
        scroll->setMinimumWidth(m_content->minimumSizeHint().width()
                                + m_layout->contentsMargins().left()
                                + m_layout->contentsMargins().right()
                                + scroll->verticalScrollBar()->sizeHint().width());
    }
    --m_updating;
    updateValues();
}

void PropertiesWidget::addParameter(QFormLayout *form, const ParameterInfo &info)
{
    const QString key = info.key;
    QWidget *row = nullptr;
    switch (info.type) {
    case ParameterInfo::Type::Real:
    case ParameterInfo::Type::Integer: {
        const bool integer = info.type == ParameterInfo::Type::Integer;
        QAbstractSpinBox *spinBase;
        std::function<void(double)> setSpin;
        if (integer) {
            auto *spin = wholeSpin(int(std::max(finiteOr(info.minimum, -spinLimit), -spinLimit)),
                                   int(std::min(finiteOr(info.maximum, spinLimit), spinLimit)));
            spin->setRefusal(refusal(info.label));
            connect(spin, &QSpinBox::valueChanged, this, [this, key](int v) { apply(key, v); });
            setSpin = [spin](double v) { spin->setValue(int(std::lround(v))); };
            spinBase = spin;
        } else {
            auto *spin = realSpin(info.minimum, info.maximum);
            spin->setRefusal(refusal(info.label));
            connect(spin, &QDoubleSpinBox::valueChanged, this,
                    [this, key](double v) { apply(key, v); });
            setSpin = [spin](double v) { spin->setValue(v); };
            spinBase = spin;
        }
        spinBase->setToolTip(info.toolTip);
        m_editors.insert(key, spinBase);
        QSlider *slider = nullptr;
        if (info.hasSlider()) {
            slider = new QSlider(Qt::Horizontal);
            const double lo = info.sliderMinimum, hi = info.sliderMaximum;
            const int steps = integer ? int(std::lround(hi - lo)) : sliderSteps;
            slider->setRange(0, std::max(1, steps));
            slider->setToolTip(info.toolTip);
            m_sliders.insert(key, slider);
            auto gesture = std::make_shared<int>(0);
            connect(slider, &QSlider::sliderPressed, this,
                    [this, gesture, key] { *gesture = beginGesture(key); });
            connect(slider, &QSlider::sliderReleased, this,
                    [this, gesture] { endGesture(*gesture); *gesture = 0; });
            connect(slider, &QSlider::valueChanged, this,
                    [this, key, lo, hi, steps, integer, gesture](int pos) {
                        const double v = lo + (hi - lo) * pos / double(std::max(1, steps));
                        apply(key, integer ? QVariant(int(std::lround(v))) : QVariant(v),
                              *gesture);
                    });
            m_bindings.append({key, [this, key, slider, lo, hi, steps](const Infos &) {
                if (slider->isSliderDown())
                    return;  // never move the slider under the user's hand
                const double v = m_item->parameter(key).toDouble();
                const QSignalBlocker block(slider);
                slider->setValue(int(std::lround((v - lo) / (hi - lo) * steps)));
            }});
        }
        m_bindings.append({key, [this, key, spinBase, setSpin, slider](const Infos &infos) {
            const QSignalBlocker block(spinBase);
            if (const auto it = infos.find(key); it != infos.end()) {
                // Bounds that follow the state (the deepest level the maps allow).
                if (auto *whole = qobject_cast<QSpinBox *>(spinBase))
                    whole->setRange(
                        int(std::max(finiteOr(it->minimum, -spinLimit), -spinLimit)),
                        int(std::min(finiteOr(it->maximum, spinLimit), spinLimit)));
            }
            setSpin(m_item->parameter(key).toDouble());
            const bool enabled = m_item->properties().enabled(*m_item, key);
            spinBase->setEnabled(enabled);
            if (slider)
                slider->setEnabled(enabled);
        }});
        if (slider) {
            // Both must stay usable in a narrow dock: a slider squeezed to a few pixels looks
            // like a check box.
            slider->setMinimumWidth(70);
            spinBase->setMinimumWidth(64);
            row = new QWidget;
            auto *h = new QHBoxLayout(row);
            h->setContentsMargins(0, 0, 0, 0);
            h->addWidget(slider, 1);
            h->addWidget(spinBase);
        } else {
            row = spinBase;
        }
        break;
    }
    case ParameterInfo::Type::Choice: {
        auto *combo = compactCombo();
        combo->addItems(info.choices);
        combo->setToolTip(info.toolTip);
        combo->setEnabled(!info.readOnly);
        connect(combo, &QComboBox::currentIndexChanged, this,
                [this, key](int i) { apply(key, i); });
        m_bindings.append({key, [this, key, combo](const Infos &infos) {
            const QSignalBlocker block(combo);
            // Choices that follow the project (a plot's sources) or the state (a layout).
            if (const auto it = infos.find(key); it != infos.end()) {
                QStringList now;
                for (int i = 0; i < combo->count(); ++i)
                    now << combo->itemText(i);
                if (now != it->choices) {
                    combo->clear();
                    combo->addItems(it->choices);
                }
                combo->setEnabled(!it->readOnly && m_item->properties().enabled(*m_item, key));
            }
            combo->setCurrentIndex(m_item->parameter(key).toInt());
        }});
        m_editors.insert(key, combo);
        row = combo;
        break;
    }
    case ParameterInfo::Type::Complex: {
        auto *re = realSpin(-spinLimit, spinLimit);
        auto *im = realSpin(-spinLimit, spinLimit);
        re->setPrefix(tr("Re "));
        im->setPrefix(tr("Im "));
        re->setRefusal(refusal(info.label));
        im->setRefusal(refusal(info.label));
        re->setToolTip(info.toolTip);
        im->setToolTip(info.toolTip);
        const auto send = [this, key, re, im] { apply(key, QPointF(re->value(), im->value())); };
        connect(re, &QDoubleSpinBox::valueChanged, this, send);
        connect(im, &QDoubleSpinBox::valueChanged, this, send);
        // Dragging t in its plane (the discs of 004 Fig. 3.3): one gesture, one undo step,
        // every view updated on the way.
        auto *plane = new ComplexPlanePicker;
        plane->setObjectName(QStringLiteral("complexPlane:") + key);
        auto gesture = std::make_shared<int>(0);
        connect(plane, &ComplexPlanePicker::pressed, this,
                [this, gesture, key] { *gesture = beginGesture(key); });
        connect(plane, &ComplexPlanePicker::moved, this,
                [this, key, gesture](const QPointF &t) { apply(key, t, *gesture); });
        connect(plane, &ComplexPlanePicker::released, this,
                [this, gesture] { endGesture(*gesture); *gesture = 0; });
        m_bindings.append({key, [this, key, re, im, plane](const Infos &) {
            const QPointF z = m_item->parameter(key).toPointF();
            const QSignalBlocker b1(re), b2(im);
            re->setValue(z.x());
            im->setValue(z.y());
            plane->setValue(z);
        }});
        m_editors.insert(key, re);
        // Stacked: side by side they do not fit a narrow dock.
        row = new QWidget;
        auto *v = new QVBoxLayout(row);
        v->setContentsMargins(0, 0, 0, 0);
        v->addWidget(re);
        v->addWidget(im);
        v->addWidget(plane);
        break;
    }
    case ParameterInfo::Type::Bool: {
        auto *check = new QCheckBox;
        check->setToolTip(info.toolTip);
        connect(check, &QCheckBox::toggled, this, [this, key](bool on) { apply(key, on); });
        m_bindings.append({key, [this, key, check](const Infos &) {
            const QSignalBlocker block(check);
            check->setChecked(m_item->parameter(key).toBool());
        }});
        m_editors.insert(key, check);
        row = check;
        break;
    }
    case ParameterInfo::Type::Text: {
        if (info.readOnly) {
            auto *shown = new QLabel;
            shown->setWordWrap(true);
            shown->setTextInteractionFlags(Qt::TextSelectableByMouse);
            shown->setToolTip(info.toolTip);
            m_bindings.append({key, [this, key, shown](const Infos &) {
                shown->setText(m_item->parameter(key).toString());
            }});
            row = shown;
            break;
        }
        // Committed when typing ends (Return or focus out): one edit, one undo step; a
        // refused text comes back as the item has it, with the reason.
        auto *line = new QLineEdit;
        line->setToolTip(info.toolTip);
        line->setObjectName(QStringLiteral("text:") + key);
        connect(line, &QLineEdit::editingFinished, this, [this, key, line] {
            if (line->text() != m_item->parameter(key).toString())
                apply(key, line->text());
        });
        m_bindings.append({key, [this, key, line](const Infos &) {
            const QSignalBlocker block(line);
            line->setText(m_item->parameter(key).toString());
            line->setCursorPosition(0);  // the text's start, not its tail
            line->setToolTip(line->text().size() > 30 ? line->text() : QString());
            line->setEnabled(m_item->properties().enabled(*m_item, key));
        }});
        m_editors.insert(key, line);
        row = line;
        break;
    }
    }
    auto *label = new QLabel(info.label + QLatin1Char(':'));
    label->setToolTip(info.toolTip);
    form->addRow(label, row);
}

} // namespace awb
