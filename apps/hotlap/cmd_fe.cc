// `hotlap fe inflate|footprint|roll|abs`: the finite-element tyre's steps (docs/fe-tyre.md).
// Each step runs the ones before it (footprint inflates first, and so on). Outputs: a history CSV
// per step, the footprint pressure map (CSV and SVG), deformed shapes as .vtu, a JSON summary.
// The abs step can write checkpoints (--checkpoint-every-s) and continue from one (--restart).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "commands.h"
#include "fe_abs_report.h"
#include "hotlap/brake/abs_controller.h"
#include "hotlap/brake/brake_hydraulics.h"
#include "hotlap/common/atomic_file.h"
#include "hotlap/common/csv.h"
#include "hotlap/common/error.h"
#include "hotlap/fe/checkpoint.h"
#include "hotlap/fe/fe_config.h"
#include "hotlap/fe/tyre_steps.h"
#include "hotlap/fe/vtu_writer.h"
#include "hotlap/sim/abs_config.h"
#include "hotlap/sim/abs_metrics.h"
#include "output.h"

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
  double checkpoint_every_s = 0.0;  // 0: no checkpoints
  std::string restart;              // checkpoint to continue from
};

constexpr const char* kCheckpointName = "abs_checkpoint.bin";

/// What the checkpoint is for: the mesh and the bytes of both configuration files (the FE file
/// and the ABS file it names). --duration-s is not part of it: a restart may run longer.
fe::CheckpointKey MakeCheckpointKey(const fe::TyreRun& run) {
  const auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) throw InputError(fmt::format("cannot read '{}'", p.string()));
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  fe::CheckpointKey key;
  key.mesh_hash = fe::HashMesh(run.tyre().mesh);
  key.nodes = run.tyre().mesh.nodes.size();
  key.elements = run.tyre().mesh.elements.size();
  key.config_hash =
      fe::Fnv1a64(bytes(run.config().abs_config), fe::Fnv1a64(bytes(run.config().file)));
  return key;
}

/// The ABS controller, its hydraulic delay line and the wheel-cylinder pressure, stepped at the
/// controller's period inside the FE braking step, with what a checkpoint needs.
class AbsTorque {
 public:
  AbsTorque(const sim::AbsConfig& ac, const brake::AbsControllerParams& cp)
      : ac_(ac), cp_(cp), delay_(ac.DelayTicks(), 0.0) {}

  /// Brake torque capacity at brake-step time t, N m.
  double operator()(double t, double vx, double spin) {
    while (t >= next_tick_ - 1e-12) {
      const int cycles = state_.cycles;
      const brake::AbsCommand cmd =
          brake::StepAbsController(cp_, state_, {vx, spin, ac_.driver.PressureAt(next_tick_)});
      if (state_.cycles > cycles) cycle_starts_.push_back(next_tick_);
      if (state_.state == brake::AbsState::kExit && !abs_exit_) abs_exit_ = next_tick_;
      target_ = Push(cmd.pressure_target);
      next_tick_ += cp_.period_s;
    }
    const brake::BrakeHydraulicsParams<double>& hyd = ac_.plant.hydraulics;
    pressure_ += (t - t_prev_) * brake::CalcPressureRate(hyd, pressure_, target_);
    t_prev_ = t;
    return brake::CalcBrakeTorqueCapacity(hyd, pressure_);
  }
  const brake::AbsControllerState& state() const { return state_; }
  /// Brake-step times (s from the braking step's start) of the controller's ticks that began a
  /// control cycle (a pressure release, as the lumped `hotlap abs` counts them).
  const std::vector<double>& cycle_starts() const { return cycle_starts_; }
  /// Brake-step time of the first tick in kExit (the ABS handing back to the driver), if any.
  std::optional<double> abs_exit() const { return abs_exit_; }

