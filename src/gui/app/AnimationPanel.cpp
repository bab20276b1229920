#include "gui/app/AnimationPanel.h"

#include "model/Animation.h"
#include "model/Item.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSlider>
#include <QStyle>
#include <QTimer>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace awb {

namespace {

constexpr int trackRole = Qt::UserRole;
constexpr int keyRole = Qt::UserRole + 1;

QString valueText(const std::vector<double> &v)
{
    QStringList parts;
    for (double x : v)
        parts << QString::number(x, 'g', 10);
    return parts.join(QStringLiteral(", "));
}

// "0.5", "0.5, 0.25" or "0.5 0.25": the numbers, or empty when one does not parse.
std::vector<double> parseValue(const QString &text)
{
    static const QRegularExpression sep(QStringLiteral("[,;\\s]+"));
    std::vector<double> v;
    for (const QString &part : text.trimmed().split(sep, Qt::SkipEmptyParts)) {
        bool ok = false;
        const double x = part.toDouble(&ok);
        if (!ok || !std::isfinite(x))
            return {};
        v.push_back(x);
    }
    return v;
}

QString targetLabel(const Item &item, const QString &target)
{
    for (const AnimationTarget &t : animationTargets(item))
        if (t.key == target)
            return t.label;
    return target;
}

} // namespace

