#include "gui/app/RegularityAtlasWindow.h"

#include "gui/app/Dialogs.h"
#include "gui/views/AtlasPlot.h"
#include "gui/views/ThemeColours.h"
#include "model/Project.h"
#include "model/ProjectIO.h"
#include "model/SchemeFamily.h"
#include "model/SubdivisionCurveItem.h"

#include <QCheckBox>
#include <QCloseEvent>
#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QProcessEnvironment>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QThread>
#include <QVBoxLayout>

#include <cmath>
#include <functional>

namespace awb {

namespace {

QDoubleSpinBox *valueSpin(QWidget *parent)
{
    auto *s = new QDoubleSpinBox(parent);
    s->setDecimals(6);
    s->setRange(-1e6, 1e6);
    s->setSingleStep(0.01);
    return s;
}

AtlasBoundary boundaryFromJson(const QJsonObject &o)
{
    return {o.value("inner").toDouble(), o.value("outer").toDouble(),
            o.value("range_end").toBool(),
            !o.value("range_end").toBool() && !o.value("certified_not").toBool()};
}

// Rows of the module's JSON (a progress event's "new", the result's "rows"), each with its cell
// in a 2D atlas (none in 1D); a row that does not read is left out.
void appendRows(const QJsonArray &json, const std::vector<AtlasAxis> &axes,
                std::vector<AtlasRow> &rows, std::vector<std::vector<double>> &cells,
                const std::function<std::vector<double>(const QJsonObject &)> &cellOf)
{
    for (const QJsonValue &v : json) {
        try {
            rows.push_back(atlasRowFromJson(v.toObject(), axes));
        } catch (const std::exception &) {
            continue;
        }
        cells.push_back(axes.size() == 2 ? cellOf(v.toObject()) : std::vector<double>{});
    }
}

// "w = -0.125, v = 0.005"
QString paramsText(const QStringList &names, const std::vector<double> &params)
{
    QStringList where;
    for (int a = 0; a < names.size() && size_t(a) < params.size(); ++a)
        where << QStringLiteral("%1 = %2").arg(names[a],
                                               QString::number(params[size_t(a)], 'g', 10));
    return where.join(QStringLiteral(", "));
}

QStringList axisNames(const std::vector<AtlasAxis> &axes)
{
    QStringList names;
    for (const AtlasAxis &a : axes)
        names << QString::fromStdString(a.name);
    return names;
}

} // namespace

RegularityAtlasWindow::RegularityAtlasWindow(Project *project, QWidget *parent)
    : QWidget(parent), m_project(project)
{
    setObjectName(QStringLiteral("regularityAtlasWindow"));
    setWindowTitle(tr("Regularity Atlas"));
    auto *layout = new QVBoxLayout(this);
    auto *form = new QFormLayout;
    m_itemLabel = new QLabel(this);
    m_itemLabel->setWordWrap(true);
    form->addRow(tr("Item:"), m_itemLabel);
    m_mask = new QLineEdit(this);
    m_mask->setObjectName(QStringLiteral("atlasMask"));
    m_mask->setToolTip(tr("The mask with the parameters written into it, e.g. \"v, 0, w, 0, "
                          "1/2 - w - v, 1, 1/2 - w - v, 0, w, 0, v\" (the six-point family)."));
    form->addRow(tr("&Mask:"), m_mask);
    for (int a = 0; a < 2; ++a) {
        AxisFields &f = m_fields[a];
        auto *row = new QHBoxLayout;
        f.name = new QLineEdit(this);
        f.name->setMaximumWidth(90);
        f.from = valueSpin(this);
        f.to = valueSpin(this);
        f.count = new QSpinBox(this);
        f.count->setRange(2, a == 0 ? 100000 : 2000);
        f.count->setValue(11);
        f.name->setToolTip(tr("The parameter's name: omega, a, b, or a name in the mask."));
        f.count->setToolTip(tr("Grid values, both ends included."));
        row->addWidget(f.name);
        row->addWidget(new QLabel(tr("from"), this));
        row->addWidget(f.from, 1);
        row->addWidget(new QLabel(tr("to"), this));
        row->addWidget(f.to, 1);
        row->addWidget(new QLabel(tr("values"), this));
        row->addWidget(f.count);
        if (a == 1) {
            m_second = new QCheckBox(tr("&Second parameter:"), this);
            form->addRow(m_second, row);
            connect(m_second, &QCheckBox::toggled, this, &RegularityAtlasWindow::updateForm);
        } else {
            auto *label = new QLabel(tr("&Parameter:"), this);
            label->setBuddy(f.name);
            form->addRow(label, row);
        }
    }
    auto *options = new QHBoxLayout;
    m_smoothness = new QSpinBox(this);
    m_smoothness->setRange(0, 10);
    m_smoothness->setValue(1);
    m_smoothness->setPrefix(QStringLiteral("C^"));
    m_smoothness->setToolTip(tr("The class the atlas refines around: its C^k boundaries."));
    m_tolerance = new QLineEdit(QStringLiteral("1e-6"), this);
    m_tolerance->setMaximumWidth(90);
    m_tolerance->setToolTip(tr("One parameter: each boundary's bracket narrows to this width."));
    m_refine = new QSpinBox(this);
    m_refine->setRange(0, 10);
    m_refine->setValue(3);
    m_refine->setToolTip(tr("Two parameters: how many times a cell whose corners disagree is "
                            "split."));
    options->addWidget(new QLabel(tr("Class:"), this));
    options->addWidget(m_smoothness);
    options->addWidget(new QLabel(tr("Tolerance:"), this));
    options->addWidget(m_tolerance);
    options->addWidget(new QLabel(tr("Refinement levels:"), this));
    options->addWidget(m_refine);
    options->addStretch(1);
    form->addRow(tr("Atlas:"), options);
    m_where = new QComboBox(this);
    m_where->setObjectName(QStringLiteral("atlasWhere"));
    const Preferences prefs = Preferences::load();
    const int cores = prefs.atlasWorkers > 0 ? prefs.atlasWorkers
                                             : std::max(1, QThread::idealThreadCount());
    m_where->addItem(tr("A local Dask cluster (%n worker(s))", nullptr, cores));
    m_where->addItem(prefs.daskScheduler.isEmpty()
                         ? tr("The Dask scheduler named in Preferences (none set)")
                         : tr("The Dask scheduler at %1").arg(prefs.daskScheduler));
    m_where->addItem(tr("This machine, one process (no Dask)"));
    m_where->setCurrentIndex(prefs.daskScheduler.isEmpty() ? 0 : 1);
    form->addRow(tr("&Run on:"), m_where);
    layout->addLayout(form);

    auto *buttons = new QHBoxLayout;
    m_startButton = new QPushButton(tr("&Compute"), this);
    m_startButton->setObjectName(QStringLiteral("atlasStart"));
    m_cancelButton = new QPushButton(tr("Cancel"), this);
    m_cancelButton->setEnabled(false);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    buttons->addWidget(m_startButton);
    buttons->addWidget(m_cancelButton);
    buttons->addWidget(m_progress, 1);
    layout->addLayout(buttons);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("atlasStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_status);
    m_plot = new AtlasPlot(this);
    layout->addWidget(m_plot, 1);
    connect(m_startButton, &QPushButton::clicked, this, &RegularityAtlasWindow::start);
    connect(m_cancelButton, &QPushButton::clicked, this, &RegularityAtlasWindow::cancel);
    connect(m_plot, &AtlasPlot::rowClicked, this, &RegularityAtlasWindow::offerItemAt);
    resize(760, 720);
    updateForm();
}

RegularityAtlasWindow::~RegularityAtlasWindow()
{
    if (m_process) {
        m_process->disconnect(this);
        m_process->terminate();
        if (!m_process->waitForFinished(5000))
            m_process->kill();
        m_process->waitForFinished(2000);
    }
}

void RegularityAtlasWindow::setItem(SubdivisionCurveItem *item)
{
    m_item = item;
    if (!item) {
        m_itemLabel->setText(tr("(none: select a subdivision curve)"));
        updateForm();
        return;
    }
    m_itemLabel->setText(item->name());
    const SchemeSpec s = item->scheme();
    showStatus(s.kind == SchemeSpec::Kind::Mask
                   ? tr("Write the parameters' names into the mask (\"v, 0, w, 0, 1/2 - w - v, "
                        "1, …\"), give their ranges, and Compute.")
                   : tr("Give the parameters' ranges and Compute: each point is a certified "
                        "joint spectral radius, computed by python3 -m "
                        "attractor_workbench.atlas."));
    m_mask->setText(s.kind == SchemeSpec::Kind::Mask ? s.maskLine() : QString());
    m_second->setChecked(false);
    switch (s.kind) {
    case SchemeSpec::Kind::FourPoint:
        setAxes({{"omega", 0.0, 0.25, 26}});
        break;
    case SchemeSpec::Kind::CornerCutting:
        setAxes({{"a", 0.0, 0.5, 11}, {"b", 0.5, 1.0, 11}});
        break;
    default:
        setAxes({{"w", -0.1, 0.1, 21}});
        break;
    }
    updateForm();
}

SubdivisionCurveItem *RegularityAtlasWindow::item() const
{
    return m_item;
}

void RegularityAtlasWindow::setAxes(const std::vector<AtlasAxis> &axes)
{
    for (size_t a = 0; a < 2 && a < axes.size(); ++a) {
        m_fields[a].name->setText(QString::fromStdString(axes[a].name));
        m_fields[a].from->setValue(axes[a].from);
        m_fields[a].to->setValue(axes[a].to);
        m_fields[a].count->setValue(axes[a].count);
    }
    m_second->setChecked(axes.size() > 1);
    updateForm();
}

std::vector<AtlasAxis> RegularityAtlasWindow::axes() const
{
    std::vector<AtlasAxis> out;
    for (int a = 0; a < (m_second->isChecked() ? 2 : 1); ++a)
        out.push_back({m_fields[a].name->text().trimmed().toStdString(),
                       m_fields[a].from->value(), m_fields[a].to->value(),
                       m_fields[a].count->value()});
    return out;
}

void RegularityAtlasWindow::setMask(const QString &mask)
{
    m_mask->setText(mask);
}

void RegularityAtlasWindow::setSmoothness(int k)
{
    m_smoothness->setValue(k);
}

void RegularityAtlasWindow::setTolerance(double tolerance)
{
    m_tolerance->setText(QString::number(tolerance, 'g', 10));
}

void RegularityAtlasWindow::setRefinement(int levels)
{
    m_refine->setValue(levels);
}

void RegularityAtlasWindow::setWhere(Where where)
{
    m_where->setCurrentIndex(int(where));
}

RegularityAtlasWindow::Where RegularityAtlasWindow::where() const
{
    return Where(m_where->currentIndex());
}

void RegularityAtlasWindow::updateForm()
{
    const bool mask = m_item && m_item->scheme().kind == SchemeSpec::Kind::Mask;
    m_mask->setEnabled(mask && !isRunning());
    const AxisFields &second = m_fields[1];
    for (QWidget *w : std::initializer_list<QWidget *>{second.name, second.from, second.to,
                                                       second.count})
        w->setEnabled(m_second->isChecked() && !isRunning());
    m_tolerance->setEnabled(!m_second->isChecked());
    m_refine->setEnabled(m_second->isChecked());
    m_startButton->setEnabled(m_item && !isRunning());
    m_cancelButton->setEnabled(isRunning());
}

QString RegularityAtlasWindow::pythonProgram()
{
    const QString chosen = QSettings().value(QStringLiteral("preferences/python")).toString();
    if (!chosen.isEmpty())
        return chosen;
    // Debian's Python, which has python3-distributed and the package's dist-packages.
    const QString debian = QStringLiteral("/usr/bin/python3");
    return QFileInfo::exists(debian) ? debian : QStringLiteral("python3");
}

QString RegularityAtlasWindow::modulePath()
{
    const QString env = qEnvironmentVariable("AWB_PYTHONPATH");
    if (!env.isEmpty())
        return env;
    // The build tree: build/bin/attractor-workbench beside build/python/attractor_workbench
    // (tests run from build/tests). An installed package is on Python's own path.
    for (const char *up : {"../python", "../../python"}) {
        const QString dir = QDir(QCoreApplication::applicationDirPath()).filePath(up);
        if (QFileInfo::exists(dir + "/attractor_workbench/__init__.py"))
            return QDir::cleanPath(dir);
    }
    return {};
}

bool RegularityAtlasWindow::isRunning() const
{
    return m_process != nullptr;
}

QString RegularityAtlasWindow::statusText() const
{
    return m_status->text();
}

void RegularityAtlasWindow::showStatus(const QString &text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(
        error ? QStringLiteral("color: %1").arg(errorTextColour(palette()).name()) : QString());
}

bool RegularityAtlasWindow::start()
{
    if (isRunning())
        return false;
    if (!m_item) {
        showStatus(tr("Select a subdivision curve first: the atlas moves its scheme's "
                      "parameters."),
                   true);
        return false;
    }
    const std::vector<AtlasAxis> axes = this->axes();
    const QString mask = m_mask->isEnabled() ? m_mask->text().trimmed() : QString();
    const QStringList names = axisNames(axes);
    bool toleranceOk = false;
    const double tolerance = m_tolerance->text().toDouble(&toleranceOk);
    // The form checked as the module will check it, here, with the model's own messages.
    try {
        SchemeFamily::ofItem(*m_item, names, mask);
        AtlasOptions o;
        o.smoothness = m_smoothness->value();
        o.tolerance = toleranceOk ? tolerance : -1.0;
        o.refineLevels = m_refine->value();
        AtlasPlan check(axes, o);
    } catch (const std::exception &e) {
        showStatus(QString::fromStdString(e.what()), true);
        return false;
    }
    if (where() == Where::Scheduler && Preferences::load().daskScheduler.isEmpty()) {
        showStatus(tr("No Dask scheduler is set: name one in Edit > Preferences, or run on a "
                      "local cluster."),
                   true);
        return false;
    }
    m_dir = std::make_unique<QTemporaryDir>();
    const QString projectFile = m_dir->filePath(QStringLiteral("atlas.awb"));
    QString why;
    if (!m_dir->isValid() ||
        !ProjectIO::writeFile(projectFile, ProjectIO::toBytes(ProjectIO::toJson(*m_project)),
                              &why)) {
        showStatus(tr("Could not write the project for the atlas: %1").arg(why), true);
        return false;
    }
    QStringList args{QStringLiteral("-m"), QStringLiteral("attractor_workbench.atlas"),
                     projectFile, QStringLiteral("--item"), m_item->name()};
    for (const AtlasAxis &a : axes)
        args << QStringLiteral("--grid")
             << QStringLiteral("%1=%2:%3:%4")
                    .arg(QString::fromStdString(a.name))
                    .arg(a.from, 0, 'g', 17)
                    .arg(a.to, 0, 'g', 17)
                    .arg(a.count);
    if (!mask.isEmpty())
        args << QStringLiteral("--mask") << mask;
    args << QStringLiteral("--smoothness") << QString::number(m_smoothness->value())
         << QStringLiteral("--tolerance") << QString::number(tolerance, 'g', 17)
         << QStringLiteral("--refine") << QString::number(m_refine->value());
    const Preferences prefs = Preferences::load();
    switch (where()) {
    case Where::LocalCluster:
        if (prefs.atlasWorkers > 0)
            args << QStringLiteral("--workers") << QString::number(prefs.atlasWorkers);
        break;
    case Where::Scheduler:
        args << QStringLiteral("--scheduler") << prefs.daskScheduler;
        break;
    case Where::InProcess:
        args << QStringLiteral("--in-process");
        break;
    }
    args << QStringLiteral("--progress") << QStringLiteral("jsonl") << QStringLiteral("--json")
         << m_dir->filePath(QStringLiteral("atlas.json"));

    m_process = new QProcess(this);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    const QString path = modulePath();
    if (!path.isEmpty()) {
        const QString old = env.value(QStringLiteral("PYTHONPATH"));
        env.insert(QStringLiteral("PYTHONPATH"), old.isEmpty() ? path : path + ":" + old);
    }
    env.remove(QStringLiteral("LD_PRELOAD"));
    m_process->setProcessEnvironment(env);
    connect(m_process, &QProcess::readyReadStandardOutput, this,
            &RegularityAtlasWindow::readOutput);
    connect(m_process, &QProcess::readyReadStandardError, this,
            [this] { m_errors += m_process->readAllStandardError(); });
    connect(m_process, &QProcess::finished, this, &RegularityAtlasWindow::processFinished);
    connect(m_process, &QProcess::errorOccurred, this, [this](QProcess::ProcessError e) {
        if (e == QProcess::FailedToStart)
            processFinished(-1, QProcess::CrashExit);
    });
    m_runAxes = axes;
    m_runSmoothness = m_smoothness->value();
    m_round = 0;
    m_cancelled = false;
    m_pending.clear();
    m_errors.clear();
    m_plot->start(axes, m_runSmoothness);
    m_progress->setRange(0, 0);
    showStatus(where() == Where::InProcess ? tr("Computing in one process…")
                                           : tr("Starting the Dask cluster…"));
    m_process->start(pythonProgram(), args);
    updateForm();
    return true;
}

void RegularityAtlasWindow::cancel()
{
    if (!m_process)
        return;
    m_cancelled = true;
    showStatus(tr("Cancelling: the cluster's tasks are being cancelled…"));
    m_process->terminate();   // SIGTERM: the module cancels the tasks and closes its cluster
}

void RegularityAtlasWindow::readOutput()
{
    m_pending += m_process->readAllStandardOutput();
    int end;
    while ((end = m_pending.indexOf('\n')) >= 0) {
        const QByteArray line = m_pending.left(end);
        m_pending.remove(0, end + 1);
        const QJsonObject event = QJsonDocument::fromJson(line).object();
        const QString kind = event.value("event").toString();
        if (kind == "round") {
            m_round = event.value("round").toInt();
            m_progress->setRange(0, event.value("points").toInt());
            m_progress->setValue(0);
            showStatus(m_round == 1 ? tr("Round 1: the grid's %1 points…")
                                          .arg(event.value("points").toInt())
                                    : tr("Round %1: %2 points where the class changes…")
                                          .arg(m_round)
                                          .arg(event.value("points").toInt()));
        } else if (kind == "progress") {
            std::vector<AtlasRow> rows;
            std::vector<std::vector<double>> cells;
            // Round r of a 2D atlas refines cells to 1 / 2^(r-1) of the grid's.
            appendRows(event.value("new").toArray(), m_runAxes, rows, cells,
                       [this](const QJsonObject &) {
                           std::vector<double> cell;
                           for (const AtlasAxis &a : m_runAxes)
                               cell.push_back((a.to - a.from) / (a.count - 1) /
                                              std::ldexp(1.0, m_round - 1));
                           return cell;
                       });
            m_plot->addRows(rows, cells);
            m_progress->setValue(event.value("done").toInt());
            showStatus(tr("Round %1: %2 of %3 points; %4 in all, %5 s")
                           .arg(m_round)
                           .arg(event.value("done").toInt())
                           .arg(event.value("total").toInt())
                           .arg(event.value("rows").toInt())
                           .arg(event.value("elapsed").toDouble(), 0, 'f', 1));
        }
    }
}

void RegularityAtlasWindow::processFinished(int code, QProcess::ExitStatus status)
{
    if (!m_process)
        return;
    readOutput();
    m_errors += m_process->readAllStandardError();
    QProcess *process = m_process;
    m_process = nullptr;
    process->deleteLater();
    m_progress->setRange(0, 1);
    m_progress->setValue(code == 0 ? 1 : 0);
    bool ok = false;
    if (code == 0 && status == QProcess::NormalExit) {
        QFile f(m_dir->filePath(QStringLiteral("atlas.json")));
        const QJsonObject result = f.open(QIODevice::ReadOnly)
                                       ? QJsonDocument::fromJson(f.readAll()).object()
                                       : QJsonObject();
        std::vector<AtlasRow> rows;
        std::vector<std::vector<double>> cells;
        appendRows(result.value("rows").toArray(), m_runAxes, rows, cells,
                   [](const QJsonObject &row) {
                       std::vector<double> cell;
                       for (const QJsonValue &c : row.value("cell").toArray())
                           cell.push_back(c.toDouble());
                       return cell;
                   });
        std::vector<AtlasRun> runs;
        QStringList ends;
        for (const QJsonValue &v : result.value("runs").toArray()) {
            const AtlasRun run{boundaryFromJson(v.toObject().value("from").toObject()),
                               boundaryFromJson(v.toObject().value("to").toObject())};
            runs.push_back(run);
            const auto end = [](const AtlasBoundary &b) {
                const auto n = [](double v) { return QString::number(v, 'g', 10); };
                return b.rangeEnd ? n(b.inner)
                                  : QStringLiteral("[%1, %2]").arg(n(std::min(b.inner, b.outer)),
                                                                   n(std::max(b.inner, b.outer)));
            };
            ends << tr("from %1 to %2").arg(end(run.from), end(run.to));
        }
        ok = !rows.empty();
        if (ok) {
            m_plot->finish(rows, cells, runs);
            QString text = tr("%n point(s) in %1 round(s), %2 s on %3 worker(s) (%4).", nullptr,
                              int(rows.size()))
                               .arg(result.value("rounds").toInt())
                               .arg(result.value("seconds").toDouble(), 0, 'f', 1)
                               .arg(result.value("workers").toInt())
                               .arg(result.value("scheduler").toString());
            if (m_runAxes.size() == 1)
                text += " " + (ends.isEmpty()
                                   ? tr("Nowhere certified C^%1.").arg(m_runSmoothness)
                                   : tr("C^%1 %2.").arg(m_runSmoothness).arg(ends.join("; ")));
            showStatus(text);
        } else {
            showStatus(tr("The atlas gave no rows."), true);
        }
    } else if (m_cancelled) {
        showStatus(tr("Cancelled; the points computed so far are shown."));
    } else {
        // The module's last message ("atlas: ..."), or why Python did not start.
        QString message;
        const QStringList lines = QString::fromUtf8(m_errors).split('\n', Qt::SkipEmptyParts);
        for (const QString &l : lines)
            if (l.startsWith(QStringLiteral("atlas: ")) || l.contains(QStringLiteral("Error")))
                message = l;
        if (code < 0)
            message = tr("could not start %1: %2").arg(pythonProgram(), process->errorString());
        else if (message.isEmpty())
            message = lines.isEmpty() ? tr("exit code %1").arg(code) : lines.last();
        showStatus(tr("The atlas failed: %1").arg(message), true);
    }
    updateForm();
    emit finished(ok);
}

void RegularityAtlasWindow::offerItemAt(int row, const QPoint &globalPos)
{
    if (row < 0 || size_t(row) >= m_plot->rows().size() || !m_item)
        return;
    const std::vector<double> params = m_plot->rows()[size_t(row)].params;
    QMenu menu(this);
    QAction *add =
        menu.addAction(tr("Add an item with %1").arg(paramsText(axisNames(m_runAxes), params)));
    if (menu.exec(globalPos) == add)
        addItemAt(params);
}

Item *RegularityAtlasWindow::addItemAt(const std::vector<double> &params)
{
    if (!m_item)
        return nullptr;
    const QStringList names = axisNames(m_runAxes.empty() ? axes() : m_runAxes);
    QString why;
    try {
        const SchemeFamily family = SchemeFamily::ofItem(
            *m_item, names, m_item->scheme().kind == SchemeSpec::Kind::Mask ? m_mask->text()
                                                                            : QString());
        const std::optional<SchemeSpec> spec = family.member(params, &why);
        std::unique_ptr<Item> copy = spec ? ProjectIO::copyItem(*m_item, &why) : nullptr;
        auto *curve = qobject_cast<SubdivisionCurveItem *>(copy.get());
        if (curve && curve->setScheme(*spec)) {
            curve->setName(m_project->uniqueName(
                QStringLiteral("%1 (%2)").arg(m_item->name(), paramsText(names, params))));
            Item *added = m_project->addItem(std::move(copy));
            showStatus(tr("Added \"%1\" (Edit > Undo removes it).").arg(added->name()));
            return added;
        }
        if (curve)
            why = tr("the scheme refuses these parameters");
    } catch (const std::exception &e) {
        why = QString::fromStdString(e.what());
    }
    showStatus(tr("No item added: %1").arg(why), true);
    return nullptr;
}

void RegularityAtlasWindow::closeEvent(QCloseEvent *event)
{
    cancel();
    QWidget::closeEvent(event);
}

} // namespace awb
