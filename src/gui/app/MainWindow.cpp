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

// Resources of a static library are only registered when asked for (outside any namespace).
static void initResources()
{
    Q_INIT_RESOURCE(resources);
}

namespace awb {

MainWindow::MainWindow(Messages *messages, const QString &recoveryDirectory, QWidget *parent)
    : QMainWindow(parent), m_messages(messages), m_project(std::make_unique<Project>()),
      m_recoveryDirectory(recoveryDirectory.isEmpty() ? Recovery::defaultDirectory()
                                                      : recoveryDirectory),
      m_preferences(Preferences::load())
{
    if (!m_messages) {
        m_ownMessages = std::make_unique<Messages>();
        m_messages = m_ownMessages.get();
    }
    initResources();
    // Without a desktop session (offscreen, a bare X server) Qt may look for icon themes only
    // in its resources: add the XDG icon folders and take an installed theme.
    if (!QIcon::hasThemeIcon(QStringLiteral("document-open"))) {
        QStringList paths = QIcon::themeSearchPaths();
        const QString dataDirs = qEnvironmentVariable("XDG_DATA_DIRS");
        for (const QString &dir : (dataDirs.isEmpty() ? QStringLiteral("/usr/local/share:/usr/share")
                                                      : dataDirs)
                                      .split(QLatin1Char(':'), Qt::SkipEmptyParts))
            if (!paths.contains(dir + QStringLiteral("/icons")))
                paths << dir + QStringLiteral("/icons");
        QIcon::setThemeSearchPaths(paths);
        for (const QString &theme : {QStringLiteral("Adwaita"), QStringLiteral("breeze")}) {
            const QString old = QIcon::themeName();
            QIcon::setThemeName(theme);
            if (QIcon::hasThemeIcon(QStringLiteral("document-open")))
                break;
            QIcon::setThemeName(old);
        }
    }
    setObjectName(QStringLiteral("MainWindow"));
    setWindowIcon(QIcon(QStringLiteral(":/icons/attractor-workbench.svg")));
    setDockOptions(AnimatedDocks | AllowNestedDocks | AllowTabbedDocks);
    createViews();
    createActions();
    createDocks();
    createMenus();

    connect(m_project.get(), &Project::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_project.get(), &Project::fileNameChanged, this, &MainWindow::updateTitle);
    connect(m_project.get(), &Project::aboutToReset, this, [this] { setCurrentItem(nullptr); });
    connect(m_project.get(), &Project::reset, this, &MainWindow::selectFirstItem);
    connect(m_project.get(), &Project::itemInserted, this,
            [this](Item *item) { setCurrentItem(item); });
    connect(m_project.get(), &Project::itemAboutToBeRemoved, this, [this](Item *item) {
        if (m_current && (m_current == item || item->isAncestorOf(m_current)))
            setCurrentItem(nullptr);
    });
    connect(m_project.get(), &Project::itemRemoved, this, [this] {
        if (!m_current)
            selectFirstItem();
    });
    connect(m_project->undoStack(), &QUndoStack::indexChanged, this, &MainWindow::updateActions);

    m_recovery = std::make_unique<Recovery>(m_project.get(), m_recoveryDirectory);
    connect(m_recovery.get(), &Recovery::autosaveFailed, this, [this](const QString &message) {
        statusBar()->showMessage(tr("Autosave failed: %1").arg(message), 8000);
    });
    applyPreferences(m_preferences);

    // A first size that uses most of the screen; the saved geometry wins when there is one.
    if (const QScreen *screen = QGuiApplication::primaryScreen())
        resize(screen->availableSize() * 0.9);
    else
        resize(1400, 900);
    m_defaultState = saveState();
    QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    updateRecentMenu();
    newProject();
}

MainWindow::~MainWindow()
{
    // The controller and the properties read the items: unbind before the project goes.
    m_animation->setItem(nullptr);
    m_controller->setItem(nullptr);
    m_properties->setItem(nullptr);
    // The project (a member) dies before the child widgets: detach the views that read it.
    m_tree->setModel(nullptr);
    delete m_treeModel;
    m_undoView->setStack(nullptr);
    m_recovery.reset();
}

QAction *MainWindow::action(const QString &objectName) const
{
    return findChild<QAction *>(objectName);
}

Item *MainWindow::currentItem() const { return m_current; }

void MainWindow::createViews()
{
    m_attractor = new AttractorView;
    m_attractor->setObjectName(QStringLiteral("attractorView"));
    // The central view follows the current item's dimension: the plane view for curves, the
    // 3D view for surfaces.
    m_surface = new SurfaceView;
    m_surface->setObjectName(QStringLiteral("surfaceView"));
    m_central = new QStackedWidget;
    m_central->addWidget(m_attractor);
    m_central->addWidget(m_surface);
    // An eigenvalue plot item shows its plot in the centre (its source has its own item).
    m_plotView = new SpectrumView;
    m_plotView->setObjectName(QStringLiteral("eigenvaluePlotView"));
    m_central->addWidget(m_plotView);
    setCentralWidget(m_central);
    m_matrices = new MatrixView;
    m_spectrum = new SpectrumView;
    m_charts = new AnalysisCharts;
    m_properties = new PropertiesWidget(m_messages);
    m_treeModel = new ProjectTreeModel(m_project.get(), this);
    m_tree = new QTreeView;
    m_tree->setModel(m_treeModel);
    m_tree->setHeaderHidden(false);
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_tree->header()->setSectionResizeMode(1, QHeaderView::Interactive);
    m_tree->header()->resizeSection(1, 90);
    m_tree->header()->setStretchLastSection(false);
    // The name gets the room ("000 Fig. 11 (top): Sierpinski g…" and "(bottom): …" stay
    // apart); the tooltip has the whole name and kind.
    m_tree->setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::DoubleClicked);
    connect(m_tree->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex &index) {
                Item *item = m_treeModel->itemAt(index);
                if (item != m_current)
                    setCurrentItem(item);
            });
    m_undoView = new QUndoView(m_project->undoStack());
    m_undoView->setEmptyLabel(tr("<original>"));
    // During gestures the view under the pointer gets the frames, the docks follow a few
    // times a second: the document's gestures (drags, sliders) and playback count.
    m_budget = new FrameBudget(this);
    connect(m_project.get(), &Project::gestureActiveChanged, m_budget, [this](bool active) {
        active ? m_budget->beginGesture() : m_budget->endGesture();
    });
    m_properties->setFrameBudget(m_budget);
    m_controller = new ItemController(m_attractor, m_matrices, m_spectrum, m_charts, m_budget,
                                      this);
    m_controller->setSurfaceView(m_surface);
    m_controller->setPlotView(m_plotView);
    // The scheme's certified regularity sits under the Analysis dock's charts (issue 16).
    auto *regularity = new RegularityPanel;
    m_charts->layout()->addWidget(regularity);
    m_controller->setRegularityPanel(regularity);
    // A mesh's extraordinary vertices (issue 31): a click on one in the 3D view shows its
    // verdict and characteristic map here, its matrix and eigenvalues in their docks.
    m_vertexPanel = new VertexPanel;
    m_valenceChart = new ValenceChart;
    m_charts->tabs()->addTab(m_vertexPanel, tr("Vertex"));
    m_charts->tabs()->addTab(m_valenceChart, tr("Valences"));
    m_controller->setVertexViews(m_vertexPanel, m_valenceChart);
    // Addresses of the attractor (issue 16): the status bar shows the hovered one, the
    // Address dock selects a sub-copy.
    m_address = new AddressPanel(m_controller, m_attractor);
    m_address->setObjectName(QStringLiteral("addressPanel"));
    // Parameter animation (issue 16): keys of the current item, and its frames in the views.
    m_animation = new AnimationPanel;
    m_animation->setObjectName(QStringLiteral("animationPanel"));
    connect(m_animation, &AnimationPanel::frameChanged, m_controller, &ItemController::showFrame);
    connect(m_animation, &AnimationPanel::playingChanged, m_budget, [this](bool playing) {
        playing ? m_budget->beginGesture() : m_budget->endGesture();
    });
    connect(m_animation, &AnimationPanel::problem, this,
            [this](const QString &message) { statusBar()->showMessage(message, 8000); });
    // A click on a control point in the 3D view selects its row: x, y, z to edit exactly.
    connect(m_surface, &SurfaceView::controlPointPressed, this, [this](int index) {
        if (auto *t = qobject_cast<QTableWidget *>(m_properties->editor(QStringLiteral("points"))))
            t->selectRow(index);
    });

    // Status bar: cursor position, problems, long-work progress with a cancel button.
    // Set on every mouse move: a readout that never lays out the window again.
    m_cursorLabel = new StatusText(QStringLiteral("x = −0.123456, y = −0.123456   "
                                                  "w = 0,1,2,0,1,2,0,1   t = 0.1234567"));
    m_cursorLabel->setObjectName(QStringLiteral("cursorReadout"));
    m_problemLabel = new QLabel;
    m_problemLabel->setObjectName(QStringLiteral("problemLabel"));
    // A long explanation must not widen the window: elided here, whole in the tooltip and in
    // the Analysis panel's note.
    m_problemLabel->setMinimumWidth(40);
    m_problemLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_progress = new QProgressBar;
    m_progress->setRange(0, 100);
    m_progress->setMaximumWidth(160);
    m_progress->setVisible(false);
    m_cancel = new QToolButton;
    m_cancel->setText(tr("Cancel"));
    m_cancel->setToolTip(tr("Cancel the analysis"));
    m_cancel->setVisible(false);
    m_renderProgress = new QProgressBar;
    m_renderProgress->setObjectName(QStringLiteral("renderProgress"));
    m_renderProgress->setRange(0, 100);
    m_renderProgress->setMaximumWidth(160);
    m_renderProgress->setFormat(tr("Drawing %p%"));
    m_renderProgress->setVisible(false);
    m_renderCancel = new QToolButton;
    m_renderCancel->setObjectName(QStringLiteral("renderCancel"));
    m_renderCancel->setText(tr("Stop"));
    m_renderCancel->setToolTip(tr("Stop drawing the attractor (Esc); F5 draws it again"));
    m_renderCancel->setVisible(false);
    m_renderShowTimer = new QTimer(this);
    m_renderShowTimer->setSingleShot(true);
    m_renderShowTimer->setInterval(400);
    statusBar()->addWidget(m_problemLabel, 1);
    statusBar()->addPermanentWidget(m_renderProgress);
    statusBar()->addPermanentWidget(m_renderCancel);
    statusBar()->addPermanentWidget(m_progress);
    statusBar()->addPermanentWidget(m_cancel);
    connect(m_renderCancel, &QToolButton::clicked, m_attractor, &AttractorView::cancelRender);
    // An export or a print that draws the attractor anew (another framing, a hidden view)
    // shows its progress after a moment and can be cancelled.
    m_attractor->setExportProgress([this](double fraction) {
        if (!m_exportProgress) {
            m_exportProgress = new QProgressDialog(tr("Drawing the attractor for the figure…"),
                                                   tr("Cancel"), 0, 100, this);
            m_exportProgress->setObjectName(QStringLiteral("exportProgress"));
            m_exportProgress->setWindowTitle(tr("Figure"));
            m_exportProgress->setWindowModality(Qt::ApplicationModal);
            m_exportProgress->setMinimumDuration(400);
            m_exportProgress->setAutoReset(false);
            m_exportProgress->setAutoClose(false);
            m_exportProgress->setValue(0);
        }
        m_exportProgress->setValue(std::clamp(int(std::lround(100 * fraction)), 0, 99));
        QCoreApplication::processEvents();
        return !m_exportProgress->wasCanceled();
    });
    connect(m_attractor->renderer(), &AttractorRenderer::busyChanged, this, [this](bool busy) {
        // Esc stops a drawing from anywhere in the window, and only then takes the key.
        action(QStringLiteral("actionStopRender"))->setEnabled(m_attractor->isRendering());
        if (busy) {
            m_renderProgress->setValue(0);
            if (!m_renderShowTimer->isActive() && !m_renderProgress->isVisible())
                m_renderShowTimer->start();
        } else {
            m_renderShowTimer->stop();
            m_renderProgress->setVisible(false);
            m_renderCancel->setVisible(false);
        }
    });
    connect(m_renderShowTimer, &QTimer::timeout, this, [this] {
        if (m_attractor->isRendering()) {
            m_renderProgress->setVisible(true);
            m_renderCancel->setVisible(true);
        }
    });
    connect(m_attractor, &AttractorView::renderProgress, this,
            [this](double f) { m_renderProgress->setValue(int(std::lround(100 * f))); });
    connect(m_attractor, &AttractorView::renderCancelled, this, [this] {
        statusBar()->showMessage(tr("Drawing stopped; press F5 to draw again."), 6000);
    });
    statusBar()->addPermanentWidget(m_cursorLabel);
    connect(m_cancel, &QToolButton::clicked, m_controller, &ItemController::cancelAnalysis);
    // An eigenvalue plot's source may change between a curve and a surface.
    connect(m_project.get(), &Project::itemChanged, this, [this](Item *item) {
        if (item == m_current)
            updateCentralView();
    });
    // A click on an eigenvalue marker marks that map's matrices and its part of the attractor.
    for (SpectrumView *plot : {m_spectrum, m_plotView})
        connect(plot, &SpectrumView::mapClicked, this, [this](int map) {
            m_matrices->setHighlightedMap(map);
            m_spectrum->setHighlightedMap(map);
            m_plotView->setHighlightedMap(map);
            m_controller->setHighlightedMap(map);
        });
    connect(m_controller, &ItemController::analysisStarted, this, [this] {
        m_progress->setValue(0);
        m_progress->setFormat(tr("Analysis %p%"));
        m_progress->setVisible(true);
        m_cancel->setVisible(true);
    });
    connect(m_controller, &ItemController::analysisProgress, this,
            [this](double f) { m_progress->setValue(int(f * 100)); });
    connect(m_controller, &ItemController::analysisFinished, this, [this](bool cancelled) {
        m_progress->setVisible(false);
        m_cancel->setVisible(false);
        if (cancelled)
            statusBar()->showMessage(tr("Analysis cancelled."), 4000);
    });
    connect(m_controller, &ItemController::problemChanged, this, &MainWindow::showProblem);
    connect(m_controller, &ItemController::focusedVertexChanged, this, [this](int index) {
        if (index < 0)
            return;
        // The vertex's verdict and map in front; its eigenvalues are in the Spectrum dock.
        if (auto *analysis = findChild<QDockWidget *>(QStringLiteral("dockAnalysis")))
            analysis->raise();
        m_charts->tabs()->setCurrentWidget(m_vertexPanel);
        QString where = m_controller->focusedVertexName();
        if (!where.isEmpty())
            where[0] = where[0].toUpper();
        statusBar()->showMessage(tr("%1: its spectrum, verdict and characteristic map are in "
                                    "the Spectrum, Matrices and Analysis docks")
                                     .arg(where),
                                 6000);
    });
    m_controller->setRebalanceQuestion([this](const QString &question) {
        return m_messages->question(this, tr("Row sum"), question,
                                    QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes)
               == QMessageBox::Yes;
    });
    connect(m_controller, &ItemController::editRefused, this, [this](const QString &message) {
        m_messages->error(this, tr("Edit refused"), message);
    });
    connect(m_attractor, &AttractorView::cursorMoved, this, [this](const QPointF &w) {
        // The address under the cursor is sampled from the IFS, which a drag changes on every
        // move: during gestures the readout shows the coordinates only.
        const QString address = m_budget->inGesture() ? QString() : m_address->hoverText(w);
        const QString at = tr("x = %1, y = %2").arg(w.x(), 0, 'g', 5).arg(w.y(), 0, 'g', 5);
        m_cursorLabel->setText(address.isEmpty() ? at : at + QStringLiteral("   ") + address);
    });
    connect(m_attractor, &AttractorView::cursorLeft, m_cursorLabel, &StatusText::clear);
    connect(m_attractor, &AttractorView::renderFailed, this, [this](const QString &message) {
        statusBar()->showMessage(tr("Drawing failed: %1").arg(message), 8000);
    });
}

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
    make(QStringLiteral("actionImport"), tr("&Import…"), QStringLiteral("document-import"),
         QKeySequence(tr("Ctrl+I")), &MainWindow::importDialog);
    make(QStringLiteral("actionExportItemAs"), tr("Export &Item As…"),
         QStringLiteral("document-export"), QKeySequence(), &MainWindow::exportItemAsDialog);
    make(QStringLiteral("actionImportMesh"), tr("&Import Mesh…"),
         QStringLiteral("document-import"), QKeySequence(), &MainWindow::importMeshDialog);
    make(QStringLiteral("actionExportMesh"), tr("Export &Mesh…"),
         QStringLiteral("document-export"), QKeySequence(), &MainWindow::exportMeshDialog);
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
         QStringLiteral("document-print-preview"), QKeySequence(tr("Ctrl+Shift+P")),
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

