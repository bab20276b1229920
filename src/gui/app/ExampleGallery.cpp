#include "gui/app/ExampleGallery.h"

#include "model/AttractorItem.h"
#include "model/Project.h"
#include "render/ItemFigure.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPainter>
#include <QPushButton>
#include <QSaveFile>
#include <QStandardPaths>
#include <QVBoxLayout>

#include <algorithm>

namespace awb {

namespace {

constexpr int thumbWidth = 240, thumbHeight = 180;
// The figure's caption band (render/ItemFigure.cpp): drawn, then cut off the thumbnail.
constexpr int captionBand = 26;

QIcon placeholder()
{
    QPixmap p(thumbWidth, thumbHeight);
    p.fill(QColor(246, 246, 246));
    QPainter painter(&p);
    painter.setPen(QColor(200, 200, 200));
    painter.drawRect(p.rect().adjusted(0, 0, -1, -1));
    return QIcon(p);
}

QString cacheFile(const QString &path)
{
    const QFileInfo f(path);
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::CacheLocation)
                        + QStringLiteral("/example-thumbnails");
    // The file's size and time, and the program's version: a changed example or renderer
    // draws again.
    return QStringLiteral("%1/%2-%3-%4-%5.png")
        .arg(dir, f.completeBaseName())
        .arg(f.size())
        .arg(f.lastModified().toSecsSinceEpoch())
        .arg(QCoreApplication::applicationVersion());
}

// Draws the thumbnail of `path` into the cache; "" if the example has nothing to draw.
QString drawThumbnail(const QString &path, const std::atomic<bool> *cancel)
{
    const QString out = cacheFile(path);
    if (QFileInfo::exists(out))
        return out;
    QDir().mkpath(QFileInfo(out).absolutePath());
    Project project;
    if (!project.open(path))
        return {};
    AttractorItem *item = nullptr;
    for (Item *i : project.items())
        if ((item = qobject_cast<AttractorItem *>(i)))
            break;
    if (!item)
        return {};
    FigureOptions o;
    o.width = 2 * thumbWidth;
    o.height = 2 * thumbHeight + captionBand;
    o.threads = 1;  // beside the window's own drawing
    o.cancel = cancel;
    // Random iteration: enough points for a small picture, not the figure's hundreds of
    // millions.
    if (item->algorithm().mode == AlgorithmSpec::Mode::Random)
        o.samples = std::min<std::uint64_t>(std::uint64_t(item->algorithm().samples), 2'000'000);
    const QString drawn = out + QStringLiteral(".figure.png");
    try {
        renderItemFigure(project, item, o, drawn);
    } catch (const std::exception &) {
        QFile::remove(drawn);
        return {};
    }
    QImage image(drawn);
    QFile::remove(drawn);
    if (image.isNull())
        return {};
    // Plane figures carry their caption in a band at the bottom: the title says it.
    if (image.height() == o.height)
        image = image.copy(0, 0, image.width(), o.height - captionBand);
    image = image.scaled(thumbWidth, thumbHeight, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    QSaveFile file(out);
    if (!file.open(QIODevice::WriteOnly) || !image.save(&file, "PNG") || !file.commit())
        return {};
    return out;
}

} // namespace

QString ExampleGallery::exampleTitle(const QString &path)
{
    QString title = QFileInfo(path).completeBaseName();
    QFile f(path);
    if (f.open(QIODevice::ReadOnly)) {
        const QJsonArray items = QJsonDocument::fromJson(f.read(1 << 20))
                                     .object()
                                     .value(QStringLiteral("items"))
                                     .toArray();
        const QString name =
            items.isEmpty()
                ? QString()
                : items.first().toObject().value(QStringLiteral("name")).toString();
        if (!name.isEmpty())
            title = name.size() > 90 ? name.left(88) + QStringLiteral("…") : name;
    }
    return title;
}

QString ExampleGallery::thumbnailFile(const QString &path) { return drawThumbnail(path, nullptr); }

ExampleGallery::ExampleGallery(const QString &directory, QWidget *parent) : QDialog(parent)
{
    setWindowTitle(tr("Open Example"));
    setObjectName(QStringLiteral("exampleGallery"));
    auto *layout = new QVBoxLayout(this);
    auto *intro = new QLabel(tr("One project per figure of the papers, and examples of meshes, "
                                "masks and animations. An example opens as a copy: Save As "
                                "keeps it."));
    intro->setWordWrap(true);
    layout->addWidget(intro);
    m_filter = new QLineEdit;
    m_filter->setObjectName(QStringLiteral("exampleFilter"));
    m_filter->setPlaceholderText(tr("Filter: a paper (003), a figure, a word (Koch, mesh)…"));
    m_filter->setClearButtonEnabled(true);
    layout->addWidget(m_filter);
    m_list = new QListWidget;
    m_list->setObjectName(QStringLiteral("exampleList"));
    m_list->setViewMode(QListView::IconMode);
    m_list->setIconSize(QSize(thumbWidth, thumbHeight));
    m_list->setGridSize(QSize(thumbWidth + 24, thumbHeight + 56));
    m_list->setResizeMode(QListView::Adjust);
    m_list->setMovement(QListView::Static);
    m_list->setWordWrap(true);
    m_list->setUniformItemSizes(true);
    m_list->setSpacing(4);
    layout->addWidget(m_list, 1);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Cancel);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &ExampleGallery::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_list, &QListWidget::itemActivated, this, [this] { accept(); });
    connect(m_filter, &QLineEdit::textChanged, this, &ExampleGallery::applyFilter);
    QPushButton *open = buttons->button(QDialogButtonBox::Open);
    open->setEnabled(false);
    connect(m_list, &QListWidget::currentItemChanged, this,
            [open](QListWidgetItem *current) { open->setEnabled(current); });

    const QDir dir(directory);
    const QIcon empty = placeholder();
    for (const QString &name : dir.entryList({QStringLiteral("*.awb")}, QDir::Files, QDir::Name)) {
        const QString path = dir.filePath(name);
        const QString title = exampleTitle(path);
        auto *item = new QListWidgetItem(empty, title, m_list);
        item->setToolTip(QStringLiteral("%1\n%2").arg(title, name));
        item->setData(Qt::UserRole, path);
        item->setTextAlignment(Qt::AlignHCenter | Qt::AlignTop);
        m_files << path;
    }
    if (m_files.isEmpty())
        m_list->addItem(tr("No examples installed"));
    resize(4 * (thumbWidth + 24) + 60, 720);
    startThumbnails();
}

