// Mesh files (issue 30, the core): OBJ, OFF and PLY read with the file's own vertex numbering,
// face order and polygons; PLY in its three encodings with properties and elements to skip;
// writeObj read back to the same doubles; every refusal named with its place.

#include "core/mesh/MeshFiles.h"

#include <QtTest>

#include "TestMain.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

using namespace awb;

namespace {

// A cube of edge 3.75 written in a deliberately unsorted vertex order (corner c = x + 2y + 4z
// of the unit cube is file vertex {1, 6, 3, 4, 5, 2, 7, 0}[c]), faces turned outward and begun
// at different corners.
Mesh cube()
{
    Mesh m;
    m.vertices.resize(8, 3);
    const int corner[8] = {7, 0, 5, 2, 3, 4, 1, 6};
    for (int v = 0; v < 8; ++v)
        for (int axis = 0; axis < 3; ++axis)
            m.vertices(v, axis) = corner[v] >> axis & 1 ? 2.25 : -1.5;
    m.faces = {{4, 6, 1, 3}, {5, 2, 0, 7}, {1, 6, 2, 5}, {3, 7, 0, 4}, {1, 5, 7, 3}, {6, 4, 0, 2}};
    return m;
}

const char *const cubeObj = R"(# a cube, vertices not sorted
mtllib cube.mtl
o cube
v 2.25 2.25 2.25
v -1.5 -1.5 -1.5
v 2.25 -1.5 2.25
v -1.5 2.25 -1.5
v 2.25 2.25 -1.5
v -1.5 -1.5 2.25
v 2.25 -1.5 -1.5
v -1.5 2.25 2.25
g bottom
usemtl red
s 1
f 5 7 2 4
f 6 3 1 8
g sides
usemtl blue
f 2 7 3 6
f 4 8 1 5
l 1 2
t crease 2/1/0 1 6 3.0
f 2 6 8 4
f 7 5 1 3
)";

// The same cube with v/vt/vn corners and indices relative to the 8 vertices above them.
const char *const cubeObjRelative = "v 2.25 2.25 2.25\nv -1.5 -1.5 -1.5\nv 2.25 -1.5 2.25\n"
                                    "v -1.5 2.25 -1.5\nv 2.25 2.25 -1.5\nv -1.5 -1.5 2.25\n"
                                    "v 2.25 -1.5 -1.5\nv -1.5 2.25 2.25\n"
                                    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
                                    "f -4/1/1 -2/2/1 -7/3/1 -5/4/1\n"
                                    "f -3//1 -6//1 -8//1 -1//1\n"
                                    "f -7/1 -2/2 -6/3 -3/4\n"
                                    "f 4/-4/-1 8/-3/-1 1/-2/-1 5/-1/-1\n"
                                    "f -7 -3 -1 -5\n"
                                    "f -2/1/1 -4/1/1 -8/1/1 -6/1/1\n";

const char *const cubeOff = R"(# COFF: a colour per vertex and face
COFF
8 6 12

2.25 2.25 2.25 255 0 0 255
-1.5 -1.5 -1.5 0 255 0 255
2.25 -1.5 2.25 0 0 255 255
-1.5 2.25 -1.5 0 0 0 255   # black
2.25 2.25 -1.5 1 1 1 255
-1.5 -1.5 2.25 1 1 1 255
2.25 -1.5 -1.5 1 1 1 255
-1.5 2.25 2.25 1 1 1 255
4 4 6 1 3 0.5 0.5 0.5
4 5 2 0 7
4 1 6 2 5
4 3 7 0 4
4 1 5 7 3 1 0 0
4 6 4 0 2
)";

// The bytes of a binary PLY body in a chosen byte order.
struct Bytes {
    bool big = false;
    std::string data;
    template<class T>
    Bytes &operator<<(T v)
    {
        char b[sizeof v];
        std::memcpy(b, &v, sizeof v);
        if (big != (std::endian::native == std::endian::big))
            std::reverse(b, b + sizeof v);
        data.append(b, sizeof v);
        return *this;
    }
};

