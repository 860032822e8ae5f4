#include "hotlap/ocp/stint.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/interpolation.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/stint_checkpoint.h"

namespace hotlap::ocp {
namespace {

// `values` (at the nodes of `distance`) at distance s, linear between nodes.
double At(const std::vector<double>& distance, const std::vector<double>& values, double s) {
  return InterpolateClamped<double>(distance, values, s);
}

// The thermal state at the last node of a solution: where the next lap starts.
sim::ReplayInitialState EndState(const LapSolution& s) {
  return StateAtNode(s, s.corners[0].tread_temp.size() - 1);
}

vehicle::Car WithMass(const vehicle::Car& car, double mass_kg) {
  vehicle::Car c = car;
  c.vehicle->chassis.mass = mass_kg;
  return c;
}

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

}  // namespace

vehicle::Car StintCar(const vehicle::Car& car, double wear_scale) {
  vehicle::Car c = car;
  for (tyre::TyreFile& t : c.tyres) t.params.wear_coeff *= wear_scale;
  return c;
}

std::vector<StintLap> StintLaps(const LapSolution& solution, const track::Track& single_track,
                                int laps, double fuel_start_kg,
                                const std::vector<double>& lap_mass_kg, double bsfc_kg_per_J,
                                double driveline_efficiency) {
  const std::vector<double>& d = solution.distance;
  const double length = single_track.length_m();
  std::vector<StintLap> out;
  double fuel = fuel_start_kg;
  for (int i = 0; i < laps; ++i) {
    StintLap lap;
    lap.lap = i + 1;
    const double s0 = i * length, s1 = (i + 1) * length;
    lap.time_s = At(d, solution.time, s1) - At(d, solution.time, s0);
    lap.mass_kg = i < static_cast<int>(lap_mass_kg.size()) ? lap_mass_kg[i] : 0.0;
    for (int c = 0; c < 4; ++c) lap.wear_end_mm[c] = At(d, solution.corners[c].wear, s1);
    constexpr double kInf = std::numeric_limits<double>::infinity();
    lap.min_tread_temp_K.fill(kInf);
    lap.min_carcass_temp_K.fill(kInf);
    lap.min_disc_temp_K.fill(kInf);
    // Nodes of the lap: s0 <= d <= s1 (a node on the line belongs to both laps' peaks).
    double burnt = 0.0;
    for (size_t k = 0; k < d.size(); ++k) {
      if (d[k] < s0 - 1e-9 || d[k] > s1 + 1e-9) continue;
      lap.top_speed_mps = std::max(lap.top_speed_mps, std::hypot(solution.u[k], solution.v[k]));
      for (int c = 0; c < 4; ++c) {
        const CornerTrace& t = solution.corners[c];
        lap.peak_tread_temp_K[c] = std::max(lap.peak_tread_temp_K[c], t.tread_temp[k]);
        lap.peak_carcass_temp_K[c] = std::max(lap.peak_carcass_temp_K[c], t.carcass_temp[k]);
        lap.peak_disc_temp_K[c] = std::max(lap.peak_disc_temp_K[c], t.disc_temp[k]);
        lap.min_tread_temp_K[c] = std::min(lap.min_tread_temp_K[c], t.tread_temp[k]);
        lap.min_carcass_temp_K[c] = std::min(lap.min_carcass_temp_K[c], t.carcass_temp[k]);
        lap.min_disc_temp_K[c] = std::min(lap.min_disc_temp_K[c], t.disc_temp[k]);
      }
      // The engine's work over the interval to the next node, if it is in the lap.
      if (k + 1 < d.size() && d[k + 1] <= s1 + 1e-9) {
        const double dt = solution.time[k + 1] - solution.time[k];
        burnt += 0.5 * (solution.drive_power[k] + solution.drive_power[k + 1]) * dt /
                 driveline_efficiency * bsfc_kg_per_J;
      }
    }
    for (int c = 0; c < 4; ++c) {
      const CornerTrace& t = solution.corners[c];
      if (t.gas_temp.empty()) continue;
      lap.end_pressure_Pa[c] = At(d, t.pressure, s1);
      // The time-weighted mean over the lap's nodes (s0 <= d <= s1).
      const auto first = std::lower_bound(d.begin(), d.end(), s0 - 1e-9) - d.begin();
      const auto end = std::upper_bound(d.begin(), d.end(), s1 + 1e-9) - d.begin();
      lap.mean_gas_temp_K[c] =
          sim::CalcHistoryStats({solution.time.begin() + first, solution.time.begin() + end},
                                {t.gas_temp.begin() + first, t.gas_temp.begin() + end})
              .mean;
    }
    lap.fuel_burnt_kg = fuel_start_kg > 0.0 ? burnt : 0.0;
    fuel -= lap.fuel_burnt_kg;
    lap.fuel_end_kg = fuel;
    out.push_back(lap);
  }
  return out;
}

SolveResult ConcatenateLaps(const std::vector<const SolveResult*>& laps,
                            const LapLayout& lap_layout) {
  const LapLayout& L = lap_layout;
  const int n_laps = static_cast<int>(laps.size());
  const int I = L.intervals();
  if (n_laps < 1 || I < 1) throw std::invalid_argument("ConcatenateLaps: no laps");
  for (const SolveResult* r : laps) {
    if (r->x.size() != static_cast<size_t>(L.variables()) || r->z_lower.size() != r->x.size() ||
        r->z_upper.size() != r->x.size() || r->lambda.size() != static_cast<size_t>(L.rows())) {
      throw std::invalid_argument("ConcatenateLaps: a lap's solve is not of the layout given");
    }
  }
  const LapLayout S = L.WithNodes(n_laps * I + 1);
  SolveResult out;
  out.x.resize(S.variables());
  out.z_lower.resize(S.variables());
  out.z_upper.resize(S.variables());
  out.lambda.resize(S.rows());
  // The lap and its node for stint node k (the last node: the last lap's last).
  const auto node = [&](int k) {
    const int lap = std::min(k / I, n_laps - 1);
    return std::pair{lap, k - lap * I};
  };
  const int vpn = L.vars_per_node, rpn = L.rows_per_node, dpi = L.defects_per_interval;
  for (int k = 0; k < S.nodes; ++k) {
    const auto [lap, local] = node(k);
    for (int i = 0; i < vpn; ++i) {
      out.x[k * vpn + i] = laps[lap]->x[local * vpn + i];
      out.z_lower[k * vpn + i] = laps[lap]->z_lower[local * vpn + i];
      out.z_upper[k * vpn + i] = laps[lap]->z_upper[local * vpn + i];
    }
    for (int i = 0; i < rpn; ++i) out.lambda[k * rpn + i] = laps[lap]->lambda[local * rpn + i];
  }
  // Rows after the node equations: defects per interval, the closure, then the rate blocks.
  const int lap_defects = L.nodes * rpn, stint_defects = S.nodes * rpn;
  const int lap_closure = lap_defects + I * dpi,
            stint_closure = stint_defects + S.intervals() * dpi;
  const int lap_rates = lap_closure + L.closure_rows, stint_rates = stint_closure + S.closure_rows;
  for (int j = 0; j < S.intervals(); ++j) {
    const int lap = j / I, local = j % I;
    for (int i = 0; i < dpi; ++i) {
      out.lambda[stint_defects + j * dpi + i] = laps[lap]->lambda[lap_defects + local * dpi + i];
    }
    for (int b = 0; b < L.rate_blocks; ++b) {
      for (int i = 0; i < 2; ++i) {
        out.lambda[stint_rates + b * 2 * S.intervals() + 2 * j + i] =
            laps[lap]->lambda[lap_rates + b * 2 * I + 2 * local + i];
      }
    }
  }
  for (int i = 0; i < L.closure_rows; ++i) {
    out.lambda[stint_closure + i] = laps.back()->lambda[lap_closure + i];
  }
  return out;
}

namespace {

void CheckStintOptions(const vehicle::Car& car, const StintOptions& options) {
  if (options.laps < 1 || options.laps > 100) {
    throw InputError(fmt::format("laps: a stint is 1 to 100 laps, not {}", options.laps));
  }
  if (!(options.wear_scale >= 0.0) || !std::isfinite(options.wear_scale)) {
    throw InputError(fmt::format("wear scale: {} is not a factor >= 0", options.wear_scale));
  }
  const double mass0 = car.vehicle->chassis.mass;
  if (!(options.fuel_kg >= 0.0) || !(options.fuel_kg < 0.5 * mass0)) {
    throw InputError(
        fmt::format("fuel: {} kg is not fuel a {:.0f} kg car carries", options.fuel_kg, mass0));
  }
  if (options.lap.thermal_start == ThermalStart::kPeriodic) {
    throw InputError("a stint's thermal states run on from lap to lap: not periodic");
  }
  if (options.lap.collocation != Collocation::kTrapezoid ||
      options.lap.coarse_collocation != Collocation::kTrapezoid) {
    throw InputError("a stint is transcribed by the trapezoid (Hermite-Simpson: single laps only)");
  }
}

// The stint's options with every lap of the same mesh: the single lap's spacing rounded to a
// whole number of intervals.
StintOptions OnCommonMesh(const track::Track& track, const StintOptions& options) {
  StintOptions o = options;
  const int intervals = LapNodeCount(track, options.lap.step_m) - 1;
  o.lap.step_m = track.length_m() / intervals;
  // The wear stays in the programme: it grows lap after lap (LapProblemOptions::
  // wear_in_programme).
  o.lap.wear_in_programme = true;
  if (options.checkpoint_every < 1) {
    throw InputError(fmt::format("checkpoint interval: {} is not a number of iterations >= 1",
                                 options.checkpoint_every));
  }
  return o;
}

void Say(const StintLog& log, const std::string& text) {
  if (log) log(text);
}

// Runs a checkpoint's write: one that cannot be written (a full disk) costs the resume, not the
// run, and is said once.
class CheckpointSaver {
 public:
  explicit CheckpointSaver(const StintLog& log) : log_(log) {}

