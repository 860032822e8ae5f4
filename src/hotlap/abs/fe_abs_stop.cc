#include "hotlap/abs/fe_abs_stop.h"

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/read_file.h"

namespace hotlap::sim {

fe::CheckpointKey MakeFeCheckpointKey(const fe::TyreRun& run,
                                      const std::vector<YamlOverride>& abs_overrides) {
  const auto bytes = [](const std::filesystem::path& p) { return ReadWholeFile(p); };
  fe::CheckpointKey key;
  key.mesh_hash = fe::HashMesh(run.tyre().mesh);
  key.nodes = run.tyre().mesh.nodes.size();
  key.elements = run.tyre().mesh.elements.size();
  key.config_hash =
      fe::Fnv1a64(bytes(run.config().abs_config), fe::Fnv1a64(bytes(run.config().file)));
  for (const YamlOverride& o : abs_overrides) {
    key.config_hash = fe::Fnv1a64(fmt::format("{}={:.17g}", o.field, o.value), key.config_hash);
  }
  return key;
}

void FeAbsStop::MakeTorque() {
  brake::AbsControllerParams params = config_.controller;
  params.wheel_radius_m = run_.slip_radius_m();
  torque_ = std::make_unique<FeAbsTorque>(config_, params);
}

FeAbsCheckpointInfo FeAbsStop::Restore(const std::filesystem::path& file,
                                       const fe::CheckpointKey& key) {
  const std::string payload = fe::ReadCheckpointFile(file, key);
  fe::BinaryReader r(payload, file.string());
  run_.LoadState(r);
  MakeTorque();
  torque_->Load(r);
  FeAbsCheckpointInfo info;
  r.ExpectTag("SUMM");
  info.summary = r.GetString();
  r.ExpectTag("THRD");
  info.threads = r.GetU64();
  r.ExpectTag("KERN");
  const std::uint64_t kernel = r.GetU64();
  r.ExpectEnd();
  if (kernel > static_cast<std::uint64_t>(fe::ElementKernel::kAvx2)) {
    r.Damaged("an element kernel out of range");
  }
  info.kernel = static_cast<fe::ElementKernel>(kernel);
  restored_ = true;
  return info;
}

void FeAbsStop::WriteCheckpoint(const std::filesystem::path& file, const fe::CheckpointKey& key,
                                const std::string& summary) const {
  fe::BinaryWriter w;
  run_.SaveState(w);
  torque_->Save(w);
  w.PutTag("SUMM");
  w.PutString(summary);
  w.PutTag("THRD");
  w.PutU64(run_.solver().threads());
  w.PutTag("KERN");
  w.PutU64(static_cast<std::uint64_t>(run_.solver().element_kernel()));
  fe::WriteCheckpointFile(file, key, w.bytes());
}

FeAbsStopResult FeAbsStop::Run(const FeAbsStopOptions& options) {
  if (!restored_) MakeTorque();
  const fe::BrakeTorqueFn torque = [this](double t, double vx, double spin) {
    return (*torque_)(t, vx, spin);
  };
  fe::StepHooks hooks = options.hooks;
  hooks.checkpoint = nullptr;
  hooks.checkpoint_interval_s = 0.0;
  if (options.checkpoint_every_s > 0.0) {
    hooks.checkpoint_interval_s = options.checkpoint_every_s;
    hooks.checkpoint = [this, &options] {
      WriteCheckpoint(options.checkpoint_file, options.checkpoint_key, options.summary);
    };
  }
  FeAbsStopResult r;
  r.brake = restored_ ? run_.ResumeBrake(options.duration_s, torque, hooks)
                      : run_.Brake(options.duration_s, torque, hooks);
  // The control cycles as the lumped `hotlap abs` counts them, on the histories' clock.
  const double t0 = run_.brake_start_s();
  for (double t : torque_->cycle_starts()) r.cycle_starts_s.push_back(t0 + t);
  if (torque_->abs_exit()) r.abs_exit_s = t0 + *torque_->abs_exit();
  std::vector<double> time, slip;
  for (const fe::HistoryRow& row : r.brake.history) {
    time.push_back(row.time_s);
    slip.push_back(row.slip);
  }
  const double end = r.brake.history.empty() ? t0 : r.brake.history.back().time_s;
  r.cycles = CalcCycleWindow(time, slip, r.cycle_starts_s, r.abs_exit_s, end);
  return r;
}

}  // namespace hotlap::sim
