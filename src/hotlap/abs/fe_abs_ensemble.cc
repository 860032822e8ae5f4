#include "hotlap/abs/fe_abs_ensemble.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include <fmt/format.h>

#include "hotlap/abs/fe_abs_stop.h"
#include "hotlap/common/error.h"

namespace hotlap::sim {

namespace {

// One member's stop: its figures and the histories the band needs.
struct MemberRun {
  FeAbsFigures figures;
  std::vector<double> time, slip, vx, spin, torque;
};

MemberRun RunMember(const fe::TyreRun& rolled, const AbsConfig& abs, const FeAbsEnsembleOptions& o,
                    int member) {
  fe::TyreRun run = rolled;
  run.mutable_solver().set_threads(1);
  ApplyFePerturbation(o.perturbation, o.first_member + member, o.members, run);
  FeAbsStop stop(run, abs);
  FeAbsStopOptions so;
  so.duration_s = o.duration_s;
  so.hooks.history_interval_s = o.history_interval_s;
  const FeAbsStopResult r = stop.Run(so);
  MemberRun m;
  m.figures = CalcFeAbsFigures(r, o.duration_s);
  for (const fe::HistoryRow& row : r.brake.history) {
    m.time.push_back(row.time_s);
    m.slip.push_back(row.slip);
    m.vx.push_back(row.rim_vx_mps);
    m.spin.push_back(row.spin_rad_per_s);
    m.torque.push_back(row.brake_torque_Nm);
  }
  return m;
}

// The band of one channel over the members' first `rows` rows.
EnsembleBand MakeBand(const std::vector<MemberRun>& runs, size_t rows,
                      std::vector<double> MemberRun::*channel, double scale = 1.0) {
  EnsembleBand b;
  for (size_t k = 0; k < rows; ++k) {
    double sum = 0.0, lo = 0.0, hi = 0.0;
    for (size_t m = 0; m < runs.size(); ++m) {
      const double v = scale * (runs[m].*channel)[k];
      sum += v;
      lo = m == 0 ? v : std::min(lo, v);
      hi = m == 0 ? v : std::max(hi, v);
    }
    b.mean.push_back(sum / static_cast<double>(runs.size()));
    b.min.push_back(lo);
    b.max.push_back(hi);
  }
  return b;
}

}  // namespace

void CheckFeEnsembleShard(FePerturbation perturbation, int first_member) {
  if (first_member < 0) throw InputError("--first-member: at least 0");
  if (first_member > 0 && perturbation == FePerturbation::kSpin) {
    throw InputError(
        "--first-member: a shard of an ensemble needs --perturb sum-order or round-off (a spin "
        "member's perturbation depends on the ensemble's size)");
  }
}

FeAbsEnsembleResult RunFeAbsEnsemble(const fe::TyreRun& rolled, const AbsConfig& abs,
                                     const FeAbsEnsembleOptions& options) {
  if (options.members < 1) throw InputError("--ensemble: at least one member");
  if (options.threads < 1) throw InputError("--threads: at least one");
  CheckFeEnsembleShard(options.perturbation, options.first_member);
  std::vector<MemberRun> runs(options.members);
  std::atomic<int> next{0};
  std::mutex done_mutex;
  std::exception_ptr failure;
  const auto work = [&] {
    for (int m = next++; m < options.members; m = next++) {
      try {
        runs[m] = RunMember(rolled, abs, options, m);
        const std::lock_guard<std::mutex> lock(done_mutex);
        if (options.member_done) options.member_done(options.first_member + m, runs[m].figures);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(done_mutex);
        if (!failure) failure = std::current_exception();
        next = options.members;  // no new members
      }
    }
  };
  std::vector<std::thread> pool;
  const int threads = std::min(options.threads, options.members);
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);

  FeAbsEnsembleResult e;
  e.perturbation = options.perturbation;
  e.first_member = options.first_member;
  for (const MemberRun& r : runs) e.members.push_back(r.figures);
  for (const FeAbsFigureValue& f : ListFeAbsFigures(e.members.front())) {
    e.keys.push_back(f.key);
    e.units.push_back(f.unit);
  }
  for (size_t k = 0; k < e.keys.size(); ++k) {
    std::vector<double> values;
    for (const FeAbsFigures& f : e.members) {
      const std::optional<double> v = ListFeAbsFigures(f)[k].value;
      if (v) values.push_back(*v);
    }
    e.stats.push_back(CalcEnsembleStat(values));
  }
  size_t rows = runs.front().time.size();
  for (const MemberRun& r : runs) rows = std::min(rows, r.time.size());
  e.time_s.assign(runs.front().time.begin(), runs.front().time.begin() + rows);
  e.slip_radius_m = rolled.slip_radius_m();
  e.slip = MakeBand(runs, rows, &MemberRun::slip);
  e.vx_mps = MakeBand(runs, rows, &MemberRun::vx);
  e.omega_r_mps = MakeBand(runs, rows, &MemberRun::spin, e.slip_radius_m);
  e.torque_Nm = MakeBand(runs, rows, &MemberRun::torque);
  return e;
}

const EnsembleStat& FindEnsembleStat(const FeAbsEnsembleResult& e, const std::string& key) {
  for (size_t k = 0; k < e.keys.size(); ++k) {
    if (e.keys[k] == key) return e.stats[k];
  }
  throw InputError(fmt::format("no ensemble figure '{}'", key));
}

}  // namespace hotlap::sim
