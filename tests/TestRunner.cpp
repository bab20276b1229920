// The main() of a layer's test executable (TestMain.h): `<layer>_tests NAME [QTest options]`
// runs the test of tests/<layer>/NAME.cpp in the application it asked for; without a name it
// lists the tests.

#include "TestMain.h"

#include <QCoreApplication>
#include <QFileInfo>
#if defined(QT_WIDGETS_LIB)
#include <QApplication>
#endif
#if defined(QT_GUI_LIB)
#include <QGuiApplication>
#endif

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace awb::test {

namespace {

struct Entry {
    std::string name;
    Application application;
    int (*run)(int, char **);
};

std::vector<Entry> &registry()
{
    static std::vector<Entry> entries;
    return entries;
}

std::string &current()
{
    static std::string name;
    return name;
}

} // namespace

int registerTest(const char *file, Application application, int (*run)(int, char **))
{
    registry().push_back({QFileInfo(QString::fromUtf8(file)).completeBaseName().toStdString(),
                          application, run});
    return 0;
}

QStringList childArguments(const QStringList &arguments)
{
    return QStringList{QString::fromStdString(current())} + arguments;
}

} // namespace awb::test

int main(int argc, char **argv)
{
    using namespace awb::test;
    const Entry *entry = nullptr;
    for (const Entry &e : registry())
        if (argc > 1 && e.name == argv[1])
            entry = &e;
    if (!entry) {
        std::fprintf(stderr, "usage: %s TEST [Qt Test options]; the tests:\n", argv[0]);
        for (const Entry &e : registry())
            std::fprintf(stderr, "  %s\n", e.name.c_str());
        return 2;
    }
    current() = entry->name;
    // The test sees its own arguments, as if it were an executable of its own.
    std::vector<char *> args{argv[0]};
    for (int i = 2; i < argc; ++i)
        args.push_back(argv[i]);
    args.push_back(nullptr);
    int n = int(args.size()) - 1;
    char **a = args.data();
    std::unique_ptr<QCoreApplication> app;
    switch (entry->application) {
    case Application::None: break;
    case Application::Core: app = std::make_unique<QCoreApplication>(n, a); break;
#if defined(QT_GUI_LIB)
    case Application::Gui: app = std::make_unique<QGuiApplication>(n, a); break;
#endif
#if defined(QT_WIDGETS_LIB)
    case Application::Widgets: app = std::make_unique<QApplication>(n, a); break;
#endif
    default: break; // the layer does not link it: no test asks for it (TestMain.h)
    }
    if (app)
        app->setAttribute(Qt::AA_Use96Dpi, true);
    return entry->run(n, a);
}
