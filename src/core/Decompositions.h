#pragma once
// Eigen's dense decompositions on the core's matrices (Mat, CMat), compiled once, in
// Decompositions.cpp, instead of in every file that uses one. Include this header instead of
// <Eigen/Dense> or <Eigen/Eigenvalues>: its explicit instantiation declarations stop each
// includer from instantiating and optimising the decompositions' bodies again (EigenSolver and
// ComplexEigenSolver alone were about half of Spectrum.cpp's 65 s at -O3; clang -ftime-trace,
// issue 29). Only the members that take the core's own matrix types are shared: an eigen
// solver handed an expression (M.transpose()) instantiates its own copy, so the callers pass
// a Mat or CMat.

#include "core/Types.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

// AWB_EIGEN_DECOMPOSITIONS(extern) declares, AWB_EIGEN_DECOMPOSITIONS() defines them.
#define AWB_EIGEN_DECOMPOSITIONS(EXTERN)                                                       \
    EXTERN template class Eigen::JacobiSVD<awb::Mat>;                                          \
    EXTERN template class Eigen::JacobiSVD<awb::CMat>;                                         \
    EXTERN template class Eigen::FullPivLU<awb::Mat>;                                          \
    EXTERN template class Eigen::FullPivLU<awb::CMat>;                                         \
    EXTERN template class Eigen::PartialPivLU<awb::Mat>;                                       \
    EXTERN template class Eigen::HouseholderQR<awb::Mat>;                                      \
    EXTERN template class Eigen::ColPivHouseholderQR<awb::Mat>;                                \
    EXTERN template class Eigen::CompleteOrthogonalDecomposition<awb::Mat>;                    \
    EXTERN template class Eigen::LLT<awb::Mat>;                                                \
    EXTERN template class Eigen::EigenSolver<awb::Mat>;                                        \
    EXTERN template Eigen::EigenSolver<awb::Mat> &Eigen::EigenSolver<awb::Mat>::compute(       \
        const Eigen::EigenBase<awb::Mat> &, bool);                                             \
    EXTERN template class Eigen::ComplexEigenSolver<awb::CMat>;                                \
    EXTERN template Eigen::ComplexEigenSolver<awb::CMat>                                       \
        &Eigen::ComplexEigenSolver<awb::CMat>::compute(const Eigen::EigenBase<awb::CMat> &,    \
                                                      bool);                                   \
    EXTERN template class Eigen::SelfAdjointEigenSolver<awb::Mat>;                             \
    EXTERN template Eigen::SelfAdjointEigenSolver<awb::Mat>                                    \
        &Eigen::SelfAdjointEigenSolver<awb::Mat>::compute(const Eigen::EigenBase<awb::Mat> &,  \
                                                          int);

AWB_EIGEN_DECOMPOSITIONS(extern)
