// The mesh error estimate (ocp/mesh_error.h) on the Darlington lap, against the lap-time change
// of solving on a finer mesh (docs/validation/optimal-lap.md, "Mesh").
//
// BM_DarlingtonMeshError/{0,1}: the free lap (the main job's, 25 degC air, 40 degC track, racing
// start) on uniform meshes given as node lists (OptimalLapOptions::mesh_m: the adaptive mesh's
// penalties, the same integral of the squared steer rate on every mesh), solved in a chain, each
// from the last one's point: 24 m from the QSS guess, then 12, 6 and 3 m ("up"), then 6 and 12 m
// again from the 3 m lap ("back": the 3 m lap's own branch). /0 the car's own models, /1 the
// paper's (`--paper-models`). Counters: every lap time (s), every estimate (ms), and for 12 and 6 m
// against 3 m on each branch the true difference and the estimated one (the coarse lap's estimate
// less the 3 m lap's), ms. The estimate is judged on "back": "up" may change branch on the way to
// 3 m (a local optimum tens of ms away, which no mesh estimate measures).
//
// Run: ./build/mesh_error_bench --benchmark_min_time=0 --benchmark_filter=/0   (about 15 minutes)
//      (--benchmark_format=json for the counters' every digit)

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "hotlap/common/data_path.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/mesh_resample.h"
#include "hotlap/ocp/optimal_lap.h"
#include "hotlap/ocp/solver_memory.h"
#include "hotlap/track/track_io.h"

namespace {

using namespace hotlap;

void BM_DarlingtonMeshError(benchmark::State& state) {
  ocp::KeepSolverMemory();  // as the commands do
  const vehicle::Car car = vehicle::LoadCar(ResolveCarFile("gen7"));
  const track::Track track = track::LoadTrack("darlington");
  ocp::OptimalLapOptions options;
  options.ambient_temp = CelsiusToKelvin(25.0);
  options.track_temp = CelsiusToKelvin(40.0);
  options.coarse_step_m = 0.0;
  options.paper_models = state.range(0) == 1;
  options.derivative_threads = 2;
  options.wear_in_programme = true;
  const ocp::LapWarmUp warm_up = ocp::RunLapWarmUp(car, track, options);
  // One solve on the uniform mesh of `step_m` as a node list, from `from` (null: the QSS guess).
  const auto solve = [&](double step_m, const ocp::OptimalLapRun* from) {
    ocp::OptimalLapOptions o = options;
    const int n = static_cast<int>(std::round(track.length_m() / step_m));
    for (int k = 0; k <= n; ++k) o.mesh_m.push_back(track.length_m() * k / n);
    if (from != nullptr) {
      ocp::StartFromSolutionOnMesh(from->solution.solve, from->solution.layout, track.length_m(),
                                   o.mesh_m, false, o.start_point, o.ipopt);
    }
    return ocp::RunOptimalLap(car, track, o, &warm_up);
  };
  const std::vector<double> chain = {24.0, 12.0, 6.0, 3.0, 6.0, 12.0};
  std::vector<ocp::OptimalLapRun> runs;
  for (auto _ : state) {
    runs.clear();
    for (double step : chain) runs.push_back(solve(step, runs.empty() ? nullptr : &runs.back()));
  }
  bool converged = true;
  for (size_t i = 0; i < runs.size(); ++i) {
    const std::string name = std::to_string(static_cast<int>(chain[i])) + (i > 3 ? "m_back" : "m");
    state.counters["lap_" + name + "_s"] = runs[i].solution.lap_time;
    state.counters["estimate_" + name + "_ms"] = 1e3 * runs[i].mesh_error.lap_time_error_s;
    state.counters["iterations_" + name] = runs[i].solution.solve.iterations;
    converged = converged && runs[i].solution.solve.ok();
  }
  // Against the 3 m lap (runs[3]): the coarse lap's difference and its estimate.
  const auto against_fine = [&](const std::string& name, const ocp::OptimalLapRun& coarse) {
    const ocp::OptimalLapRun& fine = runs[3];
    state.counters["true_" + name + "_ms"] =
        1e3 * (coarse.solution.lap_time - fine.solution.lap_time);
    state.counters["estimated_" + name + "_ms"] =
        1e3 * (coarse.mesh_error.lap_time_error_s - fine.mesh_error.lap_time_error_s);
  };
  against_fine("12m_up", runs[1]);
  against_fine("6m_up", runs[2]);
  against_fine("6m_back", runs[4]);
  against_fine("12m_back", runs[5]);
  state.counters["converged"] = converged ? 1 : 0;
}
BENCHMARK(BM_DarlingtonMeshError)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