// The cube as PLY with extra vertex properties (nx, ny, nz, red), an element between vertex and
// face with a list (material), and around the face list a scalar (flags) and a list (texcoord).
std::string cubePly(const std::string &format)
{
    const bool ascii = format == "ascii";
    const std::string index = format == "binary_big_endian" ? "int" : "uint";
    std::string text = "ply\nformat " + format + " 1.0\ncomment made by test_mesh_files\n"
                       "element vertex 8\nproperty double x\nproperty float nx\n"
                       "property float y\nproperty float z\nproperty float ny\n"
                       "property float nz\nproperty uchar red\n"
                       "element material 2\nproperty list uchar float coefficients\n"
                       "property int id\n"
                       "element face 6\nproperty uchar flags\n"
                       "property list uchar " + index + " vertex_indices\n"
                       "property list uchar float texcoord\nend_header\n";
    const Mesh m = cube();
    Bytes b{format == "binary_big_endian", {}};
    std::ostringstream a;
    for (int v = 0; v < 8; ++v) {
        b << double(m.vertices(v, 0)) << 0.5f << float(m.vertices(v, 1))
          << float(m.vertices(v, 2)) << -0.5f << 1.0f << std::uint8_t(200);
        a << m.vertices(v, 0) << " 0.5 " << m.vertices(v, 1) << ' ' << m.vertices(v, 2)
          << " -0.5 1 200\n";
    }
    b << std::uint8_t(3) << 0.1f << 0.2f << 0.3f << std::int32_t(7);
    b << std::uint8_t(0) << std::int32_t(8);
    a << "3 0.1 0.2 0.3 7\n0 8\n";
    for (const auto &f : m.faces) {
        b << std::uint8_t(1) << std::uint8_t(f.size());
        a << "1 " << f.size();
        for (int v : f) {
            b << std::uint32_t(v);
            a << ' ' << v;
        }
        b << std::uint8_t(2) << 0.25f << 0.75f;
        a << " 2 0.25 0.75\n";
    }
    return text + (ascii ? a.str() : b.data);
}

Mesh read(const std::string &bytes, MeshFormat format)
{
    std::istringstream in(bytes);
    return readMesh(in, format, "test." + toString(format));
}

QString refusal(const std::string &bytes, MeshFormat format)
{
    try {
        read(bytes, format);
    } catch (const InputError &e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

void compareMeshes(const Mesh &a, const Mesh &b)
{
    QCOMPARE(a.vertices.rows(), b.vertices.rows());
    QCOMPARE(a.vertices.cols(), Eigen::Index(3));
    QVERIFY(a.vertices == b.vertices); // the same doubles, not only close ones
    QCOMPARE(a.faces, b.faces);
}

} // namespace

class TestMeshFiles : public QObject {
    Q_OBJECT
private slots:
    void formatsByExtension();
    void readsCubes_data();
    void readsCubes();
    void objRelativeIndicesAcrossVertices();
    void objFaceOfMoreThan255Vertices();
    void objTagsAreNamedNotDropped();
    void byteOrderMarksAndForeignHeaderLines();
    void writeObjReadsBackTheSameDoubles();
    void readsAFileByPath();
    void refusals_data();
    void refusals();
    void binaryPlyRefusals();
};

void TestMeshFiles::formatsByExtension()
{
    // QVERIFY: QCOMPARE would print them with awb::toString, found by ADL.
    QVERIFY(meshFormatForPath("a/b.obj") == MeshFormat::Obj);
    QVERIFY(meshFormatForPath("B.OFF") == MeshFormat::Off);
    QVERIFY(meshFormatForPath("/tmp/x.y/mesh.Ply") == MeshFormat::Ply);
    const auto refusal = [](const std::string &path) {
        try {
            meshFormatForPath(path);
        } catch (const InputError &e) {
            return QString::fromStdString(e.what());
        }
        return QString();
    };
    QCOMPARE(refusal("mesh.stl"), QStringLiteral("unknown mesh file extension '.stl' of mesh.stl "
                                                 "(expected .obj, .off or .ply)"));
    QVERIFY(refusal("dir.d/mesh").contains(QStringLiteral("has no file extension")));
}

void TestMeshFiles::readsCubes_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<int>("format");
    const auto row = [](const char *name, const std::string &bytes, MeshFormat format) {
        QTest::newRow(name) << QByteArray::fromStdString(bytes) << int(format);
    };
    row("obj", cubeObj, MeshFormat::Obj);
    row("obj relative v/vt/vn", cubeObjRelative, MeshFormat::Obj);
    std::string crlf;
    for (char c : std::string(cubeObj))
        crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    row("obj crlf", crlf, MeshFormat::Obj);
    row("coff", cubeOff, MeshFormat::Off);
    std::string counts = cubeOff;
    counts.replace(counts.find("COFF\n8 6 12"), 11, "COFF 8 6 12");
    row("off counts on the header line", counts, MeshFormat::Off);
    row("off without header", std::string(cubeOff).substr(std::string(cubeOff).find("8 6 12")),
        MeshFormat::Off);
    row("ply ascii", cubePly("ascii"), MeshFormat::Ply);
    row("ply binary_little_endian", cubePly("binary_little_endian"), MeshFormat::Ply);
    row("ply binary_big_endian", cubePly("binary_big_endian"), MeshFormat::Ply);
}

