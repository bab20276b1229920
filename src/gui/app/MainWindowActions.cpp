// MainWindow: its actions (File, Edit, View, Item, Help: the QActions with their shortcuts,
// icons and handlers) and the menus and tool bar that hold them, the language menu among them.

#include "gui/app/MainWindow.h"

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
#include "gui/views/AttractorRenderer.h"
#include "gui/views/AttractorView.h"
#include "gui/views/MatrixView.h"
#include "gui/app/RegularityAtlasWindow.h"
#include "gui/views/RegularityChart.h"
#include "gui/views/RegularityPanel.h"
#include "gui/views/SpectrumView.h"
#include "i18n/Translations.h"
#include "gui/views/SurfaceView.h"
#include "gui/views/VertexPanel.h"
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
#include "model/SubdivisionMeshItem.h"
#include "core/ifs/SurfaceIfs.h"

#include "model/NamedMatrix.h"
#include <QGuiApplication>
#include <QClipboard>
#include <QAction>
#include <QActionGroup>
#include <QStyle>
#include <QLayout>
#include <QApplication>
#include <QBuffer>
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
#include <QPdfWriter>
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
#include <QSvgGenerator>
#include <QTabWidget>
#include <QTableWidget>
#include <QToolBar>
#include <QToolButton>
#include <QTreeView>
#include <QUndoView>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace awb {

