#include "model/PointExport.h"

#include "model/AttractorItem.h"

#include <QCoreApplication>
#include <QIODevice>

#include <charconv>
#include <type_traits>

namespace awb {

namespace {

// lupdate takes the context of PointExportTr::tr() from the macro (a free tr() would get the
// enclosing namespace as its context).
struct PointExportTr {
    Q_DECLARE_TR_FUNCTIONS(awb::PointExport)
};

// Writes `bytes` or throws: a full disk must not give a silently short file.
void put(QIODevice &out, const QByteArray &bytes)
{
    if (out.write(bytes) != bytes.size())
        throw InputError(
            PointExportTr::tr("cannot write the points: %1").arg(out.errorString()).toStdString());
}

// The map an image was made by last, numbered as the item numbers its maps (-1 for X0): the
// address's first symbol when there is one.
int lastMap(const DerivedIfs &d, const Address &address, const std::uint8_t *a, int n)
{
    return !address.empty() ? d.analysisIndex(address.front())
           : n > 0          ? d.analysisIndex(a[0])
                            : -1;
}

// Streams f_w(F^depth(X0)) (w = `address`, empty: the identity) to `visit(point row of one
// view, view index, 0-based map or -1)`.
template <class Visit>
void iteratePoints(const DerivedIfs &d, const StartSet &start, int depth, const Address &address,
                   const IterationControl &control, Visit &&visit)
{
    const bool own = d.iterate && !d.iterateDrawsIfs;
    if (!address.empty() && own)
        throw InputError(PointExportTr::tr("--address needs an item drawn by one IFS; this one is drawn by "
                            "an automaton").toStdString());
    const AffineMap prefix = composeAddress(d.ifs, address);
    CallbackSink sink([&](const Mat &v, StartSet::Kind, const std::uint8_t *a, int n) {
        const int map = lastMap(d, address, a, n);
        const Mat x = address.empty() ? v : applyMap(prefix, v);
        for (std::size_t k = 0; k < d.ifs.views.size(); ++k) {
            const Mat p = awb::project(d.ifs.views[k], x);
            for (Eigen::Index r = 0; r < p.rows(); ++r)
                visit(RowVec(p.row(r)), int(k), map);
        }
    });
    if (own)
        d.iterate(start, depth, {&sink}, control);
    else
        iterate(d.ifs, start, depth, sink, control);
}

// A flame's points come from its own chaos game: F^depth of its affine parts is another set.
void requireIteratedPoints(const DerivedIfs &d)
{
    if (d.chaos)
        throw InputError(QCoreApplication::translate(
                             "awb::PointExport",
                             "this item is a fractal flame: its points come from its own chaos "
                             "game, not from iterating maps (render its picture instead)")
                             .toStdString());
}

} // namespace

double exportPointCount(const DerivedIfs &d, const StartSet &start, int depth)
{
    if (d.iterate && !d.iterateDrawsIfs)
        return d.pointCount ? d.pointCount(start, depth) * double(d.ifs.views.size()) : -1;
    return imageCount(d.ifs, depth) * double(start.vertices.rows())
           * double(d.ifs.views.size());
}

bool exportsSpacePoints(const DerivedIfs &d)
{
    return !d.ifs.views.empty() && d.ifs.views.front().outDim() == 3;
}

std::uint64_t writePointsCsv(QIODevice &out, const DerivedIfs &d, const StartSet &start,
                             int depth, const IterationControl &control, const Address &address)
{
    requireIteratedPoints(d);
    put(out, exportsSpacePoints(d) ? "x,y,z,map,view\n" : "x,y,map,view\n");
    QByteArray buffer;
    std::uint64_t written = 0;
    // Numbers as the shortest text that reads back to the same double (std::to_chars, as the
    // .ifs and .flame writers), formatted in place: no allocation per number (a mesh's depth-2
    // points are millions of lines; printf's %.17g through to_chars took a quarter of them).
    char text[64];
    const auto number = [&](auto value) {
        buffer.append(text, std::to_chars(text, text + sizeof text, value).ptr - text);
    };
    iteratePoints(d, start, depth, address, control, [&](const RowVec &p, int view, int map) {
        for (Eigen::Index c = 0; c < p.size(); ++c) {
            number(p(c));
            buffer += ',';
        }
        number(map + 1);
        buffer += ',';
        number(view + 1);
        buffer += '\n';
        ++written;
        if (buffer.size() > (1 << 20)) {
            put(out, buffer);
            buffer.clear();
        }
    });
    put(out, buffer);
    return written;
}

namespace {

// collectPoints' sink: the projected vertices of every image appended in place, with no
// temporary matrix per image (an image is often one point: F^12 of the Koch curve's start
// point is 16.7 million calls).
class CollectingSink : public AttractorSink {
public:
    CollectingSink(const DerivedIfs &d, const Address &address, int columns,
                   std::vector<double> &coordinates, CollectedPoints &out)
        : m_d(d), m_address(address), m_prefix(composeAddress(d.ifs, address)),
          m_columns(columns), m_coordinates(coordinates), m_out(out)
    {
    }
    void consume(const Mat &v, StartSet::Kind, const std::uint8_t *a, int n) override
    {
        const int map = lastMap(m_d, m_address, a, n);
        const Mat *x = &v;
        if (!m_address.empty()) {
            m_mapped = applyMap(m_prefix, v);
            x = &m_mapped;
        }
        for (std::size_t k = 0; k < m_d.ifs.views.size(); ++k) {
            const Projection &view = m_d.ifs.views[k];
            const Eigen::Index inner = std::min(view.V.rows(), x->cols());
            for (Eigen::Index r = 0; r < x->rows(); ++r) {
                for (int c = 0; c < m_columns; ++c) {
                    double s = 0.0;
                    if (c < view.V.cols()) {
                        s = view.c(c);
                        for (Eigen::Index j = 0; j < inner; ++j)
                            s += (*x)(r, j) * view.V(j, c);
                    }
                    m_coordinates.push_back(s);
                }
                m_out.maps.push_back(map);
                m_out.views.push_back(int(k));
            }
        }
    }

private:
    const DerivedIfs &m_d;
    const Address &m_address;
    AffineMap m_prefix;
    int m_columns;
    std::vector<double> &m_coordinates;
    CollectedPoints &m_out;
    Mat m_mapped;
};

} // namespace

CollectedPoints collectPoints(const DerivedIfs &d, const StartSet &start, int depth,
                              const IterationControl &control, const Address &address)
{
    requireIteratedPoints(d);
    const bool own = d.iterate && !d.iterateDrawsIfs;
    if (!address.empty() && own)
        throw InputError(PointExportTr::tr("--address needs an item drawn by one IFS; this one "
                                           "is drawn by an automaton")
                             .toStdString());
    const int columns = exportsSpacePoints(d) ? 3 : 2;
    const double expected = exportPointCount(d, start, depth);
    std::vector<double> coordinates;
    CollectedPoints out;
    if (expected > 0 && expected < 5e7) {  // more grows as it comes (and can be cancelled)
        coordinates.reserve(std::size_t(expected) * std::size_t(columns));
        out.maps.reserve(std::size_t(expected));
        out.views.reserve(std::size_t(expected));
    }
    CollectingSink sink(d, address, columns, coordinates, out);
    if (own)
        d.iterate(start, depth, {&sink}, control);
    else
        iterate(d.ifs, start, depth, sink, control);
    out.points = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic,
                                                Eigen::RowMajor>>(
        coordinates.data(), Eigen::Index(out.maps.size()), columns);
    return out;
}

std::uint64_t writePointsPly(QIODevice &out, const QString &title, const DerivedIfs &d,
                             const StartSet &start, int depth,
                             const std::function<QColor(int)> &color,
                             const IterationControl &control)
{
    requireIteratedPoints(d);
    const double n = exportPointCount(d, start, depth);
    if (n < 0)
        throw InputError(QCoreApplication::translate("awb::PointExport",
                                                     "'%1' is drawn by an automaton: PLY export "
                                                     "covers items with one IFS")
                             .arg(title)
                             .toStdString());
    put(out, QString("ply\nformat binary_little_endian 1.0\n"
                     "comment Attractor Workbench: item %1, F^%2(X0)\n"
                     "element vertex %3\n"
                     "property float x\nproperty float y\nproperty float z\n"
                     "property uchar red\nproperty uchar green\n"
                     "property uchar blue\nproperty uchar map\nend_header\n")
                 .arg(title)
                 .arg(depth)
                 .arg(qint64(n))
                 .toUtf8());
    QByteArray buffer;
    std::uint64_t written = 0;
    iteratePoints(d, start, depth, {}, control, [&](const RowVec &p, int, int map) {
        map = std::max(map, 0);
        const QColor c = color(map);
        const float xyz[3] = {float(p(0)), float(p(1)), p.size() > 2 ? float(p(2)) : 0.0f};
        buffer.append(reinterpret_cast<const char *>(xyz), sizeof xyz);
        const char rgbm[4] = {char(c.red()), char(c.green()), char(c.blue()),
                              char(std::uint8_t(map))};
        buffer.append(rgbm, 4);
        ++written;
        if (buffer.size() > (1 << 20)) {
            put(out, buffer);
            buffer.clear();
        }
    });
    put(out, buffer);
    const bool cancelled = control.cancel && control.cancel->load();
    if (!cancelled && written != std::uint64_t(n))
        throw InputError(QCoreApplication::translate("awb::PointExport",
                                                     "wrote %1 points, expected %2")
                             .arg(written)
                             .arg(qint64(n))
                             .toStdString());
    return written;
}

} // namespace awb
