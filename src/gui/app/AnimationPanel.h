#pragma once
// AnimationPanel: parameter animation (issue 16, part 2), the content of the Animation dock
// (layer 3, GUI). It edits the current item's keyframes — every edit one undo step through
// Item::setAnimation — and plays them: Play/Pause, Stop and a time slider with one step per
// frame. While playing or scrubbed the views show a frame, a copy of the item with the values
// at that time (model/Animation.h: the same copy `attractor-cli animate` renders), through
// ItemController::showFrame: the attractor, the spectrum (its eigenvalues move in the complex
// plane) and the matrices follow; the document itself does not move, and the views refuse
// edits until Stop returns them to the item.
//
// Keying works as in animation programs: set a value in the Properties dock (or drag a
// control point), move the slider to a time, choose the parameter and press Set Key.
#include <QPointer>
#include <QWidget>
#include <QElapsedTimer>
#include <memory>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSlider;
class QTimer;
class QToolButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace awb {

class Item;
struct AnimationSpec;

class AnimationPanel : public QWidget {
    Q_OBJECT
public:
    explicit AnimationPanel(QWidget *parent = nullptr);
    ~AnimationPanel() override;

    // The item whose animation is edited (stops a preview of the previous one).
    void setItem(Item *item);
    Item *item() const { return m_item; }

    // The time shown, in seconds (a frame time: k / fps).
    double time() const;
    int frame() const;
    // Shows frame `frame` (clamped): the views follow. Starts the preview.
    void setFrame(int frame);
    bool isPlaying() const;
    bool isPreviewing() const { return m_previewing; }
    // The copy shown (nullptr when the views show the item).
    std::shared_ptr<Item> shownFrame() const { return m_frame; }

    // Adds or replaces the key of `target` at the current time with the item's present value
    // (one undo step). False with *error saying why.
    bool setKey(const QString &target, QString *error = nullptr);
    // Removes the selected key (or track, when a track is selected). One undo step.
    bool removeSelected(QString *error = nullptr);

public slots:
    void play();
    void pause();
    void togglePlay();
    // Back to the item itself, at time 0.
    void stop();

signals:
    // The views should draw `frame` instead of the item (nullptr: the item itself).
    void frameChanged(std::shared_ptr<Item> frame);
    // An edit was refused or a frame could not be made: the message says why.
    void problem(const QString &message);
    // Play started or ended (a gesture for the window's FrameBudget).
    void playingChanged(bool playing);

private:
    void rebuild();           // the widgets from the item's animation
    void rebuildTargets();
    void showTrackOptions();
    void updateTimeLabel();
    void updateFrame();       // makes and emits the frame at the slider's time
    void tick();
    bool commit(const AnimationSpec &spec, QString *error = nullptr);
    // The selected track and key (-1 when none).
    int selectedTrack() const;
    int selectedKey() const;
    void onTreeEdited(QTreeWidgetItem *row, int column);
    void onTrackOptionEdited();

    QPointer<Item> m_item;
    std::shared_ptr<Item> m_frame;
    bool m_previewing = false;
    bool m_rebuilding = false;

    QToolButton *m_play = nullptr;
    QToolButton *m_stop = nullptr;
    QSlider *m_slider = nullptr;
    QLabel *m_timeLabel = nullptr;
    QCheckBox *m_loop = nullptr;
    QDoubleSpinBox *m_duration = nullptr;
    QDoubleSpinBox *m_fps = nullptr;
    QTreeWidget *m_tree = nullptr;
    QComboBox *m_target = nullptr;
    QPushButton *m_setKey = nullptr;
    QPushButton *m_remove = nullptr;
    QWidget *m_trackBox = nullptr;
    QComboBox *m_path = nullptr;
    QComboBox *m_easing = nullptr;
    QLineEdit *m_center = nullptr;
    QDoubleSpinBox *m_turns = nullptr;
    QLabel *m_status = nullptr;
    QTimer *m_timer = nullptr;
    QElapsedTimer m_clock;
    double m_playStart = 0.0;  // the time at which the clock started
};

} // namespace awb
