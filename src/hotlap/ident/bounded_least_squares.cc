#include "hotlap/ident/bounded_least_squares.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <ceres/ceres.h>

namespace hotlap::ident {

namespace {

// r = A D u - b with its constant Jacobian A D (D: the column scales).
class LinearResidual final : public ceres::CostFunction {
 public:
  explicit LinearResidual(const Eigen::MatrixXd& ad, const Eigen::VectorXd& b) : ad_(ad), b_(b) {
    set_num_residuals(static_cast<int>(ad.rows()));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(ad.cols()));
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Map<const Eigen::VectorXd> u(parameters[0], ad_.cols());
    Eigen::Map<Eigen::VectorXd>(residuals, ad_.rows()) = ad_ * u - b_;
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          jacobians[0], ad_.rows(), ad_.cols()) = ad_;
    }
    return true;
  }

 private:
  const Eigen::MatrixXd& ad_;
  const Eigen::VectorXd& b_;
};

}  // namespace

Eigen::VectorXd SolveBoundedLeastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                                         const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                         const Eigen::VectorXd& start) {
  const int n = static_cast<int>(a.cols());
  Eigen::VectorXd scale(n);
  for (int j = 0; j < n; ++j) {
    const double norm = a.col(j).norm();
    scale(j) = norm > 0.0 && std::isfinite(norm) ? 1.0 / norm : 1.0;
  }
  const Eigen::MatrixXd ad = a * scale.asDiagonal();
  std::vector<double> u(n);
  for (int j = 0; j < n; ++j) u[j] = std::clamp(start(j), lower(j), upper(j)) / scale(j);
  ceres::Problem problem;
  problem.AddResidualBlock(new LinearResidual(ad, b), nullptr, u.data());
  for (int j = 0; j < n; ++j) {
    if (std::isfinite(lower(j))) problem.SetParameterLowerBound(u.data(), j, lower(j) / scale(j));
    if (std::isfinite(upper(j))) problem.SetParameterUpperBound(u.data(), j, upper(j) / scale(j));
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 200;
  options.function_tolerance = 1e-14;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-12;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  Eigen::VectorXd x(n);
  for (int j = 0; j < n; ++j) x(j) = u[j] * scale(j);
  return x;
}

}  // namespace hotlap::ident
