#pragma once
// Shared by the GUI tests that drive the whole main window: settings in test mode, a window
// with recorded messages shown on the screen, and waiting for a finished attractor drawing.
#include "gui/app/MainWindow.h"
#include "gui/app/Messages.h"
#include "gui/views/AttractorRenderer.h"
#include "gui/views/AttractorView.h"

#include <QCoreApplication>
#include <QStandardPaths>
#include <QtTest>

#include "TestTime.h"

namespace awb::test {

// QSettings and the standard paths of the test, apart from the user's.
inline void useTestSettings(const char *application)
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("awb-test"));
    QCoreApplication::setApplicationName(QString::fromLatin1(application));
}

// A main window whose messages are recorded (no modal boxes), shown at `size` (empty: its own
// first size); `exposed` says whether it reached the screen.
struct ShownWindow {
    explicit ShownWindow(const QString &recoveryDirectory, QSize size = {})
        : window(&messages, recoveryDirectory)
    {
        if (!size.isEmpty())
            window.resize(size);
        window.show();
        exposed = QTest::qWaitForWindowExposed(&window);
    }
    RecordingMessages messages;
    MainWindow window;
    bool exposed = false;
};

// Waits for the final raster of the current drawing, with lit pixels.
inline bool waitForFinalImage(AttractorView *view)
{
    return QTest::qWaitFor([view] {
        return view->currentImageInfo().final && view->currentImageInfo().litPixels > 0
               && !view->renderer()->isBusy();
    }, awb::test::ms(30000));
}

} // namespace awb::test
