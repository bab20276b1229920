// Bad input, answered (issue 14): every row of docs/bad-input.md is run here. A row names an
// input (made here, by its id, in a fresh folder), the attractor-cli command run on it in that
// folder, the exit status and the answer: the first line of standard error (or of standard
// output when nothing went to standard error). The table is the documentation: a message
// changed in the code fails this test until the table says the same, and every input made here
// must have its row. Files an input marks as kept must come out of the command unchanged (a
// failed write never truncates an existing file).

#include "TestPaths.h"
#include "CliRunner.h"

#include <QBuffer>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include "TestMain.h"

#include "TestTime.h"

#include <functional>
#include <map>

#include <unistd.h>

using namespace awb::test;

namespace {

struct Row {
    QString id, command, answer;
    int exit = 0;
    int line = 0;
};

QByteArray readBytes(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeBytes(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

// The rows of the table: | `id` | what | `command` | exit | `answer` |
QList<Row> tableRows(QString *error)
{
    QFile f(awb::test::sourceDir() + "/docs/bad-input.md");
    if (!f.open(QIODevice::ReadOnly)) {
        *error = "cannot read docs/bad-input.md";
        return {};
    }
    QList<Row> rows;
    int line = 0;
    static const QRegularExpression code("^`(.*)`$");
    while (!f.atEnd()) {
        ++line;
        const QString text = QString::fromUtf8(f.readLine()).trimmed();
        if (!text.startsWith("| `"))
            continue;
        // Cells are split at " | "; an answer holding " | " is not allowed in the table.
        QStringList cells = text.mid(1, text.size() - 2).split(" | ");
        for (QString &c : cells)
            c = c.trimmed();
        if (cells.size() != 5) {
            *error = QString("docs/bad-input.md:%1: expected 5 cells, got %2").arg(line).arg(cells.size());
            return {};
        }
        Row r;
        r.line = line;
        r.id = code.match(cells[0]).captured(1);
        r.command = code.match(cells[2]).captured(1);
        bool ok = false;
        r.exit = cells[3].toInt(&ok);
        r.answer = code.match(cells[4]).captured(1).replace("\\|", "|");
        if (r.id.isEmpty() || r.command.isEmpty() || !ok) {
            *error = QString("docs/bad-input.md:%1: a row is | `id` | what | `command` | exit | "
                             "`answer` |").arg(line);
            return {};
        }
        rows << r;
    }
    return rows;
}

// ---- the inputs ---------------------------------------------------------------------------

QByteArray example(const QString &name)
{
    return readBytes(examplePath(name));
}

QJsonObject exampleJson(const QString &name)
{
    return QJsonDocument::fromJson(example(name)).object();
}

QByteArray toBytes(const QJsonObject &o)
{
    return QJsonDocument(o).toJson(QJsonDocument::Indented);
}

// The first item of 000 Fig. 2 (a cubic B-spline on five points) changed by `edit`, without
// its eigenvalue-plot child.
QByteArray curveWith(const std::function<void(QJsonObject &)> &edit)
{
    QJsonObject root = exampleJson("000-fig02-cubic-bspline-from-point.awb");
    QJsonArray items = root["items"].toArray();
    QJsonObject item = items[0].toObject();
    item.remove("children");
    edit(item);
    items = QJsonArray{item};
    root["items"] = items;
    return toBytes(root);
}

QJsonArray points(std::initializer_list<std::pair<double, double>> list)
{
    QJsonArray a;
    for (const auto &[x, y] : list)
        a.append(QJsonArray{x, y});
    return a;
}

// Replaces the first occurrence of `from` in the bytes of 000 Fig. 2 by `to`.
QByteArray fig2Replacing(const QByteArray &from, const QByteArray &to)
{
    QByteArray bytes = example("000-fig02-cubic-bspline-from-point.awb");
    const qsizetype at = bytes.indexOf(from);
    if (at >= 0)
        bytes.replace(at, from.size(), to);
    return bytes;
}

QByteArray nonFiniteControlPoint(const QByteArray &spelling)
{
    // The second control point's x (1.2 in the example).
    return fig2Replacing("1.2,", spelling + ",");
}

using Maker = std::function<bool(QDir &dir, QStringList *kept)>;

bool file(QDir &dir, const QString &name, const QByteArray &bytes)
{
    return writeBytes(dir.filePath(name), bytes);
}

// Copies an example into the folder (commands name the short copy).
bool copyExample(QDir &dir, const QString &example, const QString &as)
{
    return file(dir, as, readBytes(examplePath(example)));
}

const std::map<QString, Maker> &inputs()
{
    static const std::map<QString, Maker> m = {
        // ---- files that are not projects
        {"empty", [](QDir &d, QStringList *) { return file(d, "empty.awb", {}); }},
        {"blank", [](QDir &d, QStringList *) { return file(d, "blank.awb", " \n\t\n"); }},
        {"truncated", [](QDir &d, QStringList *) {
             return file(d, "truncated.awb", example("000-fig02-cubic-bspline-from-point.awb").left(100));
         }},
        {"binary", [](QDir &d, QStringList *) {
             QByteArray b("\x7f" "ELF\x02\x01\x01", 7);
             for (int i = 0; i < 200; ++i)
                 b.append(char((i * 37 + 11) % 256));
             return file(d, "binary.awb", b);
         }},
        {"picture", [](QDir &d, QStringList *) {
             // A PNG that is not one of our figures (no project chunk).
             QByteArray png;
             {
                 QImage img(8, 8, QImage::Format_RGB32);
                 img.fill(Qt::red);
                 QBuffer buffer(&png);
                 buffer.open(QIODevice::WriteOnly);
                 img.save(&buffer, "PNG");
             }
             return file(d, "photo.png", png);
         }},
        {"utf8-bom", [](QDir &d, QStringList *) {
             return file(d, "bom.awb", "\xef\xbb\xbf" + example("000-fig02-cubic-bspline-from-point.awb"));
         }},
        {"utf16-bom", [](QDir &d, QStringList *) {
             const QString text = QString::fromUtf8(example("000-fig02-cubic-bspline-from-point.awb"));
             QByteArray b("\xff\xfe", 2);
             b.append(reinterpret_cast<const char *>(text.utf16()), text.size() * 2);
             return file(d, "utf16.awb", b);
         }},
        {"utf16-no-bom", [](QDir &d, QStringList *) {
             const QString text = QString::fromUtf8(example("000-fig02-cubic-bspline-from-point.awb"));
             return file(d, "utf16.awb", QByteArray(reinterpret_cast<const char *>(text.utf16()), text.size() * 2));
         }},
        {"nested", [](QDir &d, QStringList *) {
             return file(d, "nested.awb", QByteArray(10000, '[') + QByteArray(10000, ']'));
         }},
        {"huge", [](QDir &d, QStringList *) {
             // 200 MB (sparse: the size is what is refused, before any byte is read).
             QFile f(d.filePath("huge.awb"));
             return f.open(QIODevice::WriteOnly) && f.write("{") == 1
                    && f.resize(200ll * 1024 * 1024);
         }},
        // ---- mesh files (issue 30)
        {"mesh-index", [](QDir &d, QStringList *) {
             return file(d, "range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
         }},
        {"mesh-non-manifold", [](QDir &d, QStringList *) {
             return file(d, "fin.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\n"
                                       "f 1 2 3\nf 2 4 3\nf 3 2 5\n");
         }},
        {"mesh-orientation", [](QDir &d, QStringList *) {
             return file(d, "flip.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 3 4\n");
         }},
        {"mesh-loop-quads", [](QDir &d, QStringList *) {
             return file(d, "quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
         }},
        // ---- other tools' files (issue 34)
        {"ifs-row-length", [](QDir &d, QStringList *) {
             return file(d, "short.ifs", "square {\n  .5 0 0 .5 0 0\n}\n");
         }},
        {"ifs-not-a-number", [](QDir &d, QStringList *) {
             return file(d, "words.ifs", "half { .5 0 0 .5 0 0 .5  .5 0 0 .5 .5 0 .5 }\n"
                                         "; the next entry has a typo\n"
                                         "bad { .5 0 0 .5 x 0 .5 }\n");
         }},
        {"ifs-too-many-maps", [](QDir &d, QStringList *) {
             QByteArray text = "many {\n";
             for (int r = 0; r < 1000; ++r)
                 text += ".01 0 0 .01 0 0 1\n";
             return file(d, "many.ifs", text + "}\n");
         }},
        {"ifs-six-a-line", [](QDir &d, QStringList *) {
             QByteArray text = "sixes {\n";
             for (int r = 0; r < 7; ++r)
                 text += ".5 0 0 .5 0 0\n";
             return file(d, "sixes.ifs", text + "}\n");
         }},
        {"flame-symmetry-bomb", [](QDir &d, QStringList *) {
             return file(d, "bomb.flame", "<flame name=\"b\"><symmetry kind=\"-2147483648\"/>"
                                          "<xform weight=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>"
                                          "</flame>\n");
         }},
        {"flame-coefs", [](QDir &d, QStringList *) {
             return file(d, "short.flame", "<flame name=\"cut\">\n"
                                           "  <xform weight=\"1\" linear=\"1\" "
                                           "coefs=\"0.5 0 0 0.5 0\"/>\n</flame>\n");
         }},
        {"flame-xml", [](QDir &d, QStringList *) {
             return file(d, "unclosed.flame", "<flames>\n<flame name=\"a\">\n"
                                              "<xform coefs=\"1 0 0 1 0 0\">\n</flame>\n");
         }},
        {"flame-foreign-variation", [](QDir &d, QStringList *) {
             return file(d, "swirl.flame",
                         "<flame name=\"s\">\n"
                         "  <xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>\n"
                         "  <xform weight=\"1\" swirl=\"0.7\" spherical3D=\"0.3\" "
                         "coefs=\"0.5 0 0 0.5 1 0\"/>\n"
                         "</flame>\n");
         }},
        // ---- numbers
        {"million-points", [](QDir &d, QStringList *) {
             QByteArray pts;
             pts.reserve(20'000'000);
             for (int i = 0; i < 1'000'000; ++i)
                 pts += "[" + QByteArray::number(i * 1e-3) + ", " + QByteArray::number((i % 7) * 0.1) + "],";
             pts.chop(1);
             QByteArray bytes = curveWith([](QJsonObject &item) { item["control_points"] = "@"; });
             bytes.replace("\"@\"", "[" + pts + "]");
             return file(d, "million.awb", bytes);
         }},
        {"1e308", [](QDir &d, QStringList *) {
             return file(d, "huge-coordinates.awb", curveWith([](QJsonObject &item) {
                 item["control_points"] = points({{0, 0}, {1e308, 2.6}, {3.2, 3}, {4.6, 0.6}, {6.2, 1.8}});
             }));
         }},
        {"negative-zero", [](QDir &d, QStringList *) {
             return file(d, "zero.awb", fig2Replacing("1.2,", "-0,"));
         }},
        {"NaN", [](QDir &d, QStringList *) { return file(d, "nan.awb", nonFiniteControlPoint("NaN")); }},
        {"nan", [](QDir &d, QStringList *) { return file(d, "nan.awb", nonFiniteControlPoint("nan")); }},
        {"-Infinity", [](QDir &d, QStringList *) { return file(d, "inf.awb", nonFiniteControlPoint("-Infinity")); }},
        {"inf", [](QDir &d, QStringList *) { return file(d, "inf.awb", nonFiniteControlPoint("inf")); }},
        {"1e999", [](QDir &d, QStringList *) { return file(d, "inf.awb", nonFiniteControlPoint("1e999")); }},
        {"NaN-unknown-field", [](QDir &d, QStringList *) {
             return file(d, "nan.awb", fig2Replacing("\"format\"", "\"later\": NaN, \"format\""));
         }},
        // ---- fields
        {"wrong-type-name", [](QDir &d, QStringList *) {
             return file(d, "types.awb", curveWith([](QJsonObject &item) { item["name"] = 5; }));
         }},
        {"wrong-type-points", [](QDir &d, QStringList *) {
             return file(d, "types.awb", curveWith([](QJsonObject &item) { item["control_points"] = "P"; }));
         }},
        {"wrong-type-depth", [](QDir &d, QStringList *) {
             return file(d, "types.awb", curveWith([](QJsonObject &item) {
                 QJsonObject a = item["algorithm"].toObject();
                 a["depth"] = "deep";
                 item["algorithm"] = a;
             }));
         }},
        {"wrong-type-scheme", [](QDir &d, QStringList *) {
             return file(d, "types.awb", curveWith([](QJsonObject &item) { item["scheme"] = QJsonArray{3}; }));
         }},
        {"duplicate-names", [](QDir &d, QStringList *) {
             QJsonObject root = exampleJson("000-fig05-four-point-from-segment.awb");
             QJsonArray items = root["items"].toArray();
             QJsonObject twin = items[0].toObject();
             twin.remove("children");
             items.append(twin);
             root["items"] = items;
             return file(d, "twins.awb", toBytes(root));
         }},
        {"newer-version", [](QDir &d, QStringList *) {
             QJsonObject root = exampleJson("000-fig05-four-point-from-segment.awb");
             root["version"] = 2;
             return file(d, "future.awb", toBytes(root));
         }},
        {"version-zero", [](QDir &d, QStringList *) {
             QJsonObject root = exampleJson("000-fig05-four-point-from-segment.awb");
             root["version"] = 0;
             return file(d, "zero.awb", toBytes(root));
         }},
        {"unknown-type", [](QDir &d, QStringList *) {
             return file(d, "teapot.awb", curveWith([](QJsonObject &item) { item["type"] = "teapot"; }));
         }},
        // ---- mathematics
        {"singular-lifting", [](QDir &d, QStringList *) {
             return file(d, "collinear.awb", curveWith([](QJsonObject &item) {
                 item["control_points"] = points({{0, 0}, {1.2, 2.6}, {2, 2}, {3, 3}, {4, 4}});
             }));
         }},
        {"near-singular-lifting", [](QDir &d, QStringList *) {
             return file(d, "almost.awb", curveWith([](QJsonObject &item) {
                 item["control_points"] = points({{0, 0}, {1.2, 2.6}, {2, 2}, {3, 3}, {4, 4 + 1e-10}});
             }));
         }},
        {"non-contractive", [](QDir &d, QStringList *) {
             // Own matrices: S_1 is the identity, so f_1 fixes every point.
             return file(d, "identity.awb", curveWith([](QJsonObject &item) {
                 item["control_points"] = points({{0, 0}, {1, 2}, {3, 1}});
                 item["scheme"] = QJsonObject{
                     {"kind", "matrices"},
                     {"matrices", QJsonArray{QJsonArray{QJsonArray{1, 0, 0}, QJsonArray{0, 1, 0}, QJsonArray{0, 0, 1}},
                                             QJsonArray{QJsonArray{0.5, 0.5, 0}, QJsonArray{0, 0.5, 0.5}, QJsonArray{0, 0, 1}}}}};
             }));
         }},
        {"four-point-omega", [](QDir &d, QStringList *) {
             return file(d, "omega.awb", curveWith([](QJsonObject &item) {
                 item["control_points"] = points({{0, 0}, {1, 2}, {2, 2.5}, {3, 0.5}, {4, 0}, {5, 2}, {6, 1}});
                 item["scheme"] = QJsonObject{{"kind", "four-point"}, {"omega", 0.75}};
             }));
         }},
        {"depth-in-file", [](QDir &d, QStringList *) {
             return file(d, "deep.awb", curveWith([](QJsonObject &item) {
                 QJsonObject a = item["algorithm"].toObject();
                 a["depth"] = 1'000'000'000;
                 item["algorithm"] = a;
             }));
         }},
        // ---- command lines
        {"depth-option", [](QDir &d, QStringList *) { return copyExample(d, "000-fig11-sierpinski-with-control-points.awb", "fig11.awb"); }},
        {"samples-option", [](QDir &d, QStringList *) { return copyExample(d, "000-fig11-sierpinski-with-control-points.awb", "fig11.awb"); }},
        {"raw-density-bits", [](QDir &d, QStringList *) { return copyExample(d, "000-fig11-sierpinski-with-control-points.awb", "fig11.awb"); }},
        {"size-option", [](QDir &d, QStringList *) { return copyExample(d, "000-fig11-sierpinski-with-control-points.awb", "fig11.awb"); }},
        {"bad-address", [](QDir &d, QStringList *) { return copyExample(d, "000-fig11-sierpinski-with-control-points.awb", "fig11.awb"); }},
        {"bad-start", [](QDir &d, QStringList *) { return copyExample(d, "000-fig11-sierpinski-with-control-points.awb", "fig11.awb"); }},
        {"missing-item", [](QDir &d, QStringList *) { return copyExample(d, "000-fig11-sierpinski-with-control-points.awb", "fig11.awb"); }},
        // ---- outputs that cannot be written
        {"dev-full", [](QDir &d, QStringList *) { return copyExample(d, "000-fig11-sierpinski-with-control-points.awb", "fig11.awb"); }},
        {"missing-folder", [](QDir &d, QStringList *) { return copyExample(d, "000-fig11-sierpinski-with-control-points.awb", "fig11.awb"); }},
        {"read-only-file", [](QDir &d, QStringList *kept) {
             *kept << "figure.png";
             return copyExample(d, "000-fig11-sierpinski-with-control-points.awb", "fig11.awb")
                    && file(d, "figure.png", "an earlier figure")
                    && QFile::setPermissions(d.filePath("figure.png"), QFile::ReadOwner | QFile::ReadGroup | QFile::ReadOther);
         }},
        {"a-folder", [](QDir &d, QStringList *) {
             return copyExample(d, "000-fig11-sierpinski-with-control-points.awb", "fig11.awb") && d.mkdir("figures");
         }},
        {"file-size-limit", [](QDir &d, QStringList *kept) {
             *kept << "figure.png";
             return copyExample(d, "000-fig11-sierpinski-with-control-points.awb", "fig11.awb")
                    && file(d, "figure.png", "an earlier figure");
         }},
        {"project-size-limit", [](QDir &d, QStringList *kept) {
             *kept << "fig11.awb";
             return copyExample(d, "000-fig11-sierpinski-with-control-points.awb", "fig11.awb");
         }},
    };
    return m;
}

} // namespace

class TestBadInput : public QObject {
    Q_OBJECT
private slots:
    void everyInputHasItsRow()
    {
        QString error;
        const QList<Row> rows = tableRows(&error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QSet<QString> ids;
        for (const Row &r : rows) {
            QVERIFY2(!ids.contains(r.id), qPrintable("two rows for " + r.id));
            ids << r.id;
            QVERIFY2(inputs().count(r.id), qPrintable(QString("docs/bad-input.md:%1: no input "
                                                              "named %2 in this test").arg(r.line).arg(r.id)));
        }
        for (const auto &[id, make] : inputs())
            QVERIFY2(ids.contains(id), qPrintable("docs/bad-input.md has no row for " + id));
    }

    void rows_data()
    {
        QTest::addColumn<QString>("id");
        QTest::addColumn<QString>("command");
        QTest::addColumn<int>("exit");
        QTest::addColumn<QString>("answer");
        QString error;
        for (const Row &r : tableRows(&error))
            QTest::newRow(qPrintable(r.id)) << r.id << r.command << r.exit << r.answer;
    }

    void rows()
    {
        QFETCH(QString, id);
        QFETCH(QString, command);
        QFETCH(int, exit);
        QFETCH(QString, answer);
        QTemporaryDir tmp;
        QVERIFY(tmp.isValid());
        QDir dir(tmp.path());
        QStringList kept;
        QVERIFY2(inputs().count(id) && inputs().at(id)(dir, &kept), qPrintable("cannot make " + id));
        std::map<QString, QByteArray> before;
        for (const QString &k : kept)
            before[k] = readBytes(dir.filePath(k));

        // The command as a user types it: `attractor-cli ...`, maybe behind prlimit.
        QStringList words = QProcess::splitCommand(command);
        const int at = int(words.indexOf("attractor-cli"));
        QVERIFY2(at >= 0, qPrintable("the command does not run attractor-cli: " + command));
        words[at] = cliPath();
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        if (::geteuid() == 0 && id == "read-only-file") {
            // Root writes any file: the user of the row is nobody.
            QVERIFY(QFile::setPermissions(tmp.path(), QFile::Permissions(0x7777)));
            words = QStringList{"setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"} + words;
            env.insert("USER", "nobody");
            env.insert("HOME", tmp.path());
        }
        QProcess p;
        p.setWorkingDirectory(tmp.path());
        p.setProcessEnvironment(env);
        p.start(words.takeFirst(), words);
        QVERIFY2(p.waitForFinished(awb::test::ms(120000)), qPrintable(command + ": no answer within 120 s"));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        const QString err = QString::fromUtf8(p.readAllStandardError()).trimmed();
        const QString out = QString::fromUtf8(p.readAllStandardOutput()).trimmed();
        const QString first = (err.isEmpty() ? out : err).section('\n', 0, 0);
        // On a mismatch, the row the table would need.
        const QString row = QString("| `%1` | … | `%2` | %3 | `%4` |")
                                .arg(id, command).arg(p.exitCode()).arg(first);
        QVERIFY2(first == answer && p.exitCode() == exit,
                 qPrintable(QString("%1\n   got: exit %2: %3\n  want: exit %4: %5\n  row: %6")
                                .arg(command).arg(p.exitCode()).arg(first).arg(exit).arg(answer, row)));
        for (const auto &[name, bytes] : before)
            QVERIFY2(readBytes(dir.filePath(name)) == bytes, qPrintable(name + " changed"));
    }
};

AWB_TEST_GUILESS_MAIN(TestBadInput)
#include "test_bad_input.moc"
