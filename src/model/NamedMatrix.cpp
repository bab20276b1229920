#include "model/NamedMatrix.h"

#include "model/AttractorItem.h"
#include "model/NumberFormat.h"

#include <QMap>
#include <QStringList>

#include <cmath>

namespace awb {

QList<NamedMatrix> namedMatrices(const DerivedIfs &d, bool sEditable)
{
    QList<NamedMatrix> list;
    for (std::size_t i = 0; i < d.S.real.size(); ++i)
        list.append({QStringLiteral("S_%1").arg(i + 1), d.S.real[i], -1, sEditable});
    if (d.subdivision) {
        const auto &lifted = d.subdivision->lifted;
        for (std::size_t i = 0; i < lifted.size(); ++i)
            list.append({QStringLiteral("M_%1").arg(i + 1), lifted[i].M, int(lifted[i].A.rows()),
                         false});
    } else if (d.S.isComplex()) {
        // Complex de Casteljau L(t), R(t) and their complex lifted maps (004 §3.7).
        for (std::size_t i = 0; i < d.S.complex.size(); ++i) {
            list.append({QStringLiteral("S_%1").arg(i + 1), d.S.complex[i]});
        }
        for (std::size_t i = 0; i < d.liftedComplex.size(); ++i) {
            const CMat &M = d.liftedComplex[i];
            list.append({QStringLiteral("M_%1").arg(i + 1), M, int(M.rows()) - 1});
        }
    } else if (d.S.real.empty()) {
        // Items without subdivision matrices (fractals, automata): their affine maps.
        for (int i = 0; i < d.ifs.size(); ++i) {
            const AffineMap &f = d.ifs.maps[std::size_t(i)];
            Mat M = Mat::Zero(f.dim() + 1, f.dim() + 1);
            M.topLeftCorner(f.dim(), f.dim()) = f.A;
            M.block(f.dim(), 0, 1, f.dim()) = f.b;
            M(f.dim(), f.dim()) = 1.0;
            list.append({QStringLiteral("f_%1").arg(i + 1), M, f.dim(), false});
        }
    }
    return list;
}

QString latexNumber(double v, int digits)
{
    if (const auto f = exactFraction(v, 4096, 1e-13)) {
        if (f->denominator == 1)
            return QString::number(f->numerator);
        return QStringLiteral("%1\\frac{%2}{%3}")
            .arg(f->numerator < 0 ? QStringLiteral("-") : QString())
            .arg(std::llabs(f->numerator))
            .arg(f->denominator);
    }
    if (!std::isfinite(v))
        return std::isnan(v) ? QStringLiteral("\\mathrm{NaN}")
                             : (v > 0 ? QStringLiteral("\\infty") : QStringLiteral("-\\infty"));
    QString t = QString::number(v, 'g', digits);
    const int e = int(t.indexOf(QLatin1Char('e')));
    if (e >= 0) {
        // 1.5e-07 -> 1.5 \cdot 10^{-7}
        const int exponent = t.mid(e + 1).toInt();
        t = QStringLiteral("%1 \\cdot 10^{%2}").arg(t.left(e)).arg(exponent);
    }
    return t;
}

QString latexComplex(std::complex<double> z, int digits)
{
    const double scale = std::max(std::abs(z.real()), std::abs(z.imag()));
    const bool real = std::abs(z.imag()) <= 1e-12 * std::max(1.0, scale);
    const bool imaginary = std::abs(z.real()) <= 1e-12 * std::max(1.0, scale);
    if (real)
        return latexNumber(z.real(), digits);
    const double im = std::abs(z.imag());
    QString imText = im == 1.0 ? QString() : latexNumber(im, digits);
    if (imText.contains(QLatin1String("\\frac")) || imText.contains(QLatin1String("cdot")))
        imText = QStringLiteral("\\left(%1\\right)").arg(imText);
    const QString imPart = imText + QLatin1Char('i');
    if (imaginary)
        return (z.imag() < 0 ? QStringLiteral("-") : QString()) + imPart;
    return QStringLiteral("%1 %2 %3").arg(latexNumber(z.real(), digits),
                                          z.imag() < 0 ? QStringLiteral("-") : QStringLiteral("+"),
                                          imPart);
}

namespace {

// "S_1" -> "S_{1}", "M_12" -> "M_{12}", "S_{1}" unchanged, "P" unchanged.
QString latexName(const QString &name)
{
    const int u = int(name.indexOf(QLatin1Char('_')));
    if (u < 0 || name.mid(u + 1).startsWith(QLatin1Char('{')))
        return name;
    return QStringLiteral("%1_{%2}").arg(name.left(u), name.mid(u + 1));
}

} // namespace

QString latexMatrix(const NamedMatrix &m, int digits)
{
    QStringList rows;
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
        QStringList cells;
        for (Eigen::Index c = 0; c < m.cols(); ++c)
            cells << (m.isComplex() ? latexComplex(m.complexValues(r, c), digits)
                                    : latexNumber(m.values(r, c), digits));
        rows << QStringLiteral("  ") + cells.join(QStringLiteral(" & "));
    }
    return QStringLiteral("%1 = \\begin{bmatrix}\n%2\n\\end{bmatrix}")
        .arg(latexName(m.name), rows.join(QStringLiteral(" \\\\\n")));
}

