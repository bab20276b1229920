// attractor-workbench: the desktop application. Opens the project named on the command line,
// otherwise offers the recovery copies of crashed sessions, otherwise starts with a new project
// holding one cubic B-spline so that the window is never empty. For scripted figures it can
// also select an item, print its figure sheet to PDF and/or save a screenshot of the window,
// then quit (--print-pdf, --screenshot; with QT_QPA_PLATFORM=offscreen no display is needed).
#include "gui/app/ItemController.h"
#include "gui/app/MainWindow.h"
#include "gui/app/Messages.h"
#include "gui/views/AttractorRenderer.h"
#include "gui/views/AttractorView.h"
#include "gui/views/SurfaceView.h"
#include "model/Item.h"
#include "model/Project.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QLibraryInfo>
#include <QLocale>
#include <QTimer>
#include <QTranslator>

#include <cstdio>

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("attractor-workbench"));
    QApplication::setApplicationDisplayName(QStringLiteral("Attractor Workbench"));
    QApplication::setOrganizationName(QStringLiteral("attractor-workbench"));
    QApplication::setApplicationVersion(QStringLiteral(AWB_VERSION));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/attractor-workbench.svg")));

    // Translations: Qt's own, then ours from the resources when they are there.
    QTranslator qtTranslator, appTranslator;
    if (qtTranslator.load(QLocale(), QStringLiteral("qtbase"), QStringLiteral("_"),
                          QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QApplication::installTranslator(&qtTranslator);
    if (appTranslator.load(QLocale(), QStringLiteral("attractor-workbench"), QStringLiteral("_"),
                           QStringLiteral(":/i18n")))
        QApplication::installTranslator(&appTranslator);

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
    parser.addOptions({itemOption, pdfOption, shotOption, sizeOption});
    parser.process(app);

    const bool batch = parser.isSet(pdfOption) || parser.isSet(shotOption);
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
