#pragma once
// MainWindow: the application window over one Project. The attractor view is central; the
// project tree, properties, matrices, spectrum, analysis charts and undo history are docks
// showing the same current item (bound by ItemController). It owns the file actions (new, open,
// recent, save, revert, close) with unsaved-changes prompts, printing and export, the window
// title, settings and crash recovery. Every message to the user goes through Messages so that
// tests can drive the window without modal boxes.
#include "gui/app/Dialogs.h"
#include "core/mesh/Mesh.h"
#include "model/Item.h"
#include "render/FigureFile.h"
#include <QMainWindow>
#include <QPointer>
#include <memory>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QPrinter;
class QProgressBar;
class QProgressDialog;
class QTimer;
class QSpinBox;
class QStackedWidget;
class QToolButton;
class QTreeView;
class QUndoView;

namespace awb {

class AddressPanel;
class AnimationPanel;
class AutomatonPanel;
class AnalysisCharts;
class AttractorView;
class Item;
class FigureSheet;
class FrameBudget;
class StatusText;
class ItemController;
class MatrixView;
class Messages;
class Project;
class ProjectTreeModel;
class PythonConsole;
class ScriptRecorder;
class PropertiesWidget;
class Recovery;
class SpectrumView;
class SubdivisionMeshItem;
class SurfaceView;
class ValenceChart;
class VertexPanel;
struct SurfaceSchemeSpec;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // `messages` (not owned; nullptr: modal message boxes). `recoveryDirectory` empty: the
    // per-user default.
    explicit MainWindow(Messages *messages = nullptr, const QString &recoveryDirectory = {},
                        QWidget *parent = nullptr);
    ~MainWindow() override;

    Project *project() const { return m_project.get(); }
    Item *currentItem() const;
    void setCurrentItem(Item *item);

    // MainWindowSharpFeatures.cpp (issue 44): the sharpness of the net edge or the control
    // point selected in the 3D view of the current mesh item (Item > Crease Edge…, Item >
    // Sharpen Vertex…): one undo step; false with *error saying why (no mesh item, nothing
    // selected, a refused value).
    bool setSelectedEdgeSharpness(double sharpness, QString *error = nullptr);
    bool setSelectedVertexSharpness(double sharpness, QString *error = nullptr);
    // Item > Toggle Hole: the net face selected in the 3D view made a hole, or filled again.
    bool toggleSelectedHole(QString *error = nullptr);

    // A new project with one cubic B-spline item: the window is never empty.
    void newProject();
    // Opens without asking about unsaved changes (the caller did); reports failures.
    bool openFile(const QString &fileName);
    // File > Import Mesh…: a mesh file (OBJ, OFF, PLY) as a new mesh item, one undo step;
    // false, with the reader's or the mesh's message in *error, when it is refused (nothing
    // added).
    bool importMesh(const QString &fileName, MeshScheme scheme, QString *error = nullptr);
    // File > Import Mesh after the file dialog: asks for the scheme, imports the mesh file, and
    // when the mesh is refused offers the well-defined repairs (MeshRepair.h).
    void importMeshFile(const QString &file);
    bool importMesh(const QString &fileName, const Mesh &mesh, MeshScheme scheme,
                    QString *error = nullptr);
    // File > Import…: another tool's IFS file (Fractint .ifs, flam3 .flame/.flam3: every entry
    // or flame an item, all in one undo step) or a mesh (importMesh). False with *error when
    // nothing could be imported; entries left out are listed in *problems, what was imported
    // with a loss (a flame's non-linear variation) in *warnings (the window shows both).
    // With `replace`, the items replace the project's (File > Open of such a file: an
    // untitled project of its entries); a file that gives no item changes nothing.
    bool importIfs(const QString &fileName, QStringList *problems = nullptr,
                   QString *error = nullptr, QStringList *warnings = nullptr,
                   bool replace = false);
    // File > Export Item As…: the current item as a Fractint .ifs entry (.ifs), a flam3 genome
    // framed as the attractor view shows it (.flame, .flam3) or its matrices as MATLAB cell
    // arrays (.m), by suffix. False with the reason in *error.
    bool exportItemAs(const QString &fileName, QString *error = nullptr);
    // File > Export Mesh…: the current mesh item after `rounds` steps, every vertex at its
    // exact limit position, as OBJ. False with the reason in *error.
    bool exportMesh(const QString &fileName, int rounds, QString *error = nullptr);
    bool saveFile(const QString &fileName);
    // Offers the recovery files of crashed sessions; true when one was recovered.
    bool offerRecovery();
    // Opens a bundled example (a copy: saving asks where, the examples stay as they are).
    bool openExample(const QString &fileName);
    // Where the bundled examples are (the installed data folder, else the source tree's).
    static QString examplesDirectory();
    // The file an output of the current item is proposed as: "<project>-<item>.<suffix>" in
    // the project's folder when it can be written to, else in the user's documents.
    QString outputPath(const QString &suffix) const;

