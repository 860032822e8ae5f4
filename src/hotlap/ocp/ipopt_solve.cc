#include "hotlap/ocp/ipopt_solve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <mutex>

#include <dlfcn.h>

#include <fmt/format.h>

#include <IpIpoptApplication.hpp>
#include <IpIpoptCalculatedQuantities.hpp>
#include <IpIpoptData.hpp>
#include <IpOrigIpoptNLP.hpp>
#include <IpTNLP.hpp>
#include <IpTNLPAdapter.hpp>

#include "hotlap/common/error.h"

namespace hotlap::ocp {

namespace {

// How Ipopt's ends read in plain words.
struct StatusWords {
  Ipopt::SolverReturn ipopt;
  SolveStatus status;
  const char* message;
};

constexpr const char* kNumericalTrouble =
    "numerical trouble in Ipopt's step (a non-finite or singular system)";

constexpr StatusWords kStatusWords[] = {
    {Ipopt::SUCCESS, SolveStatus::kConverged, "converged to the requested tolerance"},
    {Ipopt::STOP_AT_ACCEPTABLE_POINT, SolveStatus::kAcceptable,
     "converged to Ipopt's acceptable (looser) tolerance only"},
    {Ipopt::LOCAL_INFEASIBILITY, SolveStatus::kInfeasible,
     "the constraints cannot all be met (locally infeasible): a limit may be too tight"},
    {Ipopt::MAXITER_EXCEEDED, SolveStatus::kIterationLimit,
     "stopped at the iteration limit before converging"},
    {Ipopt::CPUTIME_EXCEEDED, SolveStatus::kTimeLimit,
     "stopped at the time limit before converging"},
    {Ipopt::RESTORATION_FAILURE, SolveStatus::kRestorationFailed,
     "restoration failed: Ipopt lost feasibility and could not regain it (try a better initial "
     "guess or a finer mesh)"},
    {Ipopt::USER_REQUESTED_STOP, SolveStatus::kStopped, "stopped on request"},
    {Ipopt::ERROR_IN_STEP_COMPUTATION, SolveStatus::kNumericalTrouble, kNumericalTrouble},
    {Ipopt::INVALID_NUMBER_DETECTED, SolveStatus::kNumericalTrouble, kNumericalTrouble},
    {Ipopt::TOO_FEW_DEGREES_OF_FREEDOM, SolveStatus::kNumericalTrouble, kNumericalTrouble},
};

const StatusWords* FindStatusWords(Ipopt::SolverReturn status) {
  for (const StatusWords& w : kStatusWords) {
    if (w.ipopt == status) return &w;
  }
  return nullptr;
}

using Ipopt::Index;
using Ipopt::Number;

// Whether the options carry multipliers sized for this programme (a warm start).
bool HasWarmStart(const ElementNlp& nlp, const IpoptOptions& options) {
  const size_t n = static_cast<size_t>(nlp.variables());
  return options.warm_z_lower.size() == n && options.warm_z_upper.size() == n &&
         options.warm_lambda.size() == static_cast<size_t>(nlp.constraints());
}

// The current iterate of a solve in the programme's own variables and multipliers, as
// finalize_solution would give them (Ipopt 3.11 has no GetCurrentIterate): undo Ipopt's NLP
// scaling as OrigIpoptNLP::FinalizeSolution does, then TNLPAdapter's reordering and removal of
// fixed variables. False if the solve is not a TNLP's (never here).
bool CurrentIterate(const Ipopt::IpoptData& data, Ipopt::IpoptCalculatedQuantities& cq, Index n,
                    Index m, std::vector<double>& x, std::vector<double>& z_lower,
                    std::vector<double>& z_upper, std::vector<double>& lambda) {
  auto* orig = dynamic_cast<Ipopt::OrigIpoptNLP*>(Ipopt::GetRawPtr(cq.GetIpoptNLP()));
  if (orig == nullptr) return false;
  auto* adapter = dynamic_cast<Ipopt::TNLPAdapter*>(Ipopt::GetRawPtr(orig->nlp()));
  if (adapter == nullptr) return false;
  const Ipopt::SmartPtr<const Ipopt::IteratesVector> it = data.curr();
  if (!Ipopt::IsValid(it)) return false;
  Ipopt::SmartPtr<Ipopt::NLPScalingObject> scaling = orig->NLP_scaling();
  const Number obj_unscale = scaling->unapply_obj_scaling(1.0);
  const Ipopt::SmartPtr<const Ipopt::Vector> x_unscaled =
      scaling->unapply_vector_scaling_x(it->x());
  const auto multipliers = [&](const Ipopt::SmartPtr<const Ipopt::Vector>& v) {
    Ipopt::SmartPtr<Ipopt::Vector> copy = v->MakeNewCopy();
    copy->Scal(obj_unscale);
    return copy;
  };
  const Ipopt::SmartPtr<const Ipopt::Vector> y_c =
      scaling->apply_vector_scaling_c(Ipopt::ConstPtr(multipliers(it->y_c())));
  const Ipopt::SmartPtr<const Ipopt::Vector> y_d =
      scaling->apply_vector_scaling_d(Ipopt::ConstPtr(multipliers(it->y_d())));
  const Ipopt::VectorSpace& x_space = *it->x()->OwnerSpace();
  const Ipopt::SmartPtr<const Ipopt::Vector> z_l = scaling->apply_vector_scaling_x_LU(
      *orig->Px_L(), Ipopt::ConstPtr(multipliers(it->z_L())), x_space);
  const Ipopt::SmartPtr<const Ipopt::Vector> z_u = scaling->apply_vector_scaling_x_LU(
      *orig->Px_U(), Ipopt::ConstPtr(multipliers(it->z_U())), x_space);
  x.assign(static_cast<size_t>(n), 0.0);
  z_lower.assign(static_cast<size_t>(n), 0.0);
  z_upper.assign(static_cast<size_t>(n), 0.0);
  lambda.assign(static_cast<size_t>(m), 0.0);
  adapter->ResortX(*x_unscaled, x.data());
  adapter->ResortG(*y_c, *y_d, lambda.data());
  adapter->ResortBnds(*z_l, z_lower.data(), *z_u, z_upper.data());
  return true;
}

class Adaptor : public Ipopt::TNLP {
 public:
  Adaptor(const ElementNlp& nlp, const IpoptOptions& options, SolveResult& result)
      : nlp_(nlp), options_(options), result_(result) {}

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag,
                    IndexStyleEnum& index_style) override {
    n = nlp_.variables();
    m = nlp_.constraints();
    nnz_jac_g = static_cast<Index>(nlp_.JacobianPattern().rows.size());
    nnz_h_lag = static_cast<Index>(nlp_.HessianPattern().rows.size());
    index_style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l,
                       Number* g_u) override {
    nlp_.ScaledBounds(x_l, x_u, g_l, g_u);
    // Ipopt reads +-1e19 as no bound.
    for (Index i = 0; i < n; ++i) {
      if (std::isinf(x_l[i])) x_l[i] = -1e19;
      if (std::isinf(x_u[i])) x_u[i] = 1e19;
    }
    for (Index r = 0; r < m; ++r) {
      if (std::isinf(g_l[r])) g_l[r] = -1e19;
      if (std::isinf(g_u[r])) g_u[r] = 1e19;
    }
    return true;
  }

