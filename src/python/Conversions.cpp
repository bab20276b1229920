#include "python/Conversions.h"

#include "python/Handles.h"

#include "model/NumberFormat.h"
#include "model/Parameters.h"

#include <QJsonArray>
#include <QPointF>

#include <cmath>

namespace awb::python {

namespace {

QString typeName(const py::handle &h)
{
    return QString::fromStdString(py::str(py::type::of(h).attr("__name__")));
}

} // namespace

QString toQString(const py::handle &h, const char *what)
{
    if (!py::isinstance<py::str>(h))
        throw py::type_error(
            QString("%1: expected a str, got %2").arg(what, typeName(h)).toStdString());
    Py_ssize_t size = 0;
    const char *utf8 = PyUnicode_AsUTF8AndSize(h.ptr(), &size);
    if (!utf8) {
        PyErr_Clear();
        throw Error(QString("%1: not valid text (it holds a lone surrogate)").arg(what));
    }
    return QString::fromUtf8(utf8, qsizetype(size));
}

QString pathArg(const py::handle &h, const char *what)
{
    const py::module_ os = py::module_::import("os");
    if (!py::isinstance<py::str>(h) && !py::isinstance<py::bytes>(h)
        && !py::hasattr(h, "__fspath__"))
        throw py::type_error(QString("%1: expected a file name (str or os.PathLike), got %2")
                                 .arg(what, typeName(h))
                                 .toStdString());
    return toQString(os.attr("fsdecode")(h), what);
}

long long intArg(const py::handle &h, const char *what, long long lo, long long hi)
{
    if (py::isinstance<py::bool_>(h)
        || (!py::isinstance<py::int_>(h) && !py::hasattr(h, "__index__")))
        throw py::type_error(QString("%1: expected a whole number, got %2")
                                 .arg(what, typeName(h))
                                 .toStdString());
    // numpy integers and other objects with __index__ (a float or an array raises there)
    const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(h.ptr()));
    if (!index) {
        PyErr_Clear();
        throw py::type_error(QString("%1: expected a whole number, got %2")
                                 .arg(what, typeName(h))
                                 .toStdString());
    }
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
    if (overflow != 0 || v < lo || v > hi)
        throw Error(QString("%1: %2 is out of range %3..%4")
                        .arg(what, QString::fromStdString(py::repr(index)))
                        .arg(lo)
                        .arg(hi));
    return v;
}

double realArg(const py::handle &h, const char *what, double lo, double hi)
{
    if (py::isinstance<py::bool_>(h) || py::isinstance<py::str>(h) || !py::hasattr(h, "__float__"))
        throw py::type_error(
            QString("%1: expected a number, got %2").arg(what, typeName(h)).toStdString());
    const double v = PyFloat_AsDouble(h.ptr());
    if (PyErr_Occurred()) {
        PyErr_Clear();
        throw Error(QString("%1: %2 is not a number this program can use")
                        .arg(what, QString::fromStdString(py::repr(h))));
    }
    if (!std::isfinite(v) || v < lo || v > hi)
        throw Error(QString("%1: %2 is out of range %3..%4").arg(what).arg(v).arg(lo).arg(hi));
    return v;
}

py::str toPy(const QString &s) { return py::str(s.toStdString()); }

py::object toPy(const QJsonValue &v)
{
    switch (v.type()) {
    case QJsonValue::Null:
    case QJsonValue::Undefined:
        return py::none();
    case QJsonValue::Bool:
        return py::bool_(v.toBool());
    case QJsonValue::Double: {
        const QVariant var = v.toVariant();
        if (var.typeId() == QMetaType::LongLong)
            return py::int_(var.toLongLong());
        return py::float_(v.toDouble());
    }
    case QJsonValue::String:
        return toPy(v.toString());
    case QJsonValue::Array: {
        py::list l;
        for (const QJsonValue &e : v.toArray())
            l.append(toPy(e));
        return l;
    }
    case QJsonValue::Object:
        return toPy(v.toObject());
    }
    return py::none();
}

py::dict toPy(const QJsonObject &o)
{
    py::dict d;
    for (auto it = o.begin(); it != o.end(); ++it)
        d[toPy(it.key())] = toPy(it.value());
    return d;
}

