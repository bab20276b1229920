#include "model/ProjectIO.h"

#include "model/FileWriting.h"
#include "model/ItemRegistry.h"
#include "model/NumberFormat.h"
#include "model/Project.h"

#include <QFile>
#include <QJsonDocument>
#include <QRegularExpression>

#include <cmath>
#include <cstdlib>

namespace awb {

namespace {

// A number the JSON parser refused (1e400, NaN, Infinity) is replaced by a string with this
// prefix, so that the field it sits in can be named in the message.
const QString notFiniteMarker = QStringLiteral("\x1f" "awb-not-finite:");
constexpr double maxExactInteger = 9007199254740992.0; // 2^53

// An error inside item `label` (1-based, "2" or "2.1" for a child).
struct ItemError {
    QString label;
    QString name;
    LoadError error;
};

QString quoted(const QString &s) { return QLatin1Char('"') + s + QLatin1Char('"'); }

// Throws LoadError for the first number the JSON parser refused anywhere in `v` (a field no
// reader asked for, kept as unknown or ignored, must not carry NaN or 1e999 back out).
void rejectNotFinite(const QJsonValue &v, const QString &path)
{
    if (v.isString() && v.toString().startsWith(notFiniteMarker)) {
        FieldReader::toNumber(v, path); // throws with the number's own message
    } else if (v.isArray()) {
        const QJsonArray a = v.toArray();
        for (qsizetype i = 0; i < a.size(); ++i)
            rejectNotFinite(a[i], path + QStringLiteral("[%1]").arg(i + 1));
    } else if (v.isObject()) {
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it)
            rejectNotFinite(it.value(), path.isEmpty() ? it.key() : path + '.' + it.key());
    }
}

} // namespace

// ---- FieldReader ------------------------------------------------------------------------------

FieldReader::FieldReader(QJsonObject object, QString path)
    : m_object(std::move(object)), m_path(std::move(path))
{
}

void FieldReader::fail(const QString &key, const QString &message) const
{
    throw LoadError{path(key), message};
}

void FieldReader::require(const MaybeProblem &problem, const QString &key) const
{
    if (!problem)
        return;
    QString field = key;
    if (!problem->field.isEmpty())
        field = key.isEmpty() ? problem->field : key + QLatin1Char('.') + problem->field;
    fail(field, problem->message);
}

QJsonValue FieldReader::value(const QString &key) const
{
    m_read.insert(key);
    return m_object.value(key);
}

QString FieldReader::string(const QString &key, const std::optional<QString> &fallback) const
{
    const QJsonValue v = value(key);
    if (v.isUndefined() && fallback)
        return *fallback;
    if (v.isUndefined())
        fail(key, tr("missing"));
    if (!v.isString())
        fail(key, tr("expected a string"));
    return v.toString();
}

int FieldReader::choice(const QString &key, const QStringList &names,
                        std::optional<int> fallback) const
{
    const QString s = string(key, fallback ? std::optional<QString>(names.at(*fallback))
                                           : std::nullopt);
    const int index = int(names.indexOf(s));
    if (index < 0) {
        QStringList options;
        for (const QString &n : names)
            options << quoted(n);
        fail(key, tr("expected one of %1, got %2").arg(options.join(QLatin1String(", ")),
                                                       quoted(s)));
    }
    return index;
}

qint64 FieldReader::integer(const QString &key, std::optional<qint64> fallback, qint64 min,
                            qint64 max) const
{
    const QJsonValue v = value(key);
    if (v.isUndefined() && fallback)
        return *fallback;
    if (v.isUndefined())
        fail(key, tr("missing"));
    if (v.isString() && v.toString().startsWith(notFiniteMarker))
        toNumber(v, path(key)); // throws with the "not finite" message
    const double d = v.toDouble();
    if (!v.isDouble() || d != std::floor(d) || std::abs(d) > maxExactInteger)
        fail(key, tr("expected an integer"));
    if (d < double(min) || d > double(max))
        fail(key, tr("expected an integer between %1 and %2").arg(min).arg(max));
    return qint64(d);
}

double FieldReader::number(const QString &key, std::optional<double> fallback) const
{
    const QJsonValue v = value(key);
    if (v.isUndefined() && fallback)
        return *fallback;
    if (v.isUndefined())
        fail(key, tr("missing"));
    return toNumber(v, path(key));
}