void MainWindow::createActions()
{
    const auto make = [this](const QString &name, const QString &text, const QString &icon,
                             QKeySequence key, auto slot) {
        auto *a = new QAction(QIcon::fromTheme(icon), text, this);
        a->setObjectName(name);
        if (!key.isEmpty())
            a->setShortcut(key);
        connect(a, &QAction::triggered, this, slot);
        return a;
    };
    make(QStringLiteral("actionNew"), tr("&New"), QStringLiteral("document-new"),
         QKeySequence::New, [this] {
             if (maybeSave())
                 newProject();
         });
    make(QStringLiteral("actionOpen"), tr("&Open…"), QStringLiteral("document-open"),
         QKeySequence::Open, &MainWindow::openDialog);
    make(QStringLiteral("actionExampleGallery"), tr("&Gallery…"), QStringLiteral("folder-pictures"),
         QKeySequence(), &MainWindow::exampleGalleryDialog)
        ->setStatusTip(tr("The examples as thumbnails: the papers' figures, meshes, masks"));
    make(QStringLiteral("actionImport"), tr("&Import…"), QStringLiteral("document-import"),
         QKeySequence(tr("Ctrl+I")), &MainWindow::importDialog);
    make(QStringLiteral("actionExportItemAs"), tr("Export &Item As…"),
         QStringLiteral("document-export"), QKeySequence(), &MainWindow::exportItemAsDialog);
    make(QStringLiteral("actionImportMesh"), tr("&Import Mesh…"),
         QStringLiteral("document-import"), QKeySequence(), &MainWindow::importMeshDialog);
    make(QStringLiteral("actionExportMesh"), tr("Export &Mesh…"),
         QStringLiteral("document-export"), QKeySequence(), &MainWindow::exportMeshDialog);
    make(QStringLiteral("actionCreaseEdge"), tr("&Crease Edge…"), QString(), QKeySequence(),
         &MainWindow::creaseEdgeDialog)
        ->setStatusTip(tr("The sharpness of the mesh edge clicked in the 3D view"));
    make(QStringLiteral("actionSharpenVertex"), tr("Sharpen &Vertex…"), QString(),
         QKeySequence(), &MainWindow::sharpenVertexDialog)
        ->setStatusTip(tr("The corner sharpness of the mesh vertex clicked in the 3D view"));
    make(QStringLiteral("actionToggleHole"), tr("Toggle &Hole"), QString(), QKeySequence(),
         &MainWindow::toggleHoleAction)
        ->setStatusTip(tr("Make the mesh face clicked in the 3D view a hole, or fill it"));
    make(QStringLiteral("actionSave"), tr("&Save"), QStringLiteral("document-save"),
         QKeySequence::Save, &MainWindow::save);
    make(QStringLiteral("actionSaveAs"), tr("Save &As…"), QStringLiteral("document-save-as"),
         // QKeySequence::SaveAs has no binding on some desktops (GNOME, none): say it.
         QKeySequence(tr("Ctrl+Shift+S")), &MainWindow::saveAs);
    make(QStringLiteral("actionRevert"), tr("Re&vert"), QStringLiteral("document-revert"),
         QKeySequence(), &MainWindow::revert);
    make(QStringLiteral("actionClose"), tr("&Close"), QStringLiteral("document-close"),
         QKeySequence::Close, &MainWindow::closeProject);
    make(QStringLiteral("actionPrint"), tr("&Print…"), QStringLiteral("document-print"),
         QKeySequence::Print, &MainWindow::print);
    make(QStringLiteral("actionPrintPreview"), tr("Print Pre&view…"),
         // Ctrl+Shift+P is View > Python Console's (README, docs/python.md).
         QStringLiteral("document-print-preview"), QKeySequence(tr("Ctrl+Alt+P")),
         &MainWindow::printPreview);
    make(QStringLiteral("actionPrintPdf"), tr("Print to P&DF…"), QStringLiteral("document-export"),
         QKeySequence(), [this] {
             const QString name = QFileDialog::getSaveFileName(
                 this, tr("Print to PDF"), outputPath(QStringLiteral("pdf")),
                 tr("PDF document (*.pdf)"));
             QString error;
             if (!name.isEmpty() && !printToPdf(name, &error))
                 m_messages->error(this, tr("Print to PDF"), error);
         });
    make(QStringLiteral("actionExport"), tr("&Export Figure…"), QStringLiteral("document-export"),
         QKeySequence(tr("Ctrl+E")), &MainWindow::exportDialog);
    make(QStringLiteral("actionExportPoints"), tr("Export &Points…"), QStringLiteral("document-export"),
         QKeySequence(tr("Ctrl+Shift+E")), &MainWindow::exportPointsDialog);
    // Themes without document-export (Adwaita): a picture for the figure, a page for points.
    if (QAction *a = action(QStringLiteral("actionExport")); a->icon().isNull())
        a->setIcon(QIcon::fromTheme(QStringLiteral("image-x-generic")));
    if (QAction *a = action(QStringLiteral("actionExportPoints")); a->icon().isNull())
        a->setIcon(QIcon::fromTheme(QStringLiteral("text-x-generic")));
    make(QStringLiteral("actionQuit"), tr("&Quit"), QStringLiteral("application-exit"),
         QKeySequence::Quit, &QWidget::close);
    make(QStringLiteral("actionPreferences"), tr("Pre&ferences…"),
         QStringLiteral("preferences-system"), QKeySequence::Preferences,
         &MainWindow::preferencesDialog);
    make(QStringLiteral("actionCopyLatex"), tr("Copy Matrices as &LaTeX"),
         QStringLiteral("edit-copy"), QKeySequence(tr("Ctrl+Shift+L")), [this] {
             const QString text = matricesLatex();
             if (text.isEmpty()) {
                 statusBar()->showMessage(tr("The current item has no matrices."), 4000);
                 return;
             }
             QGuiApplication::clipboard()->setText(text);
             statusBar()->showMessage(
                 tr("Copied %n matrices as LaTeX (amsmath bmatrix).", nullptr,
                    int(m_matrices->matrices().size())),
                 4000);
         });
    make(QStringLiteral("actionCopyMatlab"), tr("Copy Matrices as &MATLAB"),
         QStringLiteral("edit-copy"), QKeySequence(), [this] {
             const QList<NamedMatrix> list = m_matrices->matrices();
             if (list.isEmpty()) {
                 statusBar()->showMessage(tr("The current item has no matrices."), 4000);
                 return;
             }
             QGuiApplication::clipboard()->setText(
                 matlabMatrices(list, m_current ? m_current->name() : QString()));
             statusBar()->showMessage(
                 tr("Copied %n matrices as MATLAB cell arrays (for jsr() of the JSR toolbox).",
                    nullptr, int(list.size())),
                 4000);
         });
    make(QStringLiteral("actionDuplicate"), tr("D&uplicate Item"), QStringLiteral("edit-copy"),
         QKeySequence(tr("Ctrl+D")), &MainWindow::duplicateItem);
    make(QStringLiteral("actionDelete"), tr("&Delete Item"), QStringLiteral("edit-delete"),
         QKeySequence::Delete, &MainWindow::deleteItem);
    make(QStringLiteral("actionZoomIn"), tr("Zoom &In"), QStringLiteral("zoom-in"),
         QKeySequence::ZoomIn, [this] {
             if (m_controller->showsSurface())
                 m_surface->zoomBy(1.25);
             else
                 m_attractor->zoomIn();
         });
    make(QStringLiteral("actionZoomOut"), tr("Zoom &Out"), QStringLiteral("zoom-out"),
         QKeySequence::ZoomOut, [this] {
             if (m_controller->showsSurface())
                 m_surface->zoomBy(0.8);
             else
                 m_attractor->zoomOut();
         });
    make(QStringLiteral("actionFit"), tr("&Fit"), QStringLiteral("zoom-fit-best"),
         QKeySequence(tr("Ctrl+0")), [this] {
             if (m_controller->showsSurface())
                 m_surface->resetCamera();
             else
                 m_attractor->fitToContents();
         });
    // Window-wide (docks included, floating ones too), enabled only while a drawing runs so
    // that Esc keeps its ordinary meaning (closing a popup, cancelling a cell edit) otherwise.
    QAction *stop = make(QStringLiteral("actionStopRender"), tr("&Stop Drawing"),
                         QStringLiteral("process-stop"), QKeySequence(Qt::Key_Escape),
                         [this] { m_attractor->cancelRender(); });
    stop->setShortcutContext(Qt::WindowShortcut);
    stop->setEnabled(false);
    make(QStringLiteral("actionRenderAgain"), tr("&Draw Again"), QStringLiteral("view-refresh"),
         QKeySequence::Refresh, [this] { m_attractor->renderAgain(); });
    QAction *play = make(QStringLiteral("actionPlayAnimation"), tr("&Play/Pause Animation"),
                         QStringLiteral("media-playback-start"),
                         QKeySequence(Qt::CTRL | Qt::Key_Space), [this] {
                             m_animation->togglePlay();
                         });
    play->setShortcutContext(Qt::WindowShortcut);
    make(QStringLiteral("actionStopAnimation"), tr("S&top Animation"),
         QStringLiteral("media-playback-stop"), QKeySequence(), [this] { m_animation->stop(); });
    make(QStringLiteral("actionResetLayout"), tr("&Reset Layout"), QString(), QKeySequence(),
         &MainWindow::resetLayout);
    make(QStringLiteral("actionAbout"), tr("&About Attractor Workbench"),
         QStringLiteral("help-about"), QKeySequence(), &MainWindow::about);
    make(QStringLiteral("actionAboutQt"), tr("About &Qt"), QString(), QKeySequence(),
         [] { QApplication::aboutQt(); });
    make(QStringLiteral("actionUserGuide"), tr("&User Guide"), QStringLiteral("help-contents"),
         QKeySequence::HelpContents, &MainWindow::userGuide);

    QAction *undo = m_project->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("actionUndo"));
    undo->setShortcut(QKeySequence::Undo);
    // Without an icon theme (a bare machine) Qt's own arrows stand in.
    undo->setIcon(QIcon::fromTheme(QStringLiteral("edit-undo"),
                                   style()->standardIcon(QStyle::SP_ArrowBack)));
    QAction *redo = m_project->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("actionRedo"));
    redo->setShortcut(QKeySequence::Redo);
    redo->setIcon(QIcon::fromTheme(QStringLiteral("edit-redo"),
                                   style()->standardIcon(QStyle::SP_ArrowForward)));
    // A toolbar button without an icon shows the icon text: fixed, not the command's.
    undo->setIconText(tr("Undo"));
    redo->setIconText(tr("Redo"));
    // The command's text is in the Edit menu, the Undo History and the tooltip; the toolbar
    // shows only the icon so that it does not change width with every edit.
    const auto tip = [](QAction *a, const QString &verb, const QString &text) {
        const QString key = a->shortcut().toString(QKeySequence::NativeText);
        a->setToolTip(text.isEmpty() ? tr("Nothing to %1 (%2)").arg(verb.toLower(), key)
                                     : tr("%1 %2 (%3)").arg(verb, text, key));
    };
    connect(m_project->undoStack(), &QUndoStack::undoTextChanged, undo,
            [undo, tip](const QString &text) { tip(undo, tr("Undo"), text); });
    connect(m_project->undoStack(), &QUndoStack::redoTextChanged, redo,
            [redo, tip](const QString &text) { tip(redo, tr("Redo"), text); });
    tip(undo, tr("Undo"), QString());
    tip(redo, tr("Redo"), QString());

    // Overlays of the attractor view.
    const auto layerAction = [this](const QString &name, const QString &text,
                                    AttractorView::Layer layer, bool on) {
        auto *a = new QAction(text, this);
        a->setObjectName(name);
        a->setCheckable(true);
        a->setChecked(on);
        m_attractor->setLayerVisible(layer, on);
        connect(a, &QAction::toggled, this,
                [this, layer](bool v) { m_attractor->setLayerVisible(layer, v); });
    };
    layerAction(QStringLiteral("actionShowControl"), tr("&Control Polygon"),
                AttractorView::Layer::ControlPolygon, true);
    // The 3D view's layers and camera.
    const auto surfaceAction = [this](const QString &name, const QString &text,
                                      SurfaceView::Layer layer, bool on) {
        auto *a = new QAction(text, this);
        a->setObjectName(name);
        a->setCheckable(true);
        a->setChecked(on);
        m_surface->setLayerVisible(layer, on);
        connect(a, &QAction::toggled, this,
                [this, layer](bool v) { m_surface->setLayerVisible(layer, v); });
    };
    surfaceAction(QStringLiteral("actionShowNet"), tr("Control &Net (3D)"),
                  SurfaceView::Layer::ControlNet, true);
    surfaceAction(QStringLiteral("actionShowMesh"), tr("Subdivided &Mesh (3D)"),
                  SurfaceView::Layer::Mesh, true);
    surfaceAction(QStringLiteral("actionShowSurfaceAttractor"), tr("&Attractor (3D)"),
                  SurfaceView::Layer::Attractor, true);
    surfaceAction(QStringLiteral("actionShowAxes"), tr("A&xes (3D)"),
                  SurfaceView::Layer::Axes, true);
    surfaceAction(QStringLiteral("actionShowBox"), tr("&Bounding Box (3D)"),
                  SurfaceView::Layer::Box, false);
    auto *perspective = new QAction(tr("&Perspective (3D)"), this);
    perspective->setObjectName(QStringLiteral("actionPerspective"));
    perspective->setCheckable(true);
    connect(perspective, &QAction::toggled, m_surface, &SurfaceView::setPerspective);
    layerAction(QStringLiteral("actionShowStart"), tr("&Start Set"),
                AttractorView::Layer::StartSet, true);
    layerAction(QStringLiteral("actionShowExact"), tr("&Exact Curve"),
                AttractorView::Layer::ExactCurve, true);
    layerAction(QStringLiteral("actionShowGrid"), tr("&Grid"), AttractorView::Layer::Grid, true);
}

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    file->addAction(action(QStringLiteral("actionNew")));
    file->addAction(action(QStringLiteral("actionOpen")));
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    // The papers' figures, one project each: a copy opens (saving asks where).
    m_examplesMenu = file->addMenu(tr("Open E&xample"));
    m_examplesMenu->setObjectName(QStringLiteral("menuExamples"));
    connect(m_examplesMenu, &QMenu::aboutToShow, this, &MainWindow::fillExamplesMenu);
    file->addAction(action(QStringLiteral("actionImport")));
    file->addAction(action(QStringLiteral("actionImportMesh")));
    file->addAction(action(QStringLiteral("actionSave")));
    file->addAction(action(QStringLiteral("actionSaveAs")));
    file->addAction(action(QStringLiteral("actionRevert")));
    file->addAction(action(QStringLiteral("actionClose")));
    file->addSeparator();
    file->addAction(action(QStringLiteral("actionPrint")));
    file->addAction(action(QStringLiteral("actionPrintPreview")));
    file->addAction(action(QStringLiteral("actionPrintPdf")));
    file->addAction(action(QStringLiteral("actionExport")));
    file->addAction(action(QStringLiteral("actionExportPoints")));
    file->addAction(action(QStringLiteral("actionExportMesh")));
    file->addAction(action(QStringLiteral("actionExportItemAs")));
    file->addSeparator();
    file->addAction(action(QStringLiteral("actionQuit")));

    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(action(QStringLiteral("actionUndo")));
    edit->addAction(action(QStringLiteral("actionRedo")));
    edit->addSeparator();
    edit->addAction(action(QStringLiteral("actionCopyLatex")));
    edit->addAction(action(QStringLiteral("actionCopyMatlab")));
    edit->addSeparator();
    edit->addAction(action(QStringLiteral("actionPreferences")));
    addLanguageMenu(edit);

    QMenu *itemMenu = menuBar()->addMenu(tr("&Item"));
    QMenu *add = itemMenu->addMenu(QIcon::fromTheme(QStringLiteral("list-add")), tr("&Add"));
    for (const ItemRegistry::Kind &kind : ItemRegistry::instance().kinds()) {
        if (kind.type == SubdivisionSurfaceItem::staticType()) {
            addSurfaceMenu(add, kind.displayName());
            continue;
        }
        if (kind.type == SubdivisionMeshItem::staticType()) {
            addMeshMenu(add, kind.displayName());
            continue;
        }
        QAction *a = add->addAction(kind.displayName());
        a->setObjectName(QStringLiteral("actionAdd_") + kind.type);
        const QString type = kind.type;
        connect(a, &QAction::triggered, this, [this, type] { addItem(type); });
    }
    itemMenu->addAction(action(QStringLiteral("actionDuplicate")));
    itemMenu->addAction(action(QStringLiteral("actionDelete")));
    itemMenu->addSeparator();
    itemMenu->addAction(action(QStringLiteral("actionCreaseEdge")));
    itemMenu->addAction(action(QStringLiteral("actionSharpenVertex")));
    itemMenu->addAction(action(QStringLiteral("actionToggleHole")));

    m_viewMenu = menuBar()->addMenu(tr("&View"));
    m_viewMenu->addAction(action(QStringLiteral("actionZoomIn")));
    m_viewMenu->addAction(action(QStringLiteral("actionZoomOut")));
    m_viewMenu->addAction(action(QStringLiteral("actionFit")));
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(action(QStringLiteral("actionStopRender")));
    m_viewMenu->addAction(action(QStringLiteral("actionRenderAgain")));
    m_viewMenu->addAction(action(QStringLiteral("actionPlayAnimation")));
    m_viewMenu->addAction(action(QStringLiteral("actionStopAnimation")));
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(action(QStringLiteral("actionShowControl")));
    m_viewMenu->addAction(action(QStringLiteral("actionShowStart")));
    m_viewMenu->addAction(action(QStringLiteral("actionShowExact")));
    m_viewMenu->addAction(action(QStringLiteral("actionShowGrid")));
    m_viewMenu->addSeparator();
    for (const char *name : {"actionShowSurfaceAttractor", "actionShowNet", "actionShowMesh",
                             "actionShowAxes", "actionShowBox", "actionPerspective"})
        m_viewMenu->addAction(action(QString::fromLatin1(name)));
    m_viewMenu->addSeparator();
    for (QDockWidget *d : std::as_const(m_docks))
        m_viewMenu->addAction(d->toggleViewAction());
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(action(QStringLiteral("actionResetLayout")));
    // Issue 16: regularity of the four-point scheme against omega, in its own window.
    QAction *regularityChart = m_viewMenu->addAction(tr("Four-point &Regularity Chart…"));
    regularityChart->setObjectName(QStringLiteral("actionRegularityChart"));
    connect(regularityChart, &QAction::triggered, this, [this] {
        auto *chart = findChild<RegularityChart *>();
        if (!chart) {
            chart = new RegularityChart(this);
            chart->setWindowFlag(Qt::Window);
        }
        chart->show();
        chart->raise();
        if (chart->samples().empty() && !chart->isRunning())
            chart->compute();
    });
    // Issue 48: the certified regularity of the selected curve's family over a grid of one or
    // two parameters, computed by the Python module on a Dask cluster.
    QAction *atlas = m_viewMenu->addAction(tr("Regularity &Atlas…"));
    atlas->setObjectName(QStringLiteral("actionRegularityAtlas"));
    atlas->setStatusTip(tr("Where the selected curve's family of schemes is C^k, over one or "
                           "two of its parameters (on a Dask cluster)"));
    connect(atlas, &QAction::triggered, this, [this] {
        auto *window = findChild<RegularityAtlasWindow *>();
        if (!window) {
            window = new RegularityAtlasWindow(project(), this);
            window->setWindowFlag(Qt::Window);
        }
        auto *curve = qobject_cast<SubdivisionCurveItem *>(currentItem());
        if (curve && curve != window->item() && !window->isRunning())
            window->setItem(curve);
        else if (!window->item())
            window->setItem(nullptr);
        window->show();
        window->raise();
    });

    QMenu *tools = menuBar()->addMenu(tr("&Tools"));
    tools->setObjectName(QStringLiteral("menuTools"));
    tools->addAction(action(QStringLiteral("actionPythonConsole")));
    tools->addAction(action(QStringLiteral("actionRunScript")));
    tools->addAction(action(QStringLiteral("actionSaveRecording")));
    tools->addAction(action(QStringLiteral("actionClearRecording")));

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(action(QStringLiteral("actionUserGuide")));
    help->addSeparator();
    help->addAction(action(QStringLiteral("actionAbout")));
    help->addAction(action(QStringLiteral("actionAboutQt")));

    QToolBar *bar = addToolBar(tr("Main"));
    bar->setObjectName(QStringLiteral("toolBarMain"));
    bar->setToolButtonStyle(Qt::ToolButtonIconOnly);
    for (const char *name : {"actionNew", "actionOpen", "actionSave", "actionPrint",
                             "actionExport", "actionUndo", "actionRedo", "actionZoomIn",
                             "actionZoomOut", "actionFit"})
        bar->addAction(action(QString::fromLatin1(name)));
    bar->addSeparator();
    // Step-by-step Hutchinson iteration F^k(X0) and classic subdivision polygons.
    bar->addWidget(new QLabel(tr(" Hutchinson step: ")));
    m_hutchStep = new QSpinBox;
    m_hutchStep->setObjectName(QStringLiteral("hutchinsonStep"));
    m_hutchStep->setRange(-1, 20);
    m_hutchStep->setValue(-1);
    m_hutchStep->setSpecialValueText(tr("off"));
    m_hutchStep->setToolTip(tr("Draw Fᵏ(X₀) of the start set X₀ as vectors"));
    connect(m_hutchStep, &QSpinBox::valueChanged, m_attractor, &AttractorView::setHutchinsonStep);
    bar->addWidget(m_hutchStep);
    bar->addWidget(new QLabel(tr("  Subdivision steps: ")));
    m_subdivSteps = new QSpinBox;
    m_subdivSteps->setObjectName(QStringLiteral("subdivisionSteps"));
    m_subdivSteps->setRange(0, 8);
    m_subdivSteps->setSpecialValueText(tr("off"));
    m_subdivSteps->setToolTip(tr("Classic subdivision polygons beside the IFS attractor"));
    connect(m_subdivSteps, &QSpinBox::valueChanged, m_controller,
            &ItemController::setSubdivisionSteps);
    bar->addWidget(m_subdivSteps);
    WheelGuard::guardChildren(bar);
}