AnimationPanel::AnimationPanel(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);

    // Transport: play/pause, stop, the time slider (one step per frame), the time.
    auto *transport = new QHBoxLayout;
    m_play = new QToolButton;
    m_play->setObjectName(QStringLiteral("animationPlay"));
    m_play->setIcon(QIcon::fromTheme(QStringLiteral("media-playback-start"),
                                     style()->standardIcon(QStyle::SP_MediaPlay)));
    m_play->setToolTip(tr("Play / pause the animation (Ctrl+Space)"));
    m_stop = new QToolButton;
    m_stop->setObjectName(QStringLiteral("animationStop"));
    m_stop->setIcon(QIcon::fromTheme(QStringLiteral("media-playback-stop"),
                                     style()->standardIcon(QStyle::SP_MediaStop)));
    m_stop->setToolTip(tr("Stop: the views show the item itself again"));
    m_slider = new QSlider(Qt::Horizontal);
    m_slider->setObjectName(QStringLiteral("animationSlider"));
    m_slider->setToolTip(tr("Time: drag to see the frames (the views follow)"));
    m_timeLabel = new QLabel;
    m_timeLabel->setObjectName(QStringLiteral("animationTime"));
    m_timeLabel->setMinimumWidth(60);
    m_timeLabel->setToolTip(tr("Time and frame number"));
    m_loop = new QCheckBox(tr("Loop"));
    m_loop->setChecked(true);
    m_play->setText(tr("Play"));
    m_stop->setText(tr("Stop"));
    for (QToolButton *b : {m_play, m_stop})
        b->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    transport->addWidget(m_play);
    transport->addWidget(m_stop);
    transport->addWidget(m_timeLabel, 1);
    layout->addWidget(m_slider);
    layout->addLayout(transport);

    auto *timing = new QHBoxLayout;
    m_duration = new QDoubleSpinBox;
    m_duration->setObjectName(QStringLiteral("animationDuration"));
    m_duration->setRange(0.04, AnimationSpec::maxDuration);
    m_duration->setDecimals(2);
    m_duration->setSuffix(tr(" s"));
    m_duration->setKeyboardTracking(false);
    m_fps = new QDoubleSpinBox;
    m_fps->setObjectName(QStringLiteral("animationFps"));
    m_fps->setRange(1, AnimationSpec::maxFps);
    m_fps->setDecimals(1);
    m_fps->setKeyboardTracking(false);
    m_duration->setToolTip(tr("Duration of the animation"));
    m_fps->setToolTip(tr("Frames per second"));
    m_fps->setSuffix(tr(" fps"));
    timing->addWidget(m_duration);
    timing->addWidget(m_fps);
    timing->addWidget(m_loop);
    timing->addStretch(1);
    layout->addLayout(timing);

    m_tree = new QTreeWidget;
    m_tree->setObjectName(QStringLiteral("animationTracks"));
    m_tree->setColumnCount(2);
    m_tree->setHeaderLabels({tr("Parameter / key time (s)"), tr("Value")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_tree->header()->setSectionResizeMode(1, QHeaderView::Stretch);
    m_tree->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    m_tree->setToolTip(tr("Double-click a key's time or value to edit it"));
    layout->addWidget(m_tree, 1);

    auto *keying = new QHBoxLayout;
    m_target = new QComboBox;
    m_target->setObjectName(QStringLiteral("animationTarget"));
    m_target->setToolTip(tr("The parameter, probabilities or control point to key"));
    m_target->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_target->setMinimumContentsLength(8);
    m_setKey = new QPushButton(tr("Set Key"));
    m_setKey->setObjectName(QStringLiteral("animationSetKey"));
    m_setKey->setToolTip(tr("Store the item's present value of the parameter at the time "
                            "shown (replaces a key at that time)"));
    m_remove = new QPushButton(tr("Remove"));
    m_remove->setObjectName(QStringLiteral("animationRemove"));
    m_remove->setToolTip(tr("Remove the selected key, or the selected track with its keys"));
    layout->addWidget(m_target);
    keying->addWidget(m_setKey);
    keying->addWidget(m_remove);
    keying->addStretch(1);
    layout->addLayout(keying);

    // The selected track's interpolation and path.
    m_trackBox = new QWidget;
    auto *form = new QFormLayout(m_trackBox);
    form->setContentsMargins(0, 0, 0, 0);
    m_easing = new QComboBox;
    m_easing->setObjectName(QStringLiteral("animationEasing"));
    m_easing->addItems({tr("Linear"), tr("Smooth (ease in and out)")});
    m_path = new QComboBox;
    m_path->setObjectName(QStringLiteral("animationPath"));
    m_path->addItems({tr("Through the keys"), tr("Circle about a centre")});
    m_center = new QLineEdit;
    m_center->setObjectName(QStringLiteral("animationCenter"));
    m_center->setPlaceholderText(tr("x, y"));
    m_turns = new QDoubleSpinBox;
    m_turns->setObjectName(QStringLiteral("animationTurns"));
    m_turns->setRange(-1000, 1000);
    m_turns->setDecimals(2);
    m_turns->setKeyboardTracking(false);
    form->addRow(tr("Interpolation"), m_easing);
    form->addRow(tr("Path"), m_path);
    form->addRow(tr("Centre"), m_center);
    form->addRow(tr("Turns"), m_turns);
    layout->addWidget(m_trackBox);

    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("animationStatus"));
    m_status->setWordWrap(true);
    layout->addWidget(m_status);

    m_timer = new QTimer(this);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &AnimationPanel::tick);
    connect(m_play, &QToolButton::clicked, this, &AnimationPanel::togglePlay);
    connect(m_stop, &QToolButton::clicked, this, &AnimationPanel::stop);
    connect(m_slider, &QSlider::valueChanged, this, [this] {
        updateTimeLabel();
        if (!m_rebuilding)
            updateFrame();
    });
    connect(m_slider, &QSlider::sliderPressed, this, &AnimationPanel::pause);
    const auto timingEdited = [this] {
        if (m_rebuilding || !m_item)
            return;
        AnimationSpec spec = m_item->animation();
        spec.duration = m_duration->value();
        spec.fps = m_fps->value();
        for (AnimationTrack &t : spec.tracks) // keys past the new end are dropped
            std::erase_if(t.keys, [&](const AnimationKey &k) { return k.time > spec.duration; });
        std::erase_if(spec.tracks, [](const AnimationTrack &t) { return t.keys.empty(); });
        if (spec.isEmpty()) { // nothing keyed yet: the timing is kept for the first key
            rebuild();
            return;
        }
        commit(spec);
    };
    connect(m_duration, &QDoubleSpinBox::valueChanged, this, timingEdited);
    connect(m_fps, &QDoubleSpinBox::valueChanged, this, timingEdited);
    connect(m_setKey, &QPushButton::clicked, this, [this] {
        QString error;
        if (!setKey(m_target->currentData().toString(), &error))
            emit problem(error);
    });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        QString error;
        if (!removeSelected(&error))
            emit problem(error);
    });
    connect(m_tree, &QTreeWidget::itemChanged, this, &AnimationPanel::onTreeEdited);
    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this] {
        showTrackOptions();
        // Keying the selected track is the natural next step.
        const int t = selectedTrack();
        if (t >= 0 && m_item) {
            const int i = m_target->findData(m_item->animation().tracks[std::size_t(t)].target);
            if (i >= 0)
                m_target->setCurrentIndex(i);
        }
    });
    connect(m_easing, &QComboBox::currentIndexChanged, this, &AnimationPanel::onTrackOptionEdited);
    connect(m_path, &QComboBox::currentIndexChanged, this, &AnimationPanel::onTrackOptionEdited);
    connect(m_center, &QLineEdit::editingFinished, this, &AnimationPanel::onTrackOptionEdited);
    connect(m_turns, &QDoubleSpinBox::valueChanged, this, &AnimationPanel::onTrackOptionEdited);
    rebuild();
}