  void Save(fe::BinaryWriter& w) const {
    w.PutTag("ABS_");
    const brake::AbsControllerState& s = state_;
    w.PutU64(static_cast<std::uint64_t>(s.state));
    w.PutU64(static_cast<std::uint64_t>(s.hold_phase));
    w.PutU64((s.has_previous ? 1 : 0) | (s.seen_accel_above_a ? 2 : 0));
    w.PutI64(s.cycles);
    w.PutI64(s.ticks);
    for (double d :
         {s.pressure_command, s.time_in_state, s.step_timer, s.previous_wheel_speed,
          s.release_pressure, s.slip, s.wheel_accel, next_tick_, target_, pressure_, t_prev_}) {
      w.PutDouble(d);
    }
    w.PutDoubles(std::vector<double>(pushed_.begin(), pushed_.end()));
    w.PutDoubles(cycle_starts_);
    w.PutDoubles(abs_exit_ ? std::vector<double>{*abs_exit_} : std::vector<double>{});
  }
  void Load(fe::BinaryReader& r) {
    r.ExpectTag("ABS_");
    brake::AbsControllerState s;
    const std::uint64_t state = r.GetU64(), phase = r.GetU64(), flags = r.GetU64();
    if (state > static_cast<std::uint64_t>(brake::AbsState::kExit) ||
        phase > static_cast<std::uint64_t>(brake::AbsHoldPhase::kAfterFastIncrease) || flags > 3) {
      r.Damaged("an ABS controller state out of range");
    }
    s.state = static_cast<brake::AbsState>(state);
    s.hold_phase = static_cast<brake::AbsHoldPhase>(phase);
    s.has_previous = flags & 1;
    s.seen_accel_above_a = flags & 2;
    const std::int64_t cycles = r.GetI64(), ticks = r.GetI64();
    if (cycles < 0 || ticks < 0 || cycles > ticks || ticks > (std::int64_t{1} << 40)) {
      r.Damaged("ABS controller counters out of range");
    }
    s.cycles = static_cast<int>(cycles);
    s.ticks = static_cast<int>(ticks);
    double next_tick, target, pressure, t_prev;
    for (double* d :
         {&s.pressure_command, &s.time_in_state, &s.step_timer, &s.previous_wheel_speed,
          &s.release_pressure, &s.slip, &s.wheel_accel, &next_tick, &target, &pressure, &t_prev}) {
      *d = r.GetFinite();
    }
    const size_t n = r.GetCount(sizeof(double));
    if (n > static_cast<size_t>(std::max(0, ac_.DelayTicks()))) {
      r.Damaged("more delayed pressure commands than the hydraulic delay holds");
    }
    std::vector<double> pushed(n);
    for (double& d : pushed) d = r.GetFinite();
    // Every cycle begun has its start time (the controller's own count restarts after an exit).
    const size_t starts = r.GetCount(sizeof(double));
    if (starts < static_cast<size_t>(s.cycles)) {
      r.Damaged("fewer ABS cycle start times than the controller's cycle count");
    }
    std::vector<double> cycle_starts(starts);
    for (double& d : cycle_starts) d = r.GetFinite();
    const size_t exits = r.GetCount(sizeof(double));
    if (exits > 1) r.Damaged("more than one ABS exit time");
    std::optional<double> abs_exit;
    if (exits == 1) abs_exit = r.GetFinite();
    // Everything read: restore. The delay line is rebuilt by pushing the pending commands again.
    state_ = s;
    next_tick_ = next_tick;
    target_ = target;
    pressure_ = pressure;
    t_prev_ = t_prev;
    delay_ = brake::PressureDelayLine(ac_.DelayTicks(), 0.0);
    pushed_.clear();
    for (double d : pushed) Push(d);
    cycle_starts_ = std::move(cycle_starts);
    abs_exit_ = abs_exit;
  }

 private:
  double Push(double command) {
    pushed_.push_back(command);
    if (pushed_.size() > static_cast<size_t>(std::max(0, delay_.delay_ticks()))) {
      pushed_.pop_front();
    }
    return delay_.Push(command);
  }

  const sim::AbsConfig& ac_;
  brake::AbsControllerParams cp_;
  brake::AbsControllerState state_;
  brake::PressureDelayLine delay_;
  std::deque<double> pushed_;  // the last delay_ticks commands pushed, oldest first
  std::vector<double> cycle_starts_;
  std::optional<double> abs_exit_;
  double next_tick_ = 0.0, target_ = 0.0, pressure_ = 0.0, t_prev_ = 0.0;
};

