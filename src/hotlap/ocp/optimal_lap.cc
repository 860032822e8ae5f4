#include "hotlap/ocp/optimal_lap.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/ocp/adaptive_mesh.h"
#include "hotlap/ocp/mesh_resample.h"
#include "hotlap/ocp/min_curvature_line.h"
#include "hotlap/sim/hot_pressure.h"
#include "hotlap/sim/qss_lap.h"
#include "hotlap/sim/road.h"
#include "hotlap/track/racing_line.h"
#include "hotlap/track/track_summary.h"

namespace hotlap::ocp {

namespace {

// The car the programme runs: its own models, or the paper's (OptimalLapOptions::paper_models).
vehicle::Car ProgrammeCar(const vehicle::Car& car, const OptimalLapOptions& options) {
  return options.paper_models ? vehicle::PaperModelsOf(car) : car;
}

// The QSS options of the warm-up's first two laps (and of the QSS lap on the optimal line).
sim::QssOptions WarmUpQss(const vehicle::Car& car, const track::Track& track,
                          const OptimalLapOptions& options) {
  sim::QssOptions qss;
  qss.laps = 2;
  qss.ambient_temp = options.ambient_temp;
  qss.track_temp = options.track_temp;
  qss.initial = sim::CarStartState(car);
  qss.track_length = track.length_m();
  return qss;
}

// The lap problem's options from the optimal lap's, starting from `start`.
LapProblemOptions ProblemOptions(const OptimalLapOptions& options,
                                 const sim::ReplayInitialState& start) {
  LapProblemOptions lap;
  lap.step_m = options.step_m;
  lap.mesh_m = options.mesh_m;
  lap.collocation = options.collocation;
  lap.front_disc_limit = options.front_disc_limit;
  lap.ambient_temp = options.ambient_temp;
  lap.track_temp = options.track_temp;
  lap.car_half_width = options.car_half_width_m;
  lap.periodic_thermal = options.thermal_start == ThermalStart::kPeriodic;
  lap.initial = start;
  lap.start_point = options.start_point;
  lap.lap_mass_kg = options.lap_mass_kg;
  lap.pedal_smoothing = options.pedal_smoothing;
  lap.convex_element_hessians = options.convex_element_hessians;
  lap.derivative_threads = options.derivative_threads;
  lap.all_brake_states = options.all_brake_states;
  // From the QSS guess the wear stays in the programme either way: left out, 3 of 6 meshes
  // (10, 12, 25 m) went astray from the guess on the Gen-7-like car's lap, none with it
  // (docs/validation/optimal-control.md, "Speed"). A solve from a solution leaves it out unless
  // asked.
  lap.wear_in_programme = true;  // (the problem's default)
  lap.independent_drive_and_brake = options.independent_drive_and_brake;
  if (options.steer_smoothing_weight >= 0.0) {
    lap.steer_smoothing_weight = options.steer_smoothing_weight;
  }
  if (options.pedal_smoothing_weight >= 0.0) {
    lap.pedal_smoothing_weight = options.pedal_smoothing_weight;
  }
  return lap;
}

// A converged solve and its problem as posed: where the adaptive mesh's refinement starts.
struct SolvedProblem {
  LapSolution solution;
  LapProblemOptions problem;
};

// Coarse to fine: the same problem on the coarse mesh from the guess, then its solution on the
// fine mesh as the fine solve's start (lap.start_point and fine_ipopt's multipliers). With the
// adaptive mesh (`adaptive`) the converged coarse solve is returned instead, where the
// refinement starts.
std::optional<SolvedProblem> SolveCoarseFirst(const vehicle::Car& hot_car,
                                              const track::Track& track,
                                              const OptimalLapOptions& options, bool adaptive,
                                              const LapWarmUp& w, LapProblemOptions& lap,
                                              IpoptOptions& fine_ipopt, OptimalLapRun& run) {
  LapProblemOptions coarse = lap;
  coarse.step_m = options.coarse_step_m;
  coarse.mesh_m.clear();  // the coarse mesh is uniform
  coarse.collocation = options.coarse_collocation;
  IpoptOptions coarse_ipopt = options.ipopt;
  if (options.coarse_start) {
    // From another coarse solution: as any solve from a solution (below), the wear frozen unless
    // asked and SCOTCH's ordering.
    StartFromSolution(options.coarse_start->solve, options.coarse_start->layout,
                      LapNodeCount(track, coarse.step_m, coarse.collocation), coarse.collocation,
                      true, coarse.start_point, coarse_ipopt);
    coarse.wear_in_programme = options.wear_in_programme;
    coarse_ipopt.extra.insert(coarse_ipopt.extra.begin(), {"mumps_pivot_order", "3"});
  }
  const LapSolution c =
      SolveMinimumTimeLap(hot_car, track, coarse, w.guess, coarse_ipopt,
                          options.presolved ? &options.presolved->coarse : nullptr);
  if (options.on_coarse_solve) options.on_coarse_solve(c);
  run.coarse = c.solve;
  run.coarse_lap_time = c.lap_time;
  if (adaptive && c.solve.ok()) return SolvedProblem{c, coarse};
  if (c.solve.ok() && !lap.mesh_m.empty()) {
    StartFromSolutionOnMesh(c.solve, c.layout, track.length_m(), lap.mesh_m,
                            options.coarse_multipliers, lap.start_point, fine_ipopt);
  } else if (c.solve.ok()) {
    StartFromSolution(c.solve, c.layout, LapNodeCount(track, options.step_m, lap.collocation),
                      lap.collocation, options.coarse_multipliers, lap.start_point, fine_ipopt);
  }
  return std::nullopt;
}

// The fine solve (`lap` from the coarse solve's start, or as given), or with the adaptive mesh
// the refinement from `adaptive_start` (the coarse solve) or from the fine solve; a refinement
// done elsewhere (OptimalLapOptions::presolved with rounds) is taken as it ended. `lap` ends as
// the problem of the solve kept, as it was posed.
void SolveFine(const vehicle::Car& hot_car, const track::Track& track,
               const OptimalLapOptions& options, bool adaptive, const LapWarmUp& w,
               std::optional<SolvedProblem> adaptive_start, LapProblemOptions& lap,
               const IpoptOptions& fine_ipopt, OptimalLapRun& run) {
  if (adaptive && options.presolved && !options.presolved->rounds.empty()) {
    run.mesh_rounds = options.presolved->rounds;
    if (options.presolved->mesh_m.empty() && adaptive_start) {
      // Refined elsewhere and the coarse solve kept (within the tolerance, or no refined solve
      // converged).
      run.solution = std::move(adaptive_start->solution);
      lap = std::move(adaptive_start->problem);
      return;
    }
    // Refined elsewhere: the last solve on its mesh, from its start.
    lap.mesh_m = options.presolved->mesh_m;
    lap.start_point = options.presolved->start_point;
    lap.wear_in_programme = options.wear_in_programme;
    run.solution =
        SolveMinimumTimeLap(hot_car, track, lap, w.guess, fine_ipopt, &options.presolved->fine);
    return;
  }
  if (!adaptive_start) {
    run.solution = SolveMinimumTimeLap(hot_car, track, lap, w.guess, fine_ipopt,
                                       options.presolved ? &options.presolved->fine : nullptr);
    // From a start point (or with no coarse solve): refined from this solve.
    if (!adaptive || !run.solution.solve.ok() || options.presolved) return;
    adaptive_start = SolvedProblem{std::move(run.solution), lap};
  }
  AdaptiveMeshResult a =
      RefineLapMesh(hot_car, track, lap, w.guess, options, std::move(adaptive_start->solution),
                    std::move(adaptive_start->problem));
  run.solution = std::move(a.solution);
  run.mesh_rounds = std::move(a.rounds);
  lap = std::move(a.problem);
}

// The QSS lap on the optimal line, one lap from the optimal lap's own thermal start.
void QssOnOptimalLine(const vehicle::Car& car, const track::Track& track,
                      const sim::QssOptions& qss, OptimalLapRun& run) {
  const LapSolution& s = run.solution;
  if (s.distance.size() >= 4 && s.distance.size() == s.n.size()) {
    std::vector<double> at(s.distance), offset(s.n);
    if (at.back() >= track.length_m() - 1e-9) at.pop_back(), offset.pop_back();  // closing node
    const std::vector<sim::RoadPoint> own =
        sim::SampleRoadAlongLine(track, track::ResampleLine(at, offset, track, 2.0), 1.0);
    sim::QssOptions on_line = qss;
    on_line.laps = 1;
    on_line.initial = run.start;
    run.qss_on_line_lap_time = sim::RunQssLap(car, own, on_line).laps[0].lap_time;
  }
}

// The solution's channels as the exact models' inputs (each corner's share of the brake force).
sim::ReplayInputs ReplayInputsOf(const vehicle::Car& car, const LapSolution& s,
                                 const OptimalLapOptions& options) {
  sim::ReplayInputs in;
  in.time = s.time;
  const vehicle::VehicleParams& p = *car.vehicle;
  for (int c = 0; c < 4; ++c) {
    sim::CornerChannels& ch = in.corners[c];
    const CornerTrace& t = s.corners[c];
    ch.speed = t.speed;
    ch.fx = t.fx;
    ch.fy = t.fy;
    ch.fz = t.fz;
    ch.slip_angle = t.slip_angle;
    ch.slip_ratio = t.slip_ratio;
    const double share =
        IsFront(kAllCorners[c]) ? 0.5 * p.brakes.front_share : 0.5 * (1.0 - p.brakes.front_share);
    for (double b : s.brake_force) ch.brake_fx.push_back(-share * b);
  }
  in.ambient_temp.assign(s.time.size(), options.ambient_temp);
  in.track_temp.assign(s.time.size(), options.track_temp);
  return in;
}

// Where the replay starts: the run's start, or a periodic lap's own first node.
sim::ReplayInitialState ReplayStart(const LapSolution& s, bool periodic_thermal,
                                    const sim::ReplayInitialState& start) {
  return periodic_thermal ? StateAtNode(s, 0, start) : start;
}

// The exact models over the solution's channels, and how far they are from the solution's.
void ReplayExact(const vehicle::Car& car, const track::Track& track,
                 const OptimalLapOptions& options, bool periodic_thermal, OptimalLapRun& run) {
  const LapSolution& s = run.solution;
  if (s.time.size() < 2) return;
  const sim::ReplayInputs in = ReplayInputsOf(car, s, options);
  const sim::ReplayInitialState from = ReplayStart(s, periodic_thermal, run.start);
  // The audit a lap at a time (a stint's track repeats the lap): a stretch from each lap's
  // first node.
  sim::ReplayOptions replay;
  for (int lap = 1; lap < track.laps(); ++lap) {
    const double s0 = lap * track.length_m() / track.laps();
    const size_t k = static_cast<size_t>(
        std::lower_bound(s.distance.begin(), s.distance.end(), s0 - 1e-9) - s.distance.begin());
    const size_t last = replay.audit_starts.empty() ? 0 : replay.audit_starts.back();
    if (k > last && k + 1 < s.time.size()) replay.audit_starts.push_back(k);
  }
  run.exact = sim::RunReplay(car, in, from, replay);
  for (int c = 0; c < 4; ++c) {
    for (size_t k = 0; k < s.time.size(); ++k) {
      run.max_tread_difference_K =
          std::max(run.max_tread_difference_K,
                   std::abs(run.exact.corners[c].tread_temp[k] - s.corners[c].tread_temp[k]));
      run.max_disc_difference_K =
          std::max(run.max_disc_difference_K,
                   std::abs(run.exact.corners[c].disc_temp[k] - s.corners[c].disc_temp[k]));
    }
  }
}

// A start the solve could not get from to the optimum (not one stopped or out of time).
bool StartFailed(SolveStatus status) {
  return status == SolveStatus::kIterationLimit || status == SolveStatus::kInfeasible ||
         status == SolveStatus::kRestorationFailed || status == SolveStatus::kNumericalTrouble;
}

// Where the solve `options` pose started, after it ran into `run`: "the given start point", "a 15
// m coarse solve" (the fine solve started from it only where it converged) or "the QSS guess".
std::string StartLabel(const OptimalLapOptions& options, bool adaptive, const OptimalLapRun& run) {
  if (!options.start_point.empty()) return "the given start point";
  const bool coarse =
      adaptive ? options.coarse_step_m > 0.0 : options.coarse_step_m > options.step_m;
  if (coarse && run.coarse.ok()) return fmt::format("a {:g} m coarse solve", options.coarse_step_m);
  return "the QSS guess";
}

// One solve from the start `options` give (a coarse solve first, or the QSS guess, or the
// caller's start point): the problem as posed, the solution and the coarse solve in `run`.
LapProblemOptions SolveFromStart(const vehicle::Car& hot_car, const track::Track& track,
                                 const OptimalLapOptions& options, bool adaptive,
                                 const LapWarmUp& w, OptimalLapRun& run) {
  LapProblemOptions lap = ProblemOptions(options, run.start);
  IpoptOptions fine_ipopt = options.ipopt;
  std::optional<SolvedProblem> adaptive_start;  // the coarse solve: the refinement starts there
  if (options.start_point.empty() &&
      (adaptive ? options.coarse_step_m > 0.0 : options.coarse_step_m > options.step_m)) {
    adaptive_start = SolveCoarseFirst(hot_car, track, options, adaptive, w, lap, fine_ipopt, run);
  }
  // With the coarse solve's multipliers the fine solve is a warm start (small barrier, the point
  // kept where it is). Without them, Ipopt's own first barrier: a small one with the point alone
  // (1e-4 with the start kept 1e-6 off its bounds, IpoptOptions::primal_start_mu) helped the
  // uncalibrated car's free lap (36 iterations against 167) but stalled the calibrated car's
  // limited lap (900 and more against 66; docs/validation/optimal-control.md, "Speed").
  if (!lap.start_point.empty()) {
    lap.wear_in_programme = options.wear_in_programme;
    // From a solution (the coarse one, or another lap's): MUMPS with SCOTCH's ordering, 0.42-0.44
    // s an iteration on the 3 m lap against 0.47 with PORD's and 0.57 with its automatic choice,
    // to the same laps, and bit for bit the same from run to run on one SCOTCH thread
    // (ipopt_solve.cc). Not from the QSS guess, where SCOTCH sent the limited lap's 15 m solve the
    // long way (266 iterations against 92; docs/validation/optimal-control.md, "Speed"). First, so
    // that an option given wins.
    fine_ipopt.extra.insert(fine_ipopt.extra.begin(), {"mumps_pivot_order", "3"});
  }
  SolveFine(hot_car, track, options, adaptive, w, std::move(adaptive_start), lap, fine_ipopt, run);
  return lap;
}

}  // namespace

sim::ReplayInitialState StateAtNode(const LapSolution& s, size_t k,
                                    const sim::ReplayInitialState& fallback) {
  sim::ReplayInitialState at = fallback;
  for (int c = 0; c < 4; ++c) {
    const CornerTrace& t = s.corners[c];
    at.tyres[c] = {t.tread_temp[k], t.carcass_temp[k], t.wear[k],
                   t.rim_temp.empty() ? fallback.tyres[c].rim_temp : t.rim_temp[k]};
    at.brakes[c] = {t.disc_temp[k], t.calliper_temp[k],
                    t.disc_bulk_temp.empty() ? fallback.brakes[c].bulk_temp : t.disc_bulk_temp[k]};
  }
  return at;
}

ThermalStart ParseThermalStart(const std::string& name) {
  if (name == "racing") return ThermalStart::kRacing;
  if (name == "warm") return ThermalStart::kWarm;
  if (name == "car") return ThermalStart::kCar;
  if (name == "periodic") return ThermalStart::kPeriodic;
  throw InputError(fmt::format("thermal start '{}': expected racing, warm, car or periodic", name));
}

LapWarmUp RunLapWarmUp(const vehicle::Car& any_car, const track::Track& track,
                       const OptimalLapOptions& options) {
  // The warm-up laps run the programme's models.
  const vehicle::Car car = ProgrammeCar(any_car, options);
  vehicle::RequireVehicle(car, "the optimal lap");
  // On the minimum-curvature line from the car's starting state: one out-lap (the warm start),
  // or laps until the carcasses rise slowly (the racing start); the flying lap after it seeds the
  // solve.
  const track::RacingLine line =
      MinimumCurvatureLine(track, {.step_m = 2.0, .margin_m = options.line_margin_m});
  const std::vector<sim::RoadPoint> road = sim::SampleRoadAlongLine(track, line, 1.0);
  const sim::QssOptions qss = WarmUpQss(car, track, options);
  sim::QssResult warm = sim::RunQssLap(car, road, qss);
  const auto end_of = [&car](const sim::QssLap& lap) {
    sim::ReplayInitialState e = sim::EndState(lap.thermal);
    for (int k = 0; k < 4; ++k) {
      e.tyres[k].wear = 0.0;
      // A paper tyre keeps no rim temperature: the car's start value.
      if (!car.tyres[k].params.HasGasAndRim()) e.tyres[k].rim_temp = car.initial.rim_temp;
    }
    return e;
  };
  LapWarmUp w;
  w.start = end_of(warm.laps[0]);
  w.start_laps = 1;
  if (options.thermal_start == ThermalStart::kRacing) {
    // Lap after lap (each from the last one's end, wear kept at zero) until the carcasses rise
    // slowly enough.
    sim::QssOptions one = qss;
    one.laps = 1;
    for (sim::QssLap last = warm.laps[1]; w.start_laps < options.racing_max_laps;) {
      const sim::ReplayInitialState next = end_of(last);
      double change = 0.0;
      for (int k = 0; k < 4; ++k) {
        change = std::max(change, next.tyres[k].carcass_temp - w.start.tyres[k].carcass_temp);
      }
      w.start = next;
      ++w.start_laps;
      w.start_carcass_rise_K = change;
      if (change <= options.racing_carcass_rise_K) break;
      one.initial = w.start;
      last = std::move(sim::RunQssLap(car, road, one).laps[0]);
    }
    one.initial = w.start;
    warm.laps[1] = std::move(sim::RunQssLap(car, road, one).laps[0]);
  }
  if (options.thermal_start == ThermalStart::kCar) {
    w.start = sim::CarStartState(car);
    w.start_laps = 0;
  }
  w.guess = std::move(warm.laps[1]);
  return w;
}

OptimalLapRun RunOptimalLap(const vehicle::Car& any_car, const track::Track& track,
                            const OptimalLapOptions& options, const LapWarmUp* warm_up) {
  // The programme's models: so run its guess and its replay.
  const vehicle::Car car = ProgrammeCar(any_car, options);
  vehicle::RequireVehicle(car, "the optimal lap");
  const LapWarmUp own_warm_up = warm_up ? LapWarmUp{} : RunLapWarmUp(car, track, options);
  const LapWarmUp& w = warm_up ? *warm_up : own_warm_up;
  const sim::QssOptions qss = WarmUpQss(car, track, options);
  // The tyres' forces at the hot pressures of the guess lap (sim/hot_pressure.h).
  const vehicle::Car hot_car =
      sim::WithHotPressures(car, sim::MeanHotPressures(car, w.guess.thermal));
  OptimalLapRun run;
  run.start = w.start;
  run.start_laps = w.start_laps;
  run.start_carcass_rise_K = w.start_carcass_rise_K;
  run.qss_lap_time = w.guess.lap_time;

  const bool adaptive = options.tolerance_s > 0.0 && options.collocation == Collocation::kTrapezoid;
  const bool caller_start = !options.start_point.empty();
  // A caller's start point that may fall back gets its own iteration limit: a slow start is
  // given up early rather than run to the full limit.
  OptimalLapOptions current = options;
  if (caller_start && options.start_point_fallback && options.start_point_max_iterations > 0) {
    current.ipopt.max_iterations =
        std::min(options.start_point_max_iterations, options.ipopt.max_iterations);
  }
  LapProblemOptions lap = SolveFromStart(hot_car, track, current, adaptive, w, run);
  // Robust starts: a fixed-mesh solve that fails from its start (at the iteration limit, at a
  // locally infeasible point, or lost in restoration or numerical trouble; not stopped or out of
  // time) is solved again from the next: a caller's start point (with start_point_fallback) falls
  // back to the default start, a coarse solution to the QSS guess, the guess to a coarse solve at
  // twice the spacing. Every failed attempt is reported (OptimalLapRun::failed_starts).
  int retries = !options.fallback_start || adaptive || options.presolved || options.coarse_start ? 0
                : caller_start ? (options.start_point_fallback ? 2 : 0)
                               : 1;
  for (; retries > 0 && StartFailed(run.solution.solve.status); --retries) {
    OptimalLapOptions other = current;
    if (!current.start_point.empty()) {
      other.start_point.clear();
      other.ipopt.warm_z_lower.clear();
      other.ipopt.warm_z_upper.clear();
      other.ipopt.warm_lambda.clear();
      other.ipopt.max_iterations = options.ipopt.max_iterations;
    } else {
      // The fine solve started from the coarse solution only where that converged.
      const bool from_coarse = current.coarse_step_m > current.step_m && run.coarse.ok();
      other.coarse_step_m = from_coarse ? 0.0 : 2.0 * current.step_m;
    }
    run.failed_starts.push_back({StartLabel(current, adaptive, run), run.solution.solve.iterations,
                                 run.solution.solve.message});
    run.coarse = {};
    run.coarse_lap_time = 0.0;
    lap = SolveFromStart(hot_car, track, other, adaptive, w, run);
    current = std::move(other);
  }
  run.started_from = StartLabel(current, adaptive, run);
  run.posed = std::make_shared<const PosedLap>(PosedLap{lap, w.guess});
  run.mesh_error = EstimateMeshError(run.solution.rates);
  QssOnOptimalLine(car, track, qss, run);
  ReplayExact(car, track, options, lap.periodic_thermal, run);
  return run;
}

LapProgrammeValues EvaluateRunProgramme(const vehicle::Car& any_car, const track::Track& track,
                                        const OptimalLapOptions& options,
                                        const OptimalLapRun& run) {
  if (!run.posed || run.solution.solve.x.empty()) {
    throw InputError("optimal lap: the run has no solution to evaluate its programme at");
  }
  const vehicle::Car car = ProgrammeCar(any_car, options);
  vehicle::RequireVehicle(car, "the optimal lap");
  const vehicle::Car hot_car =
      sim::WithHotPressures(car, sim::MeanHotPressures(car, run.posed->guess.thermal));
  return EvaluateLapProgramme(hot_car, track, run.posed->problem, run.posed->guess,
                              run.solution.solve.x);
}

std::vector<TurnApproach> FindTurnApproaches(const LapSolution& solution, const track::Track& track,
                                             double wheel_power) {
  const track::TrackSummary summary = track::Summarize(track);
  std::vector<TurnApproach> out;
  const size_t n = solution.distance.size();
  if (n < 3) return out;
  const bool oval = summary.turns.size() == 2;
  for (size_t t = 0; t < summary.turns.size(); ++t) {
    const track::TrackTurn& turn = summary.turns[t];
    TurnApproach a;
    a.turn = oval ? (t == 0 ? "turns 1-2" : "turns 3-4") : fmt::format("turn {}", t + 1);
    a.entry_m = turn.entry_m;
    // The slowest node between the turn's entry and exit.
    const auto in_turn = [&](double s) {
      return turn.exit_m >= turn.entry_m ? (s >= turn.entry_m && s <= turn.exit_m)
                                         : (s >= turn.entry_m || s <= turn.exit_m);
    };
    size_t slowest = n;
    for (size_t k = 0; k + 1 < n; ++k) {
      if (in_turn(solution.distance[k]) && (slowest == n || solution.u[k] < solution.u[slowest])) {
        slowest = k;
      }
    }
    if (slowest == n) continue;
    a.min_speed_mps = solution.u[slowest];
    a.min_speed_at_m = solution.distance[slowest];
    // Walk back from the slowest point (at most 600 m) to the latest stretch off full power and
    // the latest braking: the lift point is where that stretch starts, the brake point where
    // that braking starts.
    const size_t m = n - 1;  // the last node repeats the first
    const auto prev = [m](size_t k) { return (k + m - 1) % m; };
    // (The shortest interval: on a non-uniform mesh 600 m is at most that many nodes.)
    double spacing = solution.distance[1] - solution.distance[0];
    for (size_t k = 2; k < n; ++k) {
      spacing = std::min(spacing, solution.distance[k] - solution.distance[k - 1]);
    }
    const size_t reach = std::min(m / 2, static_cast<size_t>(600.0 / spacing));
    const auto off_power = [&](size_t k) { return solution.drive_power[k] < 0.95 * wheel_power; };
    const auto braking = [&](size_t k) { return solution.brake_force[k] > 100.0; };
    const auto start_of = [&](size_t k, const auto& in_run) {
      size_t j = k;
      for (size_t i = 0; i < reach && in_run(prev(j)); ++i) j = prev(j);
      return j;
    };
    size_t k = slowest % m;
    for (size_t i = 0; i < reach; ++i, k = prev(k)) {
      if (off_power(k)) {
        a.lift_m = solution.distance[start_of(k, off_power)];
        break;
      }
    }
    k = slowest % m;
    for (size_t i = 0; i < reach; ++i, k = prev(k)) {
      if (braking(k)) {
        a.brake_m = solution.distance[start_of(k, braking)];
        break;
      }
    }
    out.push_back(a);
  }
  return out;
}

}  // namespace hotlap::ocp
