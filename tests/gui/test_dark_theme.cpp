// A dark desktop theme (issue 15): the colours the widgets choose themselves — the analysis
// note, the highlighted map's matrices, a refused value's message — stay legible. Each is drawn
// under Fusion with a dark palette and the contrast between its background and its text pixels
// is measured (WCAG 4.5 for body text). AWB_SCREENSHOT_DIR=folder keeps the window's picture.
#include "TestPaths.h"
#include "gui/app/MainWindow.h"
#include "gui/views/AnalysisCharts.h"
#include "gui/views/MatrixView.h"
#include "gui/views/ThemeColours.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QLabel>
#include <QStyleFactory>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"

#include <map>

#include "WindowTestSupport.h"

using namespace awb;

namespace {

QPalette darkPalette()
{
    QPalette p;
    p.setColor(QPalette::Window, QColor(45, 45, 48));
    p.setColor(QPalette::WindowText, QColor(230, 230, 230));
    p.setColor(QPalette::Base, QColor(30, 30, 32));
    p.setColor(QPalette::AlternateBase, QColor(50, 50, 54));
    p.setColor(QPalette::Text, QColor(230, 230, 230));
    p.setColor(QPalette::Button, QColor(55, 55, 58));
    p.setColor(QPalette::ButtonText, QColor(230, 230, 230));
    p.setColor(QPalette::ToolTipBase, QColor(60, 60, 60));
    p.setColor(QPalette::ToolTipText, QColor(230, 230, 230));
    p.setColor(QPalette::Highlight, QColor(42, 130, 218));
    p.setColor(QPalette::HighlightedText, Qt::white);
    return p;
}

// The contrast of a widget's picture: its most frequent colour is the background; the text is
// the pixel farthest from it in contrast.
double pictureContrast(QWidget *w)
{
    const QImage img = w->grab().toImage().convertToFormat(QImage::Format_RGB32);
    std::map<QRgb, int> counts;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            ++counts[img.pixel(x, y)];
    QRgb background = 0;
    int most = -1;
    for (const auto &[rgb, n] : counts)
        if (n > most)
            most = n, background = rgb;
    double best = 1.0;
    for (const auto &[rgb, n] : counts)
        if (n >= 3) // a few anti-aliased pixels are not the text
            best = std::max(best, contrastRatio(QColor(background), QColor(rgb)));
    return best;
}

} // namespace

class TestDarkTheme : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        test::useTestSettings("test_dark_theme");
        QApplication::setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
        QApplication::setPalette(darkPalette());
        QVERIFY(isDarkPalette(QApplication::palette()));
    }

    void notesHighlightsAndErrorsAreLegible()
    {
        QTemporaryDir recovery;
        test::ShownWindow w(recovery.path(), QSize(1280, 800));
        QVERIFY(w.exposed);
        QVERIFY(w.window.openFile(awb::test::sourceDir()
                                  + QStringLiteral("/examples/000-fig05-four-point-from-segment.awb")));
        QVERIFY(test::waitForFinalImage(w.window.findChild<AttractorView *>()));

        AnalysisCharts *charts = w.window.analysisCharts();
        charts->setNote(QStringLiteral("The curve has a half-tangent at the fixed point."));
        auto *note = charts->findChild<QLabel *>(QStringLiteral("analysisNote"));
        QVERIFY(note);
        note->resize(360, 60);
        const double noteContrast = pictureContrast(note);
        QVERIFY2(noteContrast >= 4.5, qPrintable(QString::number(noteContrast)));

        MatrixView *matrices = w.window.matrixView();
        matrices->setHighlightedMap(0);
        QVERIFY(matrices->isHighlighted(0));
        // The box's title on the highlight colour.
        QWidget *box = nullptr;
        for (QLabel *l : matrices->findChildren<QLabel *>())
            if (l->isVisible() && !l->text().isEmpty() && l->parentWidget()->autoFillBackground()) {
                box = l;
                break;
            }
        QVERIFY(box);
        const double boxContrast = contrastRatio(box->parentWidget()->palette().color(QPalette::Window),
                                                 box->palette().color(QPalette::WindowText));
        QVERIFY2(boxContrast >= 4.5, qPrintable(QString::number(boxContrast)));
        // Tinted cells (row sums, the blocks A_i, b_i) keep dark text on their light tint.
        for (QAbstractItemView *table : matrices->findChildren<QAbstractItemView *>()) {
            const QAbstractItemModel *m = table->model();
            for (int r = 0; r < m->rowCount(); ++r)
                for (int c = 0; c < m->columnCount(); ++c) {
                    const QVariant bg = m->index(r, c).data(Qt::BackgroundRole);
                    if (!bg.isValid())
                        continue;
                    const QColor fg = m->index(r, c).data(Qt::ForegroundRole).value<QColor>();
                    QVERIFY(fg.isValid());
                    QVERIFY2(contrastRatio(bg.value<QBrush>().color(), fg) >= 4.5,
                             qPrintable(QStringLiteral("cell %1,%2").arg(r).arg(c)));
                }
        }
        QVERIFY(contrastRatio(errorTextColour(QApplication::palette()),
                              QApplication::palette().color(QPalette::Window)) >= 4.5);
        const QPalette light(QColor(239, 239, 239)); // a light theme built from its button colour
        QVERIFY(!isDarkPalette(light));
        QVERIFY(contrastRatio(errorTextColour(light), light.color(QPalette::Window)) >= 4.5);

        if (const QByteArray dir = qgetenv("AWB_SCREENSHOT_DIR"); !dir.isEmpty())
            w.window.grab().save(QString::fromLocal8Bit(dir) + QStringLiteral("/dark-theme.png"));
    }
};

AWB_TEST_MAIN(TestDarkTheme)
#include "test_dark_theme.moc"