/// The history CSV of one step (docs/fe-tyre.md lists the columns).
void WriteHistoryCsv(const fs::path& path, const std::string& step, const fe::FeConfig& c,
                     const std::vector<fe::HistoryRow>& h, double loaded_radius) {
  const std::vector<std::string> columns = {
      "time_s",      "rim_x_m",         "rim_z_m",         "rim_vx_mps",     "spin_rad_per_s",
      "omega_R_mps", "brake_torque_Nm", "road_fx_N",       "road_fz_N",      "slip",
      "kinetic_J",   "internal_J",      "hourglass_J",     "bulk_viscous_J", "damping_J",
      "friction_J",  "contact_J",       "external_work_J", "balance_error_J"};
  std::vector<std::vector<double>> v(columns.size());
  for (const fe::HistoryRow& r : h) {
    const fe::Energies& e = r.energies;
    const double row[] = {r.time_s,          r.rim_x_m,
                          r.rim_z_m,         r.rim_vx_mps,
                          r.spin_rad_per_s,  r.spin_rad_per_s * loaded_radius,
                          r.brake_torque_Nm, r.road_fx_N,
                          r.road_fz_N,       r.slip,
                          e.kinetic,         e.internal,
                          e.Hourglass(),     e.bulk_viscous,
                          e.damping,         e.friction,
                          e.contact_stored,  e.external_work,
                          e.BalanceError()};
    for (size_t k = 0; k < columns.size(); ++k) v[k].push_back(row[k]);
  }
  WriteCsv(path, {{"config", c.file.string()}, {"step", step}}, columns, v);
}

/// The footprint pressure map as an SVG: one disc per contact node, coloured by pressure.
void WriteFootprintSvg(const fs::path& path, const fe::FootprintResult& fp) {
  WriteFileAtomically(path, [&](std::ostream& out) {
    const double scale = 2000.0;  // px per metre
    const double w = 0.35 * scale, h = 0.35 * scale;
    fmt::print(out,
               "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\">\n"
               "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
               "<text x=\"10\" y=\"20\" font-family=\"sans-serif\" font-size=\"14\">"
               "contact pressure, peak {2:.0f} kPa (x forward to the right, y up)</text>\n",
               w, h, 1e-3 * fp.peak_pressure_Pa);
    for (const fe::ContactPoint& p : fp.contact) {
      const double s = fp.peak_pressure_Pa > 0 ? p.pressure_Pa / fp.peak_pressure_Pa : 0.0;
      const int red = static_cast<int>(255 * s), blue = static_cast<int>(255 * (1 - s));
      fmt::print(out, "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"6\" fill=\"rgb({},0,{})\"/>\n",
                 0.5 * w + scale * p.x_m, 0.5 * h - scale * p.y_m, red, blue);
    }
    out << "</svg>\n";
  });
}

nlohmann::json EnergiesJson(const fe::Energies& e) {
  return {{"kinetic_J", RoundSignificant(e.kinetic, 6)},
          {"internal_J", RoundSignificant(e.internal, 6)},
          {"hourglass_J", RoundSignificant(e.Hourglass(), 6)},
          {"bulk_viscous_J", RoundSignificant(e.bulk_viscous, 6)},
          {"damping_J", RoundSignificant(e.damping, 6)},
          {"friction_J", RoundSignificant(e.friction, 6)},
          {"contact_J", RoundSignificant(e.contact_stored, 6)},
          {"external_work_J", RoundSignificant(e.external_work, 6)},
          {"balance_error_J", RoundSignificant(e.BalanceError(), 3)},
          {"hourglass_over_internal",
           RoundSignificant(e.internal > 0 ? e.Hourglass() / e.internal : 0.0, 3)}};
}

