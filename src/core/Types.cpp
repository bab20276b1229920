#include "core/Types.h"

#include <sstream>

namespace awb {

namespace {
template<class M>
void requireFiniteImpl(const M &m, const std::string &what)
{
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
        for (Eigen::Index c = 0; c < m.cols(); ++c) {
            if (!std::isfinite(std::abs(m(r, c)))) {
                std::ostringstream os;
                os << what << ": entry (row " << r + 1 << ", column " << c + 1
                   << ") is not a finite number";
                throw InputError(os.str());
            }
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
            throw InputError("matrix rows of different lengths");
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
