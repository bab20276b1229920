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
#include "gui/app/AutomatonPanel.h"
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
#include <numeric>
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
    setAcceptDrops(true);  // files dropped on the window (MainWindowExchange.cpp)
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
    m_automaton->setItem(nullptr);
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
    // A controlled IFS's automaton (issue 46): its graph and editor; its analysis is a tab of
    // the Analysis dock.
    m_automaton = new AutomatonPanel;
    m_automaton->setObjectName(QStringLiteral("automatonPanel"));
    m_charts->tabs()->addTab(m_automaton->analysisView(), tr("Automaton"));
    connect(m_automaton, &AutomatonPanel::problem, this,
            [this](const QString &message) { statusBar()->showMessage(message, 8000); });
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

    // A click on a net edge of a mesh: its sharpness, and how to change it (issue 44).
    connect(m_surface, &SurfaceView::netEdgeClicked, this, [this](int a, int b) {
        if (const auto *mesh = qobject_cast<const SubdivisionMeshItem *>(currentItem()))
            statusBar()->showMessage(
                tr("Edge %1–%2: sharpness %3 (Item > Crease Edge… changes it)")
                    .arg(a)
                    .arg(b)
                    .arg(double(mesh->edgeSharpness(a, b))),
                8000);
    });

    // A click inside a net face of a mesh: whether it is a hole, and how to change it.
    connect(m_surface, &SurfaceView::netFaceClicked, this, [this](int f) {
        if (const auto *mesh = qobject_cast<const SubdivisionMeshItem *>(currentItem()))
            statusBar()->showMessage(
                mesh->isHole(f) ? tr("Face %1: a hole (Item > Toggle Hole fills it)").arg(f)
                                : tr("Face %1 (Item > Toggle Hole makes it a hole)").arg(f),
                8000);
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
    connect(m_controller, &ItemController::notice, this, [this](const QString &message) {
        statusBar()->showMessage(message, 10000);
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
    QDockWidget *automaton = dock(QStringLiteral("dockAutomaton"), tr("Automaton"), m_automaton,
                                  Qt::RightDockWidgetArea);
    tabifyDockWidget(animation, automaton);
    mats->raise();
    createPythonConsole();
    // A sensible first layout: side columns wide enough for their tables and plots.
    resizeDocks({tree, props}, {200, 560}, Qt::Vertical);
    // The right column: the Spectrum above, the Matrices / Analysis tabs below with the larger
    // share (a mesh's Vertex and Valences tabs need it: issue 47).
    resizeDocks({spec, mats}, {360, 480}, Qt::Vertical);
    resizeDocks({props, spec}, {320, 420}, Qt::Horizontal);
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
    m_automaton->setItem(item);
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
    const bool mesh = qobject_cast<SubdivisionMeshItem *>(m_current.data()) != nullptr;
    action(QStringLiteral("actionCreaseEdge"))->setEnabled(mesh);
    action(QStringLiteral("actionSharpenVertex"))->setEnabled(mesh);
    action(QStringLiteral("actionToggleHole"))->setEnabled(mesh);
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
    // The core's formulas as the papers write them; cut at a word, the whole in the tooltip.
    const QString first = mathText(problem.section(QLatin1Char('\n'), 0, 0));
    // Before the first layout the label has no width yet: half the status bar's.
    const int room = m_problemLabel->width() > 40 ? m_problemLabel->width()
                                                  : statusBar()->width() / 2;
    m_problemLabel->setText(elidedAtWord(m_problemLabel->fontMetrics(), first,
                                         std::max(40, room)));
    m_problemLabel->setToolTip(problem.size() > first.size() || m_problemLabel->text() != first
                                   ? mathText(problem)
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
    int columnMinimum[2] = {0, 0};  // the widest minimum of the column's docks
    for (QDockWidget *d : std::as_const(m_docks)) {
        if (!d->isVisible() || d->isFloating())
            continue;
        const Qt::DockWidgetArea area = dockWidgetArea(d);
        const int side = area == Qt::LeftDockWidgetArea ? 0
                         : area == Qt::RightDockWidgetArea ? 1
                                                          : -1;
        if (side < 0)
            continue;
        if (!columns[side])
            columns[side] = d;
        columnMinimum[side] = std::max({columnMinimum[side], d->minimumSizeHint().width(),
                                        d->layout() ? d->layout()->minimumSize().width() : 0});
    }
    int docks = 0;
    for (QDockWidget *d : columns)
        docks += d ? d->width() : 0;
    if (docks <= 0)
        return;
    // The docks' share: 46% of a small window, half of a large one (the Properties' editors
    // and the right column's plots need their widths more than the view needs the last 4%).
    const double share = total >= 1300 ? 0.5 : 0.46;
    const double scale = share * total / docks;
    QList<QDockWidget *> list;
    QList<int> widths, minimum;
    for (int side = 0; side < 2; ++side)
        if (QDockWidget *d = columns[side]) {
            list << d;
            minimum << columnMinimum[side];
            widths << std::max(minimum.back(), int(d->width() * scale));
        }
    // A column held at its minimum leaves the other above its share: take the excess back from
    // the columns that can give it, the right one (plots, wider by default) first.
    int excess = int(std::accumulate(widths.begin(), widths.end(), 0) - share * total);
    for (qsizetype k = list.size() - 1; k >= 0 && excess > 0; --k) {
        const int give = std::min(excess, widths[k] - minimum[k]);
        widths[k] -= give;
        excess -= give;
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
