// MainWindow: the files of other tools (issue 34) -- File > Import (Fractint .ifs and flam3
// .flame, every entry or flame an item in one undo step, the entries left out shown with their
// line and column, a flame's dropped variations named; meshes go to importMesh) and File >
// Export Item As (a Fractint .ifs entry, a flam3 genome framed as the view shows the item,
// MATLAB cell arrays of the matrices). The model does the reading and writing
// (model/IfsExchange.h, FlameExchange.h, NamedMatrix.h).

#include "gui/app/MainWindow.h"

#include "gui/app/ItemController.h"
#include "gui/app/Messages.h"
#include "gui/views/AttractorView.h"
#include "gui/views/MatrixView.h"
#include "render/AttractorImage.h"
#include "model/AttractorItem.h"
#include "model/FileWriting.h"
#include "model/FlameExchange.h"
#include "model/IfsExchange.h"
#include "model/NamedMatrix.h"
#include "model/Project.h"

#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QMimeData>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QStatusBar>

namespace awb {

bool MainWindow::importIfs(const QString &fileName, QStringList *problems, QString *error,
                           QStringList *warnings, bool replace)
{
    ImportedItems imported;
    const QString suffix = QFileInfo(fileName).suffix().toLower();
    try {
        imported = suffix == QLatin1String("flame") || suffix == QLatin1String("flam3")
                       ? importFlame(fileName)
                       : importFractint(fileName);
    } catch (const std::exception &e) {
        if (error)
            *error = QString::fromUtf8(e.what());
        return false;
    }
    if (problems)
        *problems = imported.problems;
    if (warnings)
        *warnings = imported.warnings;
    if (imported.items.empty()) {
        if (error)
            *error = tr("%1: no entry could be imported").arg(QFileInfo(fileName).fileName());
        return false;
    }
    if (replace)
        m_project->clear();
    m_project->beginCompound(tr("Import %1").arg(QFileInfo(fileName).fileName()));
    Item *first = nullptr;
    for (auto &item : imported.items) {
        const QString base = item->name();
        QString name = base;
        for (int k = 2; m_project->findItem(name); ++k)
            name = QStringLiteral("%1 (%2)").arg(base).arg(k);
        item->setName(name);
        Item *added = m_project->addItem(std::move(item), nullptr);
        if (!first)
            first = added;
    }
    m_project->endCompound();
    setCurrentItem(first);
    return true;
}

void MainWindow::importDialog()
{
    const QString file = QFileDialog::getOpenFileName(
        this, tr("Import"), QString(),
        tr("Everything Attractor Workbench imports (*.ifs *.flame *.flam3 *.obj *.off *.ply);;"
           "Fractint IFS (*.ifs);;Fractal flames: flam3, Apophysis, JWildfire (*.flame "
           "*.flam3);;Meshes (*.obj *.off *.ply)"));
    if (file.isEmpty())
        return;
    const QString suffix = QFileInfo(file).suffix().toLower();
    if (suffix != QLatin1String("ifs") && suffix != QLatin1String("flame")
        && suffix != QLatin1String("flam3")) {
        importMeshFile(file);
        return;
    }
    importReporting(file, false);
}

bool MainWindow::importReporting(const QString &file, bool replace)
{
    QStringList problems, warnings;
    QString error;
    const bool ok = importIfs(file, &problems, &error, &warnings, replace);
    if (!ok) {
        m_messages->error(this, tr("Import"),
                          problems.isEmpty() ? error
                                             : error + QStringLiteral("\n\n")
                                                   + problems.join(QLatin1Char('\n')));
        return false;
    }
    QString text;
    if (!problems.isEmpty())
        text += tr("Imported the others; these were left out:") + QStringLiteral("\n\n")
                + problems.join(QLatin1Char('\n'));
    if (!warnings.isEmpty())
        text += (text.isEmpty() ? QString() : QStringLiteral("\n\n"))
                + tr("Imported with these losses:") + QStringLiteral("\n\n")
                + warnings.join(QLatin1Char('\n'));
    if (!text.isEmpty()) {
        // After the window has shown the new items (its panels rebuild on the way back to the
        // event loop, not inside the message's own).
        QMetaObject::invokeMethod(
            this, [this, text] { m_messages->information(this, tr("Import"), text); },
            Qt::QueuedConnection);
    } else {
        statusBar()->showMessage(tr("Imported %1").arg(QDir::toNativeSeparators(file)), 5000);
    }
    return ok;
}

bool MainWindow::exportItemAs(const QString &fileName, QString *error)
{
    const auto *item = qobject_cast<const AttractorItem *>(m_controller->drawnItem());
    QString why;
    QByteArray bytes;
    const QString suffix = QFileInfo(fileName).suffix().toLower();
    if (!item) {
        why = tr("Export Item As writes an item with maps: choose one first");
    } else if (suffix == QLatin1String("ifs")) {
        if (const auto entry = fractintEntryOf(*item, &why)) {
            try {
                bytes = QByteArray::fromStdString(fractintEntryText(*entry));
            } catch (const std::exception &e) {
                why = QString::fromUtf8(e.what());
            }
        }
    } else if (suffix == QLatin1String("flame") || suffix == QLatin1String("flam3")) {
        // Framed as the attractor view shows it, at the view's size in pixels; each map in
        // the colour the view gives it.
        const QSize size = m_attractor->size().expandedTo(QSize(64, 64));
        QStringList colours;
        const QStringList own = item->style().colors;
        for (int i = 0; i < std::max(1, item->mapCount()); ++i)
            colours << (i < own.size() ? own[i] : attractorMapColor(i).name());
        if (const auto flame =
                flameOf(*item, colours, {m_attractor->visibleWorldRect(), size}, &why))
            bytes = *flame;
    } else if (suffix == QLatin1String("m")) {
        const QList<NamedMatrix> list = m_matrices->matrices();
        if (list.isEmpty())
            why = tr("%1 has no matrices to export").arg(item->name());
        else
            bytes = matlabMatrices(list, item->name()).toUtf8();
    } else {
        why = tr("%1: Export Item As writes .ifs (Fractint), .flame (flam3) or .m (MATLAB) "
                 "files")
                  .arg(QFileInfo(fileName).fileName());
    }
    if (why.isEmpty()) {
        QString reason;
        if (!writeWholeFile(fileName, bytes, &reason))
            why = tr("cannot write %1: %2").arg(fileName, reason);
    }
    if (!why.isEmpty() && error)
        *error = why;
    return why.isEmpty();
}

void MainWindow::exportItemAsDialog()
{
    const QString file = QFileDialog::getSaveFileName(
        this, tr("Export Item As"), outputPath(QStringLiteral("ifs")),
        tr("Fractint IFS (*.ifs);;Fractal flame for flam3-render, Apophysis, JWildfire "
           "(*.flame);;MATLAB cell arrays of the matrices (*.m)"));
    if (file.isEmpty())
        return;
    QString error;
    if (!exportItemAs(file, &error))
        m_messages->error(this, tr("Export Item As"), error);
    else
        statusBar()->showMessage(tr("Wrote %1").arg(QDir::toNativeSeparators(file)), 5000);
}

namespace {

enum class DropKind { None, Project, Ifs, Mesh };

DropKind dropKind(const QString &file)
{
    const QString suffix = QFileInfo(file).suffix().toLower();
    if (suffix == QLatin1String("awb") || suffix == QLatin1String("png")
        || suffix == QLatin1String("svg"))
        return DropKind::Project;
    if (suffix == QLatin1String("ifs") || suffix == QLatin1String("flame")
        || suffix == QLatin1String("flam3"))
        return DropKind::Ifs;
    if (suffix == QLatin1String("obj") || suffix == QLatin1String("off")
        || suffix == QLatin1String("ply"))
        return DropKind::Mesh;
    return DropKind::None;
}

QStringList droppedFiles(const QMimeData *mime)
{
    QStringList files;
    if (!mime)
        return files;
    for (const QUrl &url : mime->urls())
        if (url.isLocalFile() && dropKind(url.toLocalFile()) != DropKind::None)
            files << url.toLocalFile();
    return files;
}

} // namespace

void MainWindow::dragEnterEvent(QDragEnterEvent *event)
{
    if (!droppedFiles(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent *event)
{
    const QStringList files = droppedFiles(event->mimeData());
    if (files.isEmpty())
        return;
    event->acceptProposedAction();
    // One project at a time (the first dropped); the other files are imported into it.
    bool opened = false;
    for (const QString &file : files) {
        switch (dropKind(file)) {
        case DropKind::Project:
            if (!opened && maybeSave())
                opened = openFile(file);
            break;
        case DropKind::Ifs:
            importReporting(file, false);
            break;
        case DropKind::Mesh:
            importMeshFile(file);
            break;
        case DropKind::None:
            break;
        }
    }
}

} // namespace awb