AnimationPanel::~AnimationPanel() = default;

void AnimationPanel::setItem(Item *item)
{
    if (item == m_item)
        return;
    const bool wasPlaying = isPlaying();
    m_timer->stop();
    if (wasPlaying)
        emit playingChanged(false);
    if (m_item)
        disconnect(m_item, nullptr, this, nullptr);
    const bool wasPreviewing = m_previewing;
    m_previewing = false;
    m_frame.reset();
    m_item = item;
    if (item) {
        connect(item, &Item::animationChanged, this, [this] {
            rebuild();
            if (m_previewing)
                updateFrame();
        });
        // Another input edited (Properties, a drag before the preview): the targets and, when
        // previewing, the frame follow.
        connect(item, &Item::changed, this, [this] {
            rebuildTargets();
            if (m_previewing)
                updateFrame();
        });
    }
    m_rebuilding = true;
    m_slider->setValue(0);
    m_rebuilding = false;
    rebuild();
    if (wasPreviewing)
        emit frameChanged(nullptr);
}

double AnimationPanel::time() const
{
    return m_item ? m_item->animation().frameTime(m_slider->value()) : 0.0;
}

int AnimationPanel::frame() const { return m_slider->value(); }

void AnimationPanel::setFrame(int frame)
{
    m_slider->setValue(frame);
    if (!m_previewing)
        updateFrame();
}

bool AnimationPanel::isPlaying() const { return m_timer->isActive(); }

void AnimationPanel::play()
{
    if (!m_item || m_item->animation().isEmpty())
        return;
    const AnimationSpec &spec = m_item->animation();
    if (m_slider->value() >= m_slider->maximum())
        m_slider->setValue(0);
    m_playStart = time();
    m_clock.start();
    const bool wasPlaying = isPlaying();
    m_timer->start(std::max(1, int(std::lround(1000.0 / spec.fps))));
    if (!wasPlaying)
        emit playingChanged(true);
    m_play->setIcon(QIcon::fromTheme(QStringLiteral("media-playback-pause"),
                                     style()->standardIcon(QStyle::SP_MediaPause)));
    m_play->setText(tr("Pause"));
    updateFrame();
}

void AnimationPanel::pause()
{
    const bool wasPlaying = isPlaying();
    m_timer->stop();
    if (wasPlaying)
        emit playingChanged(false);
    m_play->setIcon(QIcon::fromTheme(QStringLiteral("media-playback-start"),
                                     style()->standardIcon(QStyle::SP_MediaPlay)));
    m_play->setText(tr("Play"));
}

void AnimationPanel::togglePlay()
{
    if (isPlaying())
        pause();
    else
        play();
}

