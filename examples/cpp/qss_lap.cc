// Three quasi-steady-state laps of Darlington in the Gen-7-like car, with the tyre and brake
// thermal models along the way (hotlap's shipped car and track): lap times, and the peak tread and
// disc temperatures and wear of each corner on the last lap.
//
//   ./qss_lap [CAR] [TRACK]     (built-in names or paths; gen7 and darlington by default)

#include <algorithm>
#include <cstdio>
#include <exception>

#include "hotlap/common/data_path.h"
#include "hotlap/common/units.h"
#include "hotlap/sim/qss_lap.h"
#include "hotlap/sim/road.h"
#include "hotlap/track/track_io.h"
#include "hotlap/vehicle/car.h"

int main(int argc, char** argv) {
  using namespace hotlap;
  try {
    const vehicle::Car car = vehicle::LoadCar(ResolveCarFile(argc > 1 ? argv[1] : "gen7"));
    const track::Track track = track::LoadTrack(argc > 2 ? argv[2] : "darlington");
    const std::vector<sim::RoadPoint> road = sim::SampleRoad(track, 1.0);
    sim::QssOptions options;
    options.laps = 3;
    options.track_length = track.length_m();
    options.ambient_temp = CelsiusToKelvin(25.0);
    options.track_temp = CelsiusToKelvin(40.0);
    options.initial = sim::CarStartState(car);  // the car's initial_state (car.yaml)
    const sim::QssResult result = sim::RunQssLap(car, road, options);
    std::printf("%s on %s (%.1f m)\n", car.name.c_str(), track.name().c_str(), track.length_m());
    for (size_t i = 0; i < result.laps.size(); ++i) {
      std::printf("lap %zu: %.3f s\n", i + 1, result.laps[i].lap_time);
    }
    const sim::ReplayResult& last = result.laps.back().thermal;
    const char* names[4] = {"FL", "FR", "RL", "RR"};
    std::printf("corner,peak_tread_C,peak_disc_C,wear_mm\n");
    for (int c = 0; c < 4; ++c) {
      const sim::CornerHistory& h = last.corners[c];
      std::printf("%s,%.1f,%.1f,%.4f\n", names[c],
                  KelvinToCelsius(*std::max_element(h.tread_temp.begin(), h.tread_temp.end())),
                  KelvinToCelsius(*std::max_element(h.disc_temp.begin(), h.disc_temp.end())),
                  h.wear.back());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
