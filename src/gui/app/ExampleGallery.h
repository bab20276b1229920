#pragma once
// File > Open Example > Gallery…: the bundled examples (one project per figure of the papers,
// meshes, masks, other tools' files) as thumbnails with their titles, filtered as you type;
// double-click or Open opens a copy (issue 47: a 42-entry text menu taller than the screen).
// The thumbnails are the figures attractor-cli render draws (render/ItemFigure.h), made one
// after another on a worker thread the first time and kept in the user's cache folder, keyed
// by the example file's size and time, so that the gallery opens at once.
#include <QDialog>
#include <QString>
#include <QStringList>

#include <atomic>
#include <memory>
#include <thread>

class QLineEdit;
class QListWidget;
class QListWidgetItem;

namespace awb {

class ExampleGallery : public QDialog {
    Q_OBJECT
public:
    // The examples of `directory` (*.awb; MainWindow::examplesDirectory()).
    explicit ExampleGallery(const QString &directory, QWidget *parent = nullptr);
    ~ExampleGallery() override;

    // The example chosen (after exec() returned Accepted), or "".
    QString chosenFile() const { return m_chosen; }
    QListWidget *list() const { return m_list; }
    QLineEdit *filter() const { return m_filter; }
    // How many thumbnails are drawn so far (tests wait for them).
    int thumbnailsReady() const { return m_ready; }
    // Opens the current example (Open, Enter, a double-click).
    void accept() override;

    // An example's title: its first item's name (the figure's caption), else the file's name.
    static QString exampleTitle(const QString &path);
    // The cached thumbnail of `path` (drawn if missing; "" if it cannot be drawn).
    static QString thumbnailFile(const QString &path);

signals:
    void thumbnailReady(int row);

private:
    void applyFilter(const QString &text);
    void startThumbnails();

    QLineEdit *m_filter = nullptr;
    QListWidget *m_list = nullptr;
    QStringList m_files;
    QString m_chosen;
    int m_ready = 0;
    std::atomic<bool> m_cancel{false};
    std::thread m_worker;
};

} // namespace awb
