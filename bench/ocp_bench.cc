// Optimal-control speed.
//
// BM_DarlingtonOptimalLap/{0,1,2,3}: the two Darlington solves of `hotlap lap --method ocp
// --compare-disc-limit-C 500` (without and with the 500 degC front-disc limit), 3 m mesh (the
// default), each from its QSS warm-up through a 15 m coarse solve (coarse to fine), as the
// command does; /2 the free lap straight from the QSS guess on 3 m (coarse to fine off, the way
// before it); /3 the limited lap warm-started from the free lap's solution and multipliers (the
// command's way until 2026-11-26). The second argument 1 solves /0 and /1 the way of the morning
// of 2026-11-26, for issue 19's before/after table: every brake in the programme
// (all_brake_states) and the fine solve from the coarse point alone (no coarse_multipliers); 2
// solves /0 and /1 with Hermite-Simpson collocation on 12 m intervals (their midpoints nodes: as
// many nodes as a 6 m trapezoid) after the same 15 m trapezoid coarse solve; 3 keeps the tyres'
// wear in the programme of the fine solve too (wear_in_programme: the way before 2026-11-27's
// third session, which freezes it there and integrates it after the solve).
// Counters: lap time, Ipopt iterations and solve seconds of the fine solve (Ipopt's own clock)
// and of the coarse one, and MUMPS factorisations per Ipopt iteration (both solves; counted by
// interposing dmumps_c, bench/mumps_factorisations.cc).
//
// BM_F1PeerCatalunya: the peer case (docs/f1-peer.md), the 2014 F1 car on fastest-lap's
// Catalunya with 500 mesh points, in the same run, so that the Darlington solves can be read as a
// multiple of it (issue 19's goal: the free lap at most 6 times this).
//
// BM_ChassisElementsHessian/{per_element,dense_node_60}: why the programme is lifted
// (docs/optimal-control.md): one node's chassis elements with second-order forward AD over their
// own few inputs, and the same functions differentiated in a 60-variable space, the size of a
// whole lap-problem node, which is what a dense per-node Hessian would cost.
//
// Run: ./build/ocp_bench --benchmark_filter=Chassis   (seconds)
//      ./build/ocp_bench --benchmark_filter=F1Peer   (seconds)
//      ./build/ocp_bench --benchmark_filter=Darlington --benchmark_min_time=0   (minutes)
//      ./build/ocp_bench --benchmark_filter='Darlington.*/[01]/|F1'   (issue 19's table)
//      ./build/ocp_bench --benchmark_filter='Darlington.*/[01]/[03]/|F1'   (the frozen wear)

#include <benchmark/benchmark.h>

#include <array>
#include <type_traits>
#include <vector>

#include "hotlap/common/data_path.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/f1_lap_problem.h"
#include "hotlap/ocp/lap_elements.h"
#include "hotlap/ocp/optimal_lap.h"
#include "hotlap/ocp/solver_memory.h"
#include "hotlap/track/track_io.h"
#include "hotlap/vehicle/f1_car.h"
#include "mumps_factorisations.h"

