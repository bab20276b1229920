#pragma once
// The frame log (layer 3): what the window showed and when, for measuring the application as a
// user sees it (bench/window). Off unless the environment variable AWB_FRAME_LOG names a file;
// then the views append one line per pointer event they act on and per frame they present,
// stamped with CLOCK_MONOTONIC in milliseconds, the clock every process of the machine shares,
// so that a driver that moves the pointer (XTest) can match its own times to the frames:
//
//   input  T VIEW press|move|release GX GY          pointer event (global screen pixels)
//   frame  T VIEW image=N final=0|1 handle=GX,GY|- shows=GX,GY|- [depth=K work=W ms=M]
//          a frame presented: N numbers the attractor pictures (a new N is a new picture),
//          handle is where the dragged handle was drawn, shows the pointer position whose
//          edit the picture shows (both "-" outside a drag); the picture's depth, its images
//          or samples and the milliseconds its pass took
//   handle T VIEW I GX GY                           a handle's centre (after a final frame)
//   area   T VIEW GX GY W H                         the view's rectangle on the screen
//   note   T TEXT                                   anything else (e.g. "ready")
//
// Writing costs a formatted line and a flush per event, only while the log is on.

#include <QPoint>
#include <QString>

namespace awb::framelog {

// Whether AWB_FRAME_LOG is set (read once).
bool enabled();
// Milliseconds of CLOCK_MONOTONIC (microsecond resolution).
double now();
// Appends "KIND T REST\n" (T = now()).
void write(const char *kind, const QString &rest);
// "GX,GY".
QString point(const QPoint &global);

} // namespace awb::framelog