int RunFeCommand(const FeArgs& a) {
  const fs::path out(a.out);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (!fs::is_directory(out)) {
    throw InputError(fmt::format("--out: cannot create the folder '{}'", a.out));
  }
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
  std::optional<sim::AbsConfig> abs_config;
  if (last == 3) abs_config = sim::LoadAbsConfig(config.abs_config);

  fe::TyreRun run(config);
  run.mutable_solver().set_threads(a.threads);
  const fe::ExplicitSolver& solver = run.solver();
  const fe::MassScalingReport& ms = solver.mass_scaling();
  std::fprintf(
      stderr,
      "fe: %zu elements, %zu nodes; time step %.3g s (stable %.3g s unscaled); mass "
      "%.3f kg, mass scaling added %.3f kg in %d elements; %d threads, %s element kernel\n",
      run.tyre().mesh.elements.size(), run.tyre().mesh.nodes.size(), solver.time_step(),
      ms.stable_step_unscaled_s, ms.physical_mass_kg, ms.added_mass_kg, ms.scaled_elements,
      solver.threads(), fe::ElementKernelName(solver.element_kernel()));

  // The ABS controller of the abs step (the ABS issue's controller and hydraulics set the brake
  // torque at the controller's period; its R_l is the free-rolling radius of the roll step,
  // (002:2), known once the roll step ran or the checkpoint is read).
  std::unique_ptr<AbsTorque> abs_torque;
  const auto make_abs_torque = [&] {
    brake::AbsControllerParams cp = abs_config->controller;
    cp.wheel_radius_m = run.slip_radius_m();
    abs_torque = std::make_unique<AbsTorque>(*abs_config, cp);
  };
  nlohmann::json j;
  fe::CheckpointKey key;
  if (last == 3 && (a.checkpoint_every_s > 0.0 || !a.restart.empty())) key = MakeCheckpointKey(run);
  if (!a.restart.empty()) {
    // Read and check everything before anything is written.
    const std::string payload = fe::ReadCheckpointFile(a.restart, key);
    fe::BinaryReader r(payload, a.restart);
    run.LoadState(r);
    make_abs_torque();
    abs_torque->Load(r);
    r.ExpectTag("JSON");
    try {
      j = nlohmann::json::parse(r.GetString());
    } catch (const nlohmann::json::exception&) {
      r.Damaged("its summary of the earlier steps is not JSON");
    }
    r.ExpectTag("THRD");
    const std::uint64_t threads = r.GetU64();
    r.ExpectTag("KERN");
    const std::uint64_t kernel = r.GetU64();
    r.ExpectEnd();
    if (kernel > static_cast<std::uint64_t>(fe::ElementKernel::kAvx2)) {
      r.Damaged("an element kernel out of range");
    }
    if (threads != static_cast<std::uint64_t>(solver.threads())) {
      std::fprintf(stderr,
                   "fe: the checkpoint was written on %llu threads, this run uses %d: it continues "
                   "to round-off, not bit for bit (the element forces are summed per thread)\n",
                   static_cast<unsigned long long>(threads), solver.threads());
    }
    if (const auto written = static_cast<fe::ElementKernel>(kernel);
        written != solver.element_kernel()) {
      std::fprintf(stderr,
                   "fe: the checkpoint was written with the %s element kernel, this run uses %s: "
                   "it continues to round-off, not bit for bit (HOTLAP_FE_KERNEL chooses)\n",
                   fe::ElementKernelName(written), fe::ElementKernelName(solver.element_kernel()));
    }
    if (!j.is_object()) r.Damaged("its summary of the earlier steps is not a JSON object");
    std::fprintf(stderr, "fe: restarting from '%s' at t = %.6g s (%.6g s into the abs step)\n",
                 a.restart.c_str(), solver.time(), solver.time() - run.brake_start_s());
  }
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
  hooks.frame = [&](const std::string& step, int frame) {
    fe::WriteVtu(out / fmt::format("{}_{:03d}.vtu", step, frame), solver);
  };
  const auto begin = [&] {
    step_t0 = solver.time();
    step_wall0 = std::chrono::steady_clock::now();
  };

  const bool restarted = !a.restart.empty();
  j["config"] = config.file.string();
  j["step"] = a.step;
  j["mesh"] = {{"elements", run.tyre().mesh.elements.size()},
               {"nodes", run.tyre().mesh.nodes.size()},
               {"time_step_s", RoundSignificant(solver.time_step(), 6)},
               {"stable_step_unscaled_s", RoundSignificant(ms.stable_step_unscaled_s, 6)},
               {"physical_mass_kg", RoundSignificant(ms.physical_mass_kg, 6)},
               {"mass_scaling_added_kg", RoundSignificant(ms.added_mass_kg, 6)},
               {"mass_scaled_elements", ms.scaled_elements}};

  // The stable step counts each cord's stiffness up to kCordStrainAllowance (explicit_solver.h).
  const auto cord_strain = [](const char* step, double strain) {
    if (strain > fe::kCordStrainAllowance) {
      std::fprintf(stderr,
                   "fe %s: warning: a cord reached a strain of %.1f%%, above the %.0f%% the stable "
                   "step allows for (the safety factor covers some more; a smaller "
                   "solver.time_step_safety covers more still)\n",
                   step, 100.0 * strain, 100.0 * fe::kCordStrainAllowance);
    }
    return RoundSignificant(strain, 4);
  };
  if (!restarted) {
    begin();
    const fe::InflateResult inf = run.Inflate(hooks);
    WriteHistoryCsv(out / "inflate_history.csv", "inflate", config, inf.history, 0.0);
    j["inflate"] = {
        {"pressure_kPa", RoundSignificant(1e-3 * inf.pressure_Pa, 6)},
        {"outer_radius_before_mm", RoundSignificant(1e3 * inf.outer_radius_before_m, 6)},
        {"outer_radius_after_mm", RoundSignificant(1e3 * inf.outer_radius_after_m, 6)},
        {"section_width_before_mm", RoundSignificant(1e3 * inf.section_width_before_m, 6)},
        {"section_width_after_mm", RoundSignificant(1e3 * inf.section_width_after_m, 6)},
        {"roundness_error_mm", RoundSignificant(1e3 * inf.max_roundness_error_m, 3)},
        {"max_cord_strain", cord_strain("inflate", inf.max_cord_strain)},
        {"energies", EnergiesJson(solver.energies())}};
    std::printf("inflate: %.0f kPa, outer radius %.2f -> %.2f mm, section width %.1f -> %.1f mm\n",
                1e-3 * inf.pressure_Pa, 1e3 * inf.outer_radius_before_m,
                1e3 * inf.outer_radius_after_m, 1e3 * inf.section_width_before_m,
                1e3 * inf.section_width_after_m);

    if (last >= 1) {
      begin();
      const fe::FootprintResult fp = run.Footprint(hooks);
      WriteHistoryCsv(out / "footprint_history.csv", "footprint", config, fp.history, 0.0);
      std::vector<std::vector<double>> map(4);
      for (const fe::ContactPoint& p : fp.contact) {
        map[0].push_back(p.x_m);
        map[1].push_back(p.y_m);
        map[2].push_back(p.force_N);
        map[3].push_back(p.pressure_Pa);
      }
      WriteCsv(out / "footprint_pressure.csv", {{"config", config.file.string()}},
               {"x_m", "y_m", "force_N", "pressure_Pa"}, map);
      WriteFootprintSvg(out / "footprint_pressure.svg", fp);
      j["footprint"] = {{"vertical_load_N", RoundSignificant(fp.vertical_load_N, 6)},
                        {"road_force_z_N", RoundSignificant(fp.road_force_z_N, 6)},
                        {"loaded_radius_mm", RoundSignificant(1e3 * fp.loaded_radius_m, 6)},
                        {"deflection_mm", RoundSignificant(1e3 * fp.deflection_m, 6)},
                        {"vertical_stiffness_kN_per_m",
                         RoundSignificant(1e-3 * fp.vertical_stiffness_N_per_m, 6)},
                        {"contact_area_cm2", RoundSignificant(1e4 * fp.contact_area_m2, 6)},
                        {"contact_length_mm", RoundSignificant(1e3 * fp.contact_length_m, 6)},
                        {"contact_width_mm", RoundSignificant(1e3 * fp.contact_width_m, 6)},
                        {"peak_pressure_kPa", RoundSignificant(1e-3 * fp.peak_pressure_Pa, 6)},
                        {"mean_pressure_kPa", RoundSignificant(1e-3 * fp.mean_pressure_Pa, 6)},
                        {"max_cord_strain", cord_strain("footprint", fp.max_cord_strain)},
                        {"energies", EnergiesJson(solver.energies())}};
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
      WriteHistoryCsv(out / "roll_history.csv", "roll", config, rr.history, run.slip_radius_m());
      j["roll"] = {{"speed_mps", RoundSignificant(rr.speed_mps, 6)},
                   {"spin_rad_per_s", RoundSignificant(rr.spin_rad_per_s, 6)},
                   {"effective_radius_mm", RoundSignificant(1e3 * rr.effective_radius_m, 6)},
                   {"loaded_radius_mm", RoundSignificant(1e3 * rr.loaded_radius_m, 6)},
                   {"road_fx_N", RoundSignificant(rr.road_fx_N, 6)},
                   {"road_fz_N", RoundSignificant(rr.road_fz_N, 6)},
                   {"paper_spin_rad_per_s", 28.268},
                   {"paper_effective_radius_mm", 394.2},
                   {"max_cord_strain", cord_strain("roll", rr.max_cord_strain)},
                   {"energies", EnergiesJson(solver.energies())}};
      std::printf(
          "roll: %.3f m/s, spin %.3f rad/s, effective radius %.2f mm (paper: 28.268 rad/s, "
          "394.2 mm), loaded radius %.2f mm\n",
          rr.speed_mps, rr.spin_rad_per_s, 1e3 * rr.effective_radius_m, 1e3 * rr.loaded_radius_m);
    }
  }  // !restarted
  if (last >= 3) {
    if (!restarted) make_abs_torque();
    const fe::BrakeTorqueFn torque = [&](double t, double vx, double spin) {
      return (*abs_torque)(t, vx, spin);
    };
    fe::StepHooks abs_hooks = hooks;
    if (a.checkpoint_every_s > 0.0) {
      // The earlier steps' summary rides along, so that a restart's JSON is complete.
      const std::string summary = j.dump();
      abs_hooks.checkpoint_interval_s = a.checkpoint_every_s;
      abs_hooks.checkpoint = [&, summary] {
        fe::BinaryWriter w;
        run.SaveState(w);
        abs_torque->Save(w);
        w.PutTag("JSON");
        w.PutString(summary);
        w.PutTag("THRD");
        w.PutU64(solver.threads());
        w.PutTag("KERN");
        w.PutU64(static_cast<std::uint64_t>(solver.element_kernel()));
        fe::WriteCheckpointFile(out / kCheckpointName, key, w.bytes());
      };
    }
    begin();
    if (restarted) step_t0 = run.brake_start_s();
    const fe::BrakeResult br = restarted ? run.ResumeBrake(config.abs_duration_s, torque, abs_hooks)
                                         : run.Brake(config.abs_duration_s, torque, abs_hooks);
    WriteHistoryCsv(out / "abs_history.csv", "abs", config, br.history, run.slip_radius_m());
    // The control cycles as the lumped `hotlap abs` counts them, on the histories' clock.
    const double t0 = run.brake_start_s();
    std::vector<double> cycle_starts, time, slip;
    for (double t : abs_torque->cycle_starts()) cycle_starts.push_back(t0 + t);
    for (const fe::HistoryRow& row : br.history) {
      time.push_back(row.time_s);
      slip.push_back(row.slip);
    }
    std::optional<double> abs_exit;
    if (abs_torque->abs_exit()) abs_exit = t0 + *abs_torque->abs_exit();
    nlohmann::json cycle_starts_json = nlohmann::json::array();
    for (double t : cycle_starts) cycle_starts_json.push_back(RoundSignificant(t));
    const sim::CycleWindow cycles = sim::CalcCycleWindow(
        time, slip, cycle_starts, abs_exit, br.history.empty() ? t0 : br.history.back().time_s);
    WriteFeAbsReport(out / "abs_report.html", br.history, cycles, run.slip_radius_m(),
                     {{"configuration", config.file.string()},
                      {"mesh", fmt::format("{} elements, {} nodes", run.tyre().mesh.elements.size(),
                                           run.tyre().mesh.nodes.size())}});
    j["abs"] = {{"duration_s", RoundSignificant(config.abs_duration_s, 6)},
                {"initial_speed_mps", RoundSignificant(br.initial_speed_mps, 6)},
                {"final_speed_mps", RoundSignificant(br.final_speed_mps, 6)},
                {"distance_m", RoundSignificant(br.distance_m, 6)},
                {"max_slip", RoundSignificant(br.max_slip, 6)},
                {"max_brake_torque_Nm", RoundSignificant(br.max_brake_torque_Nm, 6)},
                {"control_cycles", cycles.cycles},
                {"cycle_starts_s", cycle_starts_json},
                {"cycles_per_s", RoundSignificant(cycles.cycles_per_s)},
                {"first_cycle_start_s", JsonOrNull(cycles.first_cycle_start_s)},
                {"second_cycle_start_s", JsonOrNull(cycles.second_cycle_start_s)},
                {"abs_exit_s", JsonOrNull(abs_exit)},
                {"max_lambda_after_first_cycle", JsonOrNull(cycles.max_lambda_after_first_cycle)},
                {"fraction_time_lambda_below_0_135",
                 JsonOrNull(cycles.fraction_time_lambda_below_0_135, 4)},
                {"max_cord_strain", cord_strain("abs", br.max_cord_strain)},
                {"energies", EnergiesJson(solver.energies())}};
    std::printf("abs: %.3f s, speed %.3f -> %.3f m/s over %.3f m, max slip %.3f, %d cycles\n",
                config.abs_duration_s, br.initial_speed_mps, br.final_speed_mps, br.distance_m,
                br.max_slip, cycles.cycles);
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
      ->check(CLI::PositiveNumber);
  sub->add_option("--threads", args->threads,
                  "Threads of the solver's element loop (default: all cores, OpenMP's default)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--checkpoint-every-s", args->checkpoint_every_s,
                  "abs: write <out>/abs_checkpoint.bin every S of simulated time and at the end")
      ->check(CLI::PositiveNumber);
  sub->add_option("--restart", args->restart,
                  "abs: continue from a checkpoint file (same configuration files and mesh)");
  return [args] { return RunFeCommand(*args); };
}

}  // namespace hotlap::app
