#include "core/Types.h"

#include "core/Messages.h"

#include <cmath>

namespace awb {

namespace {
template<class M>
void requireFiniteImpl(const M &m, const std::string &what)
{
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
        for (Eigen::Index c = 0; c < m.cols(); ++c) {
            if (!std::isfinite(std::abs(m(r, c))))
                throw InputError(formatMessage(
                    coreTranslate("awb::core", "%1: entry (row %2, column %3) is not a finite "
                                               "number"),
                    what, r + 1, c + 1));
        }
    }
}
} // namespace

Mat matrixFromRows(std::initializer_list<std::initializer_list<double>> rows)
{
    const Eigen::Index cols = rows.size() ? Eigen::Index(rows.begin()->size()) : 0;
    Mat M(Eigen::Index(rows.size()), cols);
    Eigen::Index i = 0;
    for (auto row : rows) {
        if (Eigen::Index(row.size()) != cols)
            throw InputError(coreTranslate("awb::core", "matrix rows of different lengths"));
        Eigen::Index j = 0;
        for (double v : row)
            M(i, j++) = v;
        ++i;
    }
    return M;
}

void requireFinite(const Mat &m, const std::string &what) { requireFiniteImpl(m, what); }
void requireFinite(const CMat &m, const std::string &what) { requireFiniteImpl(m, what); }

} // namespace awb
