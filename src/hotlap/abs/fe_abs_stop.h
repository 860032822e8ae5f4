#pragma once
/// @file
/// The FE tyre's ABS stop (docs/fe-tyre.md): fe::TyreRun's braking step with the brake torque set
/// by the ABS controller and hydraulics (FeAbsTorque), its checkpoints and the restart from one,
/// and the control cycles as the lumped `hotlap abs` counts them. `fe` knows nothing of the
/// controller; this is where the two meet.
///
///   fe::TyreRun run(config);
///   run.Inflate(hooks); run.Footprint(hooks); run.Roll(hooks);
///   sim::FeAbsStop stop(run, abs_config);
///   const sim::FeAbsStopResult r = stop.Run(options);   // options.checkpoint_every_s > 0: files
///
/// and to continue one (a new TyreRun of the same configuration files):
///
///   sim::FeAbsStop stop(run, abs_config);
///   const sim::FeAbsCheckpointInfo info = stop.Restore(file, MakeFeCheckpointKey(run));
///   const sim::FeAbsStopResult r = stop.Run(options);   // bit for bit as the straight run
///
/// A restart continues bit for bit on the same thread count and element kernel (the checkpoint
/// records both; FeAbsCheckpointInfo says what they were).
///
/// Checkpoint payload (inside checkpoint.h's file): the TyreRun's state (its braking step and
/// the solver's whole state), the controller ("ABS_"), the caller's summary ("SUMM"), the thread
/// count ("THRD") and the element kernel ("KERN").

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hotlap/abs/abs_config.h"
#include "hotlap/abs/abs_metrics.h"
#include "hotlap/abs/fe_abs_torque.h"
#include "hotlap/common/yaml_reader.h"
#include "hotlap/fe/checkpoint.h"
#include "hotlap/fe/tyre_steps.h"

namespace hotlap::sim {

/// What a checkpoint is for: the mesh, the bytes of both configuration files (the FE file and
/// the ABS file it names) and the ABS file's `overrides` (LoadAbsConfig's). The braking duration
/// is not part of it: a restart may run longer. Throws InputError if a file cannot be read.
fe::CheckpointKey MakeFeCheckpointKey(const fe::TyreRun& run,
                                      const std::vector<YamlOverride>& abs_overrides = {});

/// How to run the stop.
struct FeAbsStopOptions {
  double duration_s = 0.0;  ///< simulated time of the braking step from its start, s
  /// Progress, frames and history interval (its checkpoint fields are set from those below).
  fe::StepHooks hooks;
  double checkpoint_every_s = 0.0;        ///< s of simulated time (0: no checkpoints)
  std::filesystem::path checkpoint_file;  ///< written (atomically) at each checkpoint
  fe::CheckpointKey checkpoint_key;       ///< MakeFeCheckpointKey(run)
  std::string summary;  ///< saved with each checkpoint, returned by Restore (the CLI's JSON)
};

/// What the stop did.
struct FeAbsStopResult {
  fe::BrakeResult brake;               ///< the braking step (its history from its start)
  std::vector<double> cycle_starts_s;  ///< control cycle starts, on the histories' clock, s
  std::optional<double> abs_exit_s;    ///< the ABS exit, on the histories' clock, s
  CycleWindow cycles;                  ///< cycles and the slip after the first (CalcCycleWindow)
};

/// What a checkpoint held besides the run and the controller.
struct FeAbsCheckpointInfo {
  std::string summary;        ///< FeAbsStopOptions::summary of the run that wrote it
  std::uint64_t threads = 0;  ///< the thread count it was written on
  fe::ElementKernel kernel = fe::ElementKernel::kPortable;  ///< the kernel it was written with
};

/// The ABS stop of a TyreRun.
class FeAbsStop {
 public:
  /// Keeps references to `run` and `config` (the ABS file run.config().abs_config names).
  FeAbsStop(fe::TyreRun& run, const AbsConfig& config) : run_(run), config_(config) {}

  /// Reads checkpoint `file` (written for `key`) into the run, a new TyreRun of the same
  /// configuration that has not stepped, and into the controller. Throws InputError naming the
  /// file if it is missing, damaged, foreign or of another format version.
  FeAbsCheckpointInfo Restore(const std::filesystem::path& file, const fe::CheckpointKey& key);

  /// Runs the braking step (after TyreRun::Roll) or continues the restored one until
  /// options.duration_s after its start, writing checkpoints as options say.
  FeAbsStopResult Run(const FeAbsStopOptions& options);

  /// Writes a checkpoint of the run and the controller now (atomically).
  void WriteCheckpoint(const std::filesystem::path& file, const fe::CheckpointKey& key,
                       const std::string& summary) const;

  /// The controller (once Run or Restore made it).
  const FeAbsTorque& torque() const { return *torque_; }

 private:
  // The controller with the run's free-rolling radius as the slip's R_l (002:2).
  void MakeTorque();

  fe::TyreRun& run_;
  const AbsConfig& config_;
  std::unique_ptr<FeAbsTorque> torque_;
  bool restored_ = false;
};

}  // namespace hotlap::sim