  bool operator()(const std::function<void()>& write) {
    try {
      write();
      return true;
    } catch (const std::exception& e) {
      if (!warned_ && log_) log_(fmt::format("warning: no checkpoint: {}", e.what()));
      warned_ = true;
      return false;
    }
  }

 private:
  const StintLog& log_;
  bool warned_ = false;
};

// A solve's point and multipliers as the start of the next.
void WarmStartFrom(const SolveResult& from, OptimalLapOptions& lap) {
  lap.start_point = from.x;
  lap.ipopt.warm_z_lower = from.z_lower;
  lap.ipopt.warm_z_upper = from.z_upper;
  lap.ipopt.warm_lambda = from.lambda;
}

// What the greedy laps and the stint solve share.
struct StintSetup {
  const StintOptions& options;  // as given
  const StintOptions& o;        // on the common mesh
  const vehicle::Car& worn;
  const track::Track& track;
  const LapWarmUp& warm_up;
  double mass0;
  double eta;
  std::optional<StintCheckpoints>& checkpoints;
  CheckpointSaver& save;
  const StintLog& log;
};

// The greedy driver: one optimal lap after another, each from the last one's end. Fills the
// greedy fields of `result`; returns each lap's mass.
std::vector<double> RunGreedyLaps(const StintSetup& s, StintResult& result) {
  const StintOptions& options = s.options;
  const auto greedy_start = std::chrono::steady_clock::now();
  sim::ReplayInitialState state = s.warm_up.start;
  double fuel = options.fuel_kg;
  std::vector<double> masses;
  for (int i = 0; i < options.laps; ++i) {
    const double mass = s.mass0 - (options.fuel_kg - fuel);
    masses.push_back(mass);
    LapWarmUp w = s.warm_up;
    w.start = state;
    // Each lap after the first from the last one's solution and multipliers: the same lap but
    // for the state it starts from (the start's fixed states are clipped to it). From the QSS
    // guess instead, a 30 m lap from a hot start found a local optimum 1.9 s slower.
    OptimalLapOptions lap_options = s.o.lap;
    if (i > 0 && result.greedy_runs.back().solution.solve.ok()) {
      WarmStartFrom(result.greedy_runs.back().solution.solve, lap_options);
    }
    const std::optional<PresolvedLap> saved =
        s.checkpoints ? s.checkpoints->ReadGreedyLap(i + 1) : std::nullopt;
    if (saved) {
      lap_options.presolved = *saved;
      ++result.greedy_laps_resumed;
    }
    OptimalLapRun run = RunOptimalLap(WithMass(s.worn, mass), s.track, lap_options, &w);
    if (s.checkpoints && !saved) {
      s.save([&] {
        s.checkpoints->WriteGreedyLap(i + 1,
                                      PresolvedLap{run.coarse, run.solution.solve, {}, {}, {}});
      });
    }
    StintLap lap = StintLaps(run.solution, s.track, 1, fuel, {mass}, s.o.bsfc_kg_per_J, s.eta)[0];
    lap.lap = i + 1;
    if (!run.exact.audits.empty()) {
      lap.audit = run.exact.audits[0];
      lap.has_audit = true;
    }
    if (options.fuel_kg > 0.0 && lap.fuel_end_kg < 0.0) {
      throw InputError(fmt::format("fuel: {} kg runs out on lap {} of {}", options.fuel_kg, i + 1,
                                   options.laps));
    }
    fuel = lap.fuel_end_kg;
    Say(s.log, fmt::format("greedy lap {} of {}: {:.3f} s ({}, {} iterations{})", i + 1,
                           options.laps, lap.time_s, run.solution.solve.message,
                           run.solution.solve.iterations, saved ? "; from its checkpoint" : ""));
    state = EndState(run.solution);
    result.greedy_total_time_s += lap.time_s;
    result.greedy_laps.push_back(lap);
    result.greedy_runs.push_back(std::move(run));
  }
  result.greedy_solve_time_s = Seconds(greedy_start);
  return masses;
}

// The stint from the greedy laps' point and multipliers, if every greedy lap solved; returns
// whether they did.
bool StartFromGreedyLaps(const StintResult& result, OptimalLapOptions& lap) {
  bool all_ok = true;
  std::vector<const SolveResult*> solves;
  for (const OptimalLapRun& r : result.greedy_runs) {
    all_ok = all_ok && r.solution.solve.ok();
    solves.push_back(&r.solution.solve);
  }
  if (all_ok) {
    const SolveResult start = ConcatenateLaps(solves, result.greedy_runs.front().solution.layout);
    WarmStartFrom(start, lap);
  }
  return all_ok;
}

// Resuming: the stint solve's last iterate (point, multipliers, barrier) as a warm start; and
// each iterate saved as the solve goes.
void ResumeAndCheckpointStint(const StintSetup& s, OptimalLapOptions& lap, StintResult& result) {
  const std::optional<SolveResult> iterate =
      s.checkpoints ? s.checkpoints->ReadStintIterate() : std::nullopt;
  if (iterate) {  // the fingerprint says it is this stint's programme
    WarmStartFrom(*iterate, lap);
    if (iterate->barrier_mu > 0.0) lap.ipopt.warm_mu = iterate->barrier_mu;
    result.resumed_from_iteration = iterate->iterations;
  }
  if (s.checkpoints) {
    lap.ipopt.checkpoint_every = s.options.checkpoint_every;
    const int offset = result.resumed_from_iteration;
    // Each iterate saved is said once it is in its file (the event a test of a kill waits for).
    lap.ipopt.on_checkpoint = [&checkpoints = s.checkpoints, &save = s.save, &log = s.log,
                               offset](const SolveResult& at) {
      SolveResult saved = at;
      saved.iterations += offset;
      if (save([&] { checkpoints->WriteStintIterate(saved); })) {
        Say(log, fmt::format("the stint: iterate of iteration {} saved", saved.iterations));
      }
    };
  }
  if (s.checkpoints && s.checkpoints->foreign_files() > 0) {
    Say(s.log, fmt::format("checkpoints in '{}': {} file(s) of another stint, not used",
                           s.checkpoints->dir().string(), s.checkpoints->foreign_files()));
  }
}

// The stint solve's laps (with their audits), its total time and its fuel plan's error.
void StintTotals(const StintSetup& s, const std::vector<double>& masses, StintResult& result) {
  result.laps = StintLaps(result.run.solution, s.track, s.options.laps, s.options.fuel_kg, masses,
                          s.o.bsfc_kg_per_J, s.eta);
  // The exact replay's audit has a stretch a lap (RunOptimalLap on a repeated track).
  if (result.run.exact.audits.size() == result.laps.size()) {
    for (size_t i = 0; i < result.laps.size(); ++i) {
      result.laps[i].audit = result.run.exact.audits[i];
      result.laps[i].has_audit = true;
    }
  }
  for (size_t i = 0; i < result.laps.size(); ++i) {
    result.total_time_s += result.laps[i].time_s;
    result.fuel_plan_error_kg =
        std::max(result.fuel_plan_error_kg,
                 std::abs(result.laps[i].fuel_burnt_kg - result.greedy_laps[i].fuel_burnt_kg));
  }
}

}  // namespace

StintResult SolveStint(const vehicle::Car& car, const track::Track& track,
                       const StintOptions& options, const StintLog& log) {
  vehicle::RequireVehicle(car, "a stint");
  CheckStintOptions(car, options);
  const double mass0 = car.vehicle->chassis.mass;
  const double eta = car.vehicle->powertrain.driveline_efficiency;
  const StintOptions o = OnCommonMesh(track, options);
  const vehicle::Car worn = StintCar(car, options.wear_scale);
  const LapWarmUp warm_up = RunLapWarmUp(worn, track, o.lap);
  std::optional<StintCheckpoints> checkpoints;
  if (!options.checkpoint_dir.empty()) {
    checkpoints.emplace(options.checkpoint_dir, StintFingerprint(o, track, warm_up));
  }
  CheckpointSaver save(log);
  const StintSetup setup{options, o, worn, track, warm_up, mass0, eta, checkpoints, save, log};

  StintResult result;
  const std::vector<double> masses = RunGreedyLaps(setup, result);

  // The stint, from the greedy laps' point and multipliers with their fuel plan.
  const track::Track stint_track = track.Repeated(options.laps);
  StintOptions so = o;
  so.lap.lap_mass_kg = options.fuel_kg > 0.0 ? masses : std::vector<double>{};
  const bool all_ok = StartFromGreedyLaps(result, so.lap);
  // The stint's own guess: QSS laps over the whole stint (only used if a greedy lap failed).
  LapWarmUp stint_warm = warm_up;
  if (!all_ok) {
    OptimalLapOptions qss_only = so.lap;
    qss_only.thermal_start = ThermalStart::kCar;
    stint_warm = RunLapWarmUp(worn, stint_track, qss_only);
    stint_warm.start = warm_up.start;
  }
  ResumeAndCheckpointStint(setup, so.lap, result);
  Say(log, result.resumed_from_iteration > 0
               ? fmt::format("the stint: {} laps as one problem, resumed from its checkpoint at "
                             "iteration {}...",
                             options.laps, result.resumed_from_iteration)
               : fmt::format("the stint: {} laps as one problem, from the greedy laps...",
                             options.laps));
  const auto stint_start = std::chrono::steady_clock::now();
  result.run = RunOptimalLap(worn, stint_track, so.lap, &stint_warm);
  result.solve_time_s = Seconds(stint_start);
  result.ipopt_iterations = result.run.solution.solve.iterations;
  // The end as a last checkpoint: a run again with the same folder converges at once.
  if (checkpoints && result.run.solution.solve.ok()) {
    SolveResult end = result.run.solution.solve;
    end.iterations += result.resumed_from_iteration;
    save([&] { checkpoints->WriteStintIterate(end); });
  }
  StintTotals(setup, masses, result);
  Say(log, fmt::format("the stint: {} after {} iterations in {:.1f} s: {:.3f} s against the greedy "
                       "{:.3f} s",
                       result.run.solution.solve.message, result.ipopt_iterations,
                       result.solve_time_s, result.total_time_s, result.greedy_total_time_s));
  return result;
}

}  // namespace hotlap::ocp
