// MainWindow: what leaves the window -- print, print preview and PDF (the FigureSheet), figure
// export of any view (ExportDialog, --export-figure), the matrices as LaTeX, points as CSV/PLY.

#include "gui/app/MainWindow.h"

#include "render/DensityFile.h"
#include "gui/app/AddressPanel.h"
#include "gui/app/AnimationPanel.h"
#include "gui/app/FigureSheet.h"
#include "gui/app/FrameBudget.h"
#include "gui/app/StatusText.h"
#include "gui/app/ItemController.h"
#include "gui/app/Messages.h"
#include "gui/app/PaletteDialog.h"
#include "gui/app/PointExportDialog.h"
#include "gui/app/PropertiesDock.h"
#include "gui/app/UserGuideDialog.h"
#include "gui/app/WheelGuard.h"
#include "gui/views/AnalysisCharts.h"
#include "gui/views/VertexPanel.h"
#include "gui/views/AttractorRenderer.h"
#include "gui/views/AttractorView.h"
#include "gui/views/MatrixView.h"
#include "gui/views/RegularityChart.h"
#include "gui/views/RegularityPanel.h"
#include "gui/views/SpectrumView.h"
#include "i18n/Translations.h"
#include "gui/views/SurfaceView.h"
#include "render/FigureFile.h"
#include "model/FigureMetadata.h"
#include "model/FileWriting.h"
#include "model/AttractorItem.h"
#include "model/EigenvaluePlotItem.h"
#include "model/ItemRegistry.h"
#include "model/Project.h"
#include "model/ProjectIO.h"
#include "model/ProjectTreeModel.h"
#include "model/Recovery.h"
#include "model/SubdivisionCurveItem.h"
#include "model/SubdivisionSurfaceItem.h"
#include "core/ifs/SurfaceIfs.h"
#include "model/NamedMatrix.h"
#include <QGuiApplication>
#include <QClipboard>
#include <QAction>
#include <QActionGroup>
#include <QStyle>
#include <QLayout>
#include <QApplication>
#include <QChartView>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QDir>
#include <QRegularExpression>
#include <QResizeEvent>
#include <QHeaderView>
#include <QImage>
#include <QJsonArray>
#include <QLabel>
#include <QMenuBar>
#include <QPainter>
#include <QPrintDialog>
#include <QPrintPreviewDialog>
#include <QPrinter>
#include <QProgressBar>
#include <QProgressDialog>
#include <QTabBar>
#include <QTimer>
#include <QScreen>
#include <QSettings>
#include <QSpinBox>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QToolBar>
#include <QToolButton>
#include <QTreeView>
#include <QUndoView>
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <QStandardPaths>