void AnimationPanel::stop()
{
    pause();
    m_rebuilding = true;
    m_slider->setValue(0);
    m_rebuilding = false;
    updateTimeLabel();
    if (m_previewing) {
        m_previewing = false;
        m_frame.reset();
        emit frameChanged(nullptr);
    }
    m_status->setText(m_item && !m_item->animation().isEmpty()
                          ? tr("The views show the item itself.")
                          : QString());
}

void AnimationPanel::tick()
{
    if (!m_item)
        return;
    const AnimationSpec &spec = m_item->animation();
    double t = m_playStart + m_clock.elapsed() / 1000.0;
    if (t > spec.duration) {
        if (!m_loop->isChecked()) {
            m_slider->setValue(m_slider->maximum());
            pause();
            return;
        }
        t = std::fmod(t, spec.duration + 1.0 / spec.fps);
        m_playStart = t;
        m_clock.start();
    }
    // The frame due now: a slow frame is skipped, not queued (the renderer's latest wins).
    m_slider->setValue(std::clamp(int(std::floor(t * spec.fps + 1e-9)), 0, m_slider->maximum()));
}

void AnimationPanel::updateTimeLabel()
{
    const AnimationSpec *spec = m_item ? &m_item->animation() : nullptr;
    if (!spec || spec->isEmpty()) {
        m_timeLabel->setText(QStringLiteral("–"));
        return;
    }
    m_timeLabel->setText(tr("%1 s · %2/%3")
                             .arg(time(), 0, 'f', 2)
                             .arg(m_slider->value())
                             .arg(spec->frameCount() - 1));
}

void AnimationPanel::updateFrame()
{
    if (!m_item || m_item->animation().isEmpty())
        return;
    QString error;
    std::unique_ptr<Item> copy = animatedCopy(*m_item, time(), &error);
    m_previewing = true;
    if (!copy) {
        m_frame.reset();
        m_status->setText(tr("Frame at %1 s: %2").arg(time()).arg(error));
        emit problem(error);
        emit frameChanged(nullptr);
        return;
    }
    m_frame = std::shared_ptr<Item>(copy.release());
    m_status->setText(tr("The views show the frame at %1 s (not editable); Stop returns to "
                         "the item.")
                          .arg(time(), 0, 'f', 2));
    emit frameChanged(m_frame);
}

bool AnimationPanel::commit(const AnimationSpec &spec, QString *error)
{
    QString why;
    if (!m_item->setAnimation(spec, &why)) {
        if (error)
            *error = why;
        else
            emit problem(why);
        rebuild(); // the widgets show the animation as it stays
        return false;
    }
    return true;
}

bool AnimationPanel::setKey(const QString &target, QString *error)
{
    if (!m_item) {
        if (error)
            *error = tr("No item is selected.");
        return false;
    }
    QString why;
    const std::vector<double> value = animationValue(*m_item, target, &why);
    if (value.empty()) {
        if (error)
            *error = why;
        return false;
    }
    AnimationSpec spec = m_item->animation();
    if (spec.isEmpty()) {
        spec.duration = m_duration->value();
        spec.fps = m_fps->value();
    }
    const double t = spec.isEmpty() ? 0.0 : time();
    int index = spec.trackIndex(target);
    if (index < 0) {
        spec.tracks.push_back({target, AnimationTrack::Path::Keys, AnimationTrack::Easing::Linear,
                               {}, {}, 1.0});
        index = int(spec.tracks.size()) - 1;
    }
    auto &keys = spec.tracks[std::size_t(index)].keys;
    const auto at = std::lower_bound(keys.begin(), keys.end(), t,
                                     [](const AnimationKey &k, double x) { return k.time < x; });
    if (at != keys.end() && std::abs(at->time - t) < 1e-9)
        at->value = value;
    else
        keys.insert(at, {t, value});
    return commit(spec, error);
}

