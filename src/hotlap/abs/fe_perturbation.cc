#include "hotlap/abs/fe_perturbation.h"

#include <cstdint>
#include <limits>

#include <fmt/format.h>

#include "hotlap/common/enum_names.h"
#include "hotlap/common/error.h"

namespace hotlap::sim {

namespace {

// SplitMix64: a well-mixed 64-bit hash of a counter (the round-off signs).
std::uint64_t Mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

}  // namespace

constexpr EnumNames<FePerturbation, 3> kFePerturbations{
    {{{FePerturbation::kSpin, "spin"},
      {FePerturbation::kSumOrder, "sum-order"},
      {FePerturbation::kRoundOff, "round-off"}}}};

const char* FePerturbationName(FePerturbation kind) { return kFePerturbations.Name(kind); }

FePerturbation ParseFePerturbation(const std::string& name, const std::string& what) {
  if (const std::optional<FePerturbation> k = kFePerturbations.Find(name)) return *k;
  throw InputError(
      fmt::format("{}: '{}' is not a perturbation ({})", what, name, kFePerturbations.List()));
}

void ApplyFePerturbation(FePerturbation kind, int member, int members, fe::TyreRun& run) {
  fe::ExplicitSolver& solver = run.mutable_solver();
  switch (kind) {
    case FePerturbation::kSpin: {
      const double d = members > 1 ? kSpinPerturbation * (2.0 * member - (members - 1)) /
                                         static_cast<double>(members - 1)
                                   : 0.0;
      const fe::RimState& rim = solver.rim_state();
      solver.SetRimMotion(rim.velocity.x(), rim.velocity.z(), rim.spin_rad_per_s * (1.0 + d));
      break;
    }
    case FePerturbation::kSumOrder:
      solver.set_rim_sum_rotation(member);
      break;
    case FePerturbation::kRoundOff: {
      constexpr double eps = std::numeric_limits<double>::epsilon();
      std::vector<Eigen::Vector3d>& v = solver.mutable_state().v;
      const std::uint64_t seed = Mix(static_cast<std::uint64_t>(member) + 1);
      for (size_t a = 0; a < v.size(); ++a) {
        const std::uint64_t bits = Mix(seed ^ Mix(a));
        for (int d = 0; d < 3; ++d) v[a](d) *= 1.0 + ((bits >> d) & 1 ? eps : -eps);
      }
      break;
    }
  }
}

}  // namespace hotlap::sim
