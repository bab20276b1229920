// attractor_workbench.Item: one item of a project, its inputs (name, control points,
// parameters, any JSON field) as undoable edits, and what the application computes from them
// (maps and spectra, points, the analysis, the regularity, figures), through the same model,
// core and figure code as the window and attractor-cli.

#include "python/Internal.h"

#include "core/analysis/Spectrum.h"
#include "model/AttractorItem.h"
#include "model/ItemAddress.h"
#include "model/ItemAnalysisJson.h"
#include "model/MapMatrices.h"
#include "model/PointExport.h"
#include "model/Project.h"
#include "model/ProjectIO.h"
#include "model/PropertyTable.h"
#include "model/SchemeRegularity.h"
#include "model/StartSetText.h"
#include "model/SubdivisionCurveItem.h"
#include "render/ItemFigure.h"

#include <QGuiApplication>

namespace awb::python {

AttractorItem &ItemHandle::attractor() const
{
    Item &i = get();
    auto *a = qobject_cast<AttractorItem *>(&i);
    if (!a)
        throw Error(QString("item '%1' has no attractor (its kind: %2)")
                        .arg(i.name(), i.typeName()));
    return *a;
}

namespace {

std::shared_ptr<const DerivedIfs> derivedOf(const AttractorItem &item)
{
    auto d = item.derivedIfs();
    if (!d)
        throw Error(QString("item '%1': %2").arg(item.name(), item.derivedError()));
    return d;
}

py::array complexValues(const std::vector<Complex> &values)
{
    py::array_t<std::complex<double>> a(py::ssize_t(values.size()));
    auto r = a.mutable_unchecked<1>();
    for (size_t i = 0; i < values.size(); ++i)
        r(py::ssize_t(i)) = values[i];
    return a;
}

py::array rowArray(const RowVec &b)
{
    py::array_t<double> a(py::ssize_t(b.size()));
    auto r = a.mutable_unchecked<1>();
    for (Eigen::Index i = 0; i < b.size(); ++i)
        r(i) = b(i);
    return a;
}

// Map i of the item as the Matrices dock shows it (model/MapMatrices, as attractor-cli
// analyse's "maps"), with numpy arrays and exact fractions.
py::dict mapDict(const DerivedIfs &d, int i)
{
    const MapMatrices m = mapMatrices(d, i);
    py::dict o;
    o["index"] = i;
    if (m.S) {
        o["S"] = toNumpy(*m.S);
        o["S_exact"] = exactArray(*m.S);
        o["eigenvalues"] = complexValues(spectrum(*m.S).values);
    } else if (m.complexS) {
        o["S"] = toNumpy(*m.complexS);
        o["eigenvalues"] = complexValues(spectrum(*m.complexS).values);
    }
    if (m.M) {
        o["M"] = toNumpy(*m.M);
        o["M_exact"] = exactArray(*m.M);
    } else if (m.complexM) {
        o["M"] = toNumpy(*m.complexM);
    }
    if (m.A) {
        o["A"] = toNumpy(*m.A);
        o["A_exact"] = exactArray(*m.A);
    } else if (m.complexA) {
        o["A"] = toNumpy(*m.complexA);
    }
    if (m.b)
        o["b"] = rowArray(*m.b);
    else if (m.complexB)
        o["b"] = toNumpy(*m.complexB);
    if (m.A || m.complexA) {
        o["eigenvalues_A"] = complexValues(m.eigenvaluesA);
        if (!o.contains("eigenvalues"))
            o["eigenvalues"] = o["eigenvalues_A"];
    }
    return o;
}

} // namespace

// Text in figures needs a QGuiApplication; the standalone module makes one on the first
// render (off screen without a display), never at import.
void ensureGuiApplication()
{
    if (QCoreApplication::instance())
        return;
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "attractor_workbench";
    static char *argv[] = {name, nullptr};
    static auto *app = new QGuiApplication(argc, argv);
    Q_UNUSED(app);
}

namespace {

// item.update(fields): the fields as the file would have them, each changed part of the item
// through its declared, checked setter, in one undo step (PropertyTable::update).
void updateItem(ItemHandle &h, const QJsonObject &fields)
{
    Item &item = h.get();
    QString why;
    if (!item.properties().update(item, fields, &why))
        throw Error(QString("update() of '%1': %2").arg(item.name(), why));
}

} // namespace

void defineItemClass(py::module_ &m)
{
    py::class_<ItemHandle>(
        m, "Item",
        "An item of a project (project.item(name), project.items). Its inputs are edited "
        "undoably, one undo step each, refused with the window's message; what is computed "
        "from them is computed by the application's own code.")
        .def_property(
            "name", [](const ItemHandle &h) { return toPy(h.get().name()); },
            [](ItemHandle &h, const py::object &name) {
                Item &item = h.get();
                const QString n = toQString(name, "name");
                if (item.project())
                    if (const auto p = item.project()->checkName(&item, n))
                        throw Error(p->message);
                if (!item.setName(n))
                    throw Error(QString("the name '%1' is refused").arg(n));
                h.name = n;
            },
            "The item's name (unique in the project). Setting it is one undo step; items "
            "that refer to the old name follow.")
        .def_property_readonly(
            "kind", [](const ItemHandle &h) { return toPy(h.get().type()); },
            "The item's type as in the file: \"subdivision-curve\", \"fractal\", "
            "\"eigenvalue-plot\", ...")
        .def_property_readonly(
            "type_name", [](const ItemHandle &h) { return toPy(h.get().typeName()); },
            "The kind's name as the window shows it.")
        .def_property_readonly(
            "dimension",
            [](const ItemHandle &h) {
                auto *a = qobject_cast<AttractorItem *>(&h.get());
                return a ? a->pointDimension() : 0;
            },
            "Coordinates of its control points: 2 (plane) or 3 (surfaces, meshes); 0 for an "
            "item with no attractor.")
        .def_property_readonly(
            "parent",
            [](const ItemHandle &h) -> py::object {
                Item *p = h.get().parentItem();
                return p ? py::cast(ItemHandle(h.project, p)) : py::none();
            },
            "The item this one sits under (None at the top level).")
        .def_property_readonly(
            "children",
            [](const ItemHandle &h) {
                py::list l;
                Item &item = h.get();
                for (int i = 0; i < item.childCount(); ++i)
                    l.append(py::cast(ItemHandle(h.project, item.child(i))));
                return l;
            },
            "The items under this one (an eigenvalue plot under its curve).")
        .def_property(
            "control_points",
            [](const ItemHandle &h) {
                AttractorItem &a = h.attractor();
                if (a.controlPointSetCount() == 0)
                    throw Error(QString("item '%1' has no control points").arg(a.name()));
                return PointsHandle{h, 0};
            },
            [](const ItemHandle &h, const py::object &points) {
                py::cast(PointsHandle{h, 0}).attr("assign")(points);
            },
            "The control points (set 0) as a list-like view: numpy.asarray(...) is an (m, d) "
            "array; cp[i] = [x, y] moves point i, cp.insert(i, p), del cp[i], and assigning a "
            "whole (m, d) array are each one undo step.")
        .def_property_readonly(
            "point_sets",
            [](const ItemHandle &h) {
                AttractorItem &a = h.attractor();
                py::list l;
                for (int s = 0; s < a.controlPointSetCount(); ++s)
                    l.append(py::cast(PointsHandle{h, s}));
                return l;
            },
            "Every control point set (a junction curve has two), each like control_points.")
        .def_property_readonly(
            "parameters", [](const ItemHandle &h) { return ParametersHandle{h}; },
            "The parameters the Properties dock edits, by the same keys (\"scheme.omega\", "
            "\"j\", ...): a dict-like view; setting one is one undo step, refused with the "
            "dock's message.")
        .def_property_readonly(
            "error",
            [](const ItemHandle &h) -> py::object {
                const QString e = h.get().derivedError();
                return e.isEmpty() ? py::none() : py::object(toPy(e));
            },
            "Why the item's IFS cannot be computed, or None.")
        .def(
            "to_json", [](const ItemHandle &h) { return toPy(ProjectIO::itemToJson(h.get())); },
            "to_json() -> dict\n\nThe item as its JSON object in the project file (children "
            "included).")
        .def(
            "update",
            [](ItemHandle &h, const py::object &fields) {
                updateItem(h, toJsonObject(fields, "fields"));
            },
            py::arg("fields"),
            "update(fields)\n\nSets fields of the item's JSON object (\"style\", \"start_set\", "
            "\"algorithm\", \"scheme\", \"matrices\", ...), checked as a file is. One undo "
            "step.")
        .def(
            "maps",
            [](const ItemHandle &h) {
                const auto d = derivedOf(h.attractor());
                py::list l;
                for (int i = 0; i < listedMapCount(*d); ++i)
                    l.append(mapDict(*d, i));
                return l;
            },
            "maps() -> list of dict\n\nPer map i: \"S\" (the subdivision matrix S_i), \"M\" = "
            "P^-1 S_i P, its blocks \"A\" and \"b\" (numpy arrays; \"S_exact\", \"M_exact\", "
            "\"A_exact\": object arrays of fractions.Fraction where the entry is a fraction, "
            "floats elsewhere), \"eigenvalues\" of S_i and \"eigenvalues_A\" (complex arrays, "
            "largest modulus first). Items with no S_i give the IFS's A and b.")
        .def(
            "points",
            [](const ItemHandle &h, const py::object &depthArg, const py::object &startArg,
               const py::object &addressArg, const py::object &maxPoints,
               bool withMaps) -> py::object {
                AttractorItem &item = h.attractor();
                const auto d = derivedOf(item);
                const int depth = depthArg.is_none()
                                      ? item.algorithm().depth
                                      : int(intArg(depthArg, "points(): depth", 0, 64));
                const double budget = realArg(maxPoints, "points(): max_points", 1, 2e9);
                StartSet start = item.coreStartSet(*d);
                if (py::isinstance<py::str>(startArg)) {
                    try {
                        start = startSetFromText(item, *d,
                                                 toQString(startArg, "points(): start"));
                    } catch (const StartSetTextError &e) {
                        throw Error(QStringLiteral("points(): start: ") + e.message);
                    }
                } else if (!startArg.is_none()) {
                    const Mat pts = toPoints(startArg, item.pointDimension(), "points(): start");
                    start = {StartSet::Kind::Points, d->toIfsSpace(pts)};
                }
                Address address;
                if (!addressArg.is_none()) {
                    QString text;
                    if (py::isinstance<py::str>(addressArg)) {
                        text = toQString(addressArg, "points(): address");
                    } else {
                        if (!py::isinstance<py::sequence>(addressArg))
                            throw Error("points(): address: expected a list of map numbers");
                        QStringList symbols;
                        for (const py::handle s : addressArg)
                            symbols << QString::number(
                                intArg(s, "points(): address", 0, 1 << 20));
                        text = symbols.join(',');
                    }
                    address = parseItemAddress(text, *d);
                }
                const double n = exportPointCount(*d, start, depth);
                if (n > budget)
                    throw Error(QString("points(): depth %1 gives %2 points, more than "
                                        "max_points %3")
                                    .arg(depth)
                                    .arg(n, 0, 'g', 4)
                                    .arg(budget, 0, 'g', 4));
                CollectedPoints points;
                std::atomic<bool> cancel{false};
                IterationControl control;
                control.cancel = &cancel;
                runInterruptible(
                    [&] { points = collectPoints(*d, start, depth, control, address); }, cancel);
                py::array xy = toNumpy(points.points);
                if (!withMaps)
                    return xy;
                py::array_t<int> maps(py::ssize_t(points.maps.size()));
                std::copy(points.maps.begin(), points.maps.end(), maps.mutable_data());
                return py::make_tuple(xy, maps);
            },
            py::arg("depth") = py::none(), py::arg("start") = py::none(),
            py::arg("address") = py::none(), py::arg("max_points") = py::float_(1e8),
            py::arg("with_maps") = false,
            "points(depth=None, start=None, address=None, max_points=1e8, with_maps=False) -> "
            "numpy (N, d)\n\nThe points of F^depth(X0) (attractor-cli points): depth the item's "
            "by default; start the item's start set, or an (n, d) array of points, or a text as "
            "--start takes (\"segment:0,0,1,0\", \"lifted:...\", \"net:0,9,18\", "
            "\"vertex-limits\"); address "
            "a list of 0-based maps w (the sub-copy f_w(A)). With with_maps, also each point's "
            "0-based map applied last (-1 for X0). Ctrl+C cancels.")
        .def(
            "analyse",
            [](const ItemHandle &h) {
                AttractorItem &item = h.attractor();
                QJsonObject o;
                {
                    py::gil_scoped_release release;
                    o = analyseItemJson(&item);
                }
                return toPy(o);
            },
            "analyse() -> dict\n\nThe item's entry of `attractor-cli analyse --json`: per map "
            "S_i, M_i, A_i, b_i, eigenvalues, spectral radius, subdominant kind, contractivity "
            "and fixed point; the subdominant eigenvalues, the Hausdorff distance to the exact "
            "curve, the box-counting dimension and a curve's regularity.")
        .def(
            "regularity",
            [](const ItemHandle &h) {
                auto *curve = qobject_cast<SubdivisionCurveItem *>(&h.get());
                if (!curve)
                    throw Error(QString("item '%1' is not a subdivision curve: no scheme "
                                        "regularity")
                                    .arg(h.get().name()));
                Regularity r;
                {
                    py::gil_scoped_release release;
                    r = itemRegularity(*curve);
                }
                return toPy(regularityJson(r));
            },
            "regularity() -> dict\n\nThe certified Hölder regularity of a subdivision curve's "
            "scheme (analyse()[\"regularity\"]): \"lower\", \"upper\", \"smoothness\" (C^n), "
            "\"exact\", \"method\", \"sobolev\", ...")
        .def(
            "render",
            [](const ItemHandle &h, const py::object &path, const py::object &size,
               const py::object &depth, const py::object &samples, const py::object &threads) {
                AttractorItem &item = h.attractor();
                FigureOptions o;
                figureSizeArg(size, "render()", o);
                if (!depth.is_none())
                    o.depth = int(intArg(depth, "render(): depth", 0, 64));
                if (!samples.is_none())
                    o.samples = std::uint64_t(realArg(samples, "render(): samples", 1, 1e11));
                if (!threads.is_none())
                    o.threads = int(intArg(threads, "render(): threads", 0, 256));
                const QString file = pathArg(path, "render()");
                ensureGuiApplication();
                Project &project = h.project->get();
                std::atomic<bool> cancel{false};
                o.cancel = &cancel;
                runInterruptible([&] { renderItemFigure(project, &item, o, file); }, cancel);
            },
            py::arg("path"), py::arg("size") = py::none(), py::arg("depth") = py::none(),
            py::arg("samples") = py::none(), py::arg("threads") = py::none(),
            "render(path, size=None, depth=None, samples=None, threads=None)\n\nDraws the item "
            "as attractor-cli render does: PNG, SVG or PDF by the suffix (.exr: the raw "
            "density), size (width, height) in pixels (default 900 x 700), depth and samples "
            "the item's unless given, threads 0 for all cores. The PNG and SVG carry the "
            "project: open(path) reads it back. Ctrl+C cancels (no file is left).")
        .def("__eq__",
             [](const ItemHandle &a, const py::object &b) {
                 return py::isinstance<ItemHandle>(b)
                        && &a.get() == &b.cast<const ItemHandle &>().get();
             })
        .def("__hash__", [](const ItemHandle &h) { return std::hash<const void *>()(&h.get()); })
        .def("__repr__", [](const ItemHandle &h) {
            const Item &item = h.get();
            return QString("<attractor_workbench.Item '%1' (%2)>")
                .arg(item.name(), item.type())
                .toStdString();
        });
}

} // namespace awb::python