ExampleGallery::~ExampleGallery()
{
    m_cancel = true;
    if (m_worker.joinable())
        m_worker.join();
}

void ExampleGallery::startThumbnails()
{
    // One after another (the window draws beside it); each shown as soon as it is there.
    m_worker = std::thread([this, files = m_files] {
        for (int row = 0; row < files.size() && !m_cancel; ++row) {
            const QString thumb = drawThumbnail(files[row], &m_cancel);
            QMetaObject::invokeMethod(
                this,
                [this, row, thumb] {
                    ++m_ready;
                    if (!thumb.isEmpty())
                        if (QListWidgetItem *item = m_list->item(row))
                            item->setIcon(QIcon(thumb));
                    emit thumbnailReady(row);
                },
                Qt::QueuedConnection);
        }
    });
}

void ExampleGallery::applyFilter(const QString &text)
{
    const QStringList words = text.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    for (int row = 0; row < m_list->count(); ++row) {
        QListWidgetItem *item = m_list->item(row);
        const QString haystack = item->text() + QLatin1Char(' ')
                                 + QFileInfo(item->data(Qt::UserRole).toString()).fileName();
        bool shown = true;
        for (const QString &w : words)
            shown = shown && haystack.contains(w, Qt::CaseInsensitive);
        item->setHidden(!shown);
    }
}

void ExampleGallery::accept()
{
    QListWidgetItem *item = m_list->currentItem();
    if (!item || item->isHidden() || item->data(Qt::UserRole).toString().isEmpty())
        return;
    m_chosen = item->data(Qt::UserRole).toString();
    QDialog::accept();
}

} // namespace awb
