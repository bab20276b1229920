// MainWindow: the files of other tools (issue 34) -- File > Import (Fractint .ifs, every entry
// an item in one undo step, the entries left out shown with their line and column; meshes go
// to importMesh) and File > Export Item As (a Fractint .ifs entry, MATLAB cell arrays of the
// matrices). The model does the reading and writing (model/IfsExchange.h, NamedMatrix.h).

#include "gui/app/MainWindow.h"

#include "gui/app/ItemController.h"
#include "gui/app/Messages.h"
#include "gui/views/MatrixView.h"
#include "model/AttractorItem.h"
#include "model/FileWriting.h"
#include "model/IfsExchange.h"
#include "model/NamedMatrix.h"
#include "model/Project.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QStatusBar>

namespace awb {

bool MainWindow::importIfs(const QString &fileName, QStringList *problems, QString *error)
{
    ImportedItems imported;
    try {
        imported = importFractint(fileName);
    } catch (const std::exception &e) {
        if (error)
            *error = QString::fromUtf8(e.what());
        return false;
    }
    if (problems)
        *problems = imported.problems;
    if (imported.items.empty()) {
        if (error)
            *error = tr("%1: no entry could be imported").arg(QFileInfo(fileName).fileName());
        return false;
    }
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
        tr("Everything Attractor Workbench imports (*.ifs *.obj *.off *.ply);;Fractint IFS "
           "(*.ifs);;Meshes (*.obj *.off *.ply)"));
    if (file.isEmpty())
        return;
    if (QFileInfo(file).suffix().toLower() != QLatin1String("ifs")) {
        importMeshFile(file);
        return;
    }
    QStringList problems;
    QString error;
    const bool ok = importIfs(file, &problems, &error);
    if (!ok && problems.isEmpty()) {
        m_messages->error(this, tr("Import"), error);
        return;
    }
    if (!problems.isEmpty())
        m_messages->information(this, tr("Import"),
                                (ok ? tr("Imported the other entries; these were left out:")
                                    : error + QLatin1Char('\n'))
                                    + QStringLiteral("\n\n") + problems.join(QLatin1Char('\n')));
    else
        statusBar()->showMessage(tr("Imported %1").arg(QDir::toNativeSeparators(file)), 5000);
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
    } else if (suffix == QLatin1String("m")) {
        const QList<NamedMatrix> list = m_matrices->matrices();
        if (list.isEmpty())
            why = tr("%1 has no matrices to export").arg(item->name());
        else
            bytes = matlabMatrices(list, item->name()).toUtf8();
    } else {
        why = tr("%1: Export Item As writes .ifs (Fractint) or .m (MATLAB) files")
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
        tr("Fractint IFS (*.ifs);;MATLAB cell arrays of the matrices (*.m)"));
    if (file.isEmpty())
        return;
    QString error;
    if (!exportItemAs(file, &error))
        m_messages->error(this, tr("Export Item As"), error);
    else
        statusBar()->showMessage(tr("Wrote %1").arg(QDir::toNativeSeparators(file)), 5000);
}

} // namespace awb
