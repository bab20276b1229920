// The list-like view of an item's control points and the dict-like view of its parameters:
// reading gives Python values, every assignment is one undoable edit of the model.

#include "python/Internal.h"

#include "model/AttractorItem.h"
#include "model/Project.h"

#include <map>

namespace awb::python {

namespace {

AttractorItem &itemOf(const PointsHandle &h) { return h.item.attractor(); }

const PointList &pointsOf(const PointsHandle &h)
{
    AttractorItem &a = itemOf(h);
    if (h.set >= a.controlPointSetCount())
        throw Error(QString("item '%1' has no point set %2").arg(a.name()).arg(h.set));
    return a.controlPoints(h.set);
}

Mat pointMatrix(const PointsHandle &h)
{
    return toMatrix(pointsOf(h), itemOf(h).pointDimension());
}

int pointIndex(const PointsHandle &h, py::ssize_t i, bool insert = false)
{
    const py::ssize_t n = py::ssize_t(pointsOf(h).size());
    if (i < 0)
        i += n;
    if (i < 0 || i > n || (i == n && !insert))
        throw py::index_error(QString("point %1 is out of range (the item has %2)")
                                  .arg(i)
                                  .arg(n)
                                  .toStdString());
    return int(i);
}

Point toPoint(const Mat &row)
{
    Point p;
    p.x = row(0, 0);
    p.y = row(0, 1);
    if (row.cols() > 2)
        p.z = row(0, 2);
    return p;
}

QString pointRefusal(AttractorItem &a, int set)
{
    return QString("item '%1': the edit of point set %2 is refused (its scheme fixes the number "
                   "of points, or the set would have more than %3)")
        .arg(a.name())
        .arg(set)
        .arg(a.maxPointCount(set));
}

// A Python index (negative from the end) as a point number; IndexError when out of range.
int pythonIndex(const PointsHandle &h, const py::handle &key, bool insert = false)
{
    int overflow = 0;
    const long long i = PyLong_AsLongLongAndOverflow(key.ptr(), &overflow);
    if (overflow != 0)
        throw py::index_error("point index out of range");
    return pointIndex(h, py::ssize_t(i), insert);
}

// Assigns a whole point set: moves, then inserts or removes at the end, one undo step.
void assignPoints(const PointsHandle &h, const py::handle &value)
{
    AttractorItem &a = itemOf(h);
    const int dim = a.pointDimension();
    const Mat p = toPoints(value, dim, "control_points");
    const int old = int(pointsOf(h).size());
    const int n = int(p.rows());
    if (n != old && !a.pointCountEditable(h.set))
        throw Error(QString("item '%1': its scheme fixes the number of points at %2, got %3")
                        .arg(a.name())
                        .arg(old)
                        .arg(n));
    if (n > a.maxPointCount(h.set))
        throw Error(QString("item '%1': %2 points is more than the %3 a point set may have")
                        .arg(a.name())
                        .arg(n)
                        .arg(a.maxPointCount(h.set)));
    CompoundEdit edit(a.project(), QString("Set the points of %1").arg(a.name()));
    std::map<int, Point> moves;
    for (int i = 0; i < std::min(n, old); ++i)
        moves[i] = toPoint(p.row(i));
    if (!moves.empty() && !a.moveControlPoints(moves, 0, h.set))
        throw Error(pointRefusal(a, h.set));
    for (int i = old; i < n; ++i)
        if (!a.insertControlPoint(i, toPoint(p.row(i)), h.set))
            throw Error(pointRefusal(a, h.set));
    if (n < old) {
        std::vector<int> gone;
        for (int i = n; i < old; ++i)
            gone.push_back(i);
        if (!a.removeControlPoints(gone, h.set))
            throw Error(pointRefusal(a, h.set));
    }
}

const ParameterInfo &parameterInfo(const ParametersHandle &h, const QString &key,
                                   QList<ParameterInfo> &storage)
{
    storage = h.item.get().parameters();
    for (const ParameterInfo &p : storage)
        if (p.key == key)
            return p;
    QStringList keys;
    for (const ParameterInfo &p : storage)
        keys << p.key;
    throw py::key_error(QString("item '%1' has no parameter '%2'%3")
                            .arg(h.item.get().name(), key,
                                 keys.isEmpty() ? QString(" (it has none)")
                                                : " (it has: " + keys.join(", ") + ")")
                            .toStdString());
}

py::dict infoDict(const ParameterInfo &p)
{
    static const char *types[] = {"real", "integer", "choice", "complex", "bool", "text"};
    py::dict d;
    d["key"] = toPy(p.key);
    d["label"] = toPy(p.label);
    d["type"] = types[int(p.type)];
    d["minimum"] = p.minimum;
    d["maximum"] = p.maximum;
    py::list choices;
    for (const QString &c : p.choices)
        choices.append(toPy(c));
    d["choices"] = choices;
    d["group"] = toPy(p.group);
    d["tooltip"] = toPy(p.toolTip);
    d["read_only"] = p.readOnly;
    return d;
}

} // namespace

void defineContainers(py::module_ &m)
{
    py::class_<PointsHandle>(
        m, "ControlPoints",
        "An item's control point set, list-like: len(), cp[i] (a numpy row), cp[i] = [x, y] "
        "(one undo step), cp.insert(i, p), cp.append(p), del cp[i], numpy.asarray(cp) (m, d).")
        .def("__len__", [](const PointsHandle &h) { return pointsOf(h).size(); })
        .def("__array__",
             [](const PointsHandle &h, const py::object &dtype) {
                 py::array a = toNumpy(pointMatrix(h));
                 return dtype.is_none() ? a : py::array(a.attr("astype")(dtype));
             },
             py::arg("dtype") = py::none())
        .def("__getitem__",
             [](const PointsHandle &h, const py::object &key) -> py::object {
                 py::array a = toNumpy(pointMatrix(h));
                 if (py::isinstance<py::int_>(key))
                     return a[py::int_(pythonIndex(h, key))];
                 return a[key];
             })
        .def("__setitem__",
             [](const PointsHandle &h, const py::object &key, const py::object &value) {
                 AttractorItem &a = itemOf(h);
                 if (py::isinstance<py::int_>(key)) {
                     const int i = pythonIndex(h, key);
                     const Mat p = toPoints(value, a.pointDimension(),
                                            QString("control_points[%1]").arg(i));
                     if (p.rows() != 1)
                         throw Error(QString("control_points[%1]: expected one point").arg(i));
                     if (!a.moveControlPoint(i, toPoint(p), 0, h.set))
                         throw Error(pointRefusal(a, h.set));
                     return;
                 }
                 py::array arr = toNumpy(pointMatrix(h));
                 arr[key] = value;
                 assignPoints(h, arr);
             })
        .def("__delitem__",
             [](const PointsHandle &h, const py::int_ &i) {
                 AttractorItem &a = itemOf(h);
                 if (!a.removeControlPoint(pythonIndex(h, i), h.set))
                     throw Error(pointRefusal(a, h.set));
             })
        .def(
            "insert",
            [](const PointsHandle &h, const py::int_ &i, const py::object &value) {
                AttractorItem &a = itemOf(h);
                const Mat p = toPoints(value, a.pointDimension(), "insert()");
                if (p.rows() != 1 || !a.insertControlPoint(pythonIndex(h, i, true), toPoint(p),
                                                           h.set))
                    throw Error(pointRefusal(a, h.set));
            },
            py::arg("index"), py::arg("point"), "insert(index, point): one undo step.")
        .def(
            "append",
            [](const PointsHandle &h, const py::object &value) {
                AttractorItem &a = itemOf(h);
                const Mat p = toPoints(value, a.pointDimension(), "append()");
                if (p.rows() != 1
                    || !a.insertControlPoint(int(pointsOf(h).size()), toPoint(p), h.set))
                    throw Error(pointRefusal(a, h.set));
            },
            py::arg("point"), "append(point): one undo step.")
        .def("assign", &assignPoints, py::arg("points"),
             "assign(points): the whole set, (m, d); one undo step.")
        .def(
            "tolist",
            [](const PointsHandle &h) { return toNumpy(pointMatrix(h)).attr("tolist")(); },
            "tolist() -> list of [x, y] (or [x, y, z]): the points as Python lists.")
        .def_property_readonly(
            "shape",
            [](const PointsHandle &h) {
                const Mat p = pointMatrix(h);
                return py::make_tuple(p.rows(), p.cols());
            },
            "(m, d): the number of points and their coordinates.")
        .def(
            "__contains__",
            [](const PointsHandle &h, const py::object &value) {
                const Mat p = pointMatrix(h);
                const Mat q = toPoints(value, int(p.cols()), "in");
                for (Eigen::Index r = 0; r < p.rows(); ++r)
                    if (q.rows() == 1 && p.row(r) == q.row(0))
                        return true;
                return false;
            },
            "[x, y] in cp: whether a point is one of the control points (exactly).")
        .def("__repr__", [](const PointsHandle &h) {
            return "ControlPoints(" + py::repr(toNumpy(pointMatrix(h))).cast<std::string>() + ")";
        });

    py::class_<ParametersHandle>(
        m, "Parameters",
        "An item's parameters by the Properties dock's keys, dict-like: p[key], p[key] = v (one "
        "undo step; Error with the dock's message when refused), keys(), items(), info(key). "
        "Choices read as their index and take the index or the text.")
        .def(
            "keys",
            [](const ParametersHandle &h) {
                py::list l;
                for (const ParameterInfo &p : h.item.get().parameters())
                    l.append(toPy(p.key));
                return l;
            },
            "keys() -> list of str: the keys, in the Properties dock's order.")
        .def(
            "values",
            [](const ParametersHandle &h) {
                py::list l;
                Item &item = h.item.get();
                for (const ParameterInfo &p : item.parameters())
                    l.append(parameterToPy(p, item.parameter(p.key)));
                return l;
            },
            "values() -> list: the values, in the order of keys().")
        .def(
            "get",
            [](const ParametersHandle &h, const py::object &key, const py::object &fallback) {
                if (!py::isinstance<py::str>(key))
                    return fallback;
                Item &item = h.item.get();
                const QString k = toQString(key, "key");
                for (const ParameterInfo &p : item.parameters())
                    if (p.key == k)
                        return parameterToPy(p, item.parameter(k));
                return fallback;
            },
            py::arg("key"), py::arg("default") = py::none(),
            "get(key, default=None): the value, or `default` when the item has no such key.")
        .def("__iter__", [](const ParametersHandle &h) {
            return py::iter(py::cast(h).attr("keys")());
        })
        .def("__len__", [](const ParametersHandle &h) { return h.item.get().parameters().size(); })
        .def("__contains__",
             [](const ParametersHandle &h, const py::object &key) {
                 if (!py::isinstance<py::str>(key))
                     return false;
                 const QString k = toQString(key, "key");
                 for (const ParameterInfo &p : h.item.get().parameters())
                     if (p.key == k)
                         return true;
                 return false;
             })
        .def("__getitem__",
             [](const ParametersHandle &h, const py::object &key) {
                 QList<ParameterInfo> all;
                 const QString k = toQString(key, "key");
                 const ParameterInfo &info = parameterInfo(h, k, all);
                 return parameterToPy(info, h.item.get().parameter(k));
             })
        .def("__setitem__",
             [](const ParametersHandle &h, const py::object &key, const py::object &value) {
                 QList<ParameterInfo> all;
                 const QString k = toQString(key, "key");
                 const ParameterInfo &info = parameterInfo(h, k, all);
                 if (info.readOnly)
                     throw Error(QString("parameter '%1' is shown, not edited (%2)")
                                     .arg(k, info.label));
                 const QVariant v = parameterFromPy(info, value);
                 QString why;
                 if (!h.item.get().setParameter(k, v, 0, &why))
                     throw Error(refusal(why, QString("parameter '%1': the value is refused")
                                                  .arg(k)));
             })
        .def(
            "items",
            [](const ParametersHandle &h) {
                py::list l;
                Item &item = h.item.get();
                for (const ParameterInfo &p : item.parameters())
                    l.append(py::make_tuple(toPy(p.key), parameterToPy(p, item.parameter(p.key))));
                return l;
            },
            "items() -> list of (key, value).")
        .def(
            "info",
            [](const ParametersHandle &h, const py::object &key) {
                QList<ParameterInfo> all;
                return infoDict(parameterInfo(h, toQString(key, "key"), all));
            },
            py::arg("key"),
            "info(key) -> dict: label, type, minimum, maximum, choices, group, tooltip, "
            "read_only.")
        .def("__repr__", [](const ParametersHandle &h) {
            py::dict d;
            Item &item = h.item.get();
            for (const ParameterInfo &p : item.parameters())
                d[toPy(p.key)] = parameterToPy(p, item.parameter(p.key));
            return "Parameters(" + py::repr(d).cast<std::string>() + ")";
        });
}

} // namespace awb::python
