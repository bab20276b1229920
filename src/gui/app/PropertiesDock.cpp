#include "gui/app/PropertiesDock.h"

#include "gui/app/CompactEditors.h"
#include "gui/app/FrameBudget.h"
#include "gui/app/Messages.h"
#include "gui/app/WheelGuard.h"
#include "gui/views/ComplexPlanePicker.h"
#include "model/AttractorItem.h"
#include "model/EigenvaluePlotItem.h"
#include "model/NumberFormat.h"
#include "model/Project.h"

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

// The start set's default points when its kind changes: taken from the control polygon so that
// the new set lies where the curve is.
PointList startPoints(StartSetSpec::Kind kind, const PointList &control)
{
    PointList c = control.empty() ? PointList{{0, 0}, {1, 0}, {0.5, 1}} : control;
    const Point first = c.front(), last = c.back(), middle = c[c.size() / 2];
    switch (kind) {
    case StartSetSpec::Kind::Point: {
        Point m;
        for (const auto &p : c)
            m = {m.x + p.x / double(c.size()), m.y + p.y / double(c.size()),
                 m.z + p.z / double(c.size())};
        return {m};
    }
    case StartSetSpec::Kind::Segment: return {first, last};
    case StartSetSpec::Kind::Triangle:
        if (c.size() < 3)
            return {{0, 0}, {1, 0}, {0.5, 1}};
        return {first, middle, last};
    case StartSetSpec::Kind::Polygon:
        if (c.size() < 3)
            return {{0, 0}, {1, 0}, {0.5, 1}};
        return c;
    case StartSetSpec::Kind::Points: return c;
    case StartSetSpec::Kind::Lifted: return c;  // not offered by the kind box
    case StartSetSpec::Kind::VertexLimits: return {};  // mesh items
    }
    return c;
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
        const auto update = [this] { updateValues(); };
        m_connections << connect(item->project(), &Project::itemInserted, this, update);
        m_connections << connect(item->project(), &Project::itemRemoved, this, update);
        m_connections << connect(item->project(), &Project::itemChanged, this, update);
    }
    rebuild();
}

QWidget *PropertiesWidget::editor(const QString &key) const { return m_editors.value(key); }
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
        for (const Binding &b : std::as_const(m_bindings))
            if (!m_gestureKey.isEmpty() && b.key == m_gestureKey)
                b.update();
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

