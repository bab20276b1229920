#include "gui/app/PointExportDialog.h"

#include "model/FileWriting.h"

#include "model/AttractorItem.h"
#include "model/PointExport.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressDialog>
#include <QPushButton>
#include <QSpinBox>
#include <QThread>

#include <atomic>
#include <cmath>
#include <thread>

namespace awb {

namespace {

bool isPly(const QString &fileName)
{
    return QFileInfo(fileName).suffix().compare(QLatin1String("ply"), Qt::CaseInsensitive) == 0;
}

} // namespace

PointExportDialog::PointExportDialog(const AttractorItem *item, const QString &fileName,
                                     QWidget *parent)
    : QDialog(parent), m_item(item)
{
    setObjectName(QStringLiteral("pointExportDialog"));
    setWindowTitle(tr("Export Points of %1").arg(item->name()));
    auto *form = new QFormLayout(this);
    auto *fileRow = new QHBoxLayout;
    m_file = new QLineEdit(fileName);
    m_file->setMinimumWidth(280);
    auto *browse = new QPushButton(tr("&Browse…"));
    fileRow->addWidget(m_file, 1);
    fileRow->addWidget(browse);
    form->addRow(tr("File:"), fileRow);
    m_format = new QComboBox;
    m_format->addItems({tr("CSV text: x, y[, z], map, view"),
                        tr("PLY point cloud: x, y, z, map colour, map")});
    form->addRow(tr("F&ormat:"), m_format);
    m_depth = new QSpinBox;
    m_depth->setRange(0, 64);
    m_depth->setValue(item->algorithm().depth);
    m_depth->setToolTip(tr("The points of F^k(X0): every image of the start set's vertices "
                           "after k steps of the Hutchinson operator"));
    form->addRow(tr("&Depth k:"), m_depth);
    m_count = new QLabel;
    form->addRow(m_count);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Export"));
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString name = QFileDialog::getSaveFileName(
            this, tr("Export Points"), m_file->text(),
            tr("CSV text (*.csv);;PLY point cloud (*.ply)"),
            nullptr);
        if (!name.isEmpty())
            setFileName(name);
    });
    // The format follows the suffix and the suffix the format.
    connect(m_format, &QComboBox::currentIndexChanged, this, [this](int i) {
        const QFileInfo f(m_file->text());
        const QString suffix = i == 1 ? QStringLiteral("ply") : QStringLiteral("csv");
        if (f.suffix().compare(suffix, Qt::CaseInsensitive) != 0)
            m_file->setText(f.path() + QLatin1Char('/') + f.completeBaseName()
                            + QLatin1Char('.') + suffix);
    });
    connect(m_file, &QLineEdit::textChanged, this, [this](const QString &name) {
        const QSignalBlocker block(m_format);
        m_format->setCurrentIndex(isPly(name) ? 1 : 0);
    });
    connect(m_depth, &QSpinBox::valueChanged, this, &PointExportDialog::updateCount);
    m_format->setCurrentIndex(isPly(fileName) ? 1 : 0);
    updateCount();
}

QString PointExportDialog::fileName() const { return m_file->text(); }
void PointExportDialog::setFileName(const QString &fileName) { m_file->setText(fileName); }
int PointExportDialog::depth() const { return m_depth->value(); }
void PointExportDialog::setDepth(int depth) { m_depth->setValue(depth); }

double PointExportDialog::pointCount() const
{
    const auto d = m_item->derivedIfs();
    if (!d)
        return 0;
    try {
        return exportPointCount(*d, m_item->coreStartSet(*d), depth());
    } catch (const std::exception &) {
        return 0;
    }
}

void PointExportDialog::updateCount()
{
    const double n = pointCount();
    QString text = n < 0 ? tr("The number of points depends on the automaton.")
                         : tr("%1 points").arg(n < 1e15 ? QLocale().toString(qint64(n))
                                                         : QLocale().toString(n, 'g', 4));
    if (n > maxPoints)
        text += tr(" — too many (at most %1): choose a smaller depth.")
                    .arg(QLocale().toString(maxPoints, 'g', 3));
    m_count->setText(text);
}

bool PointExportDialog::exportPoints(const AttractorItem *item, const QString &fileName,
                                     int depth, const std::function<QColor(int)> &color,
                                     QWidget *parent, QString *error)
{
    const auto fail = [error](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    const auto d = item->derivedIfs();
    if (!d)
        return fail(tr("%1 cannot be computed: %2").arg(item->name(), item->derivedError()));
    StartSet start;
    try {
        start = item->coreStartSet(*d);
    } catch (const std::exception &e) {
        return fail(tr("Start set: %1").arg(QString::fromUtf8(e.what())));
    }
    const double n = exportPointCount(*d, start, depth);
    if (n > maxPoints)
        return fail(tr("Depth %1 gives %2 points, more than %3: choose a smaller depth.")
                        .arg(depth)
                        .arg(QLocale().toString(n, 'g', 4), QLocale().toString(maxPoints, 'g', 3)));
    // Written whole or not at all: a cancelled export leaves an existing file as it was.
    WholeFileWriter writer;
    QString reason;
    if (!writer.open(fileName, &reason))
        return fail(tr("Cannot write %1: %2").arg(fileName, reason));
    QIODevice &file = *writer.device();

    // The iteration writes on a worker thread; this thread shows the progress.
    std::atomic<bool> cancel{false}, done{false};
    std::atomic<double> fraction{0.0};
    QString failure;
    IterationControl control;
    control.cancel = &cancel;
    control.progress = [&fraction](double f) { fraction = f; };
    const bool ply = isPly(fileName);
    std::thread worker([&] {
        try {
            if (ply)
                writePointsPly(file, item->name(), *d, start, depth, color, control);
            else
                writePointsCsv(file, *d, start, depth, control);
        } catch (const std::exception &e) {
            failure = QString::fromUtf8(e.what());
        }
        done = true;
    });
    QProgressDialog *progress = nullptr;
    QElapsedTimer clock;
    clock.start();
    while (!done) {
        QThread::msleep(20);
        if (parent && !progress && clock.elapsed() > 400) {
            progress = new QProgressDialog(tr("Writing the points of %1…").arg(item->name()),
                                           tr("Cancel"), 0, 100, parent);
            progress->setObjectName(QStringLiteral("pointExportProgress"));
            progress->setWindowModality(Qt::ApplicationModal);
            progress->setMinimumDuration(0);
            progress->setAutoClose(false);
            progress->setAutoReset(false);
        }
        if (progress) {
            progress->setValue(std::clamp(int(std::lround(100 * fraction.load())), 0, 99));
            QCoreApplication::processEvents();
            if (progress->wasCanceled())
                cancel = true;
        }
    }
    worker.join();
    delete progress;
    if (cancel)
        return fail(tr("Exporting the points was cancelled; nothing was written."));
    if (!failure.isEmpty())
        return fail(failure);
    if (!writer.commit(&reason))
        return fail(tr("Cannot write %1: %2").arg(fileName, reason));
    return true;
}

} // namespace awb
