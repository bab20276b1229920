#pragma once
// How a test file declares its Qt Test object. Every tests/<layer>/test_*.cpp stays a CTest test
// of its own (<layer>_test_<name>), but the files of a layer link into one executable,
// <layer>_tests, whose first argument names the test to run (`gui_tests test_main_window
// -functions`): one link per layer instead of one per file, which was a third of the build.
//
//   AWB_TEST_MAIN(Class)          QTEST_MAIN's application: QApplication where the layer links
//                                 Qt Widgets, QGuiApplication where it links Qt GUI, else
//                                 QCoreApplication
//   AWB_TEST_GUILESS_MAIN(Class)  QCoreApplication
//   AWB_TEST_APPLESS_MAIN(Class)  none
//   AWB_TEST_CUSTOM_MAIN(fn)      int fn(int argc, char **argv) makes its own application
// A test that starts itself as a child process passes its arguments through childArguments().

#include <QStringList>
#include <QtTest>

namespace awb::test {

enum class Application { None, Core, Gui, Widgets };
// Registers the test of source file `file` (its base name is the test's name). Returns 0.
int registerTest(const char *file, Application application, int (*run)(int, char **));
// The arguments that start this very test in a child process of applicationFilePath().
QStringList childArguments(const QStringList &arguments);

} // namespace awb::test

#define AWB_TEST_ENTRY_(TestObject, application)                                              \
    namespace {                                                                               \
    int awbRunTest(int argc, char **argv)                                                     \
    {                                                                                         \
        TestObject tc;                                                                        \
        QTEST_SET_MAIN_SOURCE_PATH                                                            \
        return QTest::qExec(&tc, argc, argv);                                                 \
    }                                                                                         \
    [[maybe_unused]] const int awbRegistered =                                                \
        awb::test::registerTest(__FILE__, application, &awbRunTest);                          \
    }

#if defined(QT_WIDGETS_LIB)
#define AWB_TEST_MAIN(TestObject) AWB_TEST_ENTRY_(TestObject, awb::test::Application::Widgets)
#elif defined(QT_GUI_LIB)
#define AWB_TEST_MAIN(TestObject) AWB_TEST_ENTRY_(TestObject, awb::test::Application::Gui)
#else
#define AWB_TEST_MAIN(TestObject) AWB_TEST_ENTRY_(TestObject, awb::test::Application::Core)
#endif
#define AWB_TEST_GUILESS_MAIN(TestObject) AWB_TEST_ENTRY_(TestObject, awb::test::Application::Core)
#define AWB_TEST_APPLESS_MAIN(TestObject) AWB_TEST_ENTRY_(TestObject, awb::test::Application::None)
#define AWB_TEST_CUSTOM_MAIN(function)                                                        \
    namespace {                                                                               \
    [[maybe_unused]] const int awbRegistered =                                                \
        awb::test::registerTest(__FILE__, awb::test::Application::None, &function);           \
    }