QJsonValue toJson(const py::handle &h, const QString &where, int depth)
{
    if (depth > 200)
        throw Error(QString("%1: nested more than 200 levels deep (or a list or dict that "
                            "holds itself)").arg(where));
    if (h.is_none())
        return QJsonValue::Null;
    if (py::isinstance<py::bool_>(h))
        return h.cast<bool>();
    if (py::isinstance<py::str>(h))
        return toQString(h, "text");
    if (py::isinstance<py::int_>(h)) {
        int overflow = 0;
        const long long v = PyLong_AsLongLongAndOverflow(h.ptr(), &overflow);
        if (overflow == 0 && std::llabs(v) < 9000000000000000ll)
            return QJsonValue(qint64(v));
        return realArg(h, qPrintable(where), -1.7e308, 1.7e308);
    }
    if (py::isinstance<py::float_>(h)) {
        const double v = h.cast<double>();
        if (!std::isfinite(v))
            throw Error(QString("%1: %2 is not a finite number").arg(where).arg(v));
        return v;
    }
    if (py::isinstance<py::dict>(h)) {
        QJsonObject o;
        for (auto [k, v] : py::reinterpret_borrow<py::dict>(h)) {
            if (!py::isinstance<py::str>(k))
                throw py::type_error(QString("%1: the keys of a dict must be str, got %2")
                                         .arg(where, typeName(k))
                                         .toStdString());
            const QString key = toQString(k, "key");
            o[key] = toJson(v, where + "." + key, depth + 1);
        }
        return o;
    }
    if (py::isinstance<py::array>(h))
        return toJson(h.attr("tolist")(), where, depth + 1);
    if (py::isinstance<py::list>(h) || py::isinstance<py::tuple>(h)) {
        QJsonArray a;
        int i = 0;
        for (const py::handle e : h)
            a.append(toJson(e, QString("%1[%2]").arg(where).arg(i++), depth + 1));
        return a;
    }
    const py::module_ fractions = py::module_::import("fractions");
    if (py::isinstance(h, fractions.attr("Fraction"))) {
        const QString text = QString::fromStdString(py::str(h));
        return text;
    }
    if (py::hasattr(h, "__float__") && py::hasattr(h, "dtype"))  // numpy scalars
        return toJson(h.attr("item")(), where, depth + 1);
    throw py::type_error(QString("%1: a %2 cannot be written to a project file")
                             .arg(where, typeName(h))
                             .toStdString());
}

QJsonObject toJsonObject(const py::handle &h, const QString &where)
{
    if (!py::isinstance<py::dict>(h))
        throw py::type_error(
            QString("%1: expected a dict, got %2").arg(where, typeName(h)).toStdString());
    return toJson(h, where, 0).toObject();
}

py::array_t<double> toNumpy(const Mat &m)
{
    py::array_t<double> a({py::ssize_t(m.rows()), py::ssize_t(m.cols())});
    auto r = a.mutable_unchecked<2>();
    for (Eigen::Index i = 0; i < m.rows(); ++i)
        for (Eigen::Index j = 0; j < m.cols(); ++j)
            r(i, j) = m(i, j);
    return a;
}

py::array_t<double> toNumpy(const CMat &m)
{
    py::array_t<std::complex<double>> a({py::ssize_t(m.rows()), py::ssize_t(m.cols())});
    auto r = a.mutable_unchecked<2>();
    for (Eigen::Index i = 0; i < m.rows(); ++i)
        for (Eigen::Index j = 0; j < m.cols(); ++j)
            r(i, j) = m(i, j);
    return py::reinterpret_borrow<py::array_t<double>>(a);
}

py::array exactArray(const Mat &m)
{
    const py::object Fraction = py::module_::import("fractions").attr("Fraction");
    py::list rows;
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
        py::list row;
        for (Eigen::Index j = 0; j < m.cols(); ++j) {
            if (const auto f = exactFraction(m(i, j)))
                row.append(Fraction(f->numerator, f->denominator));
            else
                row.append(py::float_(m(i, j)));
        }
        rows.append(row);
    }
    py::array out = py::array(py::dtype("O"), {py::ssize_t(m.rows()), py::ssize_t(m.cols())}, {});
    for (Eigen::Index i = 0; i < m.rows(); ++i)
        for (Eigen::Index j = 0; j < m.cols(); ++j)
            out[py::make_tuple(i, j)] = rows[size_t(i)].cast<py::list>()[size_t(j)];
    return out;
}