    // Export of one view (format from the suffix). False with a message on failure.
    bool exportView(const ExportDialog::Options &options, QString *error = nullptr);
    // The current item's matrices as LaTeX (Edit > Copy Matrices as LaTeX, .tex export).
    QString matricesLatex() const;
    // What exported PNG and SVG files carry: the current item's project (it reopens).
    FigureMetadata figureMetadata() const;
    // The figure sheet of the current item as a PDF page.
    bool printToPdf(const QString &fileName, QString *error = nullptr);
    // The points F^depth(X0) of the item drawn (the current item, or an eigenvalue plot's
    // source) as .csv or .ply (File > Export Points); depth < 0: the item's own depth.
    bool exportPoints(const QString &fileName, int depth = -1, QString *error = nullptr);

    // The views (for tests and export).
    AttractorView *attractorView() const { return m_attractor; }
    // The 3D view of surface items (the central widget while such an item is current).
    SurfaceView *surfaceView() const { return m_surface; }
    MatrixView *matrixView() const { return m_matrices; }
    SpectrumView *spectrumView() const { return m_spectrum; }
    AnalysisCharts *analysisCharts() const { return m_charts; }
    // The Analysis dock's Vertex and Valences tabs (a mesh's extraordinary vertices).
    VertexPanel *vertexPanel() const { return m_vertexPanel; }
    ValenceChart *valenceChart() const { return m_valenceChart; }
    AddressPanel *addressPanel() const { return m_address; }
    AnimationPanel *animationPanel() const { return m_animation; }
    AutomatonPanel *automatonPanel() const { return m_automaton; }
    PropertiesWidget *propertiesWidget() const { return m_properties; }
    ItemController *controller() const { return m_controller; }
    QTreeView *projectTree() const { return m_tree; }
    QAction *action(const QString &objectName) const;
    // MainWindowPython.cpp: the Python console dock (View > Python Console) and the recording
    // of every edit as Python (Tools > Save Recording).
    PythonConsole *pythonConsole() const { return m_console; }
    ScriptRecorder *recorder() const { return m_recorder; }
    // Writes the recording as a script that replays it on the file it started from.
    bool saveRecording(const QString &fileName, QString *error);