bool AnimationPanel::removeSelected(QString *error)
{
    const int t = selectedTrack();
    if (!m_item || t < 0) {
        if (error)
            *error = tr("Select a key or a track to remove.");
        return false;
    }
    AnimationSpec spec = m_item->animation();
    const int k = selectedKey();
    auto &keys = spec.tracks[std::size_t(t)].keys;
    if (k >= 0 && keys.size() > 1)
        keys.erase(keys.begin() + k);
    else
        spec.tracks.erase(spec.tracks.begin() + t);
    return commit(spec, error);
}

int AnimationPanel::selectedTrack() const
{
    const QTreeWidgetItem *row = m_tree->currentItem();
    return row ? row->data(0, trackRole).toInt() : -1;
}

int AnimationPanel::selectedKey() const
{
    const QTreeWidgetItem *row = m_tree->currentItem();
    return row && row->parent() ? row->data(0, keyRole).toInt() : -1;
}

void AnimationPanel::rebuildTargets()
{
    const QString current = m_target->currentData().toString();
    const QSignalBlocker block(m_target);
    m_target->clear();
    if (m_item)
        for (const AnimationTarget &t : animationTargets(*m_item))
            m_target->addItem(t.label, t.key);
    int i = m_target->findData(current);
    if (i < 0 && m_item && !m_item->animation().isEmpty()) // what is animated already
        i = m_target->findData(m_item->animation().tracks.front().target);
    m_target->setCurrentIndex(std::max(0, i));
}

void AnimationPanel::rebuild()
{
    m_rebuilding = true;
    const bool has = m_item != nullptr;
    const AnimationSpec spec = has ? m_item->animation() : AnimationSpec{};
    const bool animated = has && !spec.isEmpty();
    const int track = selectedTrack(), key = selectedKey();
    if (animated) {
        m_duration->setValue(spec.duration);
        m_fps->setValue(spec.fps);
    } else if (m_duration->value() < 0.05) {
        m_duration->setValue(4.0);
        m_fps->setValue(25.0);
    }
    m_slider->setRange(0, animated ? spec.frameCount() - 1 : 0);
    m_tree->clear();
    for (std::size_t t = 0; animated && t < spec.tracks.size(); ++t) {
        const AnimationTrack &tk = spec.tracks[t];
        auto *top = new QTreeWidgetItem(m_tree);
        top->setText(0, targetLabel(*m_item, tk.target));
        top->setToolTip(0, tk.target);
        const bool inactive = animationValue(*m_item, tk.target).empty();
        top->setText(1, inactive ? tr("inactive: %1 has no such input now").arg(m_item->name())
                      : tk.path == AnimationTrack::Path::Circle
                            ? tr("circle about (%1), %2 turns")
                                  .arg(valueText(tk.center))
                                  .arg(tk.turns)
                            : QString());
        if (inactive) {
            top->setForeground(0, palette().brush(QPalette::Disabled, QPalette::Text));
            top->setToolTip(1, tr("The item does not have %1 in its present state (another "
                                  "scheme, fewer points): the track is kept and skipped.")
                                   .arg(tk.target));
        }
        top->setData(0, trackRole, int(t));
        for (std::size_t k = 0; k < tk.keys.size(); ++k) {
            auto *row = new QTreeWidgetItem(top);
            row->setText(0, QString::number(tk.keys[k].time, 'g', 10));
            row->setText(1, valueText(tk.keys[k].value));
            row->setData(0, trackRole, int(t));
            row->setData(0, keyRole, int(k));
            row->setFlags(row->flags() | Qt::ItemIsEditable);
            if (int(t) == track && int(k) == key)
                m_tree->setCurrentItem(row);
        }
        if (int(t) == track && key < 0)
            m_tree->setCurrentItem(top);
    }
    m_tree->expandAll();
    rebuildTargets();
    m_play->setEnabled(animated);
    m_stop->setEnabled(animated);
    m_slider->setEnabled(animated);
    m_setKey->setEnabled(has && m_target->count() > 0);
    m_remove->setEnabled(animated);
    m_target->setEnabled(has);
    m_duration->setEnabled(has);
    m_fps->setEnabled(has);
    if (!has)
        m_status->setText(tr("Select an item to animate its parameters."));
    else if (!animated)
        m_status->setText(m_target->count() > 0
                              ? tr("No keys yet: set a value in Properties, choose it here and "
                                   "press Set Key; then move the slider, change the value and "
                                   "key it again.")
                              : tr("%1 has no numeric parameters to animate.")
                                    .arg(m_item->name()));
    else if (!m_previewing)
        m_status->setText(tr("%1 tracks, %2 frames. Play or drag the slider to preview.")
                              .arg(spec.tracks.size())
                              .arg(spec.frameCount()));
    updateTimeLabel();
    m_rebuilding = false;
    showTrackOptions();
}