Mat toPoints(const py::handle &h, int dim, const QString &where)
{
    py::array_t<double, py::array::c_style | py::array::forcecast> a;
    try {
        a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(h);
    } catch (const py::error_already_set &) {
    }
    if (!a) {
        const QString text =
            QString("%1: expected points as a numpy array or a list of [x, y%2], got %3")
                .arg(where, dim == 3 ? ", z" : "", typeName(h));
        // Not a sequence at all: the wrong type; a list that is not one of points: a value.
        if (py::isinstance<py::list>(h) || py::isinstance<py::tuple>(h)
            || py::isinstance<py::array>(h))
            throw Error(text);
        throw py::type_error(text.toStdString());
    }
    if (a.ndim() == 1 && a.shape(0) == dim)
        a = a.reshape({py::ssize_t(1), py::ssize_t(dim)});
    if (a.ndim() != 2 || a.shape(1) != dim)
        throw Error(QString("%1: expected an array of shape (n, %2), got shape %3")
                        .arg(where)
                        .arg(dim)
                        .arg(QString::fromStdString(py::str(py::tuple(a.attr("shape"))))));
    Mat m(a.shape(0), dim);
    auto r = a.unchecked<2>();
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
        for (int j = 0; j < dim; ++j) {
            if (!std::isfinite(r(i, j)))
                throw Error(QString("%1: point %2 has a coordinate that is not a finite number "
                                    "(%3)")
                                .arg(where)
                                .arg(i)
                                .arg(r(i, j)));
            m(i, j) = r(i, j);
        }
    return m;
}

py::object parameterToPy(const ParameterInfo &info, const QVariant &value)
{
    using T = ParameterInfo::Type;
    switch (info.type) {
    case T::Real:
        return py::float_(value.toDouble());
    case T::Integer:
    case T::Choice:
        return py::int_(value.toInt());
    case T::Complex: {
        const QPointF z = value.toPointF();
        return py::reinterpret_steal<py::object>(PyComplex_FromDoubles(z.x(), z.y()));
    }
    case T::Bool:
        return py::bool_(value.toBool());
    case T::Text:
        return toPy(value.toString());
    }
    return py::none();
}

QVariant parameterFromPy(const ParameterInfo &info, const py::handle &h)
{
    using T = ParameterInfo::Type;
    const QString where = QString("parameter '%1'").arg(info.key);
    auto number = [&]() -> double {
        if (py::isinstance<py::bool_>(h) || py::isinstance<py::str>(h)
            || !py::hasattr(h, "__float__"))
            throw py::type_error(
                QString("%1: expected a number, got %2").arg(where, typeName(h)).toStdString());
        const double v = PyFloat_AsDouble(h.ptr());
        if (PyErr_Occurred()) {
            PyErr_Clear();
            throw Error(QString("%1: %2 is not a number this program can use")
                            .arg(where, QString::fromStdString(py::repr(h))));
        }
        if (!std::isfinite(v))
            throw Error(QString("%1: %2 is not a finite number").arg(where).arg(v));
        return v;
    };
    switch (info.type) {
    case T::Real:
        return number();
    case T::Integer: {
        const double v = number();
        if (v != std::floor(v) || std::abs(v) > 2e9)
            throw Error(QString("%1: expected a whole number, got %2").arg(where).arg(v));
        return int(v);
    }
    case T::Choice: {
        if (py::isinstance<py::str>(h)) {
            const QString text = toQString(h, "choice");
            for (int i = 0; i < info.choices.size(); ++i)
                if (info.choices[i].compare(text, Qt::CaseInsensitive) == 0)
                    return i;
            throw Error(QString("%1: '%2' is not one of: %3")
                            .arg(where, text, info.choices.join(", ")));
        }
        const double v = number();
        if (v != std::floor(v) || v < 0 || v >= info.choices.size())
            throw Error(QString("%1: expected a choice index 0..%2 or its text (%3)")
                            .arg(where)
                            .arg(info.choices.size() - 1)
                            .arg(info.choices.join(", ")));
        return int(v);
    }
    case T::Complex: {
        if (!py::hasattr(h, "__complex__") && !py::hasattr(h, "__float__"))
            throw py::type_error(QString("%1: expected a complex number, got %2")
                                     .arg(where, typeName(h))
                                     .toStdString());
        const Py_complex z = PyComplex_AsCComplex(h.ptr());
        if (PyErr_Occurred())
            throw py::error_already_set();
        if (!std::isfinite(z.real) || !std::isfinite(z.imag))
            throw Error(QString("%1: not a finite complex number").arg(where));
        return QPointF(z.real, z.imag);
    }
    case T::Bool:
        if (!py::isinstance<py::bool_>(h))
            throw py::type_error(QString("%1: expected True or False, got %2")
                                     .arg(where, typeName(h))
                                     .toStdString());
        return h.cast<bool>();
    case T::Text:
        return toQString(h, "text");
    }
    return {};
}

} // namespace awb::python
