#pragma once
// What the observer's tests share: the Gen-7-like car, the shipped noise file, a synthetic log of
// Darlington with given options (made once per test program), and a log's column by name.

#include <stdexcept>
#include <string>
#include <vector>

#include "hotlap/observe/observer_config.h"
#include "hotlap/sim/road.h"
#include "hotlap/sim/synth.h"
#include "hotlap/track/track_io.h"
#include "hotlap/vehicle/car.h"
#include "test_util.h"

namespace hotlap::observe::testing {

inline const vehicle::Car& Gen7() {
  static const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  return car;
}

inline ObserverConfig DefaultConfig() {
  return LoadObserverConfig(test::SourcePath("data/observer/default.yaml"));
}

/// A synthetic log of the Gen-7-like car round Darlington (the road on a 1 m spacing).
inline sim::SynthLog DarlingtonLog(const sim::SynthOptions& options) {
  return sim::SynthesizeLog(Gen7(), sim::SampleRoad(track::LoadTrack("darlington"), 1.0), options);
}

/// The log's column `name`; std::runtime_error if it has none.
inline const std::vector<double>& Column(const sim::SynthLog& log, const std::string& name) {
  for (size_t i = 0; i < log.columns.size(); ++i) {
    if (log.columns[i] == name) return log.values[i];
  }
  throw std::runtime_error("no column " + name);
}

}  // namespace hotlap::observe::testing
