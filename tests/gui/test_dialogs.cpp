// The export and preferences dialogs (Qt Designer forms): values round-trip through the
// dialogs, edits of the named widgets reach options() and preferences(), the widgets keep
// their ranges and defaults, and the labels, buddies, tooltips and tab order are in place.

#include "gui/app/Dialogs.h"
#include "gui/app/Messages.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QToolButton>
#include <QtTest>

#include "TestMain.h"

using namespace awb;

namespace {

template <typename W>
W *child(QWidget &dialog, const char *name)
{
    W *w = dialog.findChild<W *>(QLatin1String(name));
    if (!w)
        qWarning("no %s named %s", W::staticMetaObject.className(), name);
    return w;
}

// The order in which the named widgets first appear in the focus chain, starting at `first`.
QStringList focusOrder(QWidget *first, const QStringList &names)
{
    QStringList seen;
    QWidget *w = first;
    do {
        const QString name = w->objectName();
        if (names.contains(name) && !seen.contains(name) && (w->focusPolicy() & Qt::TabFocus))
            seen << name;
        w = w->nextInFocusChain();
    } while (w && w != first);
    return seen;
}

void checkLabels(QWidget &dialog)
{
    const QList<QLabel *> labels = dialog.findChildren<QLabel *>();
    QVERIFY(!labels.isEmpty());
    for (QLabel *label : labels) {
        QVERIFY2(!label->objectName().isEmpty(), qPrintable(label->text()));
        QVERIFY2(!label->text().trimmed().isEmpty(), qPrintable(label->objectName()));
        // A label with a mnemonic must hand the focus to its field.
        if (label->text().contains(QLatin1Char('&')))
            QVERIFY2(label->buddy(), qPrintable(label->objectName()));
    }
}

} // namespace

class TestDialogs : public QObject {
    Q_OBJECT
private slots:
    void exportRoundTrip_data();
    void exportRoundTrip();
    void exportDefaultsMatchOptions();
    void exportWidgetsChangeOptions();
    void exportRangesAndTooltips();
    void exportLabelsAndTabOrder();
    void preferencesRoundTrip_data();
    void preferencesRoundTrip();
    void preferencesWidgetsChangePreferences();
    void preferencesColourButtons();
    void preferencesLabelsAndTabOrder();
    void longMessageFitsTheScreen();
};

void TestDialogs::exportRoundTrip_data()
{
    QTest::addColumn<int>("target");
    QTest::addColumn<QString>("fileName");
    QTest::addColumn<QSize>("size");
    QTest::addColumn<int>("dpi");
    QTest::newRow("attractor png") << int(ExportDialog::Target::Attractor)
                                   << QStringLiteral("/tmp/a/figure.png") << QSize(1600, 1200)
                                   << 300;
    QTest::newRow("spectrum svg") << int(ExportDialog::Target::Spectrum)
                                  << QStringLiteral("spectrum.svg") << QSize(800, 450) << 96;
    QTest::newRow("matrices pdf") << int(ExportDialog::Target::Matrices)
                                  << QStringLiteral("/x/m.pdf") << QSize(16, 20000) << 36;
    QTest::newRow("analysis") << int(ExportDialog::Target::Analysis)
                              << QStringLiteral("chart.png") << QSize(20000, 16) << 2400;
    QTest::newRow("figure sheet") << int(ExportDialog::Target::FigureSheet)
                                  << QStringLiteral("/ü/sheet.pdf") << QSize(1234, 987) << 600;
}

void TestDialogs::exportRoundTrip()
{
    QFETCH(int, target);
    QFETCH(QString, fileName);
    QFETCH(QSize, size);
    QFETCH(int, dpi);
    ExportDialog::Options in;
    in.target = ExportDialog::Target(target);
    in.fileName = fileName;
    in.size = size;
    in.dpi = dpi;
    ExportDialog dialog(in);
    const ExportDialog::Options out = dialog.options();
    QCOMPARE(int(out.target), target);
    QCOMPARE(out.fileName, fileName);
    QCOMPARE(out.size, size);
    QCOMPARE(out.dpi, dpi);
    // The widgets show the values too.
    QCOMPARE(child<QComboBox>(dialog, "targetCombo")->currentIndex(), target);
    QCOMPARE(child<QLineEdit>(dialog, "fileEdit")->text(), fileName);
    QCOMPARE(child<QSpinBox>(dialog, "widthSpin")->value(), size.width());
    QCOMPARE(child<QSpinBox>(dialog, "heightSpin")->value(), size.height());
    QCOMPARE(child<QSpinBox>(dialog, "dpiSpin")->value(), dpi);
}