namespace {

using namespace hotlap;

const vehicle::Car& Car() {
  static const vehicle::Car car = vehicle::LoadCar(ResolveCarFile("gen7"));
  return car;
}

// The free lap, kept for the limited one's (warm) start.
ocp::SolveResult& FreeSolution() {
  static ocp::SolveResult x;
  return x;
}

void BM_DarlingtonOptimalLap(benchmark::State& state) {
  ocp::KeepSolverMemory();  // as the commands do
  const track::Track track = track::LoadTrack("darlington");
  ocp::OptimalLapOptions o;
  o.ambient_temp = CelsiusToKelvin(25.0);
  o.track_temp = CelsiusToKelvin(40.0);
  if (state.range(0) == 1) o.front_disc_limit = CelsiusToKelvin(500.0);
  if (state.range(0) == 3) {
    // The limited lap from the free lap's solution and multipliers.
    o.front_disc_limit = CelsiusToKelvin(500.0);
    if (FreeSolution().x.empty()) {
      ocp::OptimalLapOptions free = o;
      free.front_disc_limit.reset();
      FreeSolution() = ocp::RunOptimalLap(Car(), track, free).solution.solve;
    }
    o.start_point = FreeSolution().x;
    o.ipopt.warm_z_lower = FreeSolution().z_lower;
    o.ipopt.warm_z_upper = FreeSolution().z_upper;
    o.ipopt.warm_lambda = FreeSolution().lambda;
  }
  if (state.range(0) == 2) o.coarse_step_m = 0.0;
  if (state.range(1) == 1) {
    o.all_brake_states = true;
    o.coarse_multipliers = false;
  }
  if (state.range(1) == 2) {
    o.collocation = ocp::Collocation::kHermiteSimpson;
    o.step_m = 12.0;
  }
  if (state.range(1) == 3) o.wear_in_programme = true;
  ocp::OptimalLapRun run;
  long factorisations = 0;
  for (auto _ : state) {
    const long before = bench::MumpsFactorisations();
    run = ocp::RunOptimalLap(Car(), track, o);
    factorisations = bench::MumpsFactorisations() - before;
  }
  if (state.range(0) == 0 && state.range(1) == 0 && run.solution.solve.ok()) {
    FreeSolution() = run.solution.solve;
  }
  state.counters["lap_time_s"] = run.solution.lap_time;
  state.counters["iterations"] = run.solution.solve.iterations;
  state.counters["regularized_iterations"] = run.solution.solve.regularized_iterations;
  state.counters["ipopt_solve_s"] = run.solution.solve.solve_seconds;
  // MUMPS factorisations of both solves per Ipopt iteration of both.
  const int all_iterations = run.solution.solve.iterations + run.coarse.iterations;
  state.counters["factorisations_per_iteration"] =
      all_iterations > 0 ? static_cast<double>(factorisations) / all_iterations : 0.0;
  state.counters["coarse_iterations"] = run.coarse.iterations;
  state.counters["coarse_solve_s"] = run.coarse.solve_seconds;
  state.counters["converged"] = run.solution.solve.ok() ? 1 : 0;
  state.counters["variables"] = run.solution.variables;
}
BENCHMARK(BM_DarlingtonOptimalLap)
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({0, 2})
    ->Args({1, 2})
    ->Args({0, 3})
    ->Args({1, 3})
    ->Args({2, 0})
    ->Args({3, 0})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

void BM_F1PeerCatalunya(benchmark::State& state) {
  ocp::KeepSolverMemory();
  const vehicle::F1CarParams car = vehicle::LoadF1Car(ResolveCarFile("f1-2014"));
  const track::Track track = track::LoadTrack("catalunya-fl");
  ocp::F1LapOptions o;
  o.mesh_points = 500;
  ocp::F1LapSolution s;
  long factorisations = 0;
  for (auto _ : state) {
    const long before = bench::MumpsFactorisations();
    s = ocp::SolveF1Lap(car, track, o, ocp::F1IpoptOptions());
    factorisations = bench::MumpsFactorisations() - before;
  }
  state.counters["factorisations_per_iteration"] =
      s.solve.iterations > 0 ? static_cast<double>(factorisations) / s.solve.iterations : 0.0;
  state.counters["lap_time_s"] = s.lap_time;
  state.counters["iterations"] = s.solve.iterations;
  state.counters["regularized_iterations"] = s.solve.regularized_iterations;
  state.counters["ipopt_solve_s"] = s.solve.solve_seconds;
  state.counters["converged"] = s.solve.ok() ? 1 : 0;
  state.counters["variables"] = s.variables;
}
BENCHMARK(BM_F1PeerCatalunya)->Iterations(1)->Unit(benchmark::kSecond);

// The chassis elements of one node (four corners' kinematics, loads, totals, the longitudinal and
// lateral dynamics), each differentiated over its own inputs (kPerElement = true) or over a
// node-sized 60-variable space as a dense per-node Hessian would (false).
template <bool kPerElement>
void BM_ChassisElementsHessian(benchmark::State& state) {
  const vehicle::VehicleParams& p = *Car().vehicle;
  const ocp::internal::NodeRoad road{1.0 / 183.0, DegToRad(25.0), 0.0};
  using S = std::conditional_t<kPerElement, SecondOrder<10>, SecondOrder<60>>;
  const auto seed = [](const std::vector<double>& x) {
    std::vector<S> v;
    for (size_t i = 0; i < x.size(); ++i) v.push_back(S::Variable(x[i], static_cast<int>(i)));
    return v;
  };
  for (auto _ : state) {
    for (Corner c : kAllCorners) {
      const auto in = seed({75.0, 0.4, 0.41, 0.03, -0.02, 76.0});
      std::array<S, 2> out;
      ocp::internal::KinematicsFn{&p, c}(in.data(), out.data());
      benchmark::DoNotOptimize(out);
    }
    {
      const auto in = seed({0.03, -100.0, -120.0, 2000.0, 2500.0, 6000.0, 9000.0, 5000.0, 8000.0});
      std::array<S, 3> out;
      ocp::internal::TotalsFn{&p}(in.data(), out.data());
      benchmark::DoNotOptimize(out);
    }
    {
      const auto in = seed({75.0, 0.4, 3.0, 4000.0, 30000.0});
      std::array<S, 4> out;
      ocp::internal::LoadsFn{&p, road}(in.data(), out.data());
      benchmark::DoNotOptimize(out);
    }
    {
      const auto in = seed({0.0134, 4000.0, 75.0, 0.4, 0.41, 0.01, 5000.0, 11000.0, 6000.0, 1e4});
      std::array<S, 1> out;
      ocp::internal::LongitudinalFn{&p, road, {0.01, 0.01, 0.01, 0.01}}(in.data(), out.data());
      benchmark::DoNotOptimize(out);
    }
  }
}
BENCHMARK(BM_ChassisElementsHessian<true>)->Name("BM_ChassisElementsHessian/per_element");
BENCHMARK(BM_ChassisElementsHessian<false>)->Name("BM_ChassisElementsHessian/dense_node_60");

}  // namespace
