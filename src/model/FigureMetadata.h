#pragma once
// Figures that carry their parameters (layer 2, model: QtCore/QtGui). A PNG the application or
// the CLI exports holds, in PNG text chunks as flam3 keeps its flame parameters, the program's
// version and a complete project file holding the item drawn (and, for an eigenvalue plot, the
// item it analyses); an SVG holds the same project in its <metadata>. Opening such a PNG or SVG
// (File > Open, attractor-cli) restores the item exactly: it is read by the project loader, with
// all of its checks, as an untitled project, never saved over the picture.
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

// The kinds of figure that can carry a project, told by their first bytes, not their name:
// the PNG signature, or XML text (after a byte order mark, white space, an XML declaration or
// comments) with an <svg element in its first 4 KB.
enum class FigureFormat { None, Png, Svg };
FigureFormat figureFormat(const QByteArray &head);
// The format of a file (None when it cannot be read).
FigureFormat figureFileFormat(const QString &fileName);

// The embedded project bytes of a PNG or SVG file; empty with *error naming the problem when
// there are none (a figure from elsewhere) or the file cannot be read.
QByteArray embeddedProject(const QString &figureFile, QString *error);
// The same for the figure's bytes; `fileName` only names the file in messages. A malformed
// figure (a truncated chunk, XML that does not parse, a project over 64 MB) is refused with a
// message (tests/fuzz: fuzz_png_project, fuzz_svg_project).
QByteArray embeddedProject(const QByteArray &figure, const QString &fileName, QString *error);

} // namespace awb
