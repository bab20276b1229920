#include "gui/app/Dialogs.h"

#include "ui_exportdialog.h"
#include "ui_preferencesdialog.h"

#include <QColorDialog>
#include <QFileDialog>
#include <QSettings>

#include <algorithm>

namespace awb {

Preferences Preferences::load()
{
    QSettings s;
    Preferences p;
    p.defaultDepth = s.value(QStringLiteral("preferences/defaultDepth"), p.defaultDepth).toInt();
    p.maxRenderDepth = s.value(QStringLiteral("preferences/maxRenderDepth"), 0).toInt();
    p.autosaveSeconds =
        s.value(QStringLiteral("preferences/autosaveSeconds"), p.autosaveSeconds).toInt();
    p.daskScheduler = s.value(QStringLiteral("preferences/daskScheduler")).toString().trimmed();
    p.atlasWorkers =
        std::clamp(s.value(QStringLiteral("preferences/atlasWorkers"), 0).toInt(), 0, 256);
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
    s.setValue(QStringLiteral("preferences/daskScheduler"), daskScheduler);
    s.setValue(QStringLiteral("preferences/atlasWorkers"), atlasWorkers);
    QStringList names;
    for (const QColor &c : palette)
        names << c.name();
    s.setValue(QStringLiteral("preferences/palette"), names);
}

ExportDialog::ExportDialog(const Options &initial, QWidget *parent)
    : QDialog(parent), m_ui(std::make_unique<Ui::ExportDialog>())
{
    m_ui->setupUi(this);
    m_ui->targetCombo->setCurrentIndex(int(initial.target));
    m_ui->fileEdit->setText(initial.fileName);
    m_ui->widthSpin->setValue(initial.size.width());
    m_ui->heightSpin->setValue(initial.size.height());
    m_ui->dpiSpin->setValue(initial.dpi);
    m_ui->gridCheck->setChecked(initial.grid);
    m_ui->handlesCheck->setChecked(initial.handles);
    m_ui->cropCheck->setChecked(initial.crop);
    m_ui->fontCombo->setCurrentFont(initial.fontFamily.isEmpty() ? font()
                                                                 : QFont(initial.fontFamily));
    m_ui->fontSizeSpin->setValue(initial.fontPoints);
    connect(m_ui->browseButton, &QPushButton::clicked, this, &ExportDialog::browse);
}

ExportDialog::~ExportDialog() = default;

void ExportDialog::browse()
{
    const QString name = QFileDialog::getSaveFileName(
        this, tr("Export Figure"), m_ui->fileEdit->text(),
        tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf);;LaTeX matrices "
           "(*.tex);;OpenEXR raw density of the attractor, float32 hits per pixel (*.exr)"));
    if (!name.isEmpty())
        m_ui->fileEdit->setText(name);
}

ExportDialog::Options ExportDialog::options() const
{
    Options o;
    o.target = Target(m_ui->targetCombo->currentIndex());
    o.fileName = m_ui->fileEdit->text();
    o.size = QSize(m_ui->widthSpin->value(), m_ui->heightSpin->value());
    o.dpi = m_ui->dpiSpin->value();
    o.grid = m_ui->gridCheck->isChecked();
    o.handles = m_ui->handlesCheck->isChecked();
    o.crop = m_ui->cropCheck->isChecked();
    // The application's own font stays "as on screen" (it follows the desktop's).
    if (m_ui->fontCombo->currentFont().family() != font().family())
        o.fontFamily = m_ui->fontCombo->currentFont().family();
    o.fontPoints = m_ui->fontSizeSpin->value();
    return o;
}

PreferencesDialog::PreferencesDialog(const Preferences &initial, QWidget *parent)
    : QDialog(parent), m_ui(std::make_unique<Ui::PreferencesDialog>()), m_palette(initial.palette)
{
    m_ui->setupUi(this);
    m_ui->depthSpin->setValue(initial.defaultDepth);
    m_ui->maxDepthSpin->setValue(initial.maxRenderDepth);
    m_ui->autosaveSpin->setValue(initial.autosaveSeconds);
    m_ui->schedulerEdit->setText(initial.daskScheduler);
    m_ui->workersSpin->setValue(initial.atlasWorkers);
    const QList<QToolButton *> buttons = colourButtons();
    for (int i = 0; i < buttons.size(); ++i) {
        connect(buttons[i], &QToolButton::clicked, this, [this, i] {
            const QColor c = QColorDialog::getColor(
                i < m_palette.size() ? m_palette[i] : QColor(Qt::black), this);
            if (!c.isValid())
                return;
            while (m_palette.size() <= i)
                m_palette.append(QColor::fromHsv(m_palette.size() * 60 % 360, 200, 200));
            m_palette[i] = c;
            showColours();
        });
    }
    connect(m_ui->defaultsButton, &QPushButton::clicked, this, [this] {
        m_palette.clear();
        showColours();
    });
    showColours();
}

PreferencesDialog::~PreferencesDialog() = default;

QList<QToolButton *> PreferencesDialog::colourButtons() const
{
    return {m_ui->colourButton1, m_ui->colourButton2, m_ui->colourButton3,
            m_ui->colourButton4, m_ui->colourButton5, m_ui->colourButton6};
}

void PreferencesDialog::showColours()
{
    const QList<QToolButton *> buttons = colourButtons();
    for (int i = 0; i < buttons.size(); ++i) {
        const bool set = i < m_palette.size();
        buttons[i]->setText(set ? QString() : tr("auto"));
        buttons[i]->setStyleSheet(
            set ? QStringLiteral("background-color: %1; min-width: 24px;").arg(m_palette[i].name())
                : QString());
    }
}

Preferences PreferencesDialog::preferences() const
{
    Preferences p;
    p.defaultDepth = m_ui->depthSpin->value();
    p.maxRenderDepth = m_ui->maxDepthSpin->value();
    p.palette = m_palette;
    p.autosaveSeconds = m_ui->autosaveSpin->value();
    p.daskScheduler = m_ui->schedulerEdit->text().trimmed();
    p.atlasWorkers = m_ui->workersSpin->value();
    return p;
}

} // namespace awb
