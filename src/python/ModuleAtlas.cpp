// The regularity atlas's parts in Python (issue 48): Family, a family of a curve item's scheme
// (model SchemeFamily: plain data, picklable, so a Dask worker rebuilds it), and AtlasPlan, the
// core's plan of batches. attractor_workbench/atlas.py runs the batches -- in this process, on
// a local Dask cluster or on one named by address -- through Family.evaluate; nothing of the
// analysis is written in Python.

#include "python/Internal.h"

#include "core/analysis/RegularityAtlas.h"
#include "model/SchemeFamily.h"
#include "model/SubdivisionCurveItem.h"

#include <QJsonArray>
#include <QJsonDocument>

namespace awb::python {

namespace {

AtlasOptions atlasOptions(const py::dict &o)
{
    AtlasOptions a;
    for (const auto &[key, value] : o) {
        const std::string k = py::str(key);
        if (k == "smoothness")
            a.smoothness = int(intArg(value, "atlas option smoothness", 0, 30));
        else if (k == "tolerance")
            a.tolerance = realArg(value, "atlas option tolerance", 1e-15, 1e6);
        else if (k == "sections")
            a.sections = int(intArg(value, "atlas option sections", 1, 64));
        else if (k == "rounds")
            a.maxRounds = int(intArg(value, "atlas option rounds", 0, 64));
        else if (k == "refine")
            a.refineLevels = int(intArg(value, "atlas option refine", 0, 10));
        else if (k == "work")
            a.work = (long long)realArg(value, "atlas option work", 1000, 1e11);
        else if (k == "polytope_vertices")
            a.polytopeVertices = int(intArg(value, "atlas option polytope_vertices", 0, 100000));
        else if (k == "safety")
            a.safetySeconds = realArg(value, "atlas option safety", 1e-3, 86400);
        else
            throw Error(QString("unknown atlas option '%1' (smoothness, tolerance, sections, "
                                "rounds, refine, work, polytope_vertices, safety)")
                            .arg(QString::fromStdString(k)));
    }
    return a;
}

py::dict optionsDict(const AtlasOptions &a)
{
    py::dict d;
    d["smoothness"] = a.smoothness;
    d["tolerance"] = a.tolerance;
    d["sections"] = a.sections;
    d["rounds"] = a.maxRounds;
    d["refine"] = a.refineLevels;
    d["work"] = a.work;
    d["polytope_vertices"] = a.polytopeVertices;
    d["safety"] = a.safetySeconds;
    return d;
}

std::vector<double> valuesArg(const py::handle &h, const char *what)
{
    if (!py::isinstance<py::sequence>(h) || py::isinstance<py::str>(h))
        throw py::type_error(std::string(what) + ": expected a sequence of numbers");
    std::vector<double> out;
    for (const py::handle &v : h.cast<py::sequence>())
        out.push_back(realArg(v, what, -1e300, 1e300));
    return out;
}

py::dict runJson(const AtlasBoundary &b)
{
    py::dict d;
    d["inner"] = b.inner;
    d["outer"] = b.outer;
    d["range_end"] = b.rangeEnd;
    d["certified_not"] = !b.rangeEnd && !b.undecided;
    return d;
}

// A row as a dict, its "params" in the axes' order (a QJsonObject sorts its keys).
py::dict rowDict(const AtlasRow &row, const std::vector<AtlasAxis> &axes)
{
    py::dict d = toPy(atlasRowJson(row, axes));
    py::dict params;
    for (size_t a = 0; a < axes.size() && a < row.params.size(); ++a)
        params[py::str(axes[a].name)] = row.params[a];
    d["params"] = params;
    return d;
}

} // namespace

void defineAtlas(py::module_ &m)
{
    py::class_<SchemeFamily>(
        m, "Family",
        "A family of a subdivision curve's scheme: the item's scheme with one or two real "
        "parameters moved (omega of the four-point scheme, a and b of corner cutting, or names "
        "written into a mask). Plain data: it pickles, so a cluster's workers rebuild it.")
        .def(py::init([](const ItemHandle &h, const py::object &parameters,
                         const py::object &mask) {
                 auto *curve = qobject_cast<SubdivisionCurveItem *>(&h.get());
                 if (!curve)
                     throw Error(QString("item '%1' is not a subdivision curve: its scheme has "
                                         "no parameter to move")
                                     .arg(h.get().name()));
                 QStringList names;
                 if (py::isinstance<py::str>(parameters))
                     names << toQString(parameters, "Family(): parameters");
                 else
                     for (const py::handle &p : parameters.cast<py::sequence>())
                         names << toQString(p, "Family(): parameters");
                 return SchemeFamily::ofItem(*curve, names,
                                             mask.is_none() ? QString()
                                                            : toQString(mask, "Family(): mask"));
             }),
             py::arg("item"), py::arg("parameters"), py::arg("mask") = py::none(),
             "Family(item, parameters, mask=None)\n\n`parameters`: a name or a list of one or "
             "two names. Without `mask`: \"omega\" (four-point) or \"a\", \"b\" (corner "
             "cutting). With `mask` (a mask item): the names written in it, e.g. "
             "Family(item, [\"w\", \"v\"], \"v, 0, w, 0, 1/2 - w - v, 1, 1/2 - w - v, 0, w, 0, "
             "v\"). Raises Error when the item or the names do not fit.")
        .def_property_readonly("parameters",
                               [](const SchemeFamily &f) {
                                   py::list l;
                                   for (const QString &p : f.parameters())
                                       l.append(toPy(p));
                                   return l;
                               },
                               "The parameters' names, in the order of the values.")
        .def_property_readonly("mask", [](const SchemeFamily &f) { return toPy(f.mask()); },
                               "The mask with the parameters in it (\"\" without one).")
        .def(
            "evaluate",
            [](const SchemeFamily &f, const py::handle &values, const py::dict &options) {
                const std::vector<double> v = valuesArg(values, "evaluate(): values");
                if (v.size() != size_t(f.parameters().size()))
                    throw Error(QString("evaluate(): expected %1 values, got %2")
                                    .arg(f.parameters().size())
                                    .arg(v.size()));
                const AtlasOptions o = atlasOptions(options);
                std::vector<AtlasAxis> axes;
                for (const QString &p : f.parameters())
                    axes.push_back({p.toStdString(), 0.0, 1.0, 2});
                AtlasRow row;
                {
                    py::gil_scoped_release release;
                    row = evaluateAtlasPoint(f.atlasMember(), v, o);
                }
                py::dict d = rowDict(row, axes);
                d["seconds"] = row.seconds;
                return d;
            },
            py::arg("values"), py::arg("options") = py::dict(),
            "evaluate(values, options={}) -> dict\n\nThe atlas row of the member at `values` "
            "(one per parameter): {\"params\", \"applies\", \"lower\", \"upper\", \"exact\", "
            "\"verdict\", \"smoothness\", \"sobolev\", \"timed_out\", \"message\", "
            "\"seconds\"}. Certified under a budget of work (options \"work\", "
            "\"polytope_vertices\"), so the same on every machine.")
        .def("to_json", [](const SchemeFamily &f) { return toPy(f.toJson()); },
             "to_json() -> dict\n\nThe family as plain data: {\"scheme\", \"control_points\", "
             "\"parameters\", \"mask\"}.")
        .def_static(
            "from_json",
            [](const py::handle &d) {
                return SchemeFamily::fromJson(toJsonObject(d, "Family.from_json()"));
            },
            py::arg("json"), "from_json(json) -> Family\n\nThe family of to_json()'s dict.")
        .def(py::pickle([](const SchemeFamily &f) { return toPy(f.toJson()); },
                        [](const py::dict &d) {
                            return SchemeFamily::fromJson(toJsonObject(d, "Family pickle"));
                        }))
        .def("__repr__", [](const SchemeFamily &f) {
            return toPy(QString("<Family %1 of %2>")
                            .arg(f.parameters().join(", "),
                                 SchemeSpec::kindNames().at(int(f.base().kind))));
        });

    py::class_<AtlasPlan>(
        m, "AtlasPlan",
        "The regularity atlas's plan (core RegularityAtlas.h): batches of parameter points to "
        "evaluate, refined where the verdict C^k changes. next_batch() gives a batch, accept() "
        "takes its rows in the same order; the points of a batch are independent, so any "
        "executor runs them, and the rows are the same wherever they ran.")
        .def(py::init([](const py::handle &axes, const py::dict &options) {
                 std::vector<AtlasAxis> a;
                 for (const py::handle &axis : axes.cast<py::sequence>()) {
                     const py::sequence t = axis.cast<py::sequence>();
                     if (t.size() != 4)
                         throw Error("AtlasPlan(): each axis is (name, from, to, count)");
                     a.push_back({toQString(t[0], "AtlasPlan(): name").toStdString(),
                                  realArg(t[1], "AtlasPlan(): from", -1e300, 1e300),
                                  realArg(t[2], "AtlasPlan(): to", -1e300, 1e300),
                                  int(intArg(t[3], "AtlasPlan(): count", 0, 1 << 30))});
                 }
                 return AtlasPlan(a, atlasOptions(options));
             }),
             py::arg("axes"), py::arg("options") = py::dict(),
             "AtlasPlan(axes, options={})\n\n`axes`: one or two (name, from, to, count). "
             "`options`: smoothness (k, default 1), tolerance (1D bracket width, 1e-6), "
             "sections (1D points per bracket and round, 8), rounds (16), refine (2D levels, "
             "3), work (JSR products per point, 1e5), polytope_vertices (300), safety (s, "
             "120).")
        .def("next_batch", [](AtlasPlan &p) {
            py::list out;
            for (const std::vector<double> &point : p.nextBatch()) {
                py::list l;
                for (double v : point)
                    l.append(v);
                out.append(l);
            }
            return out;
        }, "next_batch() -> list of points (lists of floats); empty when the atlas is done")
        .def(
            "accept",
            [](AtlasPlan &p, const py::handle &rows) {
                std::vector<AtlasRow> out;
                for (const py::handle &r : rows.cast<py::sequence>())
                    out.push_back(atlasRowFromJson(toJsonObject(r, "accept(): row"), p.axes()));
                p.accept(out);
            },
            py::arg("rows"), "accept(rows): the rows of the last batch, in its order")
        .def_property_readonly("finished", &AtlasPlan::finished,
                               "True when next_batch() has nothing more to give.")
        .def_property_readonly("round", &AtlasPlan::round, "Batches handed out so far.")
        .def_property_readonly(
            "options", [](const AtlasPlan &p) { return optionsDict(p.options()); },
            "Every option with its value: what Family.evaluate needs for this plan's points.")
        .def_property_readonly("axes",
                               [](const AtlasPlan &p) {
                                   py::list l;
                                   for (const AtlasAxis &a : p.axes())
                                       l.append(py::make_tuple(a.name, a.from, a.to, a.count));
                                   return l;
                               },
                               "The axes, as (name, from, to, count).")
        .def("rows",
             [](const AtlasPlan &p) {
                 py::list l;
                 for (const AtlasRow &r : p.rows()) {
                     py::dict d = rowDict(r, p.axes());
                     py::list cell;
                     for (double c : p.cellSize(r))
                         cell.append(c);
                     d["cell"] = cell;
                     l.append(d);
                 }
                 return l;
             },
             "rows() -> list of dicts, sorted by parameter (see Family.evaluate), each with "
             "\"cell\": the size of the grid cell it stands for")
        .def(
            "runs",
            [](const AtlasPlan &p) {
                py::list l;
                for (const AtlasRun &r : p.runs()) {
                    py::dict d;
                    d["from"] = runJson(r.from);
                    d["to"] = runJson(r.to);
                    l.append(d);
                }
                return l;
            },
            "runs() -> list of {\"from\", \"to\"}: one parameter's intervals of certified C^k, "
            "each end {\"inner\" (certified C^k), \"outer\", \"range_end\", \"certified_not\"}");
}

} // namespace awb::python
