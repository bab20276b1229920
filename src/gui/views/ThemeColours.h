#pragma once
// Colours the widgets choose themselves (notes, error text, highlights), chosen for the
// palette they are shown in, so that they stay legible under a dark desktop theme as well as a
// light one. The drawing canvases (attractor, spectrum, charts) keep their white paper.
#include <QColor>
#include <QPalette>
#include <QString>

#include <cmath>
#include <utility>

namespace awb {

// Whether `palette` is a dark theme: its window colour is darker than mid-grey.
inline bool isDarkPalette(const QPalette &palette)
{
    return palette.color(QPalette::Window).lightness() < 128;
}

// Red text of a refusal or an error.
inline QColor errorTextColour(const QPalette &palette)
{
    return isDarkPalette(palette) ? QColor(255, 138, 128) : QColor(176, 30, 30);
}

// A yellow note box: background, text and border.
struct NoteColours {
    QColor background, text, border;
};
inline NoteColours noteColours(const QPalette &palette)
{
    if (isDarkPalette(palette))
        return {QColor(74, 62, 24), QColor(250, 240, 205), QColor(120, 102, 46)};
    return {QColor(255, 248, 224), QColor(38, 32, 0), QColor(230, 217, 168)};
}
inline QString noteStyleSheet(const QPalette &palette)
{
    const NoteColours c = noteColours(palette);
    return QStringLiteral("QLabel { background: %1; color: %2; border: 1px solid %3; }")
        .arg(c.background.name(), c.text.name(), c.border.name());
}

// The background of a highlighted box (the selected map's matrices) and its text.
inline QColor highlightBackground(const QPalette &palette)
{
    return isDarkPalette(palette) ? QColor(96, 78, 22) : QColor(255, 236, 179);
}
inline QColor highlightText(const QPalette &palette)
{
    return isDarkPalette(palette) ? QColor(255, 248, 225) : QColor(20, 20, 20);
}

// WCAG contrast ratio of two colours (1 … 21): 4.5 is legible body text.
inline double contrastRatio(const QColor &a, const QColor &b)
{
    const auto luminance = [](const QColor &c) {
        const auto lin = [](double v) {
            return v <= 0.03928 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
        };
        return 0.2126 * lin(c.redF()) + 0.7152 * lin(c.greenF()) + 0.0722 * lin(c.blueF());
    };
    double la = luminance(a), lb = luminance(b);
    if (la < lb)
        std::swap(la, lb);
    return (la + 0.05) / (lb + 0.05);
}

} // namespace awb
