// MainWindow: the project's files -- new, open, save, revert, close, the recent files, the
// bundled examples, the recovery of crashed sessions -- and where outputs are proposed.

#include "gui/app/MainWindow.h"
#include "gui/app/AddressPanel.h"
#include "gui/app/AnimationPanel.h"
#include "gui/app/ExampleGallery.h"
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
#include "model/ScriptRecorder.h"
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
#include <QBuffer>
#include <QChartView>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMap>
#include <QMenu>
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

#include <QStandardPaths>

#include <QJsonDocument>

#include <QJsonObject>

namespace awb {

namespace {

constexpr int maxRecentFiles = 8;

QString fileFilter()
{
    return MainWindow::tr("Attractor Workbench projects (*.awb);;All files (*)");
}

} // namespace

void MainWindow::newProject()
{
    m_project->clear();
    auto curve = std::make_unique<SubdivisionCurveItem>();
    curve->setName(tr("Cubic B-spline"));
    curve->moveControlPoints({{0, {0, 0}}, {1, {1, 2}}, {2, {3, 2.5}}, {3, {4.5, 1}}});
    curve->insertControlPoint(4, {6, 2});
    AlgorithmSpec a = curve->algorithm();
    a.depth = m_preferences.defaultDepth;
    if (!curve->checkAlgorithm(a))
        curve->setAlgorithm(a);
    StartSetSpec s;
    s.kind = StartSetSpec::Kind::Triangle;
    s.points = {{2, -0.5}, {4, -0.5}, {3, 0.5}};
    curve->setStartSet(s);
    m_project->addItem(std::move(curve));
    // Building the first item is not an edit the user made.
    m_project->undoStack()->clear();
    m_project->undoStack()->setClean();
    updateTitle();
    selectFirstItem();
}

bool MainWindow::openFile(const QString &fileName)
{
    // Another tool's IFS file (a Fractint library, a flame): an untitled project of its
    // entries, never saved over the file (File > Import adds them to the open project).
    const QString suffix = QFileInfo(fileName).suffix().toLower();
    if (suffix == QLatin1String("ifs") || suffix == QLatin1String("flame")
        || suffix == QLatin1String("flam3")) {
        if (!importReporting(fileName, true))
            return false;
        updateTitle();
        return true;
    }
    QString error;
    if (!m_project->open(fileName, &error)) {
        m_messages->error(this, tr("Open Project"), error);
        return false;
    }
    addRecentFile(QFileInfo(fileName).absoluteFilePath());
    updateTitle();
    selectFirstItem();
    statusBar()->showMessage(tr("Opened %1").arg(QFileInfo(fileName).fileName()), 4000);
    return true;
}

bool MainWindow::saveFile(const QString &fileName)
{
    QString error;
    if (!m_project->saveAs(fileName, &error)) {
        m_messages->error(this, tr("Save Project"), error);
        return false;
    }
    addRecentFile(QFileInfo(fileName).absoluteFilePath());
    updateTitle();
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(fileName).fileName()), 4000);
    return true;
}

