// Finite-element tyre speed: element updates per second of the explicit solver on the generated
// 235/75R15 (data/fe/paper_235_75r15.yaml), inflated and pressed on the road (contact active),
// at the shipped coarse mesh and at the paper's mesh size (33,792 elements here against the
// paper's 33,794: 44 meridional x 4 through the wall x 192 around), on 1 thread and on N threads
// (the element loop is OpenMP-parallel; docs/fe-tyre.md), with both parallel assemblies
// (per-thread force buffers, the default: on one thread the plain serial loop; element colours).
// Two states: "light" (coloured, buffers: inflated and pressed for 0.1 ms only, quick to prepare)
// and "loaded" (the file's 40 ms inflation and 100 ms footprint, prepared mass-scaled: cords in
// tension and the footprint on the road, as in a real run; see BenchState).
// Also reports the projected wall time of the paper's 1.5 s braking event at each mesh and thread
// count, and its stable time step (issue 9's goal: under 2 hours on this 2-core machine; the paper
// took 26 h 27 min on 8 cores).
//
// Run: ./build/fe_bench [--threads N] [google-benchmark flags]
//   --threads N: the multi-threaded runs use N threads (default: all cores, OpenMP's default).
// The element kernel is the solver's default, AVX2 where the CPU has it; HOTLAP_FE_KERNEL=portable
// (or avx2, auto) chooses, as for `hotlap fe` without --kernel (counter avx2: 1 or 0).

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "hotlap/fe/fe_config.h"
#include "hotlap/fe/tyre_steps.h"

namespace {

using namespace hotlap;

// The state the steps are timed in. kLight: inflated and pressed for 0.1 ms each (quick to
// prepare, but the tyre is barely deformed: its tension-only cords sit near zero strain and about
// half of them skip their stress). kLoaded: the file's inflation and footprint (40 + 100 ms of
// simulated time), prepared with mass scaling to 10 us (a step's cost does not depend on the
// masses) so that the cords are in tension and the footprint is on the road as in a real run;
// the projection uses the unscaled step.
enum class BenchState { kLight, kLoaded };

fe::FeConfig Config(bool paper_mesh, BenchState bench_state) {
  fe::FeConfig c =
      fe::LoadFeConfig(std::filesystem::path(HOTLAP_SOURCE_DIR) / "data/fe/paper_235_75r15.yaml");
  if (paper_mesh) {
    c.mesh.meridional_elements_half = 22;
    c.mesh.thickness_elements = 4;
    c.mesh.tread_layers = 1;
    c.mesh.circumferential_elements_contact = 48;
    c.mesh.circumferential_elements_rest = 144;
  }
  if (bench_state == BenchState::kLight) {
    // Short quasi-static steps: only the state matters here, not its accuracy.
    c.inflate.ramp_s = c.inflate.hold_s = 1e-4;
    c.footprint.ramp_s = c.footprint.hold_s = 1e-4;
  } else {
    c.solver.mass_scaling_min_step_s = 1e-5;
    c.footprint.damping_per_s = 100.0;  // the tyre is heavier: less damping (the file's note)
  }
  return c;
}

// The loaded tyre (road, pressure and rim active), prepared once per mesh and copied into each
// benchmark.
const fe::TyreRun& Prepared(bool paper_mesh, BenchState bench_state) {
  static std::map<std::pair<bool, BenchState>, std::unique_ptr<fe::TyreRun>> prepared;
  auto& run = prepared[{paper_mesh, bench_state}];
  if (!run) {
    run = std::make_unique<fe::TyreRun>(Config(paper_mesh, bench_state));
    fe::StepHooks hooks;
    hooks.history_interval_s = 1.0;
    run->Inflate(hooks);
    run->Footprint(hooks);
  }
  return *run;
}

void BM_FeTyreSteps(benchmark::State& state, bool paper_mesh, BenchState bench_state, int threads,
                    fe::Assembly assembly) {
  fe::TyreRun run = Prepared(paper_mesh, bench_state);
  fe::ExplicitSolver& solver = run.mutable_solver();
  solver.set_threads(threads);
  solver.set_assembly(assembly);
  if (const char* kernel = std::getenv("HOTLAP_FE_KERNEL"); kernel != nullptr && *kernel != '\0') {
    solver.set_element_kernel(fe::ParseElementKernel(kernel, "HOTLAP_FE_KERNEL"));
  }
  const double elements = static_cast<double>(run.tyre().mesh.elements.size());
  long steps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : state) {
    solver.Step();
    ++steps;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  state.counters["elements"] = elements;
  state.counters["threads"] = solver.threads();
  state.counters["colours"] = solver.colours();
  // 1: the AVX2 element kernel (the default where the CPU has it; HOTLAP_FE_KERNEL=portable: 0).
  state.counters["avx2"] = solver.element_kernel() == fe::ElementKernel::kAvx2 ? 1 : 0;
  state.counters["element_updates_per_s"] =
      benchmark::Counter(elements * steps, benchmark::Counter::kIsRate);
  // The step of the real run: the loaded state was prepared mass-scaled.
  const double dt =
      bench_state == BenchState::kLight
          ? solver.time_step()
          : run.config().solver.time_step_safety * solver.mass_scaling().stable_step_unscaled_s;
  state.counters["time_step_us"] = 1e6 * dt;
  // Projected wall time of a 1.5 s event, hours: (time per step) x (1.5 s / dt).
  state.counters["event_1p5s_hours"] = wall / steps * (1.5 / dt) / 3600.0;
}

}  // namespace

int main(int argc, char** argv) {
  // --threads N is ours; the rest goes to Google Benchmark.
  int threads = 0;
  std::vector<char*> rest;
  for (int k = 0; k < argc; ++k) {
    if (std::strcmp(argv[k], "--threads") == 0 && k + 1 < argc) {
      threads = std::atoi(argv[++k]);
      if (threads < 1) {
        std::fprintf(stderr, "fe_bench: --threads wants a whole number >= 1, got '%s'\n", argv[k]);
        return 2;
      }
    } else {
      rest.push_back(argv[k]);
    }
  }
  if (threads == 0) threads = fe::DefaultThreadCount();
  std::vector<int> counts = {1};
  if (threads > 1) counts.push_back(threads);
  for (const bool paper : {false, true}) {
    for (const int n : counts) {
      for (const fe::Assembly assembly : {fe::Assembly::kColoured, fe::Assembly::kThreadBuffers}) {
        const std::string name = std::string("BM_FeTyreSteps/") + (paper ? "paper" : "shipped") +
                                 "/threads:" + std::to_string(n) + "/" +
                                 (assembly == fe::Assembly::kColoured ? "coloured" : "buffers");
        benchmark::RegisterBenchmark(name.c_str(), BM_FeTyreSteps, paper, BenchState::kLight, n,
                                     assembly)
            ->Unit(benchmark::kMillisecond)
            ->MinTime(2.0)
            ->UseRealTime();
      }
      // The loaded state, with the default assembly.
      const std::string name = std::string("BM_FeTyreSteps/") + (paper ? "paper" : "shipped") +
                               "/threads:" + std::to_string(n) + "/loaded";
      benchmark::RegisterBenchmark(name.c_str(), BM_FeTyreSteps, paper, BenchState::kLoaded, n,
                                   fe::Assembly::kThreadBuffers)
          ->Unit(benchmark::kMillisecond)
          ->MinTime(2.0)
          ->UseRealTime();
    }
  }
  int n_args = static_cast<int>(rest.size());
  benchmark::Initialize(&n_args, rest.data());
  if (benchmark::ReportUnrecognizedArguments(n_args, rest.data())) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
