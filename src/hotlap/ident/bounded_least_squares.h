#pragma once
/// @file
/// Linear least squares with bounds on the unknowns, for the equation-error starting guesses of
/// the thermal fits (docs/fitting.md): min |A x - b|^2 subject to lower <= x <= upper.

#include <Eigen/Core>

namespace hotlap::ident {

/// Solves the bounded problem from `start` (clamped into the bounds) with Ceres (the columns are
/// scaled to unit norm first, so unknowns of very different sizes are treated alike). A column of
/// zeros leaves its unknown at its start. Bounds may be infinite.
Eigen::VectorXd SolveBoundedLeastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                                         const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                         const Eigen::VectorXd& start);

}  // namespace hotlap::ident