    void applyPreferences(const Preferences &preferences);

protected:
    void closeEvent(QCloseEvent *event) override;
    // Files dropped on the window (MainWindowExchange.cpp): a project or a figure with its
    // project opens (after asking to save), another tool's IFS file or a mesh is imported.
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    void createViews();
    // MainWindowActions.cpp (with addLanguageMenu): every action, and the menus and tool bar.
    void createActions();
    void createMenus();
    void createDocks();
    void createPythonConsole();
    void saveRecordingDialog();
    void updateTitle();
    void updateActions();
    void updateRecentMenu();
    void fillExamplesMenu();
    void exampleGalleryDialog();
    void addRecentFile(const QString &fileName);
    // Asks to save unsaved changes; false when the user cancels.
    bool maybeSave();
    void openDialog();
    bool save();
    bool saveAs();
    void revert();
    void closeProject();
    void print();
    void endExportProgress();
    void printPreview();
    void exportDialog();
    void exportPointsDialog();
    void userGuide();
    // The status bar's note on the current item (elided; whole in its tooltip and in the
    // Analysis panel).
    void showProblem(const QString &problem);
    // The plane or the 3D view, for the item drawn.
    void updateCentralView();
    // Narrows the docks when they leave the central view less than half of the window.
    void shareWidthWithDocks();
    void keepDockTabsWhole();
    void preferencesDialog();
    // Edit > Language: System Default, English and the translations, saved in the settings and
    // applied at the next start.
    void addLanguageMenu(QMenu *edit);
    void about();
    void addItem(const QString &type);
    // Add > Subdivision surface: one entry per scheme and layout.
    void addSurfaceMenu(QMenu *add, const QString &title);
    // MainWindowItems.cpp (with addItem, addSurface*, duplicateItem, deleteItem): Item > Add >
    // Mesh surface (the starting meshes), File > Import Mesh.
    void addMeshMenu(QMenu *add, const QString &title);
    void importMeshDialog();
    // importIfs with what was left out or lost shown in a message; false when nothing came.
    bool importReporting(const QString &file, bool replace);
    void importDialog();
    void exportItemAsDialog();
    void exportMeshDialog();
    void creaseEdgeDialog();
    void sharpenVertexDialog();
    void toggleHoleAction();
    // The current item as a mesh item, or null with *error saying so.
    SubdivisionMeshItem *currentMesh(QString *error) const;
    // MainWindowExport.cpp: the printed sheet of the current item (with a mesh's focused
    // vertex: its matrix and characteristic map).
    FigureSheet figureSheet() const;
    void addSurface(const SurfaceSchemeSpec &scheme);
    void duplicateItem();
    void deleteItem();
    void resetLayout();
    void selectFirstItem();

    Messages *m_messages;
    std::unique_ptr<Messages> m_ownMessages;
    std::unique_ptr<Project> m_project;
    ProjectTreeModel *m_treeModel = nullptr;
    std::unique_ptr<Recovery> m_recovery;
    QString m_recoveryDirectory;
    Preferences m_preferences;

    AttractorView *m_attractor = nullptr;
    SurfaceView *m_surface = nullptr;
    QStackedWidget *m_central = nullptr;
    MatrixView *m_matrices = nullptr;
    SpectrumView *m_spectrum = nullptr;
    AnalysisCharts *m_charts = nullptr;
    VertexPanel *m_vertexPanel = nullptr;
    ValenceChart *m_valenceChart = nullptr;
    AddressPanel *m_address = nullptr;
    AnimationPanel *m_animation = nullptr;
    AutomatonPanel *m_automaton = nullptr;
    PropertiesWidget *m_properties = nullptr;
    QTreeView *m_tree = nullptr;
    QUndoView *m_undoView = nullptr;
    ScriptRecorder *m_recorder = nullptr;
    PythonConsole *m_console = nullptr;
    FrameBudget *m_budget = nullptr;
    ItemController *m_controller = nullptr;
    QPointer<Item> m_current;

    QList<QDockWidget *> m_docks;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_recentMenu = nullptr;
    QMenu *m_examplesMenu = nullptr;
    QByteArray m_defaultState;
    QSpinBox *m_hutchStep = nullptr;
    QSpinBox *m_subdivSteps = nullptr;
    StatusText *m_cursorLabel = nullptr;
    SpectrumView *m_plotView = nullptr;  // the centre for an eigenvalue plot item
    QLabel *m_problemLabel = nullptr;
    QProgressBar *m_progress = nullptr;
    QToolButton *m_cancel = nullptr;
    // The attractor render's progress and cancel button, shown only for renders that take a
    // while (a drag's quick renders would make them flicker).
    QProgressBar *m_renderProgress = nullptr;
    QToolButton *m_renderCancel = nullptr;
    QTimer *m_renderShowTimer = nullptr;
    // Progress of an export's own attractor raster (created on demand, deleted after).
    QPointer<QProgressDialog> m_exportProgress;
    QString m_lastExport;
    QString m_lastPointExport;
    QString m_problem;
};

} // namespace awb