std::vector<double> FieldReader::numbers(const QString &key,
                                         const std::optional<std::vector<double>> &fallback) const
{
    const QJsonValue v = value(key);
    if (v.isUndefined() && fallback)
        return *fallback;
    if (v.isUndefined())
        fail(key, tr("missing"));
    if (!v.isArray())
        fail(key, tr("expected an array of numbers"));
    std::vector<double> out;
    const QJsonArray a = v.toArray();
    for (qsizetype i = 0; i < a.size(); ++i)
        out.push_back(toNumber(a[i], path(key) + QStringLiteral("[%1]").arg(i + 1)));
    return out;
}

PointList FieldReader::points(const QString &key, const std::optional<PointList> &fallback,
                              int dim) const
{
    const QJsonValue v = value(key);
    if (v.isUndefined() && fallback)
        return *fallback;
    if (v.isUndefined())
        fail(key, tr("missing"));
    if (!v.isArray())
        fail(key, dim == 3 ? tr("expected an array of points [x, y, z]")
                           : tr("expected an array of points [x, y]"));
    PointList out;
    const QJsonArray a = v.toArray();
    out.reserve(std::size_t(a.size()));
    for (qsizetype i = 0; i < a.size(); ++i) {
        // A point of finite numbers is read without naming where it is (a mesh's 10^5
        // points); anything else is read by toPoint, which names the place of the problem.
        const QJsonValue p = a[i];
        const QJsonArray c = p.toArray();
        if (p.isArray() && c.size() == dim) {
            const double x = c[0].toDouble(NAN), y = c[1].toDouble(NAN),
                         z = dim == 3 ? c[2].toDouble(NAN) : 0.0;
            if (std::isfinite(x) && std::isfinite(y) && std::isfinite(z)) {
                out.push_back({x, y, z});
                continue;
            }
        }
        out.push_back(toPoint(p, path(key) + QStringLiteral("[%1]").arg(i + 1), dim));
    }
    return out;
}

std::vector<Mat> FieldReader::matrices(const QString &key) const
{
    const QJsonValue v = value(key);
    if (v.isUndefined())
        fail(key, tr("missing"));
    if (!v.isArray())
        fail(key, tr("expected an array of matrices"));
    std::vector<Mat> out;
    const QJsonArray list = v.toArray();
    for (qsizetype k = 0; k < list.size(); ++k) {
        const QString where = path(key) + QStringLiteral("[%1]").arg(k + 1);
        const QJsonArray rows = list[k].toArray();
        if (!list[k].isArray() || rows.isEmpty())
            throw LoadError{where, tr("expected a matrix: a non-empty array of rows")};
        const qsizetype cols = rows[0].toArray().size();
        Mat M(rows.size(), cols);
        for (qsizetype r = 0; r < rows.size(); ++r) {
            const QString rowWhere = where + QStringLiteral("[%1]").arg(r + 1);
            const QJsonArray row = rows[r].toArray();
            if (!rows[r].isArray() || row.isEmpty())
                throw LoadError{rowWhere, tr("expected a row: a non-empty array of numbers")};
            if (row.size() != cols)
                throw LoadError{rowWhere, tr("row %1 has %2 numbers, row 1 has %3")
                                              .arg(r + 1).arg(row.size()).arg(cols)};
            for (qsizetype c = 0; c < cols; ++c)
                M(r, c) = toExactNumber(row[c], rowWhere + QStringLiteral("[%1]").arg(c + 1));
        }
        out.push_back(std::move(M));
    }
    return out;
}

std::optional<FieldReader> FieldReader::object(const QString &key, bool required) const
{
    const QJsonValue v = value(key);
    if (v.isUndefined() && !required)
        return std::nullopt;
    if (v.isUndefined())
        fail(key, tr("missing"));
    if (!v.isObject())
        fail(key, tr("expected an object"));
    return FieldReader(v.toObject(), path(key) + QLatin1Char('.'));
}

QJsonObject FieldReader::unread() const
{
    QJsonObject out;
    for (auto it = m_object.begin(); it != m_object.end(); ++it)
        if (!m_read.contains(it.key()))
            out.insert(it.key(), it.value());
    return out;
}

