// attractor-workbench: the desktop application. Opens the project named on the command line,
// otherwise offers the recovery copies of crashed sessions, otherwise starts with a new project
// holding one cubic B-spline so that the window is never empty.
#include "gui/app/MainWindow.h"
#include "model/Project.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

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
    parser.process(app);

    awb::MainWindow window;
    window.show();
    if (!parser.positionalArguments().isEmpty())
        window.openFile(parser.positionalArguments().constFirst());
    else
        window.offerRecovery();
    return app.exec();
}