namespace awb {

void MainWindow::endExportProgress()
{
    delete m_exportProgress;
    m_exportProgress = nullptr;
}

QString MainWindow::outputPath(const QString &suffix) const
{
    // The project's folder is where its figures belong, unless it cannot be written to (an
    // installed example) or is the gallery's own folder (an example opened with File > Open
    // from a source tree): then the user's documents.
    const QFileInfo project(m_project->fileName());
    QString dir = project.absolutePath();
    if (m_project->fileName().isEmpty() || !QFileInfo(dir).isWritable()
        || QFileInfo(dir).canonicalFilePath() == QFileInfo(examplesDirectory()).canonicalFilePath())
        dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (dir.isEmpty())
        dir = QDir::homePath();
    QString base = m_project->fileName().isEmpty() ? tr("untitled") : project.completeBaseName();
    if (m_current && m_project->childCount() > 1)
        base += QLatin1Char('-') + m_current->name();
    base.replace(QRegularExpression(QStringLiteral("[^\\w.()-]+")), QStringLiteral("-"));
    base.replace(QRegularExpression(QStringLiteral("-{2,}")), QStringLiteral("-"));
    return QDir(dir).filePath(base.left(120) + QLatin1Char('.') + suffix);
}

FigureSheet MainWindow::figureSheet() const
{
    FigureSheet sheet(m_current, m_attractor, m_spectrum, m_surface);
    if (m_controller->focusedVertex() >= 0)
        sheet.setVertex(m_controller->focusedMatrices(), m_vertexPanel->mapView());
    return sheet;
}

void MainWindow::print()
{
    QPrinter printer(QPrinter::HighResolution);
    printer.setPageOrientation(QPageLayout::Landscape);
    // "Print to file" proposes the project's name, not ~/print.pdf.
    printer.setDocName(QFileInfo(outputPath(QStringLiteral("pdf"))).completeBaseName());
    printer.setOutputFileName(outputPath(QStringLiteral("pdf")));
    QPrintDialog dialog(&printer, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const FigureSheet sheet = figureSheet();
    const bool ok = sheet.print(&printer);
    endExportProgress();
    if (sheet.cancelled())
        statusBar()->showMessage(tr("Printing cancelled."), 4000);
    else if (!ok)
        m_messages->error(this, tr("Print"), tr("The printer could not be started."));
}

void MainWindow::printPreview()
{
    QPrinter printer(QPrinter::HighResolution);
    printer.setPageOrientation(QPageLayout::Landscape);
    QPrintPreviewDialog preview(&printer, this);
    preview.resize(1100, 800);
    connect(&preview, &QPrintPreviewDialog::paintRequested, this, [this](QPrinter *p) {
        figureSheet().print(p);
        endExportProgress();
    });
    preview.exec();
}

bool MainWindow::printToPdf(const QString &fileName, QString *error)
{
    const bool ok = figureSheet()
                        .writePdf(fileName, error);
    endExportProgress();
    return ok;
}

bool MainWindow::exportView(const ExportDialog::Options &options, QString *error)
{
    ExportDialog::Options o = options;
    const QString suffix = QFileInfo(o.fileName).suffix().toLower();
    AttractorView::ExportStyle style;
    style.grid = o.grid;
    style.handles = o.handles;
    style.fontFamily = o.fontFamily;
    style.fontPoints = o.fontPoints;
    const bool planar = o.target == ExportDialog::Target::Attractor
                        && !m_controller->showsSurface();
    if (o.crop && planar) {
        // Tight framing: the content fills the width, the height follows its proportions,
        // with a margin of a few screen pixels at the figure's scale.
        style.framing = AttractorView::Framing::FitContents;
        style.margin = 6;
        if (const auto bounds = m_attractor->exportBounds()) {
            const double margin = 6.0 * o.size.width() / std::max(1, m_attractor->width());
            const double inner = std::max(1.0, o.size.width() - 2 * margin);
            const double h = inner * bounds->height() / bounds->width() + 2 * margin;
            o.size.setHeight(std::clamp(int(std::lround(h)), 16, 20000));
        }
    }
    if (suffix == QLatin1String("tex")) {
        // The matrices as LaTeX (the other views are pictures).
        if (o.target != ExportDialog::Target::Matrices) {
            if (error)
                *error = tr("A .tex file holds the matrices only: choose the Matrices view, or "
                            ".png, .svg or .pdf for a picture.");
            return false;
        }
        const QString text = matricesLatex();
        if (text.isEmpty()) {
            if (error)
                *error = tr("The current item has no matrices to export.");
            return false;
        }
        QString reason;
        if (!writeWholeFile(o.fileName, text.toUtf8(), &reason)) {
            if (error)
                *error = tr("Cannot write %1: %2.").arg(o.fileName, reason);
            return false;
        }
        return true;
    }
    const QRectF target(0, 0, o.size.width(), o.size.height());
    const auto paint = [this, &o, &target, &style](QPainter &p) {
        switch (o.target) {
        case ExportDialog::Target::Attractor:
            if (m_controller->showsSurface())
                m_surface->renderTo(&p, target);
            else
                m_attractor->renderTo(&p, target, style);
            break;
        case ExportDialog::Target::Spectrum:
            paintSpectrum(m_spectrum, &p, target);
            break;
        case ExportDialog::Target::Matrices: {
            const QSize s = m_matrices->size();
            const double k = std::min(target.width() / std::max(1, s.width()),
                                      target.height() / std::max(1, s.height()));
            p.scale(k, k);
            m_matrices->render(&p, QPoint(), QRegion(), QWidget::DrawChildren);
            break;
        }
        case ExportDialog::Target::Analysis: {
            // Lay the chart out at the export size (in points at the chosen resolution) so
            // that titles and axes get the room they have in the figure, not in the dock.
            // The Vertex tab exports its characteristic map, the Valences tab its chart.
            QWidget *tab = m_charts->tabs()->currentWidget();
            if (tab == m_vertexPanel) {
                m_vertexPanel->mapView()->paintMap(p, target);
                break;
            }
            auto *view = tab == m_valenceChart
                             ? m_valenceChart->valenceView()
                             : m_charts->chartView(
                                   AnalysisCharts::Tab(m_charts->tabs()->currentIndex()));
            if (!view)
                break;
            const QSize old = view->size();
            const double k = std::max(1.0, o.dpi / 96.0);
            const QSize laidOut = (QSizeF(target.size()) / k).toSize();
            view->resize(laidOut);
            view->chart()->resize(laidOut);
            view->setSceneRect(QRectF(QPointF(0, 0), laidOut));
            view->render(&p, target, QRect(QPoint(0, 0), laidOut), Qt::IgnoreAspectRatio);
            view->resize(old);
            view->chart()->resize(old);
            view->setSceneRect(QRectF(QPointF(0, 0), old));
            break;
        }
        case ExportDialog::Target::FigureSheet:
            figureSheet().paint(&p, target);
            break;
        }
    };
    if (suffix == QLatin1String("exr")) {
        // The attractor's raw density (float32 hits per pixel), as the view frames it.
        if (!planar) {
            if (error)
                *error = tr("An .exr file holds the raw density of an attractor drawn in the "
                            "plane: choose the Attractor view of such an item.");
            return false;
        }
        QString why;
        try {
            const AttractorDensity density = m_attractor->rawDensity(o.size);
            DensityFileInfo info{QRectF(density.frame.x0, density.frame.y0,
                                        density.frame.x1 - density.frame.x0,
                                        density.frame.y1 - density.frame.y0),
                                 m_current ? m_current->name() : QString(), figureMetadata()};
            if (writeDensityExr(o.fileName, density, info, &why))
                return true;
        } catch (const std::exception &e) {
            why = QString::fromUtf8(e.what());
        }
        if (error)
            *error = why;
        return false;
    }
    if (suffix != QLatin1String("png") && suffix != QLatin1String("svg")
        && suffix != QLatin1String("pdf")) {
        if (error)
            *error = tr("Unknown format \"%1\": use .png, .svg or .pdf (.tex for the matrices, "
                        ".exr for the attractor's raw density).")
                         .arg(suffix);
        return false;
    }
    const bool attractorShown = o.target == ExportDialog::Target::Attractor
                                || o.target == ExportDialog::Target::FigureSheet;
    const auto cancelled = [&] { return attractorShown && m_attractor->exportCancelled(); };
    // The one format switch (render/FigureFile.h), at the export's print resolution; written
    // whole or not at all: a cancelled or failed export leaves an existing file as it was.
    PaintedFigureOptions figure;
    figure.title = m_current ? m_current->name() : QString();
    figure.metadata = figureMetadata();
    figure.format = suffix;
    figure.dpi = o.dpi;
    figure.viewBox = target;
    figure.antialias = true;
    figure.cancelled = cancelled;
    QString writeError;
    const bool ok = writePaintedFigure(o.fileName, o.size, paint, &writeError, figure);
    endExportProgress();
    if (cancelled()) {
        // No figure without its attractor (nothing was written).
        if (error)
            *error = tr("Exporting %1 was cancelled while the attractor was drawn.")
                         .arg(QFileInfo(o.fileName).fileName());
        return false;
    }
    if (!ok && error)
        *error = writeError;
    return ok;
}

FigureMetadata MainWindow::figureMetadata() const
{
    // The current item's project: the PNG or SVG reopens as this item (File > Open).
    return m_current ? itemFigureMetadata(*m_project, *m_current) : FigureMetadata{};
}

QString MainWindow::matricesLatex() const
{
    const QList<NamedMatrix> list = m_matrices->matrices();
    if (list.isEmpty())
        return {};
    return latexMatrices(list, m_current ? m_current->name() : QString());
}

void MainWindow::exportDialog()
{
    ExportDialog::Options initial;
    initial.fileName = m_lastExport.isEmpty() ? outputPath(QStringLiteral("png")) : m_lastExport;
    initial.size = m_central->size() * 2;
    ExportDialog dialog(initial, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const ExportDialog::Options o = dialog.options();
    QString error;
    if (!exportView(o, &error))
        m_messages->error(this, tr("Export"), error);
    else
        statusBar()->showMessage(tr("Exported the figure to %1").arg(o.fileName), 10000);
    m_lastExport = o.fileName;
}

void MainWindow::exportPointsDialog()
{
    AttractorItem *item = m_controller->drawnItem();
    if (!item) {
        m_messages->error(this, tr("Export Points"),
                          tr("The current item has no attractor whose points could be "
                             "exported."));
        return;
    }
    QString name = m_lastPointExport;
    const QString suffix = item->pointDimension() == 3 ? QStringLiteral("ply")
                                                       : QStringLiteral("csv");
    if (name.isEmpty())
        name = outputPath(suffix);
    PointExportDialog dialog(item, name, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    QString error;
    m_lastPointExport = dialog.fileName();
    if (!exportPoints(dialog.fileName(), dialog.depth(), &error))
        m_messages->error(this, tr("Export Points"), error);
    else
        statusBar()->showMessage(tr("Exported the points to %1").arg(dialog.fileName()), 5000);
}

bool MainWindow::exportPoints(const QString &fileName, int depth, QString *error)
{
    const AttractorItem *item = m_controller->drawnItem();
    if (!item) {
        if (error)
            *error = tr("The current item has no attractor.");
        return false;
    }
    // The colours the view uses: the item's own, else the preferences', else the defaults.
    QList<QColor> palette;
    for (const QString &c : item->style().colors)
        palette << QColor(c);
    if (palette.isEmpty())
        palette = m_preferences.palette;
    const auto color = [palette](int map) {
        return paletteColor(palette, map, AttractorRenderer::mapColor(map));
    };
    return PointExportDialog::exportPoints(item, fileName,
                                           depth < 0 ? item->algorithm().depth : depth, color,
                                           isVisible() ? this : nullptr, error);
}

} // namespace awb
