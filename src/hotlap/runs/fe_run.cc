#include "hotlap/runs/fe_run.h"

#include <algorithm>
#include <chrono>
#include <optional>

#include <fmt/format.h>

#include "hotlap/abs/abs_config.h"
#include "hotlap/abs/abs_metrics.h"
#include "hotlap/abs/abs_run.h"
#include "hotlap/abs/fe_abs_ensemble.h"
#include "hotlap/abs/fe_abs_ensemble_report.h"
#include "hotlap/abs/fe_abs_json.h"
#include "hotlap/abs/fe_abs_report.h"
#include "hotlap/abs/fe_abs_stop.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/fe/explicit_step.h"
#include "hotlap/fe/fe_config.h"
#include "hotlap/fe/step_json.h"
#include "hotlap/fe/step_output.h"
#include "hotlap/fe/tyre_steps.h"
#include "hotlap/fe/vtu_writer.h"

namespace hotlap::runs {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kCheckpointName = "abs_checkpoint.bin";

double Seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// One run of the steps: the options, the configurations, the tyre and what is written.
class FeRunner {
 public:
  explicit FeRunner(const FeRunOptions& o) : o_(o) {}
  FeRunResult Run();

 private:
  void Note(const std::string& line) const {
    if (o_.note) o_.note(line);
  }
  void Say(const std::string& line) const {
    if (o_.say) o_.say(line);
  }
  void WarnCordStrain(const char* step, double strain) const {
    const std::string w = fe::CordStrainWarning(step, strain);
    if (!w.empty()) Note(w);
  }
  // Reads and checks the input; refuses option combinations the step does not take.
  void Prepare();
  // The solver's one-line description, on `note`.
  void Describe() const;
  // Progress, frames and checkpoint notes of every step.
  fe::StepHooks Hooks();
  // Reads the checkpoint into the run and the stop; says where the restart differs from the run
  // that wrote it. Returns the earlier steps' JSON summary.
  nlohmann::json Restart(const fe::CheckpointKey& key);
  // Inflate, footprint and roll, as far as the step asks, each with its outputs and summary.
  void RunEarlierSteps(const fe::StepHooks& hooks);
  // The abs step: one stop (continued from the checkpoint if restarted), or the ensemble.
  void RunAbsStop(const fe::StepHooks& hooks, const fe::CheckpointKey& key);
  void RunAbsEnsemble();
  // The lumped `hotlap abs` runs of the same event (speed and duration), each with its own
  // rigid wheel and brush tyre: the FE file's controller and hydraulics file, then the lumped
  // quarter car's own tuning where the FE file names one (`abs.lumped_config_file`).
  void RunLumped(double initial_speed_mps);
  // The lumped runs' JSON: `lumped` (the same ABS file) and `lumped_own_tuning`.
  void AddLumpedJson(nlohmann::json& j) const;
  void Performance(Clock::time_point wall0, long steps_at_start, bool restarted);

