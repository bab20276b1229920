#pragma once
// Editors of the Properties dock that fit a narrow dock and speak the papers' numbers:
//  - ElidingComboBox: a combo box as narrow as the dock allows, its current text elided with
//    "…" (not cut off mid-letter) and whole in the tooltip;
//  - ExactSpinBox: a spin box that shows a value exactly when it can ("1/3", "5/24" instead of
//    0.333333; short decimals as they are) and accepts what parseNumber reads ("1/3",
//    "sqrt(3)/6", "1/2 + 1/16"); a value outside its range is refused with a message naming
//    the range, not silently clamped.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSpinBox>

#include <functional>

namespace awb {

class ElidingComboBox : public QComboBox {
    Q_OBJECT
public:
    explicit ElidingComboBox(QWidget *parent = nullptr);

protected:
    void paintEvent(QPaintEvent *event) override;
};

class ExactSpinBox : public QDoubleSpinBox {
    Q_OBJECT
public:
    explicit ExactSpinBox(QWidget *parent = nullptr);

    QString textFromValue(double value) const override;
    double valueFromText(const QString &text) const override;
    QValidator::State validate(QString &text, int &pos) const override;
    // Called with a message when the text typed is a number outside the range, or no number.
    void setRefusal(std::function<void(const QString &)> refuse) { m_refuse = std::move(refuse); }

protected:
    void focusOutEvent(QFocusEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;

private:
    // Reads the line: true when it holds a number in range (then the value is set).
    bool commitText();
    std::function<void(const QString &)> m_refuse;
};

// An integer spin box that refuses a typed value outside its range with a message naming the
// range ("−3" for a depth is not turned into 3).
class CheckedSpinBox : public QSpinBox {
    Q_OBJECT
public:
    explicit CheckedSpinBox(QWidget *parent = nullptr);
    QValidator::State validate(QString &text, int &pos) const override;
    void setRefusal(std::function<void(const QString &)> refuse) { m_refuse = std::move(refuse); }

protected:
    void focusOutEvent(QFocusEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;

private:
    bool commitText();
    std::function<void(const QString &)> m_refuse;
};

} // namespace awb