void TestDialogs::exportDefaultsMatchOptions()
{
    const ExportDialog::Options defaults;
    ExportDialog dialog(defaults);
    const ExportDialog::Options out = dialog.options();
    QCOMPARE(out.target, defaults.target);
    QCOMPARE(out.fileName, defaults.fileName);
    QCOMPARE(out.size, QSize(1600, 1200));
    QCOMPARE(out.dpi, 300);
    QCOMPARE(dialog.windowTitle(), QStringLiteral("Export Figure"));
    // Every view the exporter knows is offered, in Target order.
    auto *target = child<QComboBox>(dialog, "targetCombo");
    QVERIFY(target);
    QCOMPARE(target->count(), int(ExportDialog::Target::FigureSheet) + 1);
    for (int i = 0; i < target->count(); ++i)
        QVERIFY(!target->itemText(i).isEmpty());
    QCOMPARE(target->itemText(int(ExportDialog::Target::Attractor)),
             QStringLiteral("Attractor view"));
    QCOMPARE(target->itemText(int(ExportDialog::Target::FigureSheet)),
             QStringLiteral("Figure sheet"));
}

void TestDialogs::exportWidgetsChangeOptions()
{
    ExportDialog::Options in;
    in.fileName = QStringLiteral("before.png");
    ExportDialog dialog(in);
    auto *target = child<QComboBox>(dialog, "targetCombo");
    auto *file = child<QLineEdit>(dialog, "fileEdit");
    auto *width = child<QSpinBox>(dialog, "widthSpin");
    auto *height = child<QSpinBox>(dialog, "heightSpin");
    auto *dpi = child<QSpinBox>(dialog, "dpiSpin");
    QVERIFY(target && file && width && height && dpi);

    width->setValue(640);
    QCOMPARE(dialog.options().size, QSize(640, 1200));
    height->setValue(480);
    QCOMPARE(dialog.options().size, QSize(640, 480));
    dpi->setValue(72);
    QCOMPARE(dialog.options().dpi, 72);
    target->setCurrentIndex(int(ExportDialog::Target::Analysis));
    QCOMPARE(dialog.options().target, ExportDialog::Target::Analysis);
    file->setText(QStringLiteral("after.svg"));
    QCOMPARE(dialog.options().fileName, QStringLiteral("after.svg"));

    // Typing works as well as setValue().
    width->selectAll();
    QTest::keyClicks(width, QStringLiteral("1024"));
    QCOMPARE(dialog.options().size.width(), 1024);
}

void TestDialogs::exportRangesAndTooltips()
{
    ExportDialog dialog(ExportDialog::Options{});
    auto *width = child<QSpinBox>(dialog, "widthSpin");
    auto *height = child<QSpinBox>(dialog, "heightSpin");
    auto *dpi = child<QSpinBox>(dialog, "dpiSpin");
    QVERIFY(width && height && dpi);
    for (QSpinBox *s : {width, height}) {
        QCOMPARE(s->minimum(), 16);
        QCOMPARE(s->maximum(), 20000);
        QVERIFY(s->suffix().contains(QStringLiteral("px")));
        QVERIFY2(s->toolTip().contains(QStringLiteral("pixels")), qPrintable(s->objectName()));
    }
    QCOMPARE(dpi->minimum(), 36);
    QCOMPARE(dpi->maximum(), 2400);
    QVERIFY(dpi->suffix().contains(QStringLiteral("dpi")));
    QVERIFY(dpi->toolTip().contains(QStringLiteral("dots per inch")));
    // Out-of-range values are clamped, and options() reports the clamped value.
    width->setValue(1);
    dpi->setValue(100000);
    QCOMPARE(dialog.options().size.width(), 16);
    QCOMPARE(dialog.options().dpi, 2400);

    auto *browse = child<QPushButton>(dialog, "browseButton");
    QVERIFY(browse);
    QVERIFY(!browse->text().isEmpty());
    auto *buttons = child<QDialogButtonBox>(dialog, "buttonBox");
    QVERIFY(buttons);
    QVERIFY(buttons->button(QDialogButtonBox::Ok));
    QVERIFY(buttons->button(QDialogButtonBox::Cancel));
}

