// attractor-workbench: the desktop application. Opens the project named on the command line,
// otherwise offers the recovery copies of crashed sessions, otherwise starts with a new project
// holding one cubic B-spline so that the window is never empty. For scripted figures it can
// also select an item, print its figure sheet to PDF and/or save a screenshot of the window,
// then quit (--print-pdf, --screenshot, --export-figure with its --dpi, --view, --figure-size,
// --no-grid, --no-handles, --crop, --font; with QT_QPA_PLATFORM=offscreen no display is needed).
#include "gui/app/Dialogs.h"
#include "gui/app/ItemController.h"
#include "gui/app/MainWindow.h"
#include "gui/app/Messages.h"
#include "gui/views/AttractorRenderer.h"
#include "gui/views/AttractorView.h"
#include "gui/views/SurfaceView.h"
#include "i18n/Translations.h"
#include "model/Item.h"
#include "model/Project.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QTimer>

#include <cstdio>

#include <csignal>

int main(int argc, char *argv[])
{
    // A file size limit makes a too-large save fail with a message, not kill the window.
    std::signal(SIGXFSZ, SIG_IGN);
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("attractor-workbench"));
    QApplication::setApplicationDisplayName(QStringLiteral("Attractor Workbench"));
    QApplication::setOrganizationName(QStringLiteral("attractor-workbench"));
    QApplication::setApplicationVersion(QStringLiteral(AWB_VERSION));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/attractor-workbench.svg")));

    // Translations: the language of the settings (View > Language) or of the system; Qt's own
    // strings, ours and the core's messages.
    awb::i18n::installTranslations(app);

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QApplication::translate("main", "Subdivision curves as attractors of IFS."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("file"),
                                 QApplication::translate("main", "Project file to open."),
                                 QStringLiteral("[file.awb]"));
    const QCommandLineOption itemOption(
        QStringLiteral("item"),
        QApplication::translate("main", "Select the item with this name after opening."),
        QStringLiteral("name"));
    const QCommandLineOption pdfOption(
        QStringLiteral("print-pdf"),
        QApplication::translate("main", "Print the current item's figure sheet to this PDF "
                                        "file, then quit."),
        QStringLiteral("file.pdf"));
    const QCommandLineOption shotOption(
        QStringLiteral("screenshot"),
        QApplication::translate("main", "Save a picture of the main window to this PNG file "
                                        "once the attractor is drawn, then quit."),
        QStringLiteral("file.png"));
    const QCommandLineOption sizeOption(
        QStringLiteral("window-size"),
        QApplication::translate("main", "Window size for --screenshot, WIDTHxHEIGHT."),
        QStringLiteral("size"), QStringLiteral("1400x900"));
    const QCommandLineOption figureOption(
        QStringLiteral("export-figure"),
        QApplication::translate("main", "Export a figure of the current item to this file "
                                        "(.png, .svg, .pdf; .tex for the matrices), then quit."),
        QStringLiteral("file"));
    const QCommandLineOption dpiOption(
        QStringLiteral("dpi"),
        QApplication::translate("main", "Resolution of --export-figure in dpi (36..2400)."),
        QStringLiteral("n"), QStringLiteral("300"));
    const QCommandLineOption viewOption(
        QStringLiteral("view"),
        QApplication::translate("main", "What --export-figure shows: attractor, spectrum, "
                                        "matrices, analysis or sheet."),
        QStringLiteral("view"), QStringLiteral("attractor"));
    const QCommandLineOption figureSizeOption(
        QStringLiteral("figure-size"),
        QApplication::translate("main", "Size of --export-figure in pixels at its resolution, "
                                        "WIDTHxHEIGHT (16..20000)."),
        QStringLiteral("size"), QStringLiteral("1800x1350"));
    const QCommandLineOption noGridOption(
        QStringLiteral("no-grid"),
        QApplication::translate("main", "--export-figure without the grid."));
    const QCommandLineOption noHandlesOption(
        QStringLiteral("no-handles"),
        QApplication::translate("main", "--export-figure without control polygons and start "
                                        "set."));
    const QCommandLineOption cropOption(
        QStringLiteral("crop"),
        QApplication::translate("main", "--export-figure framed tightly around the content "
                                        "(the height follows its proportions)."));
    const QCommandLineOption fontOption(
        QStringLiteral("font"),
        QApplication::translate("main", "Font of --export-figure's labels: FAMILY or "
                                        "FAMILY,POINTS."),
        QStringLiteral("font"));
    parser.addOptions({itemOption, pdfOption, shotOption, sizeOption, figureOption, dpiOption,
                       viewOption, figureSizeOption, noGridOption, noHandlesOption, cropOption,
                       fontOption});
    parser.process(app);

    // --export-figure's options, checked before any window appears.
    awb::ExportDialog::Options figure;
    if (parser.isSet(figureOption)) {
        figure.fileName = parser.value(figureOption);
        const QStringList views{QStringLiteral("attractor"), QStringLiteral("spectrum"),
                                QStringLiteral("matrices"), QStringLiteral("analysis"),
                                QStringLiteral("sheet")};
        const int view = int(views.indexOf(parser.value(viewOption)));
        bool dpiOk = false;
        figure.dpi = parser.value(dpiOption).toInt(&dpiOk);
        const QStringList wh = parser.value(figureSizeOption).split(QLatin1Char('x'));
        const int w = wh.value(0).toInt(), h = wh.value(1).toInt();
        QString problem;
        if (view < 0)
            problem = QStringLiteral("--view %1: expected attractor, spectrum, matrices, "
                                     "analysis or sheet").arg(parser.value(viewOption));
        else if (!dpiOk || figure.dpi < 36 || figure.dpi > 2400)
            problem = QStringLiteral("--dpi %1: expected a whole number 36..2400")
                          .arg(parser.value(dpiOption));
        else if (wh.size() != 2 || w < 16 || h < 16 || w > 20000 || h > 20000)
            problem = QStringLiteral("--figure-size %1: expected WIDTHxHEIGHT (16..20000)")
                          .arg(parser.value(figureSizeOption));
        if (!problem.isEmpty()) {
            std::fprintf(stderr, "attractor-workbench: %s\n", qPrintable(problem));
            return 2;
        }
        figure.target = awb::ExportDialog::Target(view);
        figure.size = QSize(w, h);
        figure.grid = !parser.isSet(noGridOption);
        figure.handles = !parser.isSet(noHandlesOption);
        figure.crop = parser.isSet(cropOption);
        if (parser.isSet(fontOption)) {
            const QStringList font = parser.value(fontOption).split(QLatin1Char(','));
            figure.fontFamily = font.value(0).trimmed();
            if (font.size() > 1)
                figure.fontPoints = font.value(1).toDouble();
        }
    }

    const bool batch = parser.isSet(pdfOption) || parser.isSet(shotOption)
                       || parser.isSet(figureOption);
    // Without a user, messages go to standard error (a modal box would wait forever).
    awb::ConsoleMessages console;
    awb::MainWindow window(batch ? &console : nullptr);
    if (batch) {
        const QStringList wh = parser.value(sizeOption).split(QLatin1Char('x'));
        const int w = wh.value(0).toInt(), h = wh.value(1).toInt();
        if (wh.size() != 2 || w < 200 || h < 150 || w > 10000 || h > 10000) {
            std::fprintf(stderr, "attractor-workbench: --window-size %s: expected WIDTHxHEIGHT "
                                 "(200x150 .. 10000x10000)\n",
                         qPrintable(parser.value(sizeOption)));
            return 2;
        }
        window.resize(w, h);
    }
    window.show();
    if (!parser.positionalArguments().isEmpty()) {
        if (!window.openFile(parser.positionalArguments().constFirst()) && batch)
            return 1; // ConsoleMessages wrote the loader's message to stderr
    } else if (!batch) {
        window.offerRecovery();
    }
    if (parser.isSet(itemOption)) {
        awb::Item *item = nullptr;
        for (awb::Item *i : window.project()->items())
            if (i->name() == parser.value(itemOption))
                item = i;
        if (!item) {
            std::fprintf(stderr, "attractor-workbench: no item named \"%s\"\n",
                         qPrintable(parser.value(itemOption)));
            return 1;
        }
        window.setCurrentItem(item);
    }
    if (!batch)
        return app.exec();

    // Batch: wait until the attractor raster is final (or the item cannot be drawn), at most a
    // minute, then write the files.
    int status = 0;
    const auto finish = [&] {
        QString error;
        if (parser.isSet(pdfOption) && !window.printToPdf(parser.value(pdfOption), &error)) {
            std::fprintf(stderr, "attractor-workbench: %s\n", qPrintable(error));
            status = 1;
        }
        if (parser.isSet(figureOption)) {
            if (!window.exportView(figure, &error)) {
                std::fprintf(stderr, "attractor-workbench: %s\n", qPrintable(error));
                status = 1;
            } else if (figure.target == awb::ExportDialog::Target::Attractor
                       && !window.controller()->showsSurface()) {
                // What the attractor became (vector paths, a raster of which size): scripts
                // and tests read it.
                std::fprintf(stderr, "attractor-workbench: %s: attractor drawn as %s\n",
                             qPrintable(figure.fileName),
                             qPrintable(window.attractorView()->lastExportKind()));
            }
        }
        if (parser.isSet(shotOption) && !window.grab().save(parser.value(shotOption))) {
            std::fprintf(stderr, "attractor-workbench: cannot write %s\n",
                         qPrintable(parser.value(shotOption)));
            status = 1;
        }
        app.quit();
    };
    QTimer poll;
    int waited = 0;
    QObject::connect(&poll, &QTimer::timeout, &app, [&] {
        waited += 100;
        awb::AttractorView *view = window.attractorView();
        // A surface item is drawn by the 3D view (its CPU renderer without GL).
        const bool surface = window.controller()->showsSurface();
        const bool done = surface ? !window.surfaceView()->isRendering()
                                  : (view->currentImageInfo().final && !view->renderer()->isBusy())
                                        || !view->lastError().isEmpty()
                                        || !window.controller()->problem().isEmpty();
        if ((done && !window.controller()->analysisRunning() && waited >= 500) || waited > 60000) {
            poll.stop();
            finish();
        }
    });
    poll.start(100);
    app.exec();
    return status;
}