double FieldReader::toNumber(const QJsonValue &v, const QString &where)
{
    if (v.isString() && v.toString().startsWith(notFiniteMarker)) {
        const QString token = v.toString().mid(notFiniteMarker.size());
        // 1e400, NaN, Infinity; else a literal like 01 or 2e-400 that is no double either.
        const double d = std::strtod(token.toLatin1().constData(), nullptr);
        throw LoadError{where, !std::isfinite(d)
                                   ? tr("%1 is not a finite number").arg(token)
                                   : tr("%1 cannot be read as a double-precision number")
                                         .arg(token)};
    }
    if (!v.isDouble())
        throw LoadError{where, tr("expected a number")};
    const double d = v.toDouble();
    if (!std::isfinite(d))
        throw LoadError{where, tr("expected a finite number")};
    return d;
}

double FieldReader::toExactNumber(const QJsonValue &v, const QString &where)
{
    if (!v.isString() || v.toString().startsWith(notFiniteMarker))
        return toNumber(v, where);
    if (const auto d = parseNumber(v.toString()))
        return *d;
    throw LoadError{where, tr("\"%1\" is not a number (a fraction such as \"3/8\" or an "
                              "expression such as \"(1 + sqrt(3))/8\" is)")
                               .arg(v.toString())};
}

Point FieldReader::toPoint(const QJsonValue &v, const QString &where, int dim)
{
    const QJsonArray a = v.toArray();
    if (!v.isArray() || a.size() != dim)
        throw LoadError{where, dim == 3 ? tr("expected a point [x, y, z]")
                                        : tr("expected a point [x, y]")};
    return {toNumber(a[0], where + QStringLiteral("[1]")),
            toNumber(a[1], where + QStringLiteral("[2]")),
            dim == 3 ? toNumber(a[2], where + QStringLiteral("[3]")) : 0.0};
}

// ---- writing ----------------------------------------------------------------------------------

QJsonObject ProjectIO::toJson(const Project &project)
{
    QJsonObject root = project.unknownFields();
    root["format"] = formatName();
    root["version"] = formatVersion;
    QJsonArray items;
    for (int i = 0; i < project.childCount(); ++i)
        items.append(itemToJson(*project.child(i)));
    root["items"] = items;
    return root;
}

QJsonObject ProjectIO::itemToJson(const Item &item)
{
    QJsonObject json;
    item.write(json);
    json["type"] = item.type();
    if (item.childCount() > 0) {
        QJsonArray children;
        for (int i = 0; i < item.childCount(); ++i)
            children.append(itemToJson(*item.child(i)));
        json["children"] = children;
    }
    return json;
}

QByteArray ProjectIO::toBytes(const QJsonObject &root)
{
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

bool ProjectIO::writeFile(const QString &fileName, const QByteArray &bytes, QString *error)
{
    QString reason;
    if (!writeWholeFile(fileName, bytes, &reason)) {
        if (error)
            *error = tr("%1: cannot save: %2").arg(fileName, reason);
        return false;
    }
    return true;
}

// ---- reading ----------------------------------------------------------------------------------

bool ProjectIO::readFile(const QString &fileName, ProjectData *out, QString *error)
{
    QFile file(fileName);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error)
            *error = tr("%1: cannot open: %2").arg(fileName, file.errorString());
        return false;
    }
    // A project of the largest nets and point sets the items accept is a few MB: a file many
    // times that size is not one, and reading it would only exhaust the memory.
    if (file.size() > maxFileBytes) {
        if (error)
            *error = tr("%1: the file is %2 MB; project files larger than %3 MB are refused "
                        "(a project is at most a few MB)")
                         .arg(fileName)
                         .arg(double(file.size()) / (1024.0 * 1024.0), 0, 'f', 1)
                         .arg(maxFileBytes / (1024 * 1024));
        return false;
    }
    const QByteArray bytes = file.readAll();
    if (file.error() != QFileDevice::NoError) {
        if (error)
            *error = tr("%1: cannot read: %2").arg(fileName, file.errorString());
        return false;
    }
    return parse(bytes, fileName, out, error);
}

bool ProjectIO::parse(const QByteArray &bytes, const QString &source, ProjectData *out,
                      QString *error)
{
    QJsonObject root;
    return parseJson(bytes, source, &root, error) && parseRoot(root, source, out, error);
}

