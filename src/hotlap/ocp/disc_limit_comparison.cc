#include "hotlap/ocp/disc_limit_comparison.h"

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/units.h"
#include "hotlap/ocp/child_solve.h"

namespace hotlap::ocp {

namespace {

// The child's adaptive mesh as one more SolveResult for the pipe: x the mesh of the solve kept
// (empty if it kept the coarse one), z_upper that solve's start point (it froze the wear),
// z_lower the rounds (seven numbers each); and back.
constexpr int kRoundNumbers = 7;

SolveResult EncodeMesh(const OptimalLapRun& run) {
  SolveResult r;
  if (run.posed) {
    r.x = run.posed->problem.mesh_m;
    if (!r.x.empty()) r.z_upper = run.posed->problem.start_point;
  }
  for (const MeshRound& m : run.mesh_rounds) {
    r.z_lower.insert(
        r.z_lower.end(),
        {static_cast<double>(m.nodes), static_cast<double>(m.iterations), m.solve_seconds,
         m.lap_time_s, m.estimated_error_s, m.abs_error_s, m.converged ? 1.0 : 0.0});
  }
  return r;
}

std::vector<MeshRound> DecodeRounds(const SolveResult& r) {
  std::vector<MeshRound> out;
  for (size_t i = 0; i + kRoundNumbers <= r.z_lower.size(); i += kRoundNumbers) {
    const double* v = r.z_lower.data() + i;
    out.push_back(
        {static_cast<int>(v[0]), static_cast<int>(v[1]), v[2], v[3], v[4], v[5], v[6] != 0.0});
  }
  return out;
}

}  // namespace

SolvedLap SolveLap(const vehicle::Car& car, const track::Track& track, OptimalLapOptions options,
                   const std::string& label, const SolveResult* from, const LapProgress& progress,
                   const LapLog& log, const LapWarmUp* warm_up) {
  if (from != nullptr) {
    // Warm start: the other solution's point and multipliers (same variables and rows).
    options.start_point = from->x;
    options.ipopt.warm_z_lower = from->z_lower;
    options.ipopt.warm_z_upper = from->z_upper;
    options.ipopt.warm_lambda = from->lambda;
  }
  if (log && !options.on_mesh) {
    options.on_mesh = [&log, label](const MeshRefinement& m) {
      double shortest = 1e300, longest = 0.0;
      for (size_t k = 1; k < m.mesh_m.size(); ++k) {
        shortest = std::min(shortest, m.mesh_m[k] - m.mesh_m[k - 1]);
        longest = std::max(longest, m.mesh_m[k] - m.mesh_m[k - 1]);
      }
      log(
          fmt::format("{}: refined mesh: {} nodes ({} intervals split, {} pairs merged), "
                      "intervals {:.2f} to {:.1f} m",
                      label, m.mesh_m.size(), m.split, m.merged, shortest, longest));
    };
  }
  if (progress) {
    options.ipopt.on_iteration = [&](int it, double obj, double pr, double du) {
      return progress(label, it, obj, pr, du);
    };
  }
  const bool adaptive = options.tolerance_s > 0.0 && options.collocation == Collocation::kTrapezoid;
  if (log && !options.presolved) {
    log(fmt::format(
        "{}: solving ({}{}{}{})...", label,
        adaptive ? fmt::format("adaptive mesh to {:g} ms", 1e3 * options.tolerance_s)
                 : fmt::format("{:.1f} m mesh", options.step_m),
        options.collocation == Collocation::kHermiteSimpson ? ", Hermite-Simpson" : "",
        options.front_disc_limit
            ? fmt::format(", front discs <= {:g} degC", KelvinToCelsius(*options.front_disc_limit))
            : "",
        from != nullptr        ? ", from the other solution"
        : options.coarse_start ? ", the coarse solve from the other lap's"
                               : ""));
  }
  SolvedLap s;
  s.label = label;
  s.front_disc_limit = options.front_disc_limit;
  s.run = RunOptimalLap(car, track, options, warm_up);
  const double wheel_power = car.vehicle->powertrain.WheelPower();
  s.figures = CalcOptimalLapFigures(s.run, wheel_power);
  s.approaches = FindTurnApproaches(s.run.solution, track, wheel_power);
  if (log) {
    const SolveResult& r = s.run.solution.solve;
    if (s.run.coarse.iterations > 0) {
      log(
          fmt::format("{}: coarse solve ({:g} m mesh) {} after {} iterations in {:.1f} s: lap "
                      "{:.3f} s; the {} starts from it",
                      label, options.coarse_step_m, s.run.coarse.message, s.run.coarse.iterations,
                      s.run.coarse.solve_seconds, s.run.coarse_lap_time,
                      adaptive ? "refinement" : "fine solve"));
    }
    for (size_t i = 1; i < s.run.mesh_rounds.size(); ++i) {
      const MeshRound& m = s.run.mesh_rounds[i];
      log(fmt::format(
          "{}: mesh round {}: {} nodes, {} iterations in {:.1f} s, lap {:.4f} s, "
          "estimated mesh error {:+.3f} ms (sum of |e| {:.3f} ms){}",
          label, i, m.nodes, m.iterations, m.solve_seconds, m.lap_time_s, 1e3 * m.estimated_error_s,
          1e3 * m.abs_error_s, m.converged ? "" : ", not converged: the mesh before is kept"));
    }
    log(
        fmt::format("{}: {} after {} iterations in {:.1f} s: lap {:.3f} s (QSS {:.3f} s on the "
                    "minimum-curvature line, {:.3f} s on this lap's line)",
                    label, r.message, r.iterations, r.solve_seconds, s.figures.lap_time_s,
                    s.run.qss_lap_time, s.run.qss_on_line_lap_time));
    if (!r.ok()) {
      log(fmt::format(
          "{}: kept the last point (its files are written): largest constraint violation {:.2g} "
          "(scaled; about 1e-7 or less on a lap the car can drive), so read its lap time as an "
          "unfinished solve's, not a lap",
          label, r.primal_infeasibility));
    }
  }
  return s;
}

DiscLimitComparison CompareDiscLimit(const vehicle::Car& car, const track::Track& track,
                                     const OptimalLapOptions& options, double front_disc_limit,
                                     const LapProgress& progress, const LapLog& log) {
  OptimalLapOptions free_options = options;
  free_options.front_disc_limit.reset();
  free_options.start_point.clear();
  OptimalLapOptions limited_options = free_options;
  limited_options.front_disc_limit = front_disc_limit;
  const std::string limited_label =
      fmt::format("discs <= {:g} degC", KelvinToCelsius(front_disc_limit));

  // The warm-up once for all solves; a limit the discs start above is refused before any.
  const LapWarmUp warm_up = RunLapWarmUp(car, track, free_options);
  if (options.thermal_start != ThermalStart::kPeriodic) {
    RequireFrontDiscsWithinLimit(warm_up.start, front_disc_limit);
  }

  // The limited lap: coarse to fine like the free one where that is on, else warm-started from
  // the free lap. Where the limit changes the lap much (the Gen-7-like car's front-left disc
  // from 846 to 500 degC) the free lap is a poor start: 241 iterations (206 s) on the 3 m mesh
  // from it against 66 after 91 on the 15 m mesh (46 s in all), the same lap. The limited coarse
  // solve starts from the free one's (52 iterations against 324 from the QSS guess, the same
  // lap; docs/validation/optimal-control.md, "Speed"), and from there the two laps are independent:
  // the limited one runs in a child process beside the free one's fine solve.
  const bool coarse_to_fine =
      options.tolerance_s > 0.0 && options.collocation == Collocation::kTrapezoid
          ? options.coarse_step_m > 0.0
          : options.coarse_step_m > options.step_m;
  if (coarse_to_fine) {
    // The two solves share the derivative threads when side by side; so they do one after the
    // other too (--single-process), so that both ways give the same laps bit for bit.
    free_options.derivative_threads = limited_options.derivative_threads =
        std::max(1, options.derivative_threads / 2);
  }
  std::optional<ChildSolve> child;
  if (coarse_to_fine) {
    free_options.on_coarse_solve = [&](const LapSolution& coarse) {
      if (!coarse.solve.ok()) return;  // the limited lap then starts from the QSS guess
      limited_options.coarse_start = OptimalLapOptions::CoarseStart{coarse.layout, coarse.solve};
      if (!options.second_process) return;
      if (log)
        log(fmt::format("{}: solving in a second process, its coarse solve from this one's",
                        limited_label));
      child.emplace([&] {
        const SolvedLap l =
            SolveLap(car, track, limited_options, limited_label, nullptr, progress, {}, &warm_up);
        return std::vector<SolveResult>{l.run.coarse, l.run.solution.solve, EncodeMesh(l.run)};
      });
    };
  }
  DiscLimitComparison c;
  c.free = SolveLap(car, track, free_options, "no limit", nullptr, progress, log, &warm_up);
  free_options.on_coarse_solve = nullptr;
  const SolveResult& free = c.free.run.solution.solve;
  if (child) {
    std::optional<std::vector<SolveResult>> r = child->Join();
    if (r && r->size() == 3) {
      limited_options.presolved = PresolvedLap{std::move((*r)[0]), std::move((*r)[1]), (*r)[2].x,
                                               DecodeRounds((*r)[2]), (*r)[2].z_upper};
      c.limited_in_second_process = true;
    } else if (log) {
      log(fmt::format("{}: the second process gave no answer; solving here", limited_label));
    }
  }
  c.limited = SolveLap(car, track, limited_options, limited_label,
                       free.ok() && !coarse_to_fine ? &free : nullptr, progress, log, &warm_up);
  limited_options.presolved.reset();
  if (coarse_to_fine && free.ok() && !c.limited.run.solution.solve.ok()) {
    // The continuation from the free lap as the fallback: slower where the limit changes the lap
    // much, but it starts from a lap that differs only where the limit acts (a brake balance of
    // 0.65 front sent the limited lap's 15 m solve from the QSS guess astray).
    if (log) {
      log(fmt::format("{}: not converged coarse to fine; solving again from the free lap",
                      limited_label));
    }
    SolvedLap again =
        SolveLap(car, track, limited_options, limited_label, &free, progress, log, &warm_up);
    if (again.run.solution.solve.ok()) {
      again.run.solution.solve.iterations += c.limited.run.solution.solve.iterations;
      again.run.solution.solve.solve_seconds += c.limited.run.solution.solve.solve_seconds;
      c.limited = std::move(again);
    }
  }
  const SolveResult& limited = c.limited.run.solution.solve;
  if (limited.ok() && c.limited.figures.lap_time_s < c.free.figures.lap_time_s) {
    if (log) {
      log(fmt::format(
          "no limit: the limited lap is {:.1f} ms faster, so the free solve stopped at a local "
          "optimum; solving it again from the limited lap",
          1e3 * (c.free.figures.lap_time_s - c.limited.figures.lap_time_s)));
    }
    SolvedLap again =
        SolveLap(car, track, free_options, "no limit", &limited, progress, log, &warm_up);
    if (again.run.solution.solve.ok() &&
        (!free.ok() || again.figures.lap_time_s < c.free.figures.lap_time_s)) {
      again.run.solution.solve.iterations += free.iterations;
      again.run.solution.solve.solve_seconds += free.solve_seconds;
      c.free = std::move(again);
      c.free_solved_again = true;
    }
  }
  return c;
}

}  // namespace hotlap::ocp
