// The surface-and-bulk disc (docs/models.md, "A disc that soaks"): its flows by hand, energy
// conserved over braking pulses with the rim as a sink, the lumped disc as its bulk-free case, and
// the bulk soaking the heat the surface sheds.

#include <cmath>

#include <gtest/gtest.h>

#include "brake/paper_brake_params.h"
#include "hotlap/brake/brake_thermal.h"
#include "hotlap/common/rk4.h"
#include "hotlap/common/units.h"

namespace hotlap::brake {
namespace {

BrakeHeatFlows<double>* const kNoFlows = nullptr;

// The paper's front brake (000 Table 5) with a bulk.
BrakeThermalParams<double> BulkParams() {
  BrakeThermalParams<double> p = test::PaperFrontBrakeParams();
  p.disc_model = DiscModel::kSurfaceBulk;
  p.bulk_conductance = 250.0;
  p.bulk_convection = 12.0;
  p.bulk_still_air_fraction = 0.1;
  p.hub_conductance = 1.5;
  p.rim_view_fraction = 0.15;
  return p;
}

TEST(DiscBulkTest, FlowsMatchHandComputation) {
  const BrakeThermalParams<double> p = BulkParams();
  const BrakeState<double> x{800.0, 420.0, 600.0};
  const BrakeInput<double> in{50.0, -2000.0, 300.0};
  const double rim = 350.0;
  BrakeHeatFlows<double> q;
  const BrakeState<double> d = CalcBrakeDerivatives(p, x, CalcBrakeInputTerms(p, in), &q, rim);
  const double sigma_a = 0.48 * kStefanBoltzmann * 0.6302;
  EXPECT_NEAR(q.radiation_to_rim, 0.15 * sigma_a * (std::pow(800.0, 4) - std::pow(rim, 4)), 1e-9);
  EXPECT_NEAR(q.q3, 0.85 * sigma_a * (std::pow(800.0, 4) - std::pow(300.0, 4)), 1e-9);
  EXPECT_NEAR(q.to_bulk, 250.0 * 200.0, 1e-9);
  // At 50 m/s the vane cooling is its reference value.
  EXPECT_NEAR(q.bulk_convection, 12.0 * 300.0, 1e-9);
  EXPECT_NEAR(q.hub_to_rim, 1.5 * 250.0, 1e-9);
  EXPECT_NEAR(q.ToRim(), q.hub_to_rim + q.radiation_to_rim, 1e-12);
  const double bulk_capacity = 0.9 * 8.8 * 480.0;
  EXPECT_NEAR(d.bulk_temp, (q.to_bulk - q.bulk_convection - q.hub_to_rim) / bulk_capacity, 1e-12);
  const double surface_capacity = 0.1 * 8.8 * 480.0;
  EXPECT_NEAR(
      d.disc_temp,
      (0.95 * q.q1 - q.q2 - q.q3 - q.q4 - q.to_bulk - q.radiation_to_rim) / surface_capacity,
      1e-12);
}

// A brake state with the net heat into it (J: the brake's work less every loss) integrated beside.
struct BulkAugmented {
  BrakeState<double> x;
  double net_in = 0.0;
  BulkAugmented operator+(const BulkAugmented& b) const { return {x + b.x, net_in + b.net_in}; }
  friend BulkAugmented operator*(double k, const BulkAugmented& a) {
    return {k * a.x, k * a.net_in};
  }
};

// Braking pulses with the rim a fixed sink: the heat into the brake is what the three masses
// stored plus what left by every path, to rounding under RK4.
TEST(DiscBulkTest, ConservesEnergy) {
  const BrakeThermalParams<double> p = BulkParams();
  const double rim = 340.0;
  const auto rhs = [&](double t, const BulkAugmented& s) {
    const BrakeInput<double> in{60.0 + 20.0 * std::sin(0.4 * t), 5000.0 * std::sin(1.1 * t), 300.0};
    BrakeHeatFlows<double> q;
    BulkAugmented d;
    d.x = CalcBrakeDerivatives(p, s.x, CalcBrakeInputTerms(p, in), &q, rim);
    d.net_in = q.q1 - q.q3 - q.q4 - q.q5 - q.q6 - q.bulk_convection - q.ToRim();
    return d;
  };
  BulkAugmented s{{500.0, 350.0, 450.0}, 0.0};
  const BulkAugmented start = s;
  for (int i = 0; i < 4000; ++i) s = Rk4Step(rhs, i * 0.005, s, 0.005);
  const double disc = 8.8 * 480.0;
  const double stored = 0.1 * disc * (s.x.disc_temp - start.x.disc_temp) +
                        0.9 * disc * (s.x.bulk_temp - start.x.bulk_temp) +
                        5.0312 * 921.1 * (s.x.calliper_temp - start.x.calliper_temp);
  EXPECT_GT(std::abs(s.x.bulk_temp - start.x.bulk_temp), 5.0);  // the bulk took part
  EXPECT_NEAR(stored, s.net_in, 1e-9 * std::abs(s.net_in) + 1e-6);
}

TEST(DiscBulkTest, TheLumpedDiscIsTheBulkFreeCase) {
  BrakeThermalParams<double> bulk = BulkParams();
  BrakeThermalParams<double> lumped = bulk;
  lumped.disc_model = DiscModel::kLumped;
  BrakeThermalParams<double> paper = bulk;
  paper.disc_model = DiscModel::kLumped;
  paper.bulk_conductance = paper.bulk_convection = paper.hub_conductance = 0.0;
  paper.rim_view_fraction = 0.0;
  const BrakeState<double> x{700.0, 400.0, 123.0};
  const BrakeInput<double> in{55.0, -3000.0, 300.0};
  const BrakeState<double> a = CalcBrakeDerivatives(lumped, x, in);
  const BrakeState<double> b = CalcBrakeDerivatives(paper, x, in);
  EXPECT_EQ(a.disc_temp, b.disc_temp);
  EXPECT_EQ(a.calliper_temp, b.calliper_temp);
  EXPECT_EQ(a.bulk_temp, 0.0);
}

// A hard stop heats the thin surface; off the brakes it sheds that heat into the bulk within
// seconds, and the bulk then cools on a time scale of minutes.
TEST(DiscBulkTest, TheBulkSoaksWhatTheSurfaceSheds) {
  const BrakeThermalParams<double> p = BulkParams();
  BrakeState<double> x{500.0, 400.0, 500.0};
  const auto run = [&](double seconds, double fx) {
    const BrakeInput<double> in{60.0, fx, 300.0};
    const auto f = [&](double, const BrakeState<double>& s) {
      return CalcBrakeDerivatives(p, s, CalcBrakeInputTerms(p, in), kNoFlows, 340.0);
    };
    for (int i = 0; i < static_cast<int>(seconds / 0.005); ++i) x = Rk4Step(f, 0.0, x, 0.005);
  };
  run(3.0, -4000.0);  // 240 kW for 3 s
  const double surface_peak = x.disc_temp, bulk_after_stop = x.bulk_temp;
  EXPECT_GT(surface_peak - bulk_after_stop, 100.0);
  run(5.0, 0.0);
  EXPECT_LT(x.disc_temp - x.bulk_temp, 0.1 * (surface_peak - bulk_after_stop));
  EXPECT_GT(x.bulk_temp, bulk_after_stop);  // it soaked
  const double bulk_soaked = x.bulk_temp;
  run(20.0, 0.0);
  // Cooling at 60 m/s: the bulk's time constant is some minutes, so 20 s takes off little of it.
  EXPECT_LT(bulk_soaked - x.bulk_temp, 0.25 * (bulk_soaked - 300.0));
  EXPECT_GT(bulk_soaked - x.bulk_temp, 0.0);
}

}  // namespace
}  // namespace hotlap::brake
