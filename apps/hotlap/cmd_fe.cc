// `hotlap fe inflate|footprint|roll|abs`: the finite-element tyre's steps (docs/fe-tyre.md).
// Each step runs the ones before it (footprint inflates first, and so on). Outputs: a history CSV
// per step, the footprint pressure map (CSV and SVG), deformed shapes as .vtu, a JSON summary.
// The abs step (sim::FeAbsStop) can write checkpoints (--checkpoint-every-s) and continue from
// one (--restart). This file parses, calls the library and writes.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/fe/fe_config.h"
#include "hotlap/fe/step_json.h"
#include "hotlap/fe/step_output.h"
#include "hotlap/fe/tyre_steps.h"
#include "hotlap/fe/vtu_writer.h"
#include "hotlap/sim/abs_config.h"
#include "hotlap/sim/abs_metrics.h"
#include "hotlap/sim/abs_run.h"
#include "hotlap/sim/fe_abs_json.h"
#include "hotlap/sim/fe_abs_report.h"
#include "hotlap/sim/fe_abs_stop.h"

namespace hotlap::app {

namespace {

namespace fs = std::filesystem;

struct FeArgs {
  std::string step;
  std::string config;
  std::string out;
  std::string json;
  double duration_s = 0.0;          // 0: the file's
  int threads = 0;                  // 0: OpenMP's default (all cores)
  std::string kernel;               // empty: HOTLAP_FE_KERNEL, else auto
  double checkpoint_every_s = 0.0;  // 0: no checkpoints
  std::string restart;              // checkpoint to continue from
  double step_scale = 1.0;          // the time step is this times the stable one's (0, 1]
};

constexpr const char* kCheckpointName = "abs_checkpoint.bin";

// --kernel, else the environment variable HOTLAP_FE_KERNEL, else auto.
fe::ElementKernel ChooseKernel(const std::string& option) {
  if (!option.empty()) return fe::ParseElementKernel(option, "--kernel");
  const char* env = std::getenv("HOTLAP_FE_KERNEL");
  if (env == nullptr || *env == '\0') return fe::BestElementKernel();
  return fe::ParseElementKernel(env, "fe: HOTLAP_FE_KERNEL");
}

// The warning for a cord strain above what the stable step allows for, on stderr.
void WarnCordStrain(const char* step, double strain) {
  const std::string w = fe::CordStrainWarning(step, strain);
  if (!w.empty()) std::fprintf(stderr, "%s\n", w.c_str());
}

// Reads the checkpoint into `run` and `stop` before anything is written; says on stderr where
// the restart differs from the run that wrote it. Returns the earlier steps' JSON summary.
nlohmann::json Restart(const std::string& file, const fe::CheckpointKey& key, fe::TyreRun& run,
                       sim::FeAbsStop& stop) {
  const sim::FeAbsCheckpointInfo info = stop.Restore(file, key);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(info.summary);
  } catch (const nlohmann::json::exception&) {
    throw InputError(fmt::format(
        "checkpoint '{}' is damaged: its summary of the earlier steps is not JSON", file));
  }
  if (!j.is_object()) {
    throw InputError(fmt::format(
        "checkpoint '{}' is damaged: its summary of the earlier steps is not a JSON object", file));
  }
  const fe::ExplicitSolver& solver = run.solver();
  if (info.threads != static_cast<std::uint64_t>(solver.threads())) {
    std::fprintf(stderr,
                 "fe: the checkpoint was written on %llu threads, this run uses %d: it continues "
                 "to round-off, not bit for bit (the element forces are summed per thread)\n",
                 static_cast<unsigned long long>(info.threads), solver.threads());
  }
  if (info.kernel != solver.element_kernel()) {
    std::fprintf(stderr,
                 "fe: the checkpoint was written with the %s element kernel, this run uses %s: "
                 "it continues to round-off, not bit for bit (--kernel chooses)\n",
                 fe::ElementKernelName(info.kernel),
                 fe::ElementKernelName(solver.element_kernel()));
  }
  std::fprintf(stderr, "fe: restarting from '%s' at t = %.6g s (%.6g s into the abs step)\n",
               file.c_str(), solver.time(), solver.time() - run.brake_start_s());
  return j;
}

int RunFeCommand(const FeArgs& a) {
  // Checked before any work, created once the input is accepted (nothing left on refusal).
  const fs::path out(a.out);
  CheckOutputDirectory(out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  fe::FeConfig config = fe::LoadFeConfig(a.config);
  const int last = a.step == "inflate" ? 0 : a.step == "footprint" ? 1 : a.step == "roll" ? 2 : 3;
  if (last != 3 && !a.restart.empty()) {
    throw InputError("--restart: only `hotlap fe abs` continues from a checkpoint");
  }
  if (last != 3 && a.checkpoint_every_s > 0.0) {
    throw InputError("--checkpoint-every-s: only `hotlap fe abs` writes checkpoints");
  }
  if (a.duration_s > 0.0) {
    if (last == 2) config.roll_duration_s = a.duration_s;
    if (last == 3) config.abs_duration_s = a.duration_s;
  }
  config.solver.time_step_scale = a.step_scale;
  const fe::ElementKernel kernel = ChooseKernel(a.kernel);
  std::optional<sim::AbsConfig> abs_config;
  if (last == 3) abs_config = sim::LoadAbsConfig(config.abs_config);

  fe::TyreRun run(config);
  run.mutable_solver().set_threads(a.threads);
  run.mutable_solver().set_element_kernel(kernel);
  const fe::ExplicitSolver& solver = run.solver();
  const fe::MassScalingReport& ms = solver.mass_scaling();
  std::fprintf(
      stderr,
      "fe: %zu elements, %zu nodes; time step %.3g s (scale %g; stable %.3g s unscaled); "
      "mass %.3f kg, mass scaling added %.3f kg in %d elements; %d threads, %s element kernel\n",
      run.tyre().mesh.elements.size(), run.tyre().mesh.nodes.size(), solver.time_step(),
      a.step_scale, ms.stable_step_unscaled_s, ms.physical_mass_kg, ms.added_mass_kg,
      ms.scaled_elements, solver.threads(), fe::ElementKernelName(solver.element_kernel()));

  // The ABS stop (its controller's R_l is the free-rolling radius of the roll step, (002:2),
  // known once the roll step ran or the checkpoint is read).
  std::optional<sim::FeAbsStop> stop;
  if (last == 3) stop.emplace(run, *abs_config);
  nlohmann::json j;
  fe::CheckpointKey key;
  if (last == 3 && (a.checkpoint_every_s > 0.0 || !a.restart.empty())) {
    key = sim::MakeFeCheckpointKey(run);
  }
  const bool restarted = !a.restart.empty();
  if (restarted) j = Restart(a.restart, key, run, *stop);
  CreateOutputDirectory(out, "--out");
  const long steps_at_start = solver.steps();

  const auto wall0 = std::chrono::steady_clock::now();
  fe::StepHooks hooks;
  hooks.frames = config.vtu_frames;
  hooks.history_interval_s = config.history_interval_s;
  double step_t0 = 0.0;
  auto step_wall0 = wall0;
  hooks.progress = [&](const std::string& step, double t, double t_end) {
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - step_wall0).count();
    const double done = std::clamp((t - step_t0) / std::max(1e-12, t_end - step_t0), 0.0, 1.0);
    const double left = done > 0 ? wall * (1.0 - done) / done : 0.0;
    const std::string eta =
        left < 120.0 ? fmt::format("{:.0f} s", left) : fmt::format("{:.0f} min", left / 60.0);
    std::fprintf(stderr, "fe %s: t = %.5f s (%.0f%%), about %s left\n", step.c_str(), t,
                 100.0 * done, eta.c_str());
  };
  // Each checkpoint once it is whole on disk (the event a test of a kill waits for); the time as
  // a restart from it reports it.
  hooks.checkpoint_written = [](double t) {
    std::fprintf(stderr, "fe abs: checkpoint written at t = %.6g s\n", t);
  };
  hooks.frame = [&](const std::string& step, int frame) {
    fe::WriteVtu(out / fmt::format("{}_{:03d}.vtu", step, frame), solver);
  };
  const auto begin = [&] {
    step_t0 = solver.time();
    step_wall0 = std::chrono::steady_clock::now();
  };

  j["config"] = config.file.string();
  j["step"] = a.step;
  j["mesh"] = fe::FeMeshJson(run);
  if (!restarted) {
    begin();
    const fe::InflateResult inf = run.Inflate(hooks);
    fe::WriteFeHistoryCsv(out / "inflate_history.csv", "inflate", config, inf.history, 0.0);
    j["inflate"] = fe::InflateJson(inf, solver.energies());
    WarnCordStrain("inflate", inf.max_cord_strain);
    std::printf("inflate: %.0f kPa, outer radius %.2f -> %.2f mm, section width %.1f -> %.1f mm\n",
                1e-3 * inf.pressure_Pa, 1e3 * inf.outer_radius_before_m,
                1e3 * inf.outer_radius_after_m, 1e3 * inf.section_width_before_m,
                1e3 * inf.section_width_after_m);
    if (last >= 1) {
      begin();
      const fe::FootprintResult fp = run.Footprint(hooks);
      fe::WriteFeHistoryCsv(out / "footprint_history.csv", "footprint", config, fp.history, 0.0);
      fe::WriteFootprintPressure(out, config, fp);
      j["footprint"] = fe::FootprintJson(fp, solver.energies());
      WarnCordStrain("footprint", fp.max_cord_strain);
      std::printf(
          "footprint: %.0f N, loaded radius %.2f mm, deflection %.2f mm, %.0f kN/m, "
          "contact %.0f cm^2 (%.0f x %.0f mm node to node), mean %.0f kPa\n",
          fp.road_force_z_N, 1e3 * fp.loaded_radius_m, 1e3 * fp.deflection_m,
          1e-3 * fp.vertical_stiffness_N_per_m, 1e4 * fp.contact_area_m2, 1e3 * fp.contact_length_m,
          1e3 * fp.contact_width_m, 1e-3 * fp.mean_pressure_Pa);
    }
    if (last >= 2) {
      begin();
      const fe::RollResult rr = run.Roll(hooks);
      fe::WriteFeHistoryCsv(out / "roll_history.csv", "roll", config, rr.history,
                            run.slip_radius_m());
      j["roll"] = fe::RollJson(rr, solver.energies());
      WarnCordStrain("roll", rr.max_cord_strain);
      std::printf(
          "roll: %.3f m/s, spin %.3f rad/s, effective radius %.2f mm (paper: 28.268 rad/s, "
          "394.2 mm), loaded radius %.2f mm\n",
          rr.speed_mps, rr.spin_rad_per_s, 1e3 * rr.effective_radius_m, 1e3 * rr.loaded_radius_m);
    }
  }
  if (last >= 3) {
    sim::FeAbsStopOptions options;
    options.duration_s = config.abs_duration_s;
    options.hooks = hooks;
    options.checkpoint_every_s = a.checkpoint_every_s;
    options.checkpoint_file = out / kCheckpointName;
    options.checkpoint_key = key;
    // The earlier steps' summary rides along, so that a restart's JSON is complete.
    if (a.checkpoint_every_s > 0.0) options.summary = j.dump();
    begin();
    if (restarted) step_t0 = run.brake_start_s();
    const sim::FeAbsStopResult r = stop->Run(options);
    const fe::BrakeResult& br = r.brake;
    fe::WriteFeHistoryCsv(out / "abs_history.csv", "abs", config, br.history, run.slip_radius_m());
    // The lumped `hotlap abs` run of the same event beside it (issue 27): the same controller
    // and hydraulics file, speed and duration, its own rigid wheel and brush tyre.
    sim::AbsEvent event = abs_config->event;
    event.initial_speed_mps = br.initial_speed_mps;
    event.duration_s = config.abs_duration_s;
    const sim::AbsRunResult lumped_run = sim::RunAbs(*abs_config, event);
    const sim::AbsMetrics lumped_metrics = sim::CalcAbsMetrics(*abs_config, lumped_run);
    const sim::FeAbsLumpedRun lumped{&lumped_run.history, lumped_metrics,
                                     abs_config->plant.wheel.radius};
    sim::WriteFeAbsReport(
        out / "abs_report.html", br.history, r.cycles, run.slip_radius_m(),
        {{"configuration", config.file.string()},
         {"mesh", fmt::format("{} elements, {} nodes", run.tyre().mesh.elements.size(),
                              run.tyre().mesh.nodes.size())}},
        &lumped);
    j["abs"] = sim::FeAbsStopJson(r, config.abs_duration_s, solver.energies());
    const auto opt = [](const std::optional<double>& v) {
      return v ? nlohmann::json(RoundSignificant(*v, 6)) : nlohmann::json(nullptr);
    };
    j["abs"]["lumped"] = {
        {"control_cycles", lumped_metrics.cycles},
        {"first_cycle_start_s", opt(lumped_metrics.first_cycle_start_s)},
        {"second_cycle_start_s", opt(lumped_metrics.second_cycle_start_s)},
        {"max_lambda_after_first_cycle", opt(lumped_metrics.max_lambda_after_first_cycle)},
        {"fraction_time_lambda_below_0_135", opt(lumped_metrics.fraction_time_lambda_below_0_135)},
        {"final_speed_mps", RoundSignificant(lumped_metrics.final_speed_mps, 6)},
        {"distance_m", RoundSignificant(lumped_metrics.distance_m, 6)}};
    WarnCordStrain("abs", br.max_cord_strain);
    std::printf("abs: %.3f s, speed %.3f -> %.3f m/s over %.3f m, max slip %.3f, %d cycles\n",
                config.abs_duration_s, br.initial_speed_mps, br.final_speed_mps, br.distance_m,
                br.max_slip, r.cycles.cycles);
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  // This process's share (after a restart, the steps since the checkpoint).
  const long steps = solver.steps() - steps_at_start;
  const double updates = double(steps) * run.tyre().mesh.elements.size();
  j["performance"] = {{"wall_s", RoundSignificant(wall, 4)},
                      {"steps", steps},
                      {"threads", solver.threads()},
                      {"element_kernel", fe::ElementKernelName(solver.element_kernel())},
                      {"element_updates_per_s", RoundSignificant(updates / wall, 4)}};
  if (restarted) j["performance"]["restarted_from"] = a.restart;
  std::printf("fe: %ld steps on %d threads, %.3g element updates in %.1f s (%.3g per second)\n",
              steps, solver.threads(), updates, wall, updates / wall);
  if (!a.json.empty()) WriteJsonFile(a.json, j);
  return 0;
}

}  // namespace

CommandRunner RegisterFeCommand(CLI::App& app) {
  auto args = std::make_shared<FeArgs>();
  CLI::App* sub = app.add_subcommand(
      "fe", "Finite-element tyre: inflate, footprint, free rolling, ABS stop (docs/fe-tyre.md)");
  sub->add_option("step", args->step, "inflate | footprint | roll | abs (runs the ones before)")
      ->required()
      ->check(CLI::IsMember({"inflate", "footprint", "roll", "abs"}));
  sub->add_option("--config", args->config, "FE tyre configuration (data/fe/*.yaml)")->required();
  sub->add_option("--out", args->out,
                  "Output folder: histories, footprint map, .vtu shapes, abs_report.html (abs)")
      ->required();
  sub->add_option("--json", args->json, "Write the summary as JSON (docs/fe-tyre.md)");
  sub->add_option("--duration-s", args->duration_s,
                  "Simulated time of the last step (roll or abs), s (default: the file's)")
      ->check(kPositive);
  sub->add_option("--threads", args->threads,
                  "Threads of the solver's element loop (default: all cores, OpenMP's default)")
      ->check(kPositive);
  sub->add_option("--kernel", args->kernel,
                  "Element loop: auto | portable | avx2 (default: HOTLAP_FE_KERNEL, else auto)")
      ->check(CLI::IsMember({"auto", "portable", "avx2"}));
  sub->add_option("--checkpoint-every-s", args->checkpoint_every_s,
                  "abs: write <out>/abs_checkpoint.bin every S of simulated time and at the end")
      ->check(kPositive);
  sub->add_option("--step-scale", args->step_scale,
                  "Time step as a fraction of the stable one's, in (0, 1] (a time-step study; "
                  "the road's penalty stiffness stays that of the full step; default 1)")
      ->check(CLI::Range(0.0, 1.0))
      ->check(kPositive);
  sub->add_option("--restart", args->restart,
                  "abs: continue from a checkpoint file (same configuration files and mesh)");
  return [args] { return RunFeCommand(*args); };
}

}  // namespace hotlap::app
