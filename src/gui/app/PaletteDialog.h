#pragma once
// PaletteDialog (layer 3, GUI): the colours of an item's maps (StyleSpec::colors), one swatch
// button per map that opens a colour chooser, and "Use the default colours". The caller applies
// the result as one undoable style edit.
#include <QColor>
#include <QDialog>
#include <QList>

class QPushButton;

namespace awb {

class PaletteDialog : public QDialog {
    Q_OBJECT
public:
    // `colors`: the item's own colours (empty: it uses `defaults`); one swatch per map.
    PaletteDialog(const QList<QColor> &colors, const QList<QColor> &defaults, int mapCount,
                  QWidget *parent = nullptr);

    // The colours chosen, one per map; empty when the defaults are chosen.
    QList<QColor> colors() const;
    void setColor(int map, const QColor &color);
    void useDefaults();
    int mapCount() const { return int(m_buttons.size()); }
    QPushButton *swatch(int map) const { return m_buttons.value(map); }

    // A row of small colour squares (an icon for the Properties button).
    static QIcon swatchIcon(const QList<QColor> &colors, int height = 14);

private:
    void showColor(int map);

    QList<QColor> m_colors, m_defaults;
    QList<QPushButton *> m_buttons;
    bool m_ownColors = false;
};

// Colour i of a palette, cycling; `fallback` when the palette is empty.
QColor paletteColor(const QList<QColor> &palette, int i, const QColor &fallback);

} // namespace awb