void TestDialogs::exportLabelsAndTabOrder()
{
    ExportDialog dialog(ExportDialog::Options{});
    checkLabels(dialog);
    if (QTest::currentTestFailed())
        return;
    const struct {
        const char *label, *buddy;
    } pairs[] = {{"targetLabel", "targetCombo"}, {"fileLabel", "fileEdit"},
                 {"widthLabel", "widthSpin"},    {"heightLabel", "heightSpin"},
                 {"dpiLabel", "dpiSpin"}};
    for (const auto &p : pairs) {
        auto *label = child<QLabel>(dialog, p.label);
        QVERIFY2(label, p.label);
        QVERIFY2(label->buddy() && label->buddy()->objectName() == QLatin1String(p.buddy),
                 p.label);
    }
    QVERIFY(child<QLabel>(dialog, "formatHintLabel"));
    const QStringList order{"targetCombo", "fileEdit",   "browseButton",
                            "widthSpin",   "heightSpin", "dpiSpin"};
    QCOMPARE(focusOrder(child<QWidget>(dialog, "targetCombo"), order), order);
}

void TestDialogs::preferencesRoundTrip_data()
{
    QTest::addColumn<int>("depth");
    QTest::addColumn<int>("maxDepth");
    QTest::addColumn<int>("autosave");
    QTest::addColumn<QList<QColor>>("palette");
    QTest::newRow("defaults") << 10 << 0 << 30 << QList<QColor>{};
    QTest::newRow("some colours") << 7 << 12 << 120
                                  << QList<QColor>{QColor(255, 0, 0), QColor(0, 128, 255),
                                                   QColor(10, 20, 30)};
    QTest::newRow("limits") << 30 << 64 << 3600
                            << QList<QColor>{Qt::black, Qt::white, Qt::red, Qt::green,
                                             Qt::blue, Qt::yellow};
    QTest::newRow("low limits") << 0 << 1 << 5 << QList<QColor>{QColor(1, 2, 3)};
}

void TestDialogs::preferencesRoundTrip()
{
    QFETCH(int, depth);
    QFETCH(int, maxDepth);
    QFETCH(int, autosave);
    QFETCH(QList<QColor>, palette);
    Preferences in;
    in.defaultDepth = depth;
    in.maxRenderDepth = maxDepth;
    in.autosaveSeconds = autosave;
    in.palette = palette;
    PreferencesDialog dialog(in);
    const Preferences out = dialog.preferences();
    QCOMPARE(out.defaultDepth, depth);
    QCOMPARE(out.maxRenderDepth, maxDepth);
    QCOMPARE(out.autosaveSeconds, autosave);
    QCOMPARE(out.palette, palette);
    QCOMPARE(child<QSpinBox>(dialog, "depthSpin")->value(), depth);
    QCOMPARE(child<QSpinBox>(dialog, "maxDepthSpin")->value(), maxDepth);
    QCOMPARE(child<QSpinBox>(dialog, "autosaveSpin")->value(), autosave);
}

void TestDialogs::preferencesWidgetsChangePreferences()
{
    PreferencesDialog dialog(Preferences{});
    QCOMPARE(dialog.windowTitle(), QStringLiteral("Preferences"));
    auto *depth = child<QSpinBox>(dialog, "depthSpin");
    auto *maxDepth = child<QSpinBox>(dialog, "maxDepthSpin");
    auto *autosave = child<QSpinBox>(dialog, "autosaveSpin");
    QVERIFY(depth && maxDepth && autosave);
    QCOMPARE(depth->minimum(), 0);
    QCOMPARE(depth->maximum(), 30);
    QCOMPARE(maxDepth->minimum(), 0);
    QCOMPARE(maxDepth->maximum(), 64);
    QCOMPARE(maxDepth->specialValueText(), QStringLiteral("no limit"));
    QCOMPARE(maxDepth->text(), QStringLiteral("no limit"));
    QCOMPARE(autosave->minimum(), 5);
    QCOMPARE(autosave->maximum(), 3600);
    QVERIFY(autosave->suffix().contains(QLatin1Char('s')));
    QVERIFY(autosave->toolTip().contains(QStringLiteral("seconds")));
    QVERIFY(!depth->toolTip().isEmpty());
    QVERIFY(!maxDepth->toolTip().isEmpty());

    depth->setValue(4);
    maxDepth->setValue(9);
    autosave->setValue(600);
    const Preferences p = dialog.preferences();
    QCOMPARE(p.defaultDepth, 4);
    QCOMPARE(p.maxRenderDepth, 9);
    QCOMPARE(p.autosaveSeconds, 600);
    autosave->setValue(1); // clamped to the minimum
    QCOMPARE(dialog.preferences().autosaveSeconds, 5);
}