bool ProjectIO::parseJson(const QByteArray &bytes, const QString &source, QJsonObject *out,
                          QString *error)
{
    auto isTokenChar = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
    };
    QString ignored;
    if (!error)
        error = &ignored;
    if (bytes.trimmed().isEmpty()) {
        *error = bytes.isEmpty() ? tr("%1: the file is empty").arg(source)
                                 : tr("%1: the file holds only white space").arg(source);
        return false;
    }
    // UTF-16 and UTF-32 text: a byte order mark, or JSON's first character ('{' or white
    // space) next to zero bytes.
    const QByteArray head = bytes.left(4);
    auto opening = [](char c) { return c == '{' || c == ' ' || c == '\n' || c == '\r' || c == '\t'; };
    const bool wide = head.startsWith("\xff\xfe") || head.startsWith("\xfe\xff")
                      || (head.size() >= 2 && head[0] == 0 && opening(head[1]))
                      || (head.size() >= 2 && head[1] == 0 && opening(head[0]))
                      || (head.size() == 4 && head[0] == 0 && head[1] == 0 && head[2] == 0);
    if (wide) {
        *error = tr("%1: the file is UTF-16 or UTF-32 text; project files are UTF-8 (save it "
                    "again as UTF-8)")
                     .arg(source);
        return false;
    }
    QByteArray text = bytes;
    for (int attempt = 0;; ++attempt) {
        QJsonParseError pe;
        const QJsonDocument doc = QJsonDocument::fromJson(text, &pe);
        if (pe.error == QJsonParseError::NoError) {
            if (!doc.isObject()) {
                *error = tr("%1: expected a JSON object at the top level").arg(source);
                return false;
            }
            *out = doc.object();
            return true;
        }
        // Qt points at or next to the offending literal: take the whole token.
        qsizetype begin = std::clamp<qsizetype>(pe.offset, 0, text.size() - 1);
        if (begin > 0 && !isTokenChar(text[begin]) && isTokenChar(text[begin - 1]))
            --begin;
        qsizetype end = begin;
        while (begin > 0 && isTokenChar(text[begin - 1]))
            --begin;
        while (end < text.size() && isTokenChar(text[end]))
            ++end;
        // Qt calls 1e999 and NaN illegal numbers, but nan or inf illegal values: a spelling of
        // a non-finite number is refused as one wherever it stands.
        static const QRegularExpression spelledNonFinite(
            QStringLiteral("^[+-]?(nan|inf|infinity)$"), QRegularExpression::CaseInsensitiveOption);
        const bool nonFinite =
            pe.error == QJsonParseError::IllegalNumber
            || spelledNonFinite.match(QString::fromLatin1(text.mid(begin, end - begin))).hasMatch();
        if (!nonFinite || end == begin || attempt >= 100) {
            const QByteArray before = text.left(pe.offset);
            const qsizetype line = before.count('\n') + 1;
            const qsizetype column = pe.offset - (before.lastIndexOf('\n') + 1) + 1;
            *error = tr("%1: not valid JSON: %2 at line %3, column %4")
                         .arg(source, pe.errorString()).arg(line).arg(column);
            return false;
        }
        const QByteArray token = text.mid(begin, end - begin);
        text.replace(begin, end - begin, "\"\\u001fawb-not-finite:" + token + "\"");
    }
}

bool ProjectIO::parseRoot(const QJsonObject &root, const QString &source, ProjectData *out,
                          QString *error)
{
    QString ignored;
    if (!error)
        error = &ignored;
    ProjectData data;
    try {
        const FieldReader r(root);
        const QJsonValue format = r.value("format");
        if (format.toString() != formatName())
            r.fail("format", tr("expected \"%1\": this is not an Attractor Workbench project")
                                 .arg(formatName()));
        const qint64 version = r.integer("version", std::nullopt, 1);
        if (version > formatVersion) {
            *error = tr("%1: the file has format version %2, written by a newer version of "
                        "Attractor Workbench; this version reads format version %3 only. "
                        "Please update the application.")
                         .arg(source).arg(version).arg(formatVersion);
            return false;
        }
        const QJsonValue items = r.value("items");
        if (!items.isArray())
            r.fail("items", items.isUndefined() ? tr("missing") : tr("expected an array"));
        QSet<QString> names;
        const QJsonArray list = items.toArray();
        for (qsizetype i = 0; i < list.size(); ++i)
            data.items.push_back(readItem(list[i], QString::number(i + 1), names));
        data.unknownFields = r.unread();
        // Every field the readers took is checked; the rest (unknown fields, kept or not)
        // here, with its path from the root ("items[2].extra").
        rejectNotFinite(root, {});
    } catch (const LoadError &e) {
        *error = tr("%1: field \"%2\": %3").arg(source, e.field, e.message);
        return false;
    } catch (const ItemError &e) {
        QString where = tr("item %1").arg(e.label);
        if (!e.name.isEmpty())
            where += QStringLiteral(" (%1)").arg(quoted(e.name));
        if (e.error.field.isEmpty())
            *error = QStringLiteral("%1: %2: %3").arg(source, where, e.error.message);
        else
            *error = tr("%1: %2: field \"%3\": %4")
                         .arg(source, where, e.error.field, e.error.message);
        return false;
    }
    *out = std::move(data);
    return true;
}