  bool get_starting_point(Index n, bool init_x, Number* x, bool init_z, Number* z_l, Number* z_u,
                          Index m, bool init_lambda, Number* lambda) override {
    if (init_x) nlp_.ScaledStart(x);
    if (init_z) {
      if (!HasWarmStart(nlp_, options_)) return false;
      std::copy(options_.warm_z_lower.begin(), options_.warm_z_lower.end(), z_l);
      std::copy(options_.warm_z_upper.begin(), options_.warm_z_upper.end(), z_u);
    }
    if (init_lambda) {
      if (!HasWarmStart(nlp_, options_)) return false;
      std::copy(options_.warm_lambda.begin(), options_.warm_lambda.end(), lambda);
    }
    (void)n, (void)m;
    return true;
  }

  bool eval_f(Index, const Number* x, bool, Number& obj_value) override {
    obj_value = nlp_.ScaledObjective(x);
    return std::isfinite(obj_value);
  }

  bool eval_grad_f(Index n, const Number* x, bool, Number* grad_f) override {
    nlp_.ScaledObjectiveGradient(x, grad_f);
    return Finite(grad_f, n);
  }

  bool eval_g(Index, const Number* x, bool, Index m, Number* g) override {
    nlp_.ScaledConstraints(x, g);
    return Finite(g, m);
  }

