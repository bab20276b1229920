#include "gui/app/PaletteDialog.h"

#include <QColorDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QPushButton>
#include <QVBoxLayout>

namespace awb {

QColor paletteColor(const QList<QColor> &palette, int i, const QColor &fallback)
{
    return palette.isEmpty() ? fallback : palette[i % palette.size()];
}

PaletteDialog::PaletteDialog(const QList<QColor> &colors, const QList<QColor> &defaults,
                             int mapCount, QWidget *parent)
    : QDialog(parent), m_defaults(defaults), m_ownColors(!colors.isEmpty())
{
    setObjectName(QStringLiteral("paletteDialog"));
    setWindowTitle(tr("Map Colours"));
    const int n = std::max(1, mapCount);
    for (int i = 0; i < n; ++i)
        m_colors << paletteColor(m_ownColors ? colors : defaults, i, Qt::black);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("The colour of the points each map f<sub>i</sub> makes "
                                    "(Style: colour by map or by address).")));
    auto *form = new QFormLayout;
    for (int i = 0; i < n; ++i) {
        auto *button = new QPushButton;
        button->setObjectName(QStringLiteral("swatch%1").arg(i + 1));
        button->setMinimumWidth(120);
        connect(button, &QPushButton::clicked, this, [this, i] {
            const QColor c = QColorDialog::getColor(m_colors[i], this,
                                                    tr("Colour of map %1").arg(i + 1));
            if (c.isValid())
                setColor(i, c);
        });
        m_buttons << button;
        form->addRow(tr("Map %1:").arg(i + 1), button);
        showColor(i);
    }
    layout->addLayout(form);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel
                                         | QDialogButtonBox::RestoreDefaults);
    buttons->button(QDialogButtonBox::RestoreDefaults)->setText(tr("Use the &Default Colours"));
    connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, this,
            &PaletteDialog::useDefaults);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

QList<QColor> PaletteDialog::colors() const
{
    return m_ownColors ? m_colors : QList<QColor>{};
}

void PaletteDialog::setColor(int map, const QColor &color)
{
    if (map < 0 || map >= m_colors.size() || !color.isValid())
        return;
    m_colors[map] = color;
    m_ownColors = true;
    showColor(map);
}

void PaletteDialog::useDefaults()
{
    m_ownColors = false;
    for (int i = 0; i < m_colors.size(); ++i) {
        m_colors[i] = paletteColor(m_defaults, i, Qt::black);
        showColor(i);
    }
}

void PaletteDialog::showColor(int map)
{
    QPushButton *b = m_buttons.value(map);
    if (!b)
        return;
    b->setIcon(swatchIcon({m_colors[map]}, 16));
    b->setText(m_colors[map].name());
}

QIcon PaletteDialog::swatchIcon(const QList<QColor> &colors, int height)
{
    const int n = std::max<qsizetype>(1, colors.size());
    QPixmap pixmap(int(n) * height, height);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    for (int i = 0; i < colors.size(); ++i) {
        p.setPen(QColor(60, 60, 60));
        p.setBrush(colors[i]);
        p.drawRect(i * height + 1, 1, height - 3, height - 3);
    }
    return QIcon(pixmap);
}

} // namespace awb