std::unique_ptr<Item> ProjectIO::copyItem(const Item &item, QString *error)
{
    QJsonObject json = itemToJson(item);
    json.remove(QStringLiteral("children"));
    QSet<QString> names;
    try {
        return readItem(json, QStringLiteral("1"), names, false);
    } catch (const ItemError &e) {
        if (error)
            *error = e.error.field.isEmpty()
                         ? e.error.message
                         : tr("field \"%1\": %2").arg(e.error.field, e.error.message);
    }
    return nullptr;
}

std::unique_ptr<Item> ProjectIO::itemFromJson(const QJsonObject &json, QString *error)
{
    QSet<QString> names;
    try {
        return readItem(json, QStringLiteral("1"), names);
    } catch (const ItemError &e) {
        if (error) {
            const QString where = e.name.isEmpty() ? tr("the item") : tr("item %1").arg(quoted(e.name));
            *error = e.error.field.isEmpty()
                         ? QStringLiteral("%1: %2").arg(where, e.error.message)
                         : tr("%1: field \"%2\": %3").arg(where, e.error.field, e.error.message);
        }
    }
    return nullptr;
}

std::unique_ptr<Item> ProjectIO::readItem(const QJsonValue &value, const QString &label,
                                          QSet<QString> &names, bool checkAnimation)
{
    if (!value.isObject())
        throw ItemError{label, {}, {{}, tr("expected an object")}};
    const FieldReader head(value.toObject());
    QString name;
    try {
        name = head.string("name");
        const QString type = head.string("type");
        std::unique_ptr<Item> item = ItemRegistry::instance().create(type);
        if (!item)
            head.fail("type", tr("unknown item type %1; this version knows %2")
                                  .arg(quoted(type), ItemRegistry::instance().types().join(", ")));
        const FieldReader r(item->upgradedFields(value.toObject()));
        r.string("name");
        r.string("type");
        item->read(r);
        item->checkLoaded(r);
        if (checkAnimation)
            if (const MaybeProblem p =
                    animationProblem(*item, item->animation(), &item->animation()))
                r.fail(p->field.isEmpty() ? QStringLiteral("animation")
                                          : QStringLiteral("animation.") + p->field,
                       p->message);
        if (names.contains(name))
            r.fail("name", tr("another item is already called %1").arg(quoted(name)));
        names.insert(name);
        const QJsonValue children = r.value("children");
        if (!children.isUndefined() && !children.isArray())
            r.fail("children", tr("expected an array of items"));
        const QJsonArray list = children.toArray();
        for (qsizetype i = 0; i < list.size(); ++i) {
            std::unique_ptr<Item> child = readItem(list[i], label + '.' + QString::number(i + 1),
                                                   names);
            child->m_parent = item.get();
            item->m_children.push_back(std::move(child));
        }
        item->m_unknownFields = r.unread();
        return item;
    } catch (const LoadError &e) {
        throw ItemError{label, name, e};
    }
}

// ---- common values ----------------------------------------------------------------------------

QJsonArray ProjectIO::rowToJson(const RowVec &row)
{
    QJsonArray a;
    for (Eigen::Index k = 0; k < row.size(); ++k)
        a.append(row(k));
    return a;
}

QJsonArray ProjectIO::pointsToJson(const PointList &points, int dim)
{
    QJsonArray out;
    for (const Point &p : points)
        out.append(dim == 3 ? QJsonArray{p.x, p.y, p.z} : QJsonArray{p.x, p.y});
    return out;
}

} // namespace awb