void AnimationPanel::showTrackOptions()
{
    const int t = selectedTrack();
    const bool show = m_item && t >= 0 && t < int(m_item->animation().tracks.size());
    m_trackBox->setVisible(show);
    if (!show)
        return;
    const AnimationTrack &track = m_item->animation().tracks[std::size_t(t)];
    const bool wasRebuilding = m_rebuilding;
    m_rebuilding = true;
    m_easing->setCurrentIndex(int(track.easing));
    m_path->setCurrentIndex(int(track.path));
    m_path->setEnabled(track.size() >= 2);
    const bool circle = track.path == AnimationTrack::Path::Circle;
    m_center->setEnabled(circle);
    m_turns->setEnabled(circle);
    m_center->setText(circle ? valueText(track.center) : QString());
    m_turns->setValue(track.turns);
    m_rebuilding = wasRebuilding;
}

void AnimationPanel::onTrackOptionEdited()
{
    const int t = selectedTrack();
    if (m_rebuilding || !m_item || t < 0)
        return;
    AnimationSpec spec = m_item->animation();
    AnimationTrack &track = spec.tracks[std::size_t(t)];
    track.easing = AnimationTrack::Easing(m_easing->currentIndex());
    track.path = AnimationTrack::Path(m_path->currentIndex());
    if (track.path == AnimationTrack::Path::Circle) {
        std::vector<double> c = parseValue(m_center->text());
        if (c.size() != 2) // a first centre: the key's point moved one unit left
            c = {track.keys.front().value.at(0) - 1.0, track.keys.front().value.at(1)};
        track.center = c;
        track.turns = m_turns->value() == 0 ? 1.0 : m_turns->value();
    } else {
        track.center.clear();
        track.turns = 1.0;
    }
    commit(spec);
}

void AnimationPanel::onTreeEdited(QTreeWidgetItem *row, int column)
{
    if (m_rebuilding || !m_item || !row->parent())
        return;
    AnimationSpec spec = m_item->animation();
    const int t = row->data(0, trackRole).toInt();
    const int k = row->data(0, keyRole).toInt();
    if (t < 0 || t >= int(spec.tracks.size()))
        return;
    auto &keys = spec.tracks[std::size_t(t)].keys;
    if (k < 0 || k >= int(keys.size()))
        return;
    AnimationKey key = keys[std::size_t(k)];
    if (column == 0) {
        bool ok = false;
        key.time = row->text(0).toDouble(&ok);
        if (!ok) {
            emit problem(tr("\"%1\" is not a time in seconds").arg(row->text(0)));
            QTimer::singleShot(0, this, &AnimationPanel::rebuild);
            return;
        }
    } else {
        key.value = parseValue(row->text(1));
        if (key.value.size() != keys[std::size_t(k)].value.size()) {
            emit problem(tr("\"%1\": expected %2 numbers")
                             .arg(row->text(1))
                             .arg(keys[std::size_t(k)].value.size()));
            QTimer::singleShot(0, this, &AnimationPanel::rebuild);
            return;
        }
    }
    keys.erase(keys.begin() + k);
    const auto at = std::lower_bound(keys.begin(), keys.end(), key.time,
                                     [](const AnimationKey &a, double x) { return a.time < x; });
    keys.insert(at, key);
    // The tree is rebuilt by animationChanged; not from inside its own itemChanged.
    QTimer::singleShot(0, this, [this, spec] {
        if (m_item)
            commit(spec);
    });
}

} // namespace awb