  bool eval_jac_g(Index, const Number* x, bool, Index, Index nele_jac, Index* iRow, Index* jCol,
                  Number* values) override {
    if (values == nullptr) {
      const Sparsity& p = nlp_.JacobianPattern();
      for (Index k = 0; k < nele_jac; ++k) {
        iRow[k] = p.rows[k];
        jCol[k] = p.cols[k];
      }
      return true;
    }
    nlp_.ScaledJacobian(x, values);
    return Finite(values, nele_jac);
  }

  bool eval_h(Index, const Number* x, bool, Number obj_factor, Index, const Number* lambda, bool,
              Index nele_hess, Index* iRow, Index* jCol, Number* values) override {
    if (values == nullptr) {
      const Sparsity& p = nlp_.HessianPattern();
      for (Index k = 0; k < nele_hess; ++k) {
        iRow[k] = p.rows[k];
        jCol[k] = p.cols[k];
      }
      return true;
    }
    nlp_.ScaledHessian(x, obj_factor, lambda, values);
    return Finite(values, nele_hess);
  }

  bool intermediate_callback(Ipopt::AlgorithmMode mode, Index iter, Number obj_value, Number inf_pr,
                             Number inf_du, Number mu, Number, Number regularization_size, Number,
                             Number, Index, const Ipopt::IpoptData* data,
                             Ipopt::IpoptCalculatedQuantities* cq) override {
    result_.iterations = iter;
    // The Hessian perturbation of the step that led here (0 where the first factorisation had
    // the right inertia).
    if (iter > 0 && regularization_size > 0.0) ++result_.regularized_iterations;
    if (options_.checkpoint_every > 0 && options_.on_checkpoint && iter > 0 &&
        iter % options_.checkpoint_every == 0 && mode == Ipopt::RegularMode && data != nullptr &&
        cq != nullptr) {
      SolveResult checkpoint;
      std::vector<double> scaled_x;
      if (CurrentIterate(*data, *cq, nlp_.variables(), nlp_.constraints(), scaled_x,
                         checkpoint.z_lower, checkpoint.z_upper, checkpoint.lambda)) {
        checkpoint.x = nlp_.Unscale(scaled_x.data());
        checkpoint.status = SolveStatus::kStopped;
        checkpoint.message = fmt::format("checkpoint at iteration {}", iter);
        checkpoint.objective = obj_value;
        checkpoint.iterations = iter;
        checkpoint.regularized_iterations = result_.regularized_iterations;
        checkpoint.primal_infeasibility = inf_pr;
        checkpoint.dual_infeasibility = inf_du;
        checkpoint.barrier_mu = mu;
        options_.on_checkpoint(checkpoint);
      }
    }
    if (options_.on_iteration) return options_.on_iteration(iter, obj_value, inf_pr, inf_du);
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn status, Index n, const Number* x, const Number* z_l,
                         const Number* z_u, Index m, const Number*, const Number* lambda,
                         Number obj_value, const Ipopt::IpoptData* data,
                         Ipopt::IpoptCalculatedQuantities* q) override {
    if (data != nullptr) result_.barrier_mu = data->curr_mu();
    result_.x = nlp_.Unscale(x);
    if (z_l != nullptr && z_u != nullptr && lambda != nullptr) {
      result_.z_lower.assign(z_l, z_l + n);
      result_.z_upper.assign(z_u, z_u + n);
      result_.lambda.assign(lambda, lambda + m);
    }
    result_.objective = obj_value;
    if (q != nullptr) {
      result_.primal_infeasibility = q->curr_constraint_violation();
      result_.dual_infeasibility = q->curr_dual_infeasibility(Ipopt::NORM_MAX);
    }
    (void)n;
    const StatusWords* words = FindStatusWords(status);
    if (words != nullptr) {
      result_.status = words->status;
      result_.message = words->message;
    } else {
      result_.status = SolveStatus::kOther;
      result_.message = "Ipopt ended without converging (status " +
                        std::to_string(static_cast<int>(status)) + ")";
    }
  }

 private:
  static bool Finite(const Number* v, Index n) {
    for (Index i = 0; i < n; ++i) {
      if (!std::isfinite(v[i])) return false;
    }
    return true;
  }