bool MainWindow::maybeSave()
{
    if (!m_project->isModified())
        return true;
    const auto answer = m_messages->question(
        this, tr("Unsaved Changes"),
        tr("The project \"%1\" has unsaved changes. Save them?")
            .arg(m_project->fileName().isEmpty() ? tr("Untitled")
                                                 : QFileInfo(m_project->fileName()).fileName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::openDialog()
{
    if (!maybeSave())
        return;
    const QString name = QFileDialog::getOpenFileName(
        this, tr("Open Project"), QFileInfo(m_project->fileName()).path(),
        tr("Projects and figures with their item (*.awb *.png *.svg);;Attractor Workbench "
           "projects (*.awb);;Exported figures (*.png *.svg);;Other tools' IFS files, as a new "
           "project (*.ifs *.flame *.flam3);;All files (*)"));
    if (!name.isEmpty())
        openFile(name);
}

bool MainWindow::save()
{
    if (m_project->fileName().isEmpty())
        return saveAs();
    return saveFile(m_project->fileName());
}

bool MainWindow::saveAs()
{
    // A new project (or an example's copy) is proposed in the user's documents.
    QString name = QFileDialog::getSaveFileName(
        this, tr("Save Project As"),
        m_project->fileName().isEmpty() || !QFileInfo(QFileInfo(m_project->fileName()).path()).isWritable()
            ? outputPath(QStringLiteral("awb"))
            : m_project->fileName(),
        fileFilter());
    if (name.isEmpty())
        return false;
    if (QFileInfo(name).suffix().isEmpty())
        name += QStringLiteral(".awb");
    return saveFile(name);
}

void MainWindow::revert()
{
    const QString file = m_project->fileName();
    if (file.isEmpty())
        return;
    const auto answer = m_messages->question(
        this, tr("Revert"), tr("Discard all changes and reload %1?").arg(QFileInfo(file).fileName()),
        QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer == QMessageBox::Discard)
        openFile(file);
}

void MainWindow::closeProject()
{
    if (maybeSave())
        newProject();
}

void MainWindow::addRecentFile(const QString &fileName)
{
    QSettings settings;
    QStringList files = settings.value(QStringLiteral("recentFiles")).toStringList();
    files.removeAll(fileName);
    files.prepend(fileName);
    while (files.size() > maxRecentFiles)
        files.removeLast();
    settings.setValue(QStringLiteral("recentFiles"), files);
    updateRecentMenu();
}

void MainWindow::updateRecentMenu()
{
    if (!m_recentMenu)
        return;
    m_recentMenu->clear();
    const QStringList files = QSettings().value(QStringLiteral("recentFiles")).toStringList();
    for (int i = 0; i < files.size(); ++i) {
        QAction *a = m_recentMenu->addAction(
            tr("&%1 %2").arg(i + 1).arg(QFileInfo(files[i]).fileName()));
        a->setToolTip(files[i]);
        const QString file = files[i];
        connect(a, &QAction::triggered, this, [this, file] {
            if (maybeSave())
                openFile(file);
        });
    }
    m_recentMenu->setEnabled(!files.isEmpty());
}

bool MainWindow::offerRecovery()
{
    const QList<RecoveryFile> files = Recovery::orphans(m_recoveryDirectory);
    for (const RecoveryFile &f : files) {
        const QString what = f.originalFile.isEmpty() ? tr("an unsaved project")
                                                      : QFileInfo(f.originalFile).fileName();
        const auto answer = m_messages->question(
            this, tr("Recover Project"),
            tr("Attractor Workbench did not shut down properly. A recovery copy of %1 from %2 "
               "exists. Recover it? (Discard deletes the copy.)")
                .arg(what, QLocale().toString(f.savedAt.toLocalTime(), QLocale::ShortFormat)),
            QMessageBox::Yes | QMessageBox::Discard | QMessageBox::Ignore, QMessageBox::Yes);
        if (answer == QMessageBox::Discard) {
            Recovery::discard(f);
        } else if (answer == QMessageBox::Yes) {
            QString error;
            if (!Recovery::recover(f, m_project.get(), &error)) {
                // Never deleted: set aside, out of the next start's way.
                const QString kept = Recovery::setAside(f);
                m_messages->error(
                    this, tr("Recover Project"),
                    kept.isEmpty()
                        ? tr("The recovery copy cannot be read: %1").arg(error)
                        : tr("The recovery copy cannot be read: %1\n\nIt was kept as %2.")
                              .arg(error, QDir::toNativeSeparators(kept)));
                continue;
            }
            Recovery::discard(f);
            updateTitle();
            selectFirstItem();
            return true;
        }
    }
    return false;
}

QString sourceTreeExamples();  // generated (src/gui/CMakeLists.txt)

QString MainWindow::examplesDirectory()
{
    // AWB_EXAMPLES_DIR, the installed data folder (beside the program: /usr/bin ->
    // /usr/share/attractor-workbench/examples, or any prefix), the generic data folders, and
    // the source tree this program was built from.
    QStringList candidates;
    if (qEnvironmentVariableIsSet("AWB_EXAMPLES_DIR"))
        candidates << qEnvironmentVariable("AWB_EXAMPLES_DIR");
    candidates << QCoreApplication::applicationDirPath()
                      + QStringLiteral("/../share/attractor-workbench/examples");
    for (const QString &d : QStandardPaths::standardLocations(QStandardPaths::GenericDataLocation))
        candidates << d + QStringLiteral("/attractor-workbench/examples");
    candidates << sourceTreeExamples();
    for (const QString &c : candidates)
        if (QDir(c).exists() && !QDir(c).entryList({QStringLiteral("*.awb")}).isEmpty())
            return QDir(c).canonicalPath();
    return {};
}

void MainWindow::fillExamplesMenu()
{
    m_examplesMenu->clear();
    // The submenus of the last time (children of the menu, not owned by its actions).
    qDeleteAll(m_examplesMenu->findChildren<QMenu *>(QString(), Qt::FindDirectChildrenOnly));
    const QDir dir(examplesDirectory());
    const QStringList files = dir.entryList({QStringLiteral("*.awb")}, QDir::Files, QDir::Name);
    if (files.isEmpty()) {
        m_examplesMenu->addAction(tr("No examples installed"))->setEnabled(false);
        return;
    }
    // The gallery first (thumbnails, a filter); then one short submenu per paper and one for
    // the rest, so that no menu is taller than the screen (issue 47: 42 entries in one).
    m_examplesMenu->addAction(action(QStringLiteral("actionExampleGallery")));
    m_examplesMenu->addSeparator();
    const QMap<QString, QString> papers{
        {QStringLiteral("000"), tr("000 Schaefer, Levin, Goldman: Subdivision Schemes and Attractors")},
        {QStringLiteral("001"), tr("001 Li et al.: Normal Vector Based Subdivision")},
        {QStringLiteral("002"), tr("002 John: All Bézier Curves Are Attractors")},
        {QStringLiteral("003"), tr("003 BCIFS Junction Curves")},
        {QStringLiteral("004"), tr("004 Ptáčková: Fractals and Splines")},
        {QStringLiteral("mesh"), tr("Meshes")}};
    QMap<QString, QMenu *> menus;
    for (const QString &file : files) {
        const QString path = dir.filePath(file);
        const QString prefix = file.section(QLatin1Char('-'), 0, 0);
        const QString group = papers.contains(prefix) ? prefix : QString();
        QMenu *&menu = menus[group];
        if (!menu)
            menu = new QMenu(group.isEmpty() ? tr("Masks, Animations and Other Tools' Files")
                                             : papers.value(group),
                             m_examplesMenu);
        menu->setToolTipsVisible(true);  // each entry's file
        QAction *a = menu->addAction(ExampleGallery::exampleTitle(path));
        a->setToolTip(path);
        connect(a, &QAction::triggered, this, [this, path] {
            if (maybeSave())
                openExample(path);
        });
    }
    for (auto it = menus.begin(); it != menus.end(); ++it)
        if (!it.key().isEmpty())
            m_examplesMenu->addMenu(it.value());
    if (QMenu *rest = menus.value(QString()))
        m_examplesMenu->addMenu(rest);
}

void MainWindow::exampleGalleryDialog()
{
    ExampleGallery gallery(examplesDirectory(), this);
    if (gallery.exec() == QDialog::Accepted && !gallery.chosenFile().isEmpty() && maybeSave())
        openExample(gallery.chosenFile());
}

bool MainWindow::openExample(const QString &fileName)
{
    ProjectData data;
    QString error;
    if (!ProjectIO::readFile(fileName, &data, &error)) {
        m_messages->error(this, tr("Open Example"), error);
        return false;
    }
    // A copy without a file: saving asks where (installed examples are read-only).
    m_project->adopt(std::move(data), QString(), false);
    // A recording made on the copy replays on the example by default.
    if (m_recorder)
        m_recorder->setOrigin(QFileInfo(fileName).absoluteFilePath());
    updateTitle();
    selectFirstItem();
    statusBar()->showMessage(tr("Opened the example %1 (a copy: Save As keeps it)")
                                 .arg(QFileInfo(fileName).fileName()),
                             6000);
    return true;
}

} // namespace awb