void MainWindow::createDocks()
{
    const auto dock = [this](const QString &name, const QString &title, QWidget *w,
                             Qt::DockWidgetArea area) {
        auto *d = new QDockWidget(title, this);
        d->setObjectName(name);
        d->setWidget(w);
        addDockWidget(area, d);
        m_docks.append(d);
        return d;
    };
    QDockWidget *tree = dock(QStringLiteral("dockProject"), tr("Project"), m_tree,
                             Qt::LeftDockWidgetArea);
    QDockWidget *props = dock(QStringLiteral("dockProperties"), tr("Properties"), m_properties,
                              Qt::LeftDockWidgetArea);
    QDockWidget *undo = dock(QStringLiteral("dockUndo"), tr("Undo History"), m_undoView,
                             Qt::LeftDockWidgetArea);
    QDockWidget *spec = dock(QStringLiteral("dockSpectrum"), tr("Spectrum"), m_spectrum,
                             Qt::RightDockWidgetArea);
    QDockWidget *mats = dock(QStringLiteral("dockMatrices"), tr("Matrices"), m_matrices,
                             Qt::RightDockWidgetArea);
    QDockWidget *charts = dock(QStringLiteral("dockAnalysis"), tr("Analysis"), m_charts,
                               Qt::RightDockWidgetArea);
    tabifyDockWidget(props, undo);
    props->raise();
    QDockWidget *address = dock(QStringLiteral("dockAddress"), tr("Address"), m_address,
                                Qt::RightDockWidgetArea);
    tabifyDockWidget(mats, charts);
    tabifyDockWidget(charts, address);
    QDockWidget *animation = dock(QStringLiteral("dockAnimation"), tr("Animation"), m_animation,
                                  Qt::RightDockWidgetArea);
    tabifyDockWidget(address, animation);
    mats->raise();
    // A sensible first layout: side columns wide enough for their tables and plots.
    resizeDocks({tree, props}, {200, 560}, Qt::Vertical);
    resizeDocks({spec, mats}, {420, 420}, Qt::Vertical);
    resizeDocks({props, spec}, {320, 350}, Qt::Horizontal);
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

void MainWindow::applyPreferences(const Preferences &preferences)
{
    m_preferences = preferences;
    m_recovery->setInterval(std::max(5, preferences.autosaveSeconds) * 1000);
    m_controller->setPalette(preferences.palette);
    m_properties->setDefaultPalette(preferences.palette);
    m_controller->setMaxDepth(preferences.maxRenderDepth);
}

void MainWindow::setCurrentItem(Item *item)
{
    m_current = item;
    m_controller->setItem(item);
    m_animation->setItem(item);
    m_spectrum->setHighlightedMap(-1);
    m_matrices->setHighlightedMap(-1);
    updateCentralView();
    m_properties->setItem(item);
    const QModelIndex index = item ? m_treeModel->indexOf(item) : QModelIndex();
    if (m_tree->currentIndex() != index)
        m_tree->setCurrentIndex(index);
    updateActions();
}

void MainWindow::selectFirstItem()
{
    setCurrentItem(m_project->childCount() > 0 ? m_project->child(0) : nullptr);
}

void MainWindow::updateTitle()
{
    const QString file = m_project->fileName();
    setWindowFilePath(file.isEmpty() ? tr("Untitled") : file);
    setWindowTitle(tr("%1[*] — Attractor Workbench")
                       .arg(file.isEmpty() ? tr("Untitled") : QFileInfo(file).fileName()));
    setWindowModified(m_project->isModified());
    updateActions();
}

void MainWindow::updateActions()
{
    const bool hasItem = m_current != nullptr;
    action(QStringLiteral("actionDuplicate"))->setEnabled(hasItem);
    action(QStringLiteral("actionDelete"))->setEnabled(hasItem);
    action(QStringLiteral("actionRevert"))
        ->setEnabled(!m_project->fileName().isEmpty() && m_project->isModified());
    for (const char *name : {"actionPrint", "actionPrintPreview", "actionPrintPdf"})
        action(QString::fromLatin1(name))->setEnabled(hasItem);
}

void MainWindow::preferencesDialog()
{
    PreferencesDialog dialog(m_preferences, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const Preferences p = dialog.preferences();
    p.save();
    applyPreferences(p);
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

void MainWindow::about()
{
    m_messages->information(
        this, tr("About Attractor Workbench"),
        tr("Attractor Workbench %1\n\nSubdivision curves as attractors of iterated function "
           "systems: control points, subdivision matrices, spectra and figures.")
                .arg(QStringLiteral(AWB_VERSION))
            + QStringLiteral("\n\n")
            + tr("Built with Qt %1 (running on Qt %2), Eigen %3 and QCustomPlot %4.")
                  .arg(QStringLiteral(QT_VERSION_STR), QString::fromLatin1(qVersion()),
                       QStringLiteral("%1.%2.%3")
                           .arg(EIGEN_WORLD_VERSION)
                           .arg(EIGEN_MAJOR_VERSION)
                           .arg(EIGEN_MINOR_VERSION),
                       qcustomplotVersion()));
}

void MainWindow::resetLayout()
{
    restoreState(m_defaultState);
    for (QDockWidget *d : std::as_const(m_docks))
        d->show();
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    event->accept();
}

} // namespace awb

namespace awb {

void MainWindow::updateCentralView()
{
    QWidget *view = qobject_cast<EigenvaluePlotItem *>(m_current)
                        ? static_cast<QWidget *>(m_plotView)
                    : m_controller->showsSurface() ? static_cast<QWidget *>(m_surface)
                                                   : m_attractor;
    if (m_central->currentWidget() != view)
        m_central->setCurrentWidget(view);
}

void MainWindow::showProblem(const QString &problem)
{
    m_problem = problem;
    const QString first = problem.section(QLatin1Char('\n'), 0, 0);
    // Before the first layout the label has no width yet: half the status bar's.
    const int room = m_problemLabel->width() > 40 ? m_problemLabel->width()
                                                  : statusBar()->width() / 2;
    m_problemLabel->setText(m_problemLabel->fontMetrics().elidedText(first, Qt::ElideRight,
                                                                      std::max(40, room)));
    m_problemLabel->setToolTip(problem.size() > first.size() || m_problemLabel->text() != first
                                   ? problem
                                   : QString());
    m_charts->setNote(problem);
}

void MainWindow::resizeEvent(QResizeEvent *event)
{
    QMainWindow::resizeEvent(event);
    // The docks keep their widths when the window gets narrower (a dock dragged wider by the
    // user stays so until then); the layout settles first. The status note is elided anew.
    const bool widthChanged = event->size().width() != event->oldSize().width();
    QTimer::singleShot(0, this, [this, widthChanged] {
        if (widthChanged)
            shareWidthWithDocks();
        showProblem(m_problem);
        keepDockTabsWhole();
    });
}

void MainWindow::keepDockTabsWhole()
{
    // The tabs of tabified docks are elided by default ("Proprié…", "Historique des
    // modificati…" in French): whole titles, with scroll buttons when they do not fit.
    for (QTabBar *bar : findChildren<QTabBar *>(QString(), Qt::FindDirectChildrenOnly)) {
        bar->setElideMode(Qt::ElideNone);
        bar->setUsesScrollButtons(true);
        bar->setExpanding(false);
    }
}

void MainWindow::shareWidthWithDocks()
{
    const int total = width();
    const int central = m_central->width();
    if (total <= 0 || central >= total / 2)
        return;
    // Shrink the columns of docks on either side (one dock stands for its column) in
    // proportion, so that the central view gets about 54% of the width; the docks' minimum
    // sizes still apply.
    QDockWidget *columns[2] = {nullptr, nullptr};
    for (QDockWidget *d : std::as_const(m_docks)) {
        if (!d->isVisible() || d->isFloating())
            continue;
        const Qt::DockWidgetArea area = dockWidgetArea(d);
        const int side = area == Qt::LeftDockWidgetArea ? 0
                         : area == Qt::RightDockWidgetArea ? 1
                                                          : -1;
        if (side >= 0 && !columns[side])
            columns[side] = d;
    }
    int docks = 0;
    for (QDockWidget *d : columns)
        docks += d ? d->width() : 0;
    if (docks <= 0)
        return;
    const double scale = 0.46 * total / docks;
    QList<QDockWidget *> list;
    QList<int> widths;
    for (QDockWidget *d : columns)
        if (d) {
            list << d;
            widths << std::max(d->minimumSizeHint().width(), int(d->width() * scale));
        }
    resizeDocks(list, widths, Qt::Horizontal);
}

void MainWindow::userGuide()
{
    QList<QAction *> actions;
    for (QAction *a : menuBar()->actions())
        if (a->menu())
            for (QAction *b : a->menu()->actions())
                if (!b->isSeparator() && !b->menu())
                    actions << b;
    auto *dialog = new UserGuideDialog(actions, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show(); // not modal: read it beside the window
}

} // namespace awb
