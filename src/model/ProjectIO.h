#pragma once
// Project files (layer 2, model): JSON, UTF-8, extension .awb, described in docs/file-format.md.
// ProjectIO reads and writes the root and drives the items, which read and write their own
// fields through FieldReader. Reading never touches an open project: it builds new items, and
// a failure is one message naming the file, the item and the field, e.g.
//   demo.awb: item 2 ("Koch"): field "scheme.degree": expected an integer
// Saving goes through QSaveFile, so a failed or interrupted save never replaces a good file.

#include "model/Item.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QSet>

#include <climits>

namespace awb {

// A failure while reading: the field's path inside the item (or the root) and the message.
struct LoadError {
    QString field;
    QString message;
};

// One JSON object being read, and where it sits in its item ("scheme." for the scheme object).
// Every accessor either returns a well-typed, finite value or throws LoadError for that field.
// Keys asked for are remembered: the others are the object's unknown fields.
class FieldReader {
    Q_DECLARE_TR_FUNCTIONS(awb::FieldReader)
public:
    explicit FieldReader(QJsonObject object, QString path = {});

    const QJsonObject &object() const { return m_object; }
    bool has(const QString &key) const { return m_object.contains(key); }
    // Full path of a key ("scheme.degree"), as shown in messages.
    QString path(const QString &key) const { return m_path + key; }
    [[noreturn]] void fail(const QString &key, const QString &message) const;
    // Fails on `problem` (a value's own check), its field taken relative to `key`.
    void require(const MaybeProblem &problem, const QString &key = {}) const;

    // The raw value (undefined when absent); marks the key as read.
    QJsonValue value(const QString &key) const;
    // With a fallback the field is optional; without one it is required.
    QString string(const QString &key, const std::optional<QString> &fallback = {}) const;
    // One of `names` (returned as its index).
    int choice(const QString &key, const QStringList &names,
               std::optional<int> fallback = {}) const;
    qint64 integer(const QString &key, std::optional<qint64> fallback = {},
                   qint64 min = INT_MIN, qint64 max = INT_MAX) const;
    double number(const QString &key, std::optional<double> fallback = {}) const;
    std::vector<double> numbers(const QString &key,
                                const std::optional<std::vector<double>> &fallback = {}) const;
    // Points of `dim` (2 or 3) coordinates each.
    PointList points(const QString &key, const std::optional<PointList> &fallback = {},
                     int dim = 2) const;
    // A list of matrices, each an array of rows (rows of equal length).
    std::vector<Mat> matrices(const QString &key) const;
    // A nested object: nullopt when absent and optional; fails when absent and required.
    std::optional<FieldReader> object(const QString &key, bool required = false) const;
    // The fields never asked for.
    QJsonObject unread() const;

    // Element-level conversions; `where` is the element's full path.
    static double toNumber(const QJsonValue &v, const QString &where);
    // A number, or a string a user would type for one: an exact fraction "3/8", an expression
    // "(1 + sqrt(3))/8" (NumberFormat's parseNumber). Masks and matrices keep exact values so.
    static double toExactNumber(const QJsonValue &v, const QString &where);
    static Point toPoint(const QJsonValue &v, const QString &where, int dim = 2);

private:
    QJsonObject m_object;
    QString m_path;
    mutable QSet<QString> m_read;
};

// A project read from a file, not yet in any Project.
struct ProjectData {
    std::vector<std::unique_ptr<Item>> items;
    QJsonObject unknownFields;
};

class Project;

class ProjectIO {
    Q_DECLARE_TR_FUNCTIONS(awb::ProjectIO)
public:
    static constexpr int formatVersion = 1;
    // Larger files are refused before they are read.
    static constexpr qint64 maxFileBytes = 64ll * 1024 * 1024;
    static QString formatName() { return QStringLiteral("attractor-workbench"); }
    static QString fileSuffix() { return QStringLiteral("awb"); }

    // ---- writing
    static QJsonObject toJson(const Project &project);
    static QJsonObject itemToJson(const Item &item);
    // UTF-8, indented, keys sorted (QJsonObject): the same project gives the same bytes.
    static QByteArray toBytes(const QJsonObject &root);
    // Atomic write (QSaveFile). The message starts with the file name.
    static bool writeFile(const QString &fileName, const QByteArray &bytes, QString *error);

    // A copy of `item` without its children, in no project (through its JSON, so every field
    // is copied); nullptr with *error when the item does not read back.
    static std::unique_ptr<Item> copyItem(const Item &item, QString *error);

    // An item (with its children) read from its JSON object as a file holds it, checked as a
    // file is, in no project (a script's project.add(), an item replaced by its changed JSON);
    // nullptr with *error ("item \"Koch\": field \"scheme.degree\": expected an integer").
    static std::unique_ptr<Item> itemFromJson(const QJsonObject &json, QString *error);

    // ---- reading. On failure: false, and *error starts with `source` (the file name).
    static bool readFile(const QString &fileName, ProjectData *out, QString *error);
    static bool parse(const QByteArray &bytes, const QString &source, ProjectData *out,
                      QString *error);
    static bool parseRoot(const QJsonObject &root, const QString &source, ProjectData *out,
                          QString *error);
    // JSON text to an object; numbers that are not finite doubles (1e400, NaN, Infinity)
    // become markers that FieldReader reports with the field they are in.
    static bool parseJson(const QByteArray &bytes, const QString &source, QJsonObject *out,
                          QString *error);

    // ---- the common values, for the items' read()/write()
    // dim: 2 writes [x, y], 3 writes [x, y, z] (surface items).
    static QJsonArray pointsToJson(const PointList &points, int dim = 2);
    // A row of numbers (a map's b, a row of its A, a limit position) as a JSON array.
    static QJsonArray rowToJson(const RowVec &row);

private:
    // `checkAnimation`: also check that the item accepts its animation's values (which reads
    // a copy of the item, read without that check).
    static std::unique_ptr<Item> readItem(const QJsonValue &value, const QString &label,
                                          QSet<QString> &names, bool checkAnimation = true);
};

} // namespace awb
