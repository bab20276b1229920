#pragma once
// Values between Python and the model (internal to src/python): JSON objects as dicts, matrices
// as numpy arrays, exact fractions as fractions.Fraction. Conversions from Python check what
// they get and raise Error naming the argument; nothing reaches the model unchecked.

#include "core/Types.h"

#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QVariant>

// Python's headers name a struct member `slots`, Qt's a macro: hide the macro from them.
#pragma push_macro("slots")
#undef slots
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#pragma pop_macro("slots")

namespace awb {
struct ParameterInfo;
}

namespace awb::python {

namespace py = pybind11;

QString toQString(const py::handle &h, const char *what);
// A file name: a str or an os.PathLike (bytes decoded as the file system does).
QString pathArg(const py::handle &h, const char *what);
// A whole number (an int, not a bool or a float) in [lo, hi]; Error naming `what` otherwise.
long long intArg(const py::handle &h, const char *what, long long lo, long long hi);
// A finite number in [lo, hi].
double realArg(const py::handle &h, const char *what, double lo, double hi);
py::str toPy(const QString &s);

py::object toPy(const QJsonValue &v);
py::dict toPy(const QJsonObject &o);
// Dicts, lists, tuples, str, bool, int, finite float, None, numpy arrays and scalars, and
// fractions.Fraction (as the exact text "p/q" the files keep); `where` names the argument.
QJsonValue toJson(const py::handle &h, const QString &where, int depth = 0);
QJsonObject toJsonObject(const py::handle &h, const QString &where);

py::array_t<double> toNumpy(const Mat &m);
py::array_t<double> toNumpy(const CMat &m);  // complex128
// A matrix's entries as fractions.Fraction where they are exact (NumberFormat's exactFraction:
// the fraction the Matrices dock shows), floats elsewhere: a numpy object array.
py::array exactArray(const Mat &m);

// Rows of `dim` finite coordinates (a numpy array or nested sequences); Error otherwise.
Mat toPoints(const py::handle &h, int dim, const QString &where);

// A parameter's value in Python (Choice: its index; Complex: complex) and back.
py::object parameterToPy(const ParameterInfo &info, const QVariant &value);
QVariant parameterFromPy(const ParameterInfo &info, const py::handle &h);

} // namespace awb::python