void TestDialogs::preferencesColourButtons()
{
    Preferences in;
    in.palette = {QColor(200, 10, 10), QColor(10, 200, 10)};
    PreferencesDialog dialog(in);
    for (int i = 1; i <= 6; ++i) {
        const QByteArray name = "colourButton" + QByteArray::number(i);
        auto *b = child<QToolButton>(dialog, name.constData());
        QVERIFY2(b, name.constData());
        QVERIFY2(b->toolTip().contains(QString::number(i)), name.constData());
        if (i <= in.palette.size()) {
            QVERIFY2(b->text().isEmpty(), name.constData());
            QVERIFY2(b->styleSheet().contains(in.palette[i - 1].name()), name.constData());
        } else {
            QCOMPARE(b->text(), QStringLiteral("auto"));
            QVERIFY2(b->styleSheet().isEmpty(), name.constData());
        }
    }
    QVERIFY(!dialog.findChild<QToolButton *>(QStringLiteral("colourButton7")));
    // "Defaults" forgets the palette and shows every button as automatic.
    auto *defaults = child<QPushButton>(dialog, "defaultsButton");
    QVERIFY(defaults);
    QTest::mouseClick(defaults, Qt::LeftButton);
    QVERIFY(dialog.preferences().palette.isEmpty());
    QCOMPARE(child<QToolButton>(dialog, "colourButton1")->text(), QStringLiteral("auto"));
    QVERIFY(child<QToolButton>(dialog, "colourButton1")->styleSheet().isEmpty());
}

void TestDialogs::preferencesLabelsAndTabOrder()
{
    PreferencesDialog dialog(Preferences{});
    checkLabels(dialog);
    if (QTest::currentTestFailed())
        return;
    const struct {
        const char *label, *buddy;
    } pairs[] = {{"depthLabel", "depthSpin"},
                 {"maxDepthLabel", "maxDepthSpin"},
                 {"coloursLabel", "colourButton1"},
                 {"autosaveLabel", "autosaveSpin"}};
    for (const auto &p : pairs) {
        auto *label = child<QLabel>(dialog, p.label);
        QVERIFY2(label, p.label);
        QVERIFY2(label->buddy() && label->buddy()->objectName() == QLatin1String(p.buddy),
                 p.label);
    }
    const QStringList order{"depthSpin",     "maxDepthSpin",  "colourButton1",
                            "colourButton2", "colourButton3", "colourButton4",
                            "colourButton5", "colourButton6", "defaultsButton",
                            "autosaveSpin"};
    QCOMPARE(focusOrder(child<QWidget>(dialog, "depthSpin"), order), order);
}

// The warnings of a flame pack (issue 47: one per flame, a box 2 144 px tall whose OK button
// was off a 1 000 px screen): the box shows the first lines and keeps every line in its
// scrollable details; a short text is shown whole.
void TestDialogs::longMessageFitsTheScreen()
{
    QStringList lines;
    for (int i = 0; i < 300; ++i)
        lines << QStringLiteral("flame %1 \"Pack %1\": variation 'julia3D' is unknown; dropped")
                     .arg(i);
    const QString text = lines.join(QLatin1Char('\n'));
    std::unique_ptr<QMessageBox> box(
        Messages::makeBox(QMessageBox::Information, nullptr, QStringLiteral("Import"), text));
    QCOMPARE(box->detailedText(), text);
    QVERIFY(box->text().startsWith(lines.first()));
    QVERIFY(box->text().contains(QStringLiteral("288 more lines")));
    QVERIFY(!box->text().contains(lines.last()));
    box->show();
    QVERIFY2(box->height() < 600, qPrintable(QString::number(box->height())));
    box->close();
    std::unique_ptr<QMessageBox> small(
        Messages::makeBox(QMessageBox::Critical, nullptr, QStringLiteral("Open"),
                          QStringLiteral("one line")));
    QCOMPARE(small->text(), QStringLiteral("one line"));
    QVERIFY(small->detailedText().isEmpty());
}

AWB_TEST_MAIN(TestDialogs)
#include "test_dialogs.moc"