  const ElementNlp& nlp_;
  const IpoptOptions& options_;
  SolveResult& result_;
};

// SCOTCH (MUMPS' ordering 3) the same for the same problem, so that a solve ordered by it is
// the same bit for bit whatever ran before it and on every run (docs/validation/optimal-control.md, "Speed"):
// - On one thread: it orders a large graph on several by default, and its threaded ordering
//   differs from run to run (two runs of the same 3 m lap differed from the 12th digit on). Set
//   before the first solve, unless the user set it; a solve orders once, so the thread costs
//   nothing measurable.
// - Its random state back to its seed: the state advances with every graph it orders, so the
//   same lap ordered after another solve (the limited lap after the free one) got other pivots
//   than in a fresh process (the comparison's child). Looked up at run time: SCOTCH is MUMPS'
//   library, not ours, and a MUMPS built without it has none.
void MakeScotchReproducible() {
  static std::once_flag once;
  std::call_once(once, [] { setenv("SCOTCH_PTHREAD_NUMBER", "1", /*overwrite=*/0); });
  using Reset = void (*)();
  static const auto reset = reinterpret_cast<Reset>(dlsym(RTLD_DEFAULT, "SCOTCH_randomReset"));
  if (reset != nullptr) reset();
}

}  // namespace

SolveResult SolveWithIpopt(const ElementNlp& nlp, const IpoptOptions& options) {
  SolveResult result;
  const auto started = std::chrono::steady_clock::now();
  MakeScotchReproducible();
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetNumericValue("tol", options.tolerance);
  app->Options()->SetNumericValue("constr_viol_tol", options.constraint_tolerance);
  app->Options()->SetIntegerValue("max_iter", options.max_iterations);
  app->Options()->SetNumericValue("max_cpu_time", options.max_cpu_seconds);
  app->Options()->SetIntegerValue("print_level", options.print_level);
  app->Options()->SetStringValue("hessian_approximation", "exact");
  app->Options()->SetStringValue("mu_strategy", "adaptive");
  app->Options()->SetStringValue("alpha_for_y", options.alpha_for_y);
  app->Options()->SetStringValue("sb", "yes");  // no banner
  if (HasWarmStart(nlp, options)) {
    // Start at the given point and multipliers, barely pushed off the bounds, with a small
    // barrier parameter.
    app->Options()->SetStringValue("warm_start_init_point", "yes");
    // The adaptive barrier update stalls from a warm start (its first mu comes from the
    // multipliers' complementarity); the monotone one brings mu down from warm_mu.
    app->Options()->SetStringValue("mu_strategy", "monotone");
    app->Options()->SetNumericValue("mu_init", options.warm_mu);
    for (const char* name :
         {"warm_start_bound_push", "warm_start_bound_frac", "warm_start_slack_bound_push",
          "warm_start_slack_bound_frac", "warm_start_mult_bound_push"}) {
      app->Options()->SetNumericValue(name, 1e-6);
    }
  } else if (options.primal_start_mu > 0.0) {
    app->Options()->SetNumericValue("mu_init", options.primal_start_mu);
    app->Options()->SetNumericValue("bound_push", 1e-6);
    app->Options()->SetNumericValue("bound_frac", 1e-6);
  }
  for (const auto& [name, value] : options.extra) {
    // The value as the option's type takes it: integer, number or text.
    char* end = nullptr;
    const long as_int = std::strtol(value.c_str(), &end, 10);
    const bool is_int = end != value.c_str() && *end == '\0';
    const double as_number = std::strtod(value.c_str(), &end);
    const bool is_number = end != value.c_str() && *end == '\0';
    Ipopt::OptionsList& o = *app->Options();
    const bool set = (is_int && o.SetIntegerValue(name, static_cast<int>(as_int))) ||
                     (is_number && o.SetNumericValue(name, as_number)) ||
                     o.SetStringValue(name, value);
    if (!set) {
      throw InputError(fmt::format(
          "Ipopt option '{}={}': Ipopt has no such option, or it does not take that value", name,
          value));
    }
  }
  if (app->Initialize() != Ipopt::Solve_Succeeded) {
    result.status = SolveStatus::kOther;
    result.message = "Ipopt could not be initialised";
    return result;
  }
  Ipopt::SmartPtr<Ipopt::TNLP> tnlp = new Adaptor(nlp, options, result);
  app->OptimizeTNLP(tnlp);
  result.solve_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace hotlap::ocp
