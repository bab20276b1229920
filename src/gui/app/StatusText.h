#pragma once
// StatusText: a line of text for the status bar that never changes the window's layout. A
// QLabel asks its layout again on every setText (updateGeometry), and the main window's layout
// then measures every dock: the cursor readout, set on every mouse move, made a drag lay out
// the whole window. This widget reserves a width, elides what does not fit and only repaints.
#include <QWidget>

class QFontMetrics;

namespace awb {

// `text` in at most `width` pixels, cut at the end of a word (never mid-word) with "…".
QString elidedAtWord(const QFontMetrics &fm, const QString &text, int width);

class StatusText : public QWidget {
    Q_OBJECT
public:
    // `sample`: a text as wide as the widget should be (it keeps that width).
    explicit StatusText(const QString &sample, QWidget *parent = nullptr);

    void setText(const QString &text);
    void clear() { setText(QString()); }
    QString text() const { return m_text; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override { return sizeHint(); }

protected:
    void paintEvent(QPaintEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    QString m_sample, m_text;
};

} // namespace awb