QString latexMatrices(const QList<NamedMatrix> &matrices, const QString &title, int digits)
{
    QString out;
    if (!title.isEmpty())
        out += QStringLiteral("% %1 (Attractor Workbench; needs \\usepackage{amsmath})\n")
                   .arg(title);
    for (const NamedMatrix &m : matrices)
        out += QStringLiteral("\\[\n%1\n\\]\n").arg(latexMatrix(m, digits));
    return out;
}

namespace {

QString matlabComplex(std::complex<double> z)
{
    if (z.imag() == 0.0)
        return exactText(z.real());
    QString im = exactText(std::abs(z.imag()));
    if (im.contains(QLatin1Char('/')))
        im = QStringLiteral("(%1)").arg(im);
    return QStringLiteral("%1%2%3i")
        .arg(exactText(z.real()), z.imag() < 0 ? QStringLiteral("-") : QStringLiteral("+"), im);
}

template <class M, class Entry>
QString matlabMatrix(const M &m, Eigen::Index rows, Eigen::Index cols, Entry entry)
{
    QStringList lines;
    for (Eigen::Index r = 0; r < rows; ++r) {
        QStringList row;
        for (Eigen::Index c = 0; c < cols; ++c)
            row << entry(m(r, c));
        lines << row.join(QLatin1Char(' '));
    }
    return QStringLiteral("[") + lines.join(QStringLiteral("; ")) + QStringLiteral("]");
}

// The cell array a matrix goes to: the letters before its subscript ("S_1" -> "S"), a MATLAB
// identifier; "S" when there is none.
QString matlabGroup(const QString &name)
{
    QString key;
    for (const QChar c : name) {
        if (!(c.isLetterOrNumber() && c.unicode() < 128))
            break;
        key += c;
    }
    return key.isEmpty() || key[0].isDigit() ? QStringLiteral("S") : key;
}

} // namespace

QString matlabMatrices(const QList<NamedMatrix> &matrices, const QString &title)
{
    // Cell arrays in the order their kinds first appear; A after M.
    QStringList order;
    QMap<QString, QStringList> cells;
    const auto add = [&](const QString &group, const QString &text) {
        if (!cells.contains(group))
            order << group;
        cells[group] << text;
    };
    for (const NamedMatrix &m : matrices) {
        const QString group = matlabGroup(m.name);
        if (m.isComplex()) {
            add(group, matlabMatrix(m.complexValues, m.rows(), m.cols(), matlabComplex));
            if (m.affineBlock > 0)
                add(QStringLiteral("A"), matlabMatrix(m.complexValues, m.affineBlock,
                                                      m.affineBlock, matlabComplex));
            continue;
        }
        add(group, matlabMatrix(m.values, m.rows(), m.cols(), exactText));
        if (m.affineBlock > 0)  // the linear parts of the M_i or f_i: what jsr() wants
            add(QStringLiteral("A"),
                matlabMatrix(m.values, m.affineBlock, m.affineBlock, exactText));
    }
    QString out;
    if (!title.isEmpty())
        out += QStringLiteral("% %1 (Attractor Workbench): cell arrays for jsr() of the JSR "
                              "toolbox\n")
                   .arg(title);
    for (const QString &group : order)
        out += QStringLiteral("%1 = {%2};\n").arg(group, cells[group].join(QStringLiteral(", ")));
    return out;
}

} // namespace awb
