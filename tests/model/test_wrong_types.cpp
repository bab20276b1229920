// Wrong types in every field (issue 14): for every bundled example, every field of its JSON
// (items, their children, nested objects and arrays, the root) is given a value of each wrong
// type in turn. The loader must either refuse the file with a message that names the field,
// or - for a field it does not read (kept and written back for a later version) - keep the
// value exactly. A known field must never take a wrong type silently (coerced or dropped).

#include "TestPaths.h"
#include "model/Project.h"
#include "model/ProjectIO.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include "TestMain.h"

#include <functional>

using namespace awb;

namespace {

// A path into a JSON document: object keys and array indices.
using Path = QList<QVariant>;

QString pathText(const Path &path)
{
    QString s;
    for (const QVariant &p : path)
        s += p.typeId() == QMetaType::Int ? QString("[%1]").arg(p.toInt() + 1)
                                          : (s.isEmpty() ? "" : ".") + p.toString();
    return s;
}

QJsonValue at(const QJsonValue &v, const Path &path, int from = 0)
{
    if (from == path.size())
        return v;
    const QVariant &p = path[from];
    return at(p.typeId() == QMetaType::Int ? v.toArray().at(p.toInt()) : v.toObject().value(p.toString()),
              path, from + 1);
}

QJsonValue replaced(const QJsonValue &v, const Path &path, const QJsonValue &with, int from = 0)
{
    if (from == path.size())
        return with;
    const QVariant &p = path[from];
    if (p.typeId() == QMetaType::Int) {
        QJsonArray a = v.toArray();
        a[p.toInt()] = replaced(a.at(p.toInt()), path, with, from + 1);
        return a;
    }
    QJsonObject o = v.toObject();
    o[p.toString()] = replaced(o.value(p.toString()), path, with, from + 1);
    return o;
}

// Every path below `v` to an object field or an array element (the first 3 elements of an
// array: the rest are alike).
void collect(const QJsonValue &v, Path &path, QList<Path> &out)
{
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it) {
            path << it.key();
            out << path;
            collect(it.value(), path, out);
            path.removeLast();
        }
    } else if (v.isArray()) {
        const QJsonArray a = v.toArray();
        for (int i = 0; i < std::min<qsizetype>(a.size(), 3); ++i) {
            path << i;
            out << path;
            collect(a.at(i), path, out);
            path.removeLast();
        }
    }
}

// Values of every type but the field's own.
QList<QJsonValue> wrongValues(const QJsonValue &v)
{
    QList<QJsonValue> all = {QJsonValue("x"), QJsonValue(7.5), QJsonValue(true), QJsonValue(),
                             QJsonArray{1, "a"}, QJsonObject{{"k", 1}}};
    QList<QJsonValue> out;
    for (const QJsonValue &w : all)
        if (w.type() != v.type() && !(v.isDouble() && w.isDouble()))
            out << w;
    return out;
}

} // namespace

class TestWrongTypes : public QObject {
    Q_OBJECT
private slots:
    void everyFieldRefusesEveryWrongType()
    {
        const QStringList files = QDir(awb::test::sourceDir() + "/examples").entryList({"*.awb"});
        QVERIFY(files.size() > 20);
        int cases = 0, refused = 0, kept = 0;
        QStringList failures;
        for (const QString &name : files) {
            QFile f(awb::test::sourceDir() + "/examples/" + name);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QJsonObject root = QJsonDocument::fromJson(f.readAll()).object();
            QList<Path> paths;
            Path path;
            collect(root, path, paths);
            for (const Path &p : paths) {
                const QJsonValue original = at(root, p);
                for (const QJsonValue &wrong : wrongValues(original)) {
                    ++cases;
                    const QJsonObject mutated = replaced(root, p, wrong).toObject();
                    const QByteArray bytes = QJsonDocument(mutated).toJson();
                    ProjectData data;
                    QString error;
                    const QString where = name + ": " + pathText(p) + " = "
                                          + QString::fromUtf8(QJsonDocument(QJsonArray{wrong}).toJson(QJsonDocument::Compact));
                    if (!ProjectIO::parse(bytes, name, &data, &error)) {
                        ++refused;
                        // The message names the field (or, for an array element, its array).
                        Path named = p;
                        while (!named.isEmpty() && named.last().typeId() == QMetaType::Int)
                            named.removeLast();
                        const QString key = named.isEmpty() ? QString() : named.last().toString();
                        // An element of items or children is an item: named by its number.
                        const bool itemItself = !p.isEmpty() && p.last().typeId() == QMetaType::Int
                                                && (key == "items" || key == "children");
                        if (itemItself ? !error.contains("item ") : !key.isEmpty() && !error.contains(key))
                            failures << where + ": refused without naming the field: " + error;
                        continue;
                    }
                    // Accepted: only a field the loader does not read, kept as it was.
                    Project project;
                    project.adopt(std::move(data), name, false);
                    const QJsonObject saved = QJsonDocument::fromJson(project.serialize()).object();
                    if (at(saved, p) != wrong)
                        failures << where + ": accepted and not kept (a known field took a "
                                            "wrong type: now " +
                                        QString::fromUtf8(QJsonDocument(QJsonArray{at(saved, p)}).toJson(QJsonDocument::Compact)) + ")";
                    else
                        ++kept;
                }
            }
        }
        qInfo("%d wrong values in %d files: %d refused, %d kept in fields the loader does not read",
              cases, int(files.size()), refused, kept);
        QVERIFY2(failures.isEmpty(), qPrintable(QString("%1 cases:\n").arg(failures.size())
                                                + failures.mid(0, 40).join('\n')));
    }
};

AWB_TEST_GUILESS_MAIN(TestWrongTypes)
#include "test_wrong_types.moc"
