#pragma once
// Figures that carry their parameters (layer 2, model: QtCore/QtGui). A PNG the application or
// the CLI exports holds, in PNG text chunks as flam3 keeps its flame parameters, the program's
// version and a complete project file holding the item drawn (and, for an eigenvalue plot, the
// item it analyses); an SVG holds the same project in its <metadata>. Opening such a PNG (File
// > Open, attractor-cli) restores the item exactly: it is read by the project loader, with all
// of its checks, as an untitled project, never saved over the picture.
#include <QByteArray>
#include <QList>
#include <QPair>
#include <QString>

namespace awb {

class Item;
class Project;

// PNG text chunk keys.
inline constexpr const char *kFigureProjectKey = "attractor-workbench:project";
inline constexpr const char *kFigureSoftwareKey = "Software";

// The project bytes (canonical .awb) holding `item` (and an eigenvalue plot's source).
QByteArray figureProjectBytes(const Project &project, const Item &item);
// The PNG text chunks (key, text): the software and version, and the project.
QList<QPair<QString, QString>> figurePngTexts(const QByteArray &projectBytes);
// The <metadata> element for an SVG (the project as CDATA), to insert after <svg ...>
// (render/FigureFile.h writes both).
QByteArray svgMetadataElement(const QByteArray &projectBytes);

// Whether the file is a PNG (by its signature, not its name).
bool isPngFile(const QString &fileName);
// The embedded project bytes of a PNG; empty with *error naming the problem when there are
// none (a PNG from elsewhere) or the file cannot be read.
QByteArray embeddedProject(const QString &pngFile, QString *error);

} // namespace awb
