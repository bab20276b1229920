#pragma once
// Basic numeric types of the math core. Conventions used everywhere in awb::core:
//  * Points are ROW vectors, as in the papers: a map acts as x |-> x A + b (x: 1 x D).
//  * Control points P: m x d (one point per row), d = 2 or 3.
//  * Subdivision matrices S_i: m x m, rows sum to 1 (row-stochastic, "affine" rows).

#include <Eigen/Core>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

namespace awb {

using Mat = Eigen::MatrixXd;
using Vec = Eigen::VectorXd;          // column vector
using RowVec = Eigen::RowVectorXd;
using CMat = Eigen::MatrixXcd;
using CVec = Eigen::VectorXcd;
using Complex = std::complex<double>;

// Bad input to the core: the message names the problem so that a user can fix it
// (e.g. "rule 2 of the scheme sums to 0.875, not 1").
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A matrix written row by row: matrixFromRows({{1, 0}, {0.5, 0.5}}). Rows must have equal
// length (InputError otherwise).
Mat matrixFromRows(std::initializer_list<std::initializer_list<double>> rows);

// Throws InputError naming `what` when m holds a NaN or an infinity.
void requireFinite(const Mat &m, const std::string &what);
void requireFinite(const CMat &m, const std::string &what);

} // namespace awb
