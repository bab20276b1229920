#include "gui/app/CompactEditors.h"

#include "model/NumberFormat.h"

#include <QKeyEvent>
#include <QLineEdit>
#include <QStyleOptionComboBox>
#include <QStylePainter>

#include <cmath>

namespace awb {

// ---- ElidingComboBox --------------------------------------------------------------------------

ElidingComboBox::ElidingComboBox(QWidget *parent) : QComboBox(parent)
{
    // The width does not follow the longest entry (a preset's long name would make the dock's
    // content wider than the dock, clipping every row's right end).
    setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    setMinimumContentsLength(8);
    connect(this, &QComboBox::currentTextChanged, this,
            [this](const QString &text) { setToolTip(text); });
}

void ElidingComboBox::paintEvent(QPaintEvent *)
{
    QStylePainter painter(this);
    QStyleOptionComboBox option;
    initStyleOption(&option);
    painter.drawComplexControl(QStyle::CC_ComboBox, option);
    const QRect field = style()->subControlRect(QStyle::CC_ComboBox, &option,
                                                QStyle::SC_ComboBoxEditField, this);
    int room = field.width();
    if (!option.currentIcon.isNull())
        room -= option.iconSize.width() + 4;
    option.currentText = fontMetrics().elidedText(option.currentText, Qt::ElideRight,
                                                  std::max(0, room));
    painter.drawControl(QStyle::CE_ComboBoxLabel, option);
}

// ---- ExactSpinBox -----------------------------------------------------------------------------

ExactSpinBox::ExactSpinBox(QWidget *parent) : QDoubleSpinBox(parent)
{
    // Values keep their full precision: the text shows them exactly or to 10 digits.
    setDecimals(15);
    setKeyboardTracking(false);
    setCorrectionMode(QAbstractSpinBox::CorrectToPreviousValue);
}

QString ExactSpinBox::textFromValue(double value) const
{
    return displayNumber(value);
}

double ExactSpinBox::valueFromText(const QString &text) const
{
    QString t = text;
    if (!prefix().isEmpty() && t.startsWith(prefix()))
        t = t.mid(prefix().size());
    if (!suffix().isEmpty() && t.endsWith(suffix()))
        t.chop(suffix().size());
    return parseNumber(t).value_or(value());
}

QValidator::State ExactSpinBox::validate(QString &text, int &) const
{
    QString t = text;
    if (!prefix().isEmpty() && t.startsWith(prefix()))
        t = t.mid(prefix().size());
    if (!suffix().isEmpty() && t.endsWith(suffix()))
        t.chop(suffix().size());
    const std::optional<double> v = parseNumber(t);
    // Anything may be on its way to a number ("sqrt(", "1/"): the text is judged when it is
    // committed, where a refusal can say why.
    return v && *v >= minimum() && *v <= maximum() ? QValidator::Acceptable
                                                   : QValidator::Intermediate;
}

bool ExactSpinBox::commitText()
{
    QString t = lineEdit()->text();
    if (!prefix().isEmpty() && t.startsWith(prefix()))
        t = t.mid(prefix().size());
    if (!suffix().isEmpty() && t.endsWith(suffix()))
        t.chop(suffix().size());
    const std::optional<double> v = parseNumber(t);
    QString why;
    if (!v)
        why = tr("“%1” is not a number (type e.g. 0.25, 1/3 or sqrt(3)/6).").arg(t.trimmed());
    else if (*v < minimum() || *v > maximum())
        why = tr("%1 is outside %2 … %3.")
                  .arg(displayNumber(*v), displayNumber(minimum()), displayNumber(maximum()));
    if (why.isEmpty()) {
        setValue(*v);
        return true;
    }
    lineEdit()->setText(textFromValue(value()));
    if (m_refuse)
        m_refuse(why);
    return false;
}

void ExactSpinBox::focusOutEvent(QFocusEvent *event)
{
    if (lineEdit()->text() != textFromValue(value()))
        commitText();
    QDoubleSpinBox::focusOutEvent(event);
}

void ExactSpinBox::keyPressEvent(QKeyEvent *event)
{
    if (event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter) {
        commitText();
        event->accept();
        return;
    }
    QDoubleSpinBox::keyPressEvent(event);
}

// ---- CheckedSpinBox ---------------------------------------------------------------------------

CheckedSpinBox::CheckedSpinBox(QWidget *parent) : QSpinBox(parent)
{
    setKeyboardTracking(false);
    setCorrectionMode(QAbstractSpinBox::CorrectToPreviousValue);
}

QValidator::State CheckedSpinBox::validate(QString &text, int &) const
{
    QString t = text.trimmed();
    t.replace(QChar(0x2212), QLatin1Char('-'));
    if (t.isEmpty() || t == QLatin1String("-") || t == QLatin1String("+"))
        return QValidator::Intermediate;
    bool ok = false;
    const qlonglong v = t.toLongLong(&ok);
    if (!ok)
        return QValidator::Invalid;
    return v >= minimum() && v <= maximum() ? QValidator::Acceptable : QValidator::Intermediate;
}

bool CheckedSpinBox::commitText()
{
    QString t = lineEdit()->text().trimmed();
    t.replace(QChar(0x2212), QLatin1Char('-'));
    bool ok = false;
    const qlonglong v = t.toLongLong(&ok);
    QString why;
    if (!ok)
        why = tr("“%1” is not a whole number.").arg(t);
    else if (v < minimum() || v > maximum())
        why = tr("%1 is outside %2 … %3.").arg(v).arg(minimum()).arg(maximum());
    if (why.isEmpty()) {
        setValue(int(v));
        return true;
    }
    lineEdit()->setText(textFromValue(value()));
    if (m_refuse)
        m_refuse(why);
    return false;
}

void CheckedSpinBox::focusOutEvent(QFocusEvent *event)
{
    if (lineEdit()->text() != textFromValue(value()))
        commitText();
    QSpinBox::focusOutEvent(event);
}

void CheckedSpinBox::keyPressEvent(QKeyEvent *event)
{
    if (event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter) {
        commitText();
        event->accept();
        return;
    }
    QSpinBox::keyPressEvent(event);
}

} // namespace awb