  const FeRunOptions& o_;
  fe::FeConfig config_;
  int last_ = 0;  // 0 inflate, 1 footprint, 2 roll, 3 abs
  std::optional<sim::AbsConfig> abs_config_;
  // The lumped quarter car's own tuning (`abs.lumped_config_file`), read with the input.
  std::optional<sim::AbsConfig> lumped_own_config_;
  std::optional<fe::TyreRun> run_;
  std::optional<sim::FeAbsStop> stop_;
  nlohmann::json j_;
  double step_t0_ = 0.0;
  Clock::time_point step_wall0_;
  // The lumped runs, once RunLumped ran (the same ABS file first).
  struct LumpedRun {
    std::string label;
    fs::path file;
    sim::AbsConfig config;
    sim::AbsRunResult run;
    sim::AbsMetrics metrics;
  };
  std::vector<LumpedRun> lumped_;
};

void FeRunner::Prepare() {
  CheckOutputDirectory(o_.out, "--out");
  config_ = fe::LoadFeConfig(o_.config);
  const std::string& s = o_.step;
  last_ = s == "inflate" ? 0 : s == "footprint" ? 1 : s == "roll" ? 2 : s == "abs" ? 3 : -1;
  if (last_ < 0) throw InputError(fmt::format("fe: no step '{}'", s));
  if (last_ != 3 && !o_.restart.empty()) {
    throw InputError("--restart: only `hotlap fe abs` continues from a checkpoint");
  }
  if (last_ != 3 && o_.checkpoint_every_s > 0.0) {
    throw InputError("--checkpoint-every-s: only `hotlap fe abs` writes checkpoints");
  }
  if (o_.ensemble > 0 && last_ != 3) throw InputError("--ensemble: only `hotlap fe abs`");
  if (o_.ensemble > 0 && (!o_.restart.empty() || o_.checkpoint_every_s > 0.0)) {
    throw InputError("--ensemble: an ensemble neither writes checkpoints nor restarts");
  }
  if (o_.first_member != 0 && o_.ensemble == 0) {
    throw InputError("--first-member: only with --ensemble");
  }
  // Before the steps before the braking, not after them.
  sim::CheckFeEnsembleShard(o_.perturbation, o_.first_member);
  if (o_.duration_s > 0.0) {
    if (last_ == 2) config_.roll_duration_s = o_.duration_s;
    if (last_ == 3) config_.abs_duration_s = o_.duration_s;
  }
  config_.solver.time_step_scale = o_.step_scale;
  if (!o_.abs_set.empty() && last_ != 3) throw InputError("--abs-set: only `hotlap fe abs`");
  if (last_ == 3) {
    abs_config_ = sim::LoadAbsConfig(config_.abs_config, sim::ParseAbsOverrides(o_.abs_set));
    if (!config_.abs_lumped_config.empty()) {
      lumped_own_config_ = sim::LoadAbsConfig(config_.abs_lumped_config);
    }
  }
  run_.emplace(config_);
  // An ensemble's steps before the braking run on one thread, so that its members (copies of
  // the rolled run) are the same bits whatever --threads (the members at once) is.
  run_->mutable_solver().set_threads(o_.ensemble > 0 ? 1 : o_.threads);
  run_->mutable_solver().set_element_kernel(o_.kernel);
  // The ABS stop (its controller's R_l is the free-rolling radius of the roll step, (002:2),
  // known once the roll step ran or the checkpoint is read).
  if (last_ == 3 && o_.ensemble == 0) stop_.emplace(*run_, *abs_config_);
}

void FeRunner::Describe() const {
  const fe::ExplicitSolver& solver = run_->solver();
  const fe::MassScalingReport& ms = solver.mass_scaling();
  Note(fmt::format(
      "fe: {} elements, {} nodes; time step {:.3g} s (scale {:g}; stable {:.3g} s unscaled); "
      "mass {:.3f} kg, mass scaling added {:.3f} kg in {} elements; {} threads, {} element kernel",
      run_->tyre().mesh.elements.size(), run_->tyre().mesh.nodes.size(), solver.time_step(),
      o_.step_scale, ms.stable_step_unscaled_s, ms.physical_mass_kg, ms.added_mass_kg,
      ms.scaled_elements, solver.threads(), fe::ElementKernelName(solver.element_kernel())));
}

fe::StepHooks FeRunner::Hooks() {
  fe::StepHooks hooks;
  hooks.frames = config_.vtu_frames;
  hooks.history_interval_s = config_.history_interval_s;
  hooks.progress = [this](const std::string& step, double t, double t_end) {
    const double wall = Seconds(step_wall0_);
    const double done = std::clamp((t - step_t0_) / std::max(1e-12, t_end - step_t0_), 0.0, 1.0);
    const double left = done > 0 ? wall * (1.0 - done) / done : 0.0;
    const std::string eta =
        left < 120.0 ? fmt::format("{:.0f} s", left) : fmt::format("{:.0f} min", left / 60.0);
    Note(fmt::format("fe {}: t = {:.5f} s ({:.0f}%), about {} left", step, t, 100.0 * done, eta));
  };
  // Each checkpoint once it is whole on disk (the event a test of a kill waits for); the time as
  // a restart from it reports it.
  hooks.checkpoint_written = [this](double t) {
    Note(fmt::format("fe abs: checkpoint written at t = {:.6g} s", t));
  };
  hooks.frame = [this](const std::string& step, int frame) {
    fe::WriteVtu(o_.out / fmt::format("{}_{:03d}.vtu", step, frame), run_->solver());
  };
  return hooks;
}

nlohmann::json FeRunner::Restart(const fe::CheckpointKey& key) {
  const std::string file = o_.restart.string();
  const sim::FeAbsCheckpointInfo info = stop_->Restore(file, key);
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
  const fe::ExplicitSolver& solver = run_->solver();
  if (info.threads != static_cast<std::uint64_t>(solver.threads())) {
    Note(fmt::format(
        "fe: the checkpoint was written on {} threads, this run uses {}: it continues to "
        "round-off, not bit for bit (the element forces are summed per thread)",
        info.threads, solver.threads()));
  }
  if (info.kernel != solver.element_kernel()) {
    Note(fmt::format(
        "fe: the checkpoint was written with the {} element kernel, this run uses {}: it "
        "continues to round-off, not bit for bit (--kernel chooses)",
        fe::ElementKernelName(info.kernel), fe::ElementKernelName(solver.element_kernel())));
  }
  Note(fmt::format("fe: restarting from '{}' at t = {:.6g} s ({:.6g} s into the abs step)", file,
                   solver.time(), solver.time() - run_->brake_start_s()));
  return j;
}

void FeRunner::RunEarlierSteps(const fe::StepHooks& hooks) {
  const fe::ExplicitSolver& solver = run_->solver();
  const auto begin = [this] {
    step_t0_ = run_->solver().time();
    step_wall0_ = Clock::now();
  };
  begin();
  const fe::InflateResult inf = run_->Inflate(hooks);
  fe::WriteFeHistoryCsv(o_.out / "inflate_history.csv", "inflate", config_, inf.history, 0.0);
  j_["inflate"] = fe::InflateJson(inf, solver.energies());
  WarnCordStrain("inflate", inf.max_cord_strain);
  Say(fmt::format(
      "inflate: {:.0f} kPa, outer radius {:.2f} -> {:.2f} mm, section width {:.1f} -> "
      "{:.1f} mm",
      1e-3 * inf.pressure_Pa, 1e3 * inf.outer_radius_before_m, 1e3 * inf.outer_radius_after_m,
      1e3 * inf.section_width_before_m, 1e3 * inf.section_width_after_m));
  if (last_ < 1) return;
  begin();
  const fe::FootprintResult fp = run_->Footprint(hooks);
  fe::WriteFeHistoryCsv(o_.out / "footprint_history.csv", "footprint", config_, fp.history, 0.0);
  fe::WriteFootprintPressure(o_.out, config_, fp);
  j_["footprint"] = fe::FootprintJson(fp, solver.energies());
  WarnCordStrain("footprint", fp.max_cord_strain);
  Say(fmt::format(
      "footprint: {:.0f} N, loaded radius {:.2f} mm, deflection {:.2f} mm, {:.0f} kN/m, "
      "contact {:.0f} cm^2 ({:.0f} x {:.0f} mm node to node), mean {:.0f} kPa",
      fp.road_force_z_N, 1e3 * fp.loaded_radius_m, 1e3 * fp.deflection_m,
      1e-3 * fp.vertical_stiffness_N_per_m, 1e4 * fp.contact_area_m2, 1e3 * fp.contact_length_m,
      1e3 * fp.contact_width_m, 1e-3 * fp.mean_pressure_Pa));
  if (last_ < 2) return;
  begin();
  const fe::RollResult rr = run_->Roll(hooks);
  fe::WriteFeHistoryCsv(o_.out / "roll_history.csv", "roll", config_, rr.history,
                        run_->slip_radius_m());
  j_["roll"] = fe::RollJson(rr, solver.energies());
  WarnCordStrain("roll", rr.max_cord_strain);
  Say(fmt::format(
      "roll: {:.3f} m/s, spin {:.3f} rad/s, effective radius {:.2f} mm (paper: 28.268 rad/s, "
      "394.2 mm), loaded radius {:.2f} mm",
      rr.speed_mps, rr.spin_rad_per_s, 1e3 * rr.effective_radius_m, 1e3 * rr.loaded_radius_m));
}

void FeRunner::RunLumped(double initial_speed_mps) {
  const auto run = [&](const std::string& label, const fs::path& file, const sim::AbsConfig& abs) {
    sim::AbsEvent event = abs.event;
    event.initial_speed_mps = initial_speed_mps;
    event.duration_s = config_.abs_duration_s;
    LumpedRun l{label, file, abs, sim::RunAbs(abs, event), {}};
    l.metrics = sim::CalcAbsMetrics(abs, l.run);
    lumped_.push_back(std::move(l));
  };
  lumped_.clear();
  run("lumped, same ABS file", config_.abs_config, *abs_config_);
  if (lumped_own_config_) {
    run("lumped, own tuning", config_.abs_lumped_config, *lumped_own_config_);
  }
}

void FeRunner::AddLumpedJson(nlohmann::json& j) const {
  j["lumped"] = sim::LumpedAbsJson(lumped_.front().metrics);
  if (lumped_.size() > 1) {
    j["lumped_own_tuning"] = sim::LumpedAbsJson(lumped_[1].metrics);
    j["lumped_own_tuning"]["config_file"] = lumped_[1].file.lexically_normal().string();
  }
}

void FeRunner::RunAbsStop(const fe::StepHooks& hooks, const fe::CheckpointKey& key) {
  sim::FeAbsStopOptions options;
  options.duration_s = config_.abs_duration_s;
  options.hooks = hooks;
  options.checkpoint_every_s = o_.checkpoint_every_s;
  options.checkpoint_file = o_.out / kCheckpointName;
  options.checkpoint_key = key;
  // The earlier steps' summary rides along, so that a restart's JSON is complete.
  if (o_.checkpoint_every_s > 0.0) options.summary = j_.dump();
  step_t0_ = o_.restart.empty() ? run_->solver().time() : run_->brake_start_s();
  step_wall0_ = Clock::now();
  const sim::FeAbsStopResult r = stop_->Run(options);
  const fe::BrakeResult& br = r.brake;
  fe::WriteFeHistoryCsv(o_.out / "abs_history.csv", "abs", config_, br.history,
                        run_->slip_radius_m());
  RunLumped(br.initial_speed_mps);
  std::vector<sim::FeAbsLumpedRun> lumped;
  for (const LumpedRun& l : lumped_) {
    lumped.push_back({&l.run.history, l.metrics, l.config.plant.wheel.radius, l.label});
  }
  sim::WriteFeAbsReport(
      o_.out / "abs_report.html", br.history, r.cycles, run_->slip_radius_m(),
      {{"configuration", config_.file.string()},
       {"mesh", fmt::format("{} elements, {} nodes", run_->tyre().mesh.elements.size(),
                            run_->tyre().mesh.nodes.size())}},
      lumped);
  j_["abs"] = sim::FeAbsStopJson(r, config_.abs_duration_s, run_->solver().energies());
  AddLumpedJson(j_["abs"]);
  WarnCordStrain("abs", br.max_cord_strain);
  Say(
      fmt::format("abs: {:.3f} s, speed {:.3f} -> {:.3f} m/s over {:.3f} m, max slip {:.3f}, {} "
                  "cycles",
                  config_.abs_duration_s, br.initial_speed_mps, br.final_speed_mps, br.distance_m,
                  br.max_slip, r.cycles.cycles));
}

void FeRunner::RunAbsEnsemble() {
  sim::FeAbsEnsembleOptions eo;
  eo.members = o_.ensemble;
  eo.perturbation = o_.perturbation;
  eo.first_member = o_.first_member;
  eo.threads = o_.threads > 0 ? o_.threads : fe::DefaultThreadCount();
  eo.duration_s = config_.abs_duration_s;
  eo.history_interval_s = config_.history_interval_s;
  const Clock::time_point wall0 = Clock::now();
  eo.member_done = [&](int member, const sim::FeAbsFigures& f) {
    // Each member's figures as it ends (a study cut short keeps what it has).
    std::string figures;
    for (const sim::FeAbsFigureValue& v : sim::ListFeAbsFigures(f)) {
      figures += fmt::format(" {}={}", v.key, v.value ? fmt::format("{:.5g}", *v.value) : "-");
    }
    const std::string of = eo.first_member == 0 ? fmt::format("{}", eo.members)
                                                : fmt::format("{}-{}", eo.first_member + 1,
                                                              eo.first_member + eo.members);
    Note(fmt::format("fe abs ensemble: member {} of {} done after {:.0f} s: cycles={}{}",
                     member + 1, of, Seconds(wall0), f.cycles, figures));
  };
  const sim::FeAbsEnsembleResult e = sim::RunFeAbsEnsemble(*run_, *abs_config_, eo);
  RunLumped(e.vx_mps.mean.empty() ? config_.roll_speed_mps : e.vx_mps.mean.front());
  sim::WriteFeAbsEnsembleCsv(o_.out / "abs_ensemble.csv", e);
  std::vector<sim::LumpedAbsColumn> columns;
  for (const LumpedRun& l : lumped_) columns.push_back({l.label, l.metrics});
  sim::WriteFeAbsEnsembleReport(
      o_.out / "abs_report.html", e, columns,
      {{"configuration", config_.file.string()},
       {"mesh", fmt::format("{} elements, {} nodes", run_->tyre().mesh.elements.size(),
                            run_->tyre().mesh.nodes.size())},
       {"ensemble", fmt::format("{} members (from member {}), perturbation {}", eo.members,
                                eo.first_member, sim::FePerturbationName(eo.perturbation))}});
  j_["abs_ensemble"] = sim::FeAbsEnsembleJson(e, config_.abs_duration_s);
  AddLumpedJson(j_["abs_ensemble"]);
  for (const std::string& line : sim::FeAbsEnsembleText(e)) Say(line);
}

void FeRunner::Performance(Clock::time_point wall0, long steps_at_start, bool restarted) {
  const fe::ExplicitSolver& solver = run_->solver();
  const double wall = Seconds(wall0);
  // This process's share (after a restart, the steps since the checkpoint; an ensemble's
  // members are not counted: they step copies of the run).
  const long steps = solver.steps() - steps_at_start;
  const double updates = double(steps) * run_->tyre().mesh.elements.size();
  j_["performance"] = {{"wall_s", RoundSignificant(wall, 4)},
                       {"steps", steps},
                       {"threads", solver.threads()},
                       {"element_kernel", fe::ElementKernelName(solver.element_kernel())},
                       {"element_updates_per_s", RoundSignificant(updates / wall, 4)}};
  if (restarted) j_["performance"]["restarted_from"] = o_.restart.string();
  Say(
      fmt::format("fe: {} steps on {} threads, {:.3g} element updates in {:.1f} s ({:.3g} per "
                  "second)",
                  steps, solver.threads(), updates, wall, updates / wall));
}

FeRunResult FeRunner::Run() {
  Prepare();
  Describe();
  fe::CheckpointKey key;
  if (stop_ && (o_.checkpoint_every_s > 0.0 || !o_.restart.empty())) {
    key = sim::MakeFeCheckpointKey(*run_, abs_config_->overrides);
  }
  const bool restarted = !o_.restart.empty();
  if (restarted) j_ = Restart(key);
  CreateOutputDirectory(o_.out, "--out");
  const long steps_at_start = run_->solver().steps();
  const Clock::time_point wall0 = Clock::now();
  const fe::StepHooks hooks = Hooks();
  j_["config"] = config_.file.string();
  if (abs_config_) j_["abs_overrides"] = sim::AbsOverridesJson(abs_config_->overrides);
  j_["step"] = o_.step;
  j_["mesh"] = fe::FeMeshJson(*run_);
  if (!restarted) RunEarlierSteps(hooks);
  if (last_ == 3 && o_.ensemble > 0) RunAbsEnsemble();
  if (last_ == 3 && o_.ensemble == 0) RunAbsStop(hooks, key);
  Performance(wall0, steps_at_start, restarted);
  return {j_};
}

}  // namespace

FeRunResult RunFe(const FeRunOptions& options) { return FeRunner(options).Run(); }

}  // namespace hotlap::runs
