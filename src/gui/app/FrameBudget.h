#pragma once
// FrameBudget: who gets the GUI thread while the user moves something. During a gesture -- a
// drag of a handle, a slider, a camera orbit, an animation playing -- the view under the
// pointer gets every frame; the other panels (Matrices, Spectrum, Analysis, Properties) are
// coalesced: each registers an update function with the widget that shows it, marks itself
// dirty on every change, and runs
//   - outside a gesture: once, at the next turn of the event loop (a burst of edits is one
//     update, as before);
//   - during a gesture: at most every panelInterval() and only while its widget is visible
//     (a dock tab behind another tab waits until it is shown);
//   - when the gesture ends: at once, visible or not, so that every panel (which exports and
//     prints read) is up to date with the document.
// Gestures are counted (a drag may start while an animation plays). The project's own gestures
// (Project::gestureActiveChanged: drags and sliders that edit the document) and view-only ones
// (beginGesture/endGesture: an orbit, playback) count alike.

#include <QElapsedTimer>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <functional>

class QWidget;

namespace awb {

class FrameBudget : public QObject {
    Q_OBJECT
public:
    explicit FrameBudget(QObject *parent = nullptr);

    // A panel shown by `widget` (nullptr: always counted visible), brought up to date by
    // `update`. Returns its id.
    int addPanel(QWidget *widget, std::function<void()> update);
    // The panel's content is stale: update it when the budget allows.
    void markDirty(int panel);
    // Runs every dirty panel's update now (visible or not).
    void flush();
    bool isDirty(int panel) const;

    void beginGesture();
    void endGesture();
    bool inGesture() const { return m_gestures > 0; }

    // The least time between two updates of a panel during a gesture (default 250 ms).
    void setPanelInterval(int ms) { m_interval = ms; }
    int panelInterval() const { return m_interval; }

signals:
    void gestureChanged(bool active);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    struct Panel {
        QPointer<QWidget> widget;
        bool hasWidget = false;
        std::function<void()> update;
        bool dirty = false;
        QElapsedTimer last;  // the last update
    };
    bool visible(const Panel &p) const;
    void run(Panel &p);
    // Runs what is due and arms the timer for what is not.
    void service();

    QList<Panel> m_panels;
    QTimer m_timer;
    int m_gestures = 0;
    int m_interval = 250;
};

} // namespace awb