void PropertiesWidget::updateValues()
{
    ++m_updating;
    for (const Binding &b : std::as_const(m_bindings))
        b.update();
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

    auto *itemBox = new QGroupBox(m_item->typeName());
    auto *itemForm = new QFormLayout(itemBox);
    auto *name = new QLineEdit;
    itemForm->addRow(tr("&Name:"), name);
    m_editors.insert(QStringLiteral("name"), name);
    connect(name, &QLineEdit::editingFinished, this, [this, name] {
        if (!m_item || m_updating || name->text() == m_item->name())
            return;
        if (!m_item->setName(name->text())) {
            QString why = tr("The name is empty or already taken.");
            if (m_item->project())
                if (auto p = m_item->project()->checkName(m_item, name->text()))
                    why = p->message;
            name->setText(m_item->name());
            report(why);
        }
    });
    m_bindings.append({QStringLiteral("name"), [this, name] {
        if (!name->hasFocus()) {
            name->setText(m_item->name());
            name->setCursorPosition(0); // the name's start, not its tail
            name->setToolTip(m_item->name());
        }
    }});
    content->addWidget(itemBox);

    // Parameters, grouped by their heading.
    QMap<QString, QFormLayout *> groups;
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
    }
    if (qobject_cast<AttractorItem *>(m_item.data()))
        addAttractorEditors();
    if (qobject_cast<EigenvaluePlotItem *>(m_item.data()))
        addEigenvaluePlotEditors();
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
            m_bindings.append({key, [this, key, slider, lo, hi, steps] {
                if (slider->isSliderDown())
                    return;  // never move the slider under the user's hand
                const double v = m_item->parameter(key).toDouble();
                const QSignalBlocker block(slider);
                slider->setValue(int(std::lround((v - lo) / (hi - lo) * steps)));
            }});
        }
        m_bindings.append({key, [this, key, spinBase, setSpin] {
            const QSignalBlocker block(spinBase);
            setSpin(m_item->parameter(key).toDouble());
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
        connect(combo, &QComboBox::currentIndexChanged, this,
                [this, key](int i) { apply(key, i); });
        m_bindings.append({key, [this, key, combo] {
            const QSignalBlocker block(combo);
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
        m_bindings.append({key, [this, key, re, im, plane] {
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
        m_bindings.append({key, [this, key, check] {
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
            m_bindings.append({key, [this, key, shown] {
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
        m_bindings.append({key, [this, key, line] {
            const QSignalBlocker block(line);
            line->setText(m_item->parameter(key).toString());
            line->setCursorPosition(0);
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

void PropertiesWidget::addAttractorEditors()
{
    auto *item = qobject_cast<AttractorItem *>(m_item.data());
    auto *content = static_cast<QVBoxLayout *>(m_content->layout());

    // ---- start set
    auto *startBox = new QGroupBox(tr("Start set X0"));
    auto *startForm = new QFormLayout(startBox);
    auto *startKind = compactCombo();
    startKind->addItems({tr("Point"), tr("Segment"), tr("Triangle"), tr("Polygon"),
                         tr("Points"), tr("Lifted points"), tr("Vertex limits")});
    startForm->addRow(tr("Kind:"), startKind);
    // A mesh starts at its vertices' exact limit positions: nothing to drag or type.
    const bool mesh = item->startsAtVertexLimits();
    auto *dragHint = new QLabel(
        mesh ? tr("Vertex limits: the exact limit positions of the mesh's vertices, where its "
                  "IFS with condensation starts. Drag the control points in the 3D view; click "
                  "a purple diamond to analyse that extraordinary vertex.")
             : tr("Drag its vertices in the attractor view."));
    dragHint->setWordWrap(true);
    startForm->addRow(dragHint);
    // Points of the lifted space (000 §2, Fig. 2 "a random homogeneous point"): typed, since
    // the extra coordinates cannot be dragged in the plane.
    auto *lifted = new QLineEdit;
    lifted->setToolTip(tr("Points of the lifted space of 000 §2: x, y, then the extra "
                          "coordinates of the lifting, the homogeneous 1 implied. Commas "
                          "between coordinates, ';' between points."));
    startForm->addRow(tr("Lifted:"), lifted);
    startForm->setRowVisible(lifted, !mesh);
    m_editors.insert(QStringLiteral("start.lifted"), lifted);
    const auto setLifted = [this, item](const std::vector<std::vector<double>> &points) {
        StartSetSpec s;
        s.kind = StartSetSpec::Kind::Lifted;
        s.points.clear();
        s.lifted = points;
        QString why;
        if (const auto d = item->derivedIfs()) {
            try {
                liftedStartPoints(*d, points);
            } catch (const std::exception &e) {
                why = QString::fromUtf8(e.what());
            }
        } else {
            why = item->derivedError();
        }
        if (why.isEmpty())
            if (auto p = item->checkStartSet(s))
                why = p->message;
        if (!why.isEmpty() || !item->setStartSet(s)) {
            report(why.isEmpty() ? tr("The start set was refused.") : why);
            updateValues();
        }
    };
    m_editors.insert(QStringLiteral("start.kind"), startKind);
    connect(startKind, &QComboBox::currentIndexChanged, this, [this, item, setLifted](int i) {
        if (m_updating)
            return;
        StartSetSpec s;
        s.kind = StartSetSpec::Kind(i);
        if (s.kind == StartSetSpec::Kind::VertexLimits) {
            s.points.clear();
            if (auto p = item->checkStartSet(s); p || !item->setStartSet(s)) {
                report(p ? p->message : tr("The start set was refused."));
                updateValues();
            }
            return;
        }
        if (s.kind == StartSetSpec::Kind::Lifted) {
            // The centroid of the control points, lifted with zero extra coordinates.
            const auto d = item->derivedIfs();
            const PointList control = item->controlPointSetCount() ? item->controlPoints(0)
                                                                   : PointList{};
            if (!d || control.empty()) {
                report(d ? tr("The item has no control points.") : item->derivedError());
                updateValues();
                return;
            }
            const int dim = item->pointDimension();
            const Mat centroid = toMatrix(control, dim).colwise().mean();
            Mat X;
            try {
                X = d->toIfsSpace(centroid);
            } catch (const std::exception &e) {
                report(QString::fromUtf8(e.what()));
                updateValues();
                return;
            }
            setLifted({std::vector<double>(X.data(), X.data() + X.size())});
            return;
        }
        s.points = startPoints(s.kind, item->controlPointSetCount() ? item->controlPoints(0)
                                                                    : PointList{});
        if (auto p = item->checkStartSet(s); p || !item->setStartSet(s)) {
            report(p ? p->message : tr("The start set was refused."));
            updateValues();
        }
    });
    connect(lifted, &QLineEdit::editingFinished, this, [this, lifted, setLifted] {
        if (m_updating)
            return;
        std::vector<std::vector<double>> points;
        for (const QString &point : lifted->text().split(';', Qt::SkipEmptyParts)) {
            std::vector<double> p;
            for (const QString &n : point.split(',', Qt::SkipEmptyParts)) {
                const auto v = parseNumber(n.trimmed());
                if (!v) {
                    report(tr("'%1' is not a number.").arg(n.trimmed()));
                    updateValues();
                    return;
                }
                p.push_back(*v);
            }
            points.push_back(std::move(p));
        }
        setLifted(points);
    });
    m_bindings.append({QStringLiteral("start.kind"), [item, startKind, lifted] {
        const QSignalBlocker block(startKind);
        startKind->setCurrentIndex(int(item->startSet().kind));
        const QSignalBlocker block2(lifted);
        const bool isLifted = item->startSet().kind == StartSetSpec::Kind::Lifted;
        QStringList text;
        for (const auto &p : item->startSet().lifted) {
            QStringList c;
            for (double v : p)
                c << QString::number(v, 'g', 12);
            text << c.join(QStringLiteral(", "));
        }
        lifted->setText(isLifted ? text.join(QStringLiteral("; ")) : QString());
        lifted->setEnabled(isLifted);
    }});
    content->addWidget(startBox);

    // ---- algorithm
    auto *algBox = new QGroupBox(tr("Algorithm"));
    auto *algForm = new QFormLayout(algBox);
    auto *mode = compactCombo();
    mode->addItems({tr("Deterministic"), tr("Random (chaos game)")});
    auto *depth = wholeSpin(0, AlgorithmSpec::maxDepth);
    depth->setRefusal(refusal(tr("Depth")));
    auto *samples = wholeSpin(1, 100'000'000);
    samples->setSingleStep(10000);
    samples->setRefusal(refusal(tr("Samples")));
    algForm->addRow(tr("Mode:"), mode);
    algForm->addRow(tr("Depth:"), depth);
    algForm->addRow(tr("Samples:"), samples);
    m_editors.insert(QStringLiteral("algorithm.depth"), depth);
    const auto setAlg = [this, item](const std::function<void(AlgorithmSpec &)> &edit) {
        if (m_updating)
            return;
        AlgorithmSpec a = item->algorithm();
        edit(a);
        if (auto p = item->checkAlgorithm(a)) {
            updateValues();
            report(p->message);
            return;
        }
        item->setAlgorithm(a);
    };
    connect(mode, &QComboBox::currentIndexChanged, this,
            [setAlg](int i) { setAlg([i](AlgorithmSpec &a) { a.mode = AlgorithmSpec::Mode(i); }); });
    connect(depth, &QSpinBox::valueChanged, this,
            [setAlg](int v) { setAlg([v](AlgorithmSpec &a) { a.depth = v; }); });
    connect(samples, &QSpinBox::valueChanged, this,
            [setAlg](int v) { setAlg([v](AlgorithmSpec &a) { a.samples = v; }); });
    m_bindings.append({QStringLiteral("algorithm"), [item, mode, depth, samples] {
        const QSignalBlocker b1(mode), b2(depth), b3(samples);
        const AlgorithmSpec &a = item->algorithm();
        // The deepest level this item's maps allow (N^k images at most 2^31): typing more is
        // refused with that number.
        depth->setMaximum(std::max(a.depth, AlgorithmSpec::maxDepthFor(item->mapCount())));
        mode->setCurrentIndex(int(a.mode));
        depth->setValue(a.depth);
        samples->setValue(int(std::min<qint64>(a.samples, 100'000'000)));
        depth->setEnabled(a.mode == AlgorithmSpec::Mode::Deterministic);
        samples->setEnabled(a.mode == AlgorithmSpec::Mode::Random);
    }});
    content->addWidget(algBox);

    // ---- style
    auto *styleBox = new QGroupBox(tr("Style"));
    auto *styleForm = new QFormLayout(styleBox);
    auto *colorBy = compactCombo();
    colorBy->addItems({tr("By map"), tr("By address prefix"), tr("Single colour")});
    auto *prefix = wholeSpin(1, StyleSpec::maxPrefixLength);
    prefix->setRefusal(refusal(tr("Prefix length")));
    auto *pointSize = realSpin(0.5, StyleSpec::maxPointSize);
    pointSize->setSingleStep(0.5);
    pointSize->setMinimumWidth(70);
    pointSize->setRefusal(refusal(tr("Point size")));
    styleForm->addRow(tr("Colour:"), colorBy);
    styleForm->addRow(tr("Prefix length:"), prefix);
    styleForm->addRow(tr("Point size:"), pointSize);
    addPaletteEditor(styleForm);
    m_editors.insert(QStringLiteral("style.colorBy"), colorBy);
    const auto setStyle = [this, item](const std::function<void(StyleSpec &)> &edit) {
        if (m_updating)
            return;
        StyleSpec s = item->style();
        edit(s);
        if (auto p = item->checkStyle(s)) {
            updateValues();
            report(p->message);
            return;
        }
        item->setStyle(s);
    };
    connect(colorBy, &QComboBox::currentIndexChanged, this, [setStyle](int i) {
        setStyle([i](StyleSpec &s) { s.colorBy = StyleSpec::ColorBy(i); });
    });
    connect(prefix, &QSpinBox::valueChanged, this,
            [setStyle](int v) { setStyle([v](StyleSpec &s) { s.prefixLength = v; }); });
    connect(pointSize, &QDoubleSpinBox::valueChanged, this,
            [setStyle](double v) { setStyle([v](StyleSpec &s) { s.pointSize = v; }); });
    m_bindings.append({QStringLiteral("style"), [item, colorBy, prefix, pointSize] {
        const QSignalBlocker b1(colorBy), b2(prefix), b3(pointSize);
        colorBy->setCurrentIndex(int(item->style().colorBy));
        prefix->setValue(item->style().prefixLength);
        prefix->setEnabled(item->style().colorBy == StyleSpec::ColorBy::Address);
        pointSize->setValue(item->style().pointSize);
    }});
    content->addWidget(styleBox);

    addPointEditors();
}

} // namespace awb