void TestMeshFiles::readsCubes()
{
    QFETCH(QByteArray, bytes);
    QFETCH(int, format);
    const Mesh m = read(bytes.toStdString(), MeshFormat(format));
    compareMeshes(m, cube());
    checkMesh(m, MeshScheme::CatmullClark); // a closed, consistently oriented cube
}

void TestMeshFiles::objRelativeIndicesAcrossVertices()
{
    // A relative index counts back from the vertices read so far, not from the file's end.
    const Mesh m = read("v 0 0 0\nv 1 0 0\nv 1 1 0\nf -3 -2 -1\nv 0 1 0\nf -4 -2 -1\n"
                        "f 1 -1 3\n",
                        MeshFormat::Obj);
    QCOMPARE(m.vertices.rows(), Eigen::Index(4));
    QCOMPARE(m.faces, (std::vector<std::vector<int>>{{0, 1, 2}, {0, 2, 3}, {0, 3, 2}}));
}

void TestMeshFiles::objTagsAreNamedNotDropped()
{
    // OpenSubdiv's regression shapes tag sharp features on `t` lines (issue 44): the six kinds it
    // applies become the mesh's tags, as its regression reader reads them (vertices from 0, a
    // negative sharpness is 0, interpolateboundary 1 is edge-and-corner); the others are named
    // with their lines, once per tag name.
    std::istringstream in("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"
                          "t crease 2/1/0 0 1 10\nt crease 4/2/0 1 2 2 3 2.5 -1\n"
                          "t corner 1/1/0 3 10\nt interpolateboundary 1/0/0 1\n"
                          "t creasemethod 0/0/1 chaikin\nt smoothtriangles 0/0/1 smooth\n"
                          "t hole 1/0/0 0\nt vertexedit 1/0/0 0\nt vertexedit 1/0/0 1\n");
    std::vector<std::string> notes;
    const Mesh m = readMesh(in, MeshFormat::Obj, "shape.obj", &notes);
    QCOMPARE(m.faces.size(), std::size_t(1));
    QCOMPARE(m.tags.edges, (std::vector<SharpEdge>{{0, 1, 10.0f}, {1, 2, 2.5f}, {2, 3, 0.0f}}));
    QCOMPARE(m.tags.vertices, (std::vector<SharpVertex>{{3, 10.0f}}));
    QCOMPARE(m.tags.holes, std::vector<int>{0});
    QVERIFY(m.tags.options.boundary == BoundaryInterpolation::EdgeAndCorner);
    QVERIFY(m.tags.options.creaseMethod == CreaseMethod::Chaikin);
    QVERIFY(m.tags.options.triangles == TriangleSubdivision::Smooth);
    QCOMPARE(int(notes.size()), 1);
    QVERIFY2(notes[0].find("shape.obj, lines 13 to 14: 2 OpenSubdiv tags 't vertexedit' are not "
                           "applied") == 0,
             notes[0].c_str());
    // Written and read back: the same tags.
    std::ostringstream out;
    writeObj(out, m, "");
    std::istringstream back(out.str());
    QVERIFY(readMesh(back, MeshFormat::Obj, "back.obj").tags == m.tags);
    // A tag that names what the file does not have, or that is not a tag, is refused with its
    // line.
    const auto refusal = [](const std::string &text) {
        std::istringstream file("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n" + text);
        try {
            readMesh(file, MeshFormat::Obj, "bad.obj");
        } catch (const InputError &e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    QCOMPARE(refusal("t crease 2/1/0 0 3 2\n"),
             std::string("bad.obj, line 5: the tag 't crease' names vertex 3, but the file has 3 "
                         "vertices (tags count from 0: 0 to 2)"));
    QCOMPARE(refusal("t hole 1/0/0 1\n"),
             std::string("bad.obj, line 5: the hole names face 1, but the file has 1 faces (0 "
                         "to 0)"));
    QCOMPARE(refusal("t crease 2/1/0 0 1\n"),
             std::string("bad.obj, line 5: the tag 't crease' announces 3 values but has 2"));
    QCOMPARE(refusal("t corner 1-1-0 0 1\n"),
             std::string("bad.obj, line 5: the tag 't corner' needs its counts as "
                         "ints/floats/strings (like 2/1/0), got '1-1-0'"));
    QCOMPARE(refusal("t interpolateboundary 1/0/0 7\n"),
             std::string("bad.obj, line 5: the tag 't interpolateboundary' needs one whole "
                         "number: 0 none, 1 edge and corner, 2 edge only"));
    QCOMPARE(refusal("t crease 2/1/0 0 1 nan\n"),
             std::string("bad.obj, line 5: 'nan' is not a number"));
    // A crease on two vertices that no edge joins: checkMesh names it (with every other fault).
    Mesh diagonal = m;
    diagonal.tags = {};
    diagonal.tags.edges = {{0, 2, 1.0f}, {1, 3, 1.0f}};
    try {
        checkMesh(diagonal, MeshScheme::CatmullClark);
        QFAIL("accepted");
    } catch (const InputError &e) {
        QCOMPARE(std::string(e.what()),
                 std::string("2 problems: a crease names vertices 0 and 2, but no edge joins "
                             "them; a crease names vertices 1 and 3, but no edge joins them"));
    }
    // A file of many tag names gets 16 notes and one for the rest, not one per name.
    std::string many = "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n";
    for (int k = 0; k < 40; ++k)
        many += "t tag" + std::to_string(k) + " 0/0/0\n";
    std::istringstream manyTags(many);
    notes.clear();
    readMesh(manyTags, MeshFormat::Obj, "many.obj", &notes);
    QCOMPARE(int(notes.size()), 17);
    QVERIFY2(notes.back().find("24 more OpenSubdiv tag lines of other names") != std::string::npos,
             notes.back().c_str());
    // Without tags, no note.
    std::istringstream plain("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n");
    notes.clear();
    readMesh(plain, MeshFormat::Obj, "plain.obj", &notes);
    QVERIFY(notes.empty());
}

void TestMeshFiles::byteOrderMarksAndForeignHeaderLines()
{
    // Windows editors write a byte-order mark; UTF-16 text is read as what it encodes.
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const Mesh utf8 = read("\xEF\xBB\xBF" + obj, MeshFormat::Obj);
    QCOMPARE(utf8.faces.size(), std::size_t(1));
    for (const bool little : {true, false}) {
        std::string utf16 = little ? "\xFF\xFE" : "\xFE\xFF";
        for (char c : obj) {
            utf16.push_back(little ? c : '\0');
            utf16.push_back(little ? '\0' : c);
        }
        const Mesh m = read(utf16, MeshFormat::Obj);
        QCOMPARE(m.vertices.rows(), Eigen::Index(3));
        QCOMPARE(m.vertices(1, 0), 1.0);
    }
    QVERIFY(refusal("\xFF\xFEv\0 \0" "0", MeshFormat::Obj).contains("odd number of bytes"));
    // A header line of an exporter's own: skipped, and said.
    std::istringstream junk("ply\nformat ascii 1.0\nx 1\ny 2\nz 3\nelement vertex 3\n"
                            "property float x\nproperty float y\nproperty float z\n"
                            "element face 1\nproperty list uchar int vertex_indices\n"
                            "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    std::vector<std::string> junkNotes;
    readMesh(junk, MeshFormat::Ply, "j.ply", &junkNotes);
    QCOMPARE(int(junkNotes.size()), 1);  // one note for all, not one per line
    QVERIFY2(junkNotes[0] == "j.ply, line 3: 3 header lines that are not PLY 1.0's, the first "
                             "'x 1', are skipped",
             junkNotes[0].c_str());
    std::istringstream ply("ply\nformat ascii 1.0\nexporter_version 3.2\nelement vertex 3\n"
                           "property float x\nproperty float y\nproperty float z\n"
                           "element face 1\nproperty list uchar int vertex_indices\n"
                           "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    std::vector<std::string> notes;
    const Mesh m = readMesh(ply, MeshFormat::Ply, "x.ply", &notes);
    QCOMPARE(m.faces.size(), std::size_t(1));
    QCOMPARE(int(notes.size()), 1);
    QVERIFY2(notes[0] == "x.ply, line 3: header line 'exporter_version 3.2' is not PLY 1.0's: "
                         "skipped",
             notes[0].c_str());
}

void TestMeshFiles::objFaceOfMoreThan255Vertices()
{
    // tinyobjloader keeps a face's vertex count in a byte: 300 would read as 44.
    std::ostringstream text;
    for (int k = 0; k < 300; ++k)
        text << "v " << std::cos(k * 0.02) << ' ' << std::sin(k * 0.02) << " 0\n";
    text << 'f';
    for (int k = 0; k < 300; ++k)
        text << ' ' << k + 1;
    const Mesh m = read(text.str() + "\nf 1 2 3\n", MeshFormat::Obj);
    QCOMPARE(m.faces.size(), std::size_t(2));
    QCOMPARE(m.faces[0].size(), std::size_t(300));
    QCOMPARE(m.faces[0][299], 299);
    QCOMPARE(m.faces[1], (std::vector<int>{0, 1, 2}));
}

void TestMeshFiles::writeObjReadsBackTheSameDoubles()
{
    std::mt19937_64 random(30);
    std::uniform_real_distribution<double> unit(-1, 1);
    Mesh m;
    m.vertices.resize(200, 3);
    for (Eigen::Index v = 0; v < m.vertices.rows(); ++v)
        for (int c = 0; c < 3; ++c)
            m.vertices(v, c) = unit(random) * std::pow(10.0, double(v % 40) - 20);
    m.vertices.row(0) << 0.1, 1.0 / 3, -0.0;
    m.vertices.row(1) << std::numeric_limits<double>::denorm_min(),
        std::numeric_limits<double>::max(), -std::numeric_limits<double>::min();
    for (int f = 0; f < 100; ++f) {
        std::vector<int> face(std::size_t(3 + f % 5));
        for (int &v : face)
            v = int(random() % 200);
        m.faces.push_back(face);
    }
    std::ostringstream out;
    writeObj(out, m, "written by test_mesh_files\nsecond line");
    const std::string text = out.str();
    QVERIFY(text.rfind("# written by test_mesh_files\n# second line\nv 0.10000000000000001 ", 0)
            == 0);
    const Mesh back = read(text, MeshFormat::Obj);
    compareMeshes(back, m);
    QVERIFY(std::signbit(back.vertices(0, 2)));
    // writeObj refuses what readMesh would, and writes nothing then.
    std::ostringstream none;
    Mesh bad = m;
    bad.faces[7][1] = 200;
    QVERIFY_THROWS_EXCEPTION(InputError, writeObj(none, bad, ""));
    bad = m;
    bad.vertices(3, 1) = std::nan("");
    QVERIFY_THROWS_EXCEPTION(InputError, writeObj(none, bad, ""));
    QVERIFY(none.str().empty());
}

void TestMeshFiles::readsAFileByPath()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.filePath(QStringLiteral("cube.PLY")).toStdString();
    std::ofstream(path, std::ios::binary) << cubePly("binary_little_endian");
    compareMeshes(readMesh(path), cube());
    try {
        readMesh(dir.filePath(QStringLiteral("missing.obj")).toStdString());
        QFAIL("a missing file was read");
    } catch (const InputError &e) {
        QVERIFY2(QString::fromStdString(e.what()).startsWith(QStringLiteral("cannot open ")),
                 e.what());
    }
}

void TestMeshFiles::refusals_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<int>("format");
    QTest::addColumn<QString>("message"); // words the message holds, '|' between them
    const auto row = [](const char *name, const std::string &bytes, MeshFormat format,
                        const char *words) {
        QTest::newRow(name) << QByteArray::fromStdString(bytes) << int(format)
                            << QString::fromUtf8(words);
    };
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    const MeshFormat obj = MeshFormat::Obj, off = MeshFormat::Off, ply = MeshFormat::Ply;
    row("obj index", tri + "f 1 2 4\n", obj,
        "test.obj, line 4: vertex index 4 is out of range (the file has 3 vertices)");
    row("obj index beyond int", tri + "f 1 2 4294967297\n", obj, "line 4|out of range");
    row("obj relative index", "v 0 0 0\nv 1 0 0\nf -3 -2 -1\nv 0 1 0\n", obj,
        "line 3: relative vertex index -3 is out of range (2 vertices precede it)");
    row("obj zero index", tri + "f 0 1 2\n", obj, "line 4: '0' is not a face corner");
    row("obj bad corner", tri + "f 1/x 2 3\n", obj, "'1/x' is not a face corner");
    row("obj nan", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", obj,
        "test.obj, line 2: 'nan' is not a finite number");
    row("obj inf", tri + "v 0 0 -inf\nf 1 2 3\n", obj, "line 4: '-inf' is not a finite number");
    row("obj overflow", "v 1e400 0 0\n", obj, "line 1: '1e400' is not a finite number");
    row("obj not a number", "v 1 2 abc\n", obj, "line 1: 'abc' is not a number");
    row("obj two coordinates", "# c\nv 0 0\n", obj,
        "line 2: a vertex needs 3 coordinates, this one has 2");
    row("obj face of 2", tri + "f 1 2\n", obj,
        "line 4: a face needs at least 3 vertices, this one has 2");
    row("obj crlf line", "v 0 0 0\r\nv 1 0 0\r\nf 1 2\r\n", obj, "line 3: a face needs");
    row("obj empty", "", obj, "test.obj is empty");
    row("obj blank", " \n\n\t\n", obj, "test.obj is empty");
    row("obj no faces", tri, obj, "test.obj holds no faces");
    row("obj is an off file", cubeOff, obj, "test.obj holds no vertices");
    row("obj nul", tri + std::string("f 1 2 3\0", 8), obj, "line 4: a NUL byte");
    row("off header", "4OFF\n1 1 0\n0 0 0 1\n3 0 0 0\n", off,
        "line 1: '4OFF' is not a header this reader takes");
    row("off binary", "OFF BINARY\n", off, "is not a header this reader takes");
    row("off not off", "solid cube\nfacet normal 0 0 1\n", off,
        "line 1: 'solid cube' is not the counts line");
    row("off huge counts", "OFF\n1000000000000 1 0\n0 0 0\n", off,
        "line 2: 1000000000000 vertices and 1 faces need more lines than the 2 left");
    row("off index", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", off,
        "test.off, line 6: vertex index 3 is out of range (the file has 3 vertices)");
    row("off negative index", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", off,
        "line 6: vertex index -1 is out of range");
    row("off face of 2", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", off,
        "line 6: a face needs at least 3 vertices, this one has 2");
    row("off short face", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n5 0 1 2\n", off,
        "line 6: the face announces 5 vertices but lists 3");
    row("off nan", "OFF\n3 1 0\n0 0 0\n1 NaN 0\n0 1 0\n3 0 1 2\n", off,
        "line 4: 'NaN' is not a finite number");
    row("off truncated", "OFF\n3 1 0\n0 0 0\n# c\n# c\n# c\n", off,
        "test.off ends after 1 of its 3 vertices");
    row("off no face line", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n\n", off,
        "test.off ends after 0 of its 1 faces");
    row("off data after", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 2 1 0\n", off,
        "line 7: data after the last face");
    row("off comments only", "# nothing\n", off, "test.off is empty");
    row("off no vertices", "OFF\n0 0 0\n", off, "test.off holds no vertices");
    const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                               "property float y\nproperty float z\nelement face 1\n"
                               "property list uchar int vertex_indices\nend_header\n";
    row("ply ascii index", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", ply,
        "test.ply, line 13 (face 0): vertex index 7 is out of range (the file has 3 vertices)");
    row("ply ascii nan", header + "0 0 0\n1 0 0\n0 nan 0\n3 0 1 2\n", ply,
        "line 12 (vertex 2): 'nan' is not a finite number");
    row("ply ascii not a number", header + "0 0 0\n1 0 0\n0 x 0\n3 0 1 2\n", ply,
        "line 12 (vertex 2): 'x' is not a number");
    row("ply ascii truncated", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n", ply,
        "line 13 (face 0): the data ends early");
    row("ply ascii face of 2", header + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", ply,
        "(face 0): a face needs at least 3 vertices, this one has 2");
    row("ply ascii data after", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n4\n", ply,
        "line 14: data after the last element");
    row("ply not ply", "OFF\n3 1 0\n", ply, "test.ply is not a PLY file");
    row("ply no end_header", "ply\nformat ascii 1.0\nelement vertex 3\n", ply,
        "test.ply: the PLY header has no end_header line");
    row("ply no format", "ply\nelement vertex 3\nend_header\n", ply, "has no format line");
    row("ply format", "ply\nformat binary_little_endian 2.0\n", ply,
        "line 2: unsupported PLY format");
    row("ply type", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\n", ply,
        "line 4: unknown PLY property type 'float128'");
    row("ply header line", "ply\nformat ascii 1.0\nelement vertex\n", ply,
        "line 3: malformed PLY header line 'element vertex'");
    row("ply count", "ply\nformat ascii 1.0\nelement vertex 1000000000000\n", ply,
        "line 3: '1000000000000' is not a valid count");
    row("ply absurd claim", "ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\n"
                            "property float y\nproperty float z\nelement face 1\n"
                            "property list uchar int vertex_indices\nend_header\n0 0 0\n",
        ply, "element vertex claims 2000000000 items, more than the rest of the file can hold");
    row("ply no z", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                    "property float y\nend_header\n0 0\n", ply,
        "the vertex element needs the scalar properties x, y and z");
    row("ply float indices", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                             "property float y\nproperty float z\nelement face 1\n"
                             "property list uchar float vertex_indices\nend_header\n", ply,
        "the face element needs one list property vertex_indices");
    row("ply no faces", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                        "property float y\nproperty float z\nend_header\n0 0 0\n", ply,
        "test.ply holds no faces");
    row("ply no vertices", "ply\nformat ascii 1.0\nend_header\n", ply,
        "test.ply holds no vertices");
    row("ply twice", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                     "property float x\n",
        ply, "line 5: property x appears twice in element vertex");
}

void TestMeshFiles::refusals()
{
    QFETCH(QByteArray, bytes);
    QFETCH(int, format);
    QFETCH(QString, message);
    const QString m = refusal(bytes.toStdString(), MeshFormat(format));
    for (const QString &words : message.split(QLatin1Char('|')))
        QVERIFY2(m.contains(words), qPrintable(QStringLiteral("refusal: '%1'").arg(m)));
}

void TestMeshFiles::binaryPlyRefusals()
{
    // A triangle: vertex x, y, z float; face list of char length and int indices.
    const std::string header = "ply\nformat binary_big_endian 1.0\nelement vertex 3\n"
                               "property float x\nproperty float y\nproperty float z\n"
                               "element face 2\nproperty list char int vertex_indices\n"
                               "end_header\n";
    const auto vertices = [](float nan) {
        Bytes b{true, {}};
        b << 0.f << 0.f << 0.f << 1.f << 0.f << 0.f << 0.f << nan << 0.f;
        return b.data;
    };
    const auto faces = [](std::int8_t count, std::int32_t last) {
        Bytes b{true, {}};
        b << std::int8_t(3) << 0 << 1 << 2 << count << 2 << 1 << last;
        return b.data;
    };
    const std::string good = header + vertices(1.f) + faces(3, 0);
    QCOMPARE(read(good, MeshFormat::Ply).faces,
             (std::vector<std::vector<int>>{{0, 1, 2}, {2, 1, 0}}));
    const std::size_t face1 = header.size() + 36 + 13; // the byte where face 1 starts
    const auto check = [&](const std::string &bytes, const QString &words) {
        const QString m = refusal(bytes, MeshFormat::Ply);
        QVERIFY2(m.contains(words), qPrintable(QStringLiteral("refusal: '%1'").arg(m)));
    };
    check(header + vertices(1.f) + faces(3, 3),
          QStringLiteral("test.ply, face 1 (byte %1): vertex index 3 is out of range (the file "
                         "has 3 vertices)")
              .arg(face1));
    check(header + vertices(std::nanf("")) + faces(3, 0),
          QStringLiteral("test.ply, vertex 2 (byte %1): 'nan' is not a finite number")
              .arg(header.size() + 24));
    check(header + vertices(1.f) + faces(-1, 0),
          QStringLiteral("face 1 (byte %1): list length -1 is negative").arg(face1));
    check(header + vertices(1.f) + faces(100, 0),
          QStringLiteral("face 1 (byte %1): the data ends early (truncated)").arg(face1));
    check(good + '\n', QStringLiteral("test.ply, byte %1: data after the last element")
                           .arg(good.size()));
    check(header + vertices(1.f).substr(0, 30),
          QStringLiteral("test.ply: element vertex claims 3 items, more than the rest of the "
                         "file can hold"));
    // A list skipped in the vertex element takes the bytes that vertex 1 needed: the element's
    // claim (13 bytes a vertex at least) holds, its data does not.
    Bytes b{true, {}};
    b << 0.f << 0.f << 0.f << std::uint8_t(3) << 1.f << 2.f << 3.f << std::uint8_t(0);
    check("ply\nformat binary_big_endian 1.0\nelement vertex 2\nproperty float x\n"
          "property float y\nproperty float z\nproperty list uchar float extra\n"
          "element face 1\nproperty list uchar int vertex_indices\nend_header\n" + b.data,
          QStringLiteral("vertex 1 (byte"));
    check("ply\nformat binary_big_endian 1.0\nelement vertex 2\nproperty float x\n"
          "property float y\nproperty float z\nproperty list uchar float extra\n"
          "element face 1\nproperty list uchar int vertex_indices\nend_header\n" + b.data,
          QStringLiteral("the data ends early"));
}

AWB_TEST_MAIN(TestMeshFiles)
#include "test_mesh_files.moc"
