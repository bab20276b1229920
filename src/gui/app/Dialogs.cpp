#include "gui/app/Dialogs.h"

#include <QColorDialog>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QToolButton>

namespace awb {

namespace {
constexpr int paletteSize = 6;
}

Preferences Preferences::load()
{
    QSettings s;
    Preferences p;
    p.defaultDepth = s.value(QStringLiteral("preferences/defaultDepth"), p.defaultDepth).toInt();
    p.maxRenderDepth = s.value(QStringLiteral("preferences/maxRenderDepth"), 0).toInt();
    p.autosaveSeconds =
        s.value(QStringLiteral("preferences/autosaveSeconds"), p.autosaveSeconds).toInt();
    for (const QString &c : s.value(QStringLiteral("preferences/palette")).toStringList())
        if (QColor(c).isValid())
            p.palette.append(QColor(c));
    return p;
}

void Preferences::save() const
{
    QSettings s;
    s.setValue(QStringLiteral("preferences/defaultDepth"), defaultDepth);
    s.setValue(QStringLiteral("preferences/maxRenderDepth"), maxRenderDepth);
    s.setValue(QStringLiteral("preferences/autosaveSeconds"), autosaveSeconds);
    QStringList names;
    for (const QColor &c : palette)
        names << c.name();
    s.setValue(QStringLiteral("preferences/palette"), names);
}

ExportDialog::ExportDialog(const Options &initial, QWidget *parent) : QDialog(parent)
{
    setWindowTitle(tr("Export Figure"));
    auto *form = new QFormLayout(this);
    m_target = new QComboBox;
    m_target->addItems({tr("Attractor view"), tr("Spectrum plot"), tr("Matrices"),
                        tr("Analysis chart (current tab)"), tr("Figure sheet")});
    m_target->setCurrentIndex(int(initial.target));
    form->addRow(tr("&View:"), m_target);
    auto *fileRow = new QWidget;
    auto *h = new QHBoxLayout(fileRow);
    h->setContentsMargins(0, 0, 0, 0);
    m_file = new QLineEdit(initial.fileName);
    m_file->setMinimumWidth(320);
    auto *browse = new QPushButton(tr("&Browse…"));
    connect(browse, &QPushButton::clicked, this, &ExportDialog::browse);
    h->addWidget(m_file, 1);
    h->addWidget(browse);
    form->addRow(tr("&File:"), fileRow);
    form->addRow(new QLabel(tr("The suffix picks the format: .png, .svg or .pdf.")));
    m_width = new QSpinBox;
    m_height = new QSpinBox;
    m_dpi = new QSpinBox;
    m_width->setRange(16, 20000);
    m_height->setRange(16, 20000);
    m_dpi->setRange(36, 2400);
    m_width->setSuffix(tr(" px"));
    m_height->setSuffix(tr(" px"));
    m_dpi->setSuffix(tr(" dpi"));
    m_width->setValue(initial.size.width());
    m_height->setValue(initial.size.height());
    m_dpi->setValue(initial.dpi);
    form->addRow(tr("&Width:"), m_width);
    form->addRow(tr("&Height:"), m_height);
    form->addRow(tr("&Resolution:"), m_dpi);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

void ExportDialog::browse()
{
    const QString name = QFileDialog::getSaveFileName(
        this, tr("Export Figure"), m_file->text(),
        tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)"));
    if (!name.isEmpty())
        m_file->setText(name);
}

ExportDialog::Options ExportDialog::options() const
{
    Options o;
    o.target = Target(m_target->currentIndex());
    o.fileName = m_file->text();
    o.size = QSize(m_width->value(), m_height->value());
    o.dpi = m_dpi->value();
    return o;
}

PreferencesDialog::PreferencesDialog(const Preferences &initial, QWidget *parent)
    : QDialog(parent), m_palette(initial.palette)
{
    setWindowTitle(tr("Preferences"));
    auto *form = new QFormLayout(this);
    m_depth = new QSpinBox;
    m_depth->setRange(0, 30);
    m_depth->setValue(initial.defaultDepth);
    m_depth->setToolTip(tr("Deterministic depth given to new items."));
    form->addRow(tr("Default &depth of new items:"), m_depth);
    m_maxDepth = new QSpinBox;
    m_maxDepth->setRange(0, 64);
    m_maxDepth->setSpecialValueText(tr("no limit"));
    m_maxDepth->setValue(initial.maxRenderDepth);
    m_maxDepth->setToolTip(tr("Draw at most this depth, whatever the item asks for."));
    form->addRow(tr("&Maximum drawn depth:"), m_maxDepth);
    auto *colours = new QWidget;
    auto *h = new QHBoxLayout(colours);
    h->setContentsMargins(0, 0, 0, 0);
    for (int i = 0; i < paletteSize; ++i) {
        auto *b = new QToolButton;
        b->setToolTip(tr("Colour of map %1").arg(i + 1));
        connect(b, &QToolButton::clicked, this, [this, i] {
            const QColor c = QColorDialog::getColor(
                i < m_palette.size() ? m_palette[i] : QColor(Qt::black), this);
            if (!c.isValid())
                return;
            while (m_palette.size() <= i)
                m_palette.append(QColor::fromHsv(m_palette.size() * 60 % 360, 200, 200));
            m_palette[i] = c;
            showColours();
        });
        m_colourButtons.append(b);
        h->addWidget(b);
    }
    auto *defaults = new QPushButton(tr("Defaults"));
    connect(defaults, &QPushButton::clicked, this, [this] {
        m_palette.clear();
        showColours();
    });
    h->addWidget(defaults);
    h->addStretch();
    form->addRow(tr("Map &colours:"), colours);
    m_autosave = new QSpinBox;
    m_autosave->setRange(5, 3600);
    m_autosave->setSuffix(tr(" s"));
    m_autosave->setValue(initial.autosaveSeconds);
    form->addRow(tr("&Autosave interval:"), m_autosave);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
    showColours();
}

void PreferencesDialog::showColours()
{
    for (int i = 0; i < m_colourButtons.size(); ++i) {
        const bool set = i < m_palette.size();
        m_colourButtons[i]->setText(set ? QString() : tr("auto"));
        m_colourButtons[i]->setStyleSheet(
            set ? QStringLiteral("background-color: %1; min-width: 24px;").arg(m_palette[i].name())
                : QString());
    }
}

Preferences PreferencesDialog::preferences() const
{
    Preferences p;
    p.defaultDepth = m_depth->value();
    p.maxRenderDepth = m_maxDepth->value();
    p.palette = m_palette;
    p.autosaveSeconds = m_autosave->value();
    return p;
}

} // namespace awb