void MainWindow::addLanguageMenu(QMenu *edit)
{
    QMenu *menu = edit->addMenu(tr("&Language"));
    menu->setObjectName(QStringLiteral("menuLanguage"));
    auto *group = new QActionGroup(menu);
    group->setExclusive(true);
    QList<i18n::Language> entries{{QString(), tr("System Default")}};
    entries += i18n::availableLanguages();
    const QString saved = i18n::savedLanguage();
    const bool known = std::any_of(entries.begin(), entries.end(),
                                   [&](const i18n::Language &l) { return l.code == saved; });
    for (const i18n::Language &language : entries) {
        // Each language under its own name, so that anyone can find theirs.
        QAction *a = menu->addAction(language.nativeName);
        a->setObjectName(QStringLiteral("actionLanguage_")
                         + (language.code.isEmpty() ? QStringLiteral("system") : language.code));
        a->setCheckable(true);
        a->setData(language.code);
        a->setChecked(known ? language.code == saved : language.code.isEmpty());
        group->addAction(a);
        if (language.code.isEmpty())
            menu->addSeparator();
    }
    connect(group, &QActionGroup::triggered, this, [this](QAction *a) {
        const QString code = a->data().toString();
        if (code == i18n::savedLanguage())
            return;
        i18n::saveLanguage(code);
        m_messages->information(
            this, tr("Language"),
            tr("The language changes when Attractor Workbench is started again."));
    });
}

} // namespace awb
