// The gas-and-rim tyre model (docs/models.md, "Tyre heat over a run"): the quasi-static gas and
// the rim against hand-computed balances, the rolling-resistance law, heat never above the car's
// work, the paper's model untouched by the new parameters, and exact derivatives.

#include <array>
#include <cmath>

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "hotlap/common/rk4.h"
#include "hotlap/common/scalar.h"
#include "hotlap/tyre/tyre_thermal.h"
#include "test_util.h"
#include "tyre/paper_tyre_params.h"

namespace hotlap::tyre {
namespace {

constexpr double kAtm = 101325.0;
TyreHeatFlows<double>* const kNoFlows = nullptr;

// The paper's rear-right tyre (000 Tables 2-4) with the gas-and-rim model's parameters.
TyreThermalParams<double> GasRimParams(bool liner) {
  TyreThermalParams<double> p = test::PaperRearRightParams();
  p.model = TyreThermalModel::kGasRim;
  p.carcass_slip_share = 0.3;
  p.rolling_resistance = 0.012;
  p.rolling_reference_temp = 333.15;
  p.rolling_reference_pressure = 200e3;
  p.rolling_temp_coefficient = 0.01;
  p.rolling_temp_floor = 0.35;
  p.rolling_pressure_exponent = 0.4;
  p.contact_length_pressure_exponent = 0.5;
  p.cold_set_temp = 298.15;
  p.cold_pressure = 300e3;
  p.liner_pressure_offset = liner ? 120e3 : 0.0;
  p.carcass_gas_conductance = 30.0;
  p.gas_rim_conductance = 8.0;
  p.gas_liner_conductance = liner ? 15.0 : 0.0;
  p.liner_rim_conductance = liner ? 15.0 : 0.0;
  p.sidewall_air_conductance = 25.0;
  p.rim_air_conductance = 20.0;
  p.still_air_fraction = 0.15;
  p.rim_mass = 11.3;
  p.rim_heat_capacity = 900.0;
  return p;
}

TyreCompound Compound() {
  const auto spec = [](CubicKind kind, double v) {
    return TemperatureCubicSpec{kind, 371.15, 333.15, v, 413.15, v, 273.15, 473.15};
  };
  return TyreCompound{"test", TemperatureCubic::Create(spec(CubicKind::kGripMaximum, 0.9), "g"),
                      TemperatureCubic::Create(spec(CubicKind::kWearMinimum, 1.5), "w"),
                      GripWearTable{{0.0, 6.0}, {1.0, 0.75}}, 1000.0};
}

TyreInput<double> Cornering(double speed = 50.0) {
  return {speed, -900.0, -5200.0, 6100.0, 0.05, -0.02, 298.15, 318.15};
}

TEST(TyreGasRimTest, GasWithoutLinerIsTheHandComputedBalance) {
  const TyreThermalParams<double> p = GasRimParams(false);
  // At 50 m/s the conductances are their reference values: 30 (400 - Tg) = 8 (Tg - 340).
  const TyreGas<double> g = CalcTyreGas(p, 400.0, 340.0, 50.0);
  const double tg = (30.0 * 400.0 + 8.0 * 340.0) / 38.0;
  EXPECT_NEAR(g.gas_temp, tg, 1e-12);
  EXPECT_NEAR(g.carcass_to_gas, 30.0 * (400.0 - tg), 1e-9);
  // Constant volume: (300 kPa + 1 atm) Tg / 298.15 K, gauge.
  EXPECT_NEAR(g.pressure, (300e3 + kAtm) * tg / 298.15 - kAtm, 1e-6);
  EXPECT_EQ(g.liner_pressure, 0.0);
  // At rest only the still-air share of each conductance is left; the balance's weights are the
  // same, so the gas temperature is too.
  EXPECT_NEAR(CalcTyreGas(p, 400.0, 340.0, 0.0).gas_temp, tg, 1e-12);
  EXPECT_NEAR(CalcTyreGas(p, 400.0, 340.0, 0.0).carcass_to_gas, 0.15 * 30.0 * (400.0 - tg), 1e-9);
}

TEST(TyreGasRimTest, GasWithLinerIsTheHandComputedBalance) {
  const TyreThermalParams<double> p = GasRimParams(true);
  const double tc = 400.0, tr = 340.0;
  // 30 (Tc - Tg) = 15 (Tg - Tl) + 8 (Tg - Tr) and 15 (Tg - Tl) = 15 (Tl - Tr), by substitution:
  // Tl = (Tg + Tr) / 2, so 30 Tc + 8 Tr + 7.5 Tr = (30 + 7.5 + 8) Tg.
  const double tg = (30.0 * tc + 15.5 * tr) / 45.5;
  const double tl = 0.5 * (tg + tr);
  const TyreGas<double> g = CalcTyreGas(p, tc, tr, 50.0);
  EXPECT_NEAR(g.gas_temp, tg, 1e-10);
  EXPECT_NEAR(g.liner_temp, tl, 1e-10);
  EXPECT_NEAR(g.liner_pressure, (420e3 + kAtm) * tl / 298.15 - kAtm, 1e-5);
  // Quasi-static: what the carcass gives the gas, the gases give the rim.
  EXPECT_NEAR(g.carcass_to_gas, 8.0 * (tg - tr) + 15.0 * (tl - tr), 1e-9);
}

TEST(TyreGasRimTest, RimSettlesAtTheHandComputedBalance) {
  TyreThermalParams<double> p = GasRimParams(false);
  p.carcass_mass = 1e9;  // a carcass that holds its temperature
  const TyreCompound compound = Compound();
  TyreInput<double> in = {50.0, 0.0, 0.0, 0.0, 0.0, 0.0, 300.0, 300.0};
  const double brake_to_rim = 400.0;
  TyreState<double> x{350.0, 390.0, 0.0, 300.0};
  const auto f = [&](double, const TyreState<double>& s) {
    TyreState<double> d = CalcTyreDerivatives(p, compound, s, CalcTyreInputTerms(p, compound, in),
                                              kNoFlows, brake_to_rim);
    d.carcass_temp = 0.0;
    return d;
  };
  for (int i = 0; i < 40000; ++i) x = Rk4Step(f, 0.0, x, 0.5);
  // The carcass-to-rim path is 30 and 8 W/K in series; the rim loses 20 W/K to the 300 K air:
  // G_s (390 - Tr) + 400 W = 20 (Tr - 300).
  const double gs = 30.0 * 8.0 / 38.0;
  const double tr = (gs * 390.0 + brake_to_rim + 20.0 * 300.0) / (gs + 20.0);
  EXPECT_NEAR(x.rim_temp, tr, 1e-6);
}

TEST(TyreGasRimTest, RollingResistanceFallsWithTemperatureAndPressure) {
  const TyreThermalParams<double> p = GasRimParams(false);
  EXPECT_NEAR(CalcRollingResistance(p, 333.15, 200e3), 0.012, 1e-15);
  const double hot = CalcRollingResistance(p, 393.15, 200e3);
  EXPECT_NEAR(hot, 0.012 * (0.35 + 0.65 * std::exp(-0.6)), 1e-15);
  EXPECT_NEAR(CalcRollingResistance(p, 333.15, 400e3), 0.012 * std::pow(2.0, -0.4), 1e-15);
  EXPECT_LT(hot, 0.012);
  // Never below the floor's share however hot.
  EXPECT_GT(CalcRollingResistance(p, 1000.0, 200e3), 0.35 * 0.012);
}

TEST(TyreGasRimTest, HeatIsNeverMoreThanTheWorkTheCarDoesOnTheTyre) {
  const TyreThermalParams<double> p = GasRimParams(true);
  const TyreCompound compound = Compound();
  int checked = 0;
  for (double speed : {5.0, 40.0, 80.0}) {
    for (double fx : {-6000.0, -500.0, 0.0, 3000.0}) {
      for (double alpha : {0.0, 0.02, 0.12}) {
        for (double tc : {300.0, 380.0, 450.0}) {
          const double kappa = fx / 60000.0;
          const TyreInput<double> in = {speed, fx,   -40000.0 * alpha, 5000.0, alpha, kappa,
                                        300.0, 320.0};
          const TyreState<double> x{360.0, tc, 0.0, 330.0};
          TyreHeatFlows<double> q;
          CalcTyreDerivatives(p, compound, x, CalcTyreInputTerms(p, compound, in), &q);
          const TyreGas<double> gas = CalcTyreGas(p, tc, 330.0, speed);
          const TyreMechanicalPower<double> work =
              CalcTyreMechanicalPower(in, gas.rolling_resistance);
          EXPECT_LE(q.q1 + q.q2, (work.sliding + work.rolling) * (1.0 + 1e-12))
              << speed << " " << fx << " " << alpha << " " << tc;
          EXPECT_NEAR(q.rolling_power, work.rolling, 1e-9);
          ++checked;
        }
      }
    }
  }
  EXPECT_EQ(checked, 108);
}

TEST(TyreGasRimTest, ThePaperModelIgnoresTheGasAndRimParameters) {
  TyreThermalParams<double> gas_rim = GasRimParams(true);
  TyreThermalParams<double> paper = gas_rim;
  paper.model = TyreThermalModel::kPaper;
  TyreThermalParams<double> bare = GasRimParams(false);
  bare.model = TyreThermalModel::kPaper;
  bare.rolling_resistance = 0.0;
  bare.carcass_gas_conductance = 0.0;
  bare.rim_mass = 0.0;
  const TyreCompound compound = Compound();
  const TyreState<double> x{360.0, 390.0, 0.1, 330.0};
  const TyreState<double> a = CalcTyreDerivatives(paper, compound, x, Cornering());
  const TyreState<double> b = CalcTyreDerivatives(bare, compound, x, Cornering());
  EXPECT_EQ(a.tread_temp, b.tread_temp);
  EXPECT_EQ(a.carcass_temp, b.carcass_temp);
  EXPECT_EQ(a.wear, b.wear);
  EXPECT_EQ(a.rim_temp, 0.0);  // the paper's tyre has no rim
  // The gas-and-rim model differs: its carcass is heated by the car's work and cooled by the gas.
  const TyreState<double> c = CalcTyreDerivatives(gas_rim, compound, x, Cornering());
  EXPECT_NE(c.carcass_temp, a.carcass_temp);
  EXPECT_NE(c.rim_temp, 0.0);
}

TEST(TyreGasRimTest, StateDerivativesMatchFiniteDifferences) {
  using J = Jet5;  // one of the instantiated sizes (common/scalar.h); the fifth part is unused
  const TyreThermalParams<double> p = GasRimParams(true);
  const TyreThermalParams<J> pj = p.Cast<J>();
  const TyreCompound compound = Compound();
  const TyreInput<double> in = Cornering(62.0);
  const TyreInput<J> inj = {J(in.speed),        J(in.fx),         J(in.fy),
                            J(in.fz),           J(in.slip_angle), J(in.slip_ratio),
                            J(in.ambient_temp), J(in.track_temp)};
  const std::array<double, 4> x0 = {365.0, 395.0, 0.2, 335.0};
  const TyreState<J> xj{J(x0[0], 0), J(x0[1], 1), J(x0[2], 2), J(x0[3], 3)};
  TyreHeatFlows<J>* const no_flows = nullptr;
  const TyreState<J> dj = CalcTyreDerivatives(
      pj, compound, xj, CalcTyreInputTerms(pj, compound, inj), no_flows, J(250.0));
  const auto at = [&](int i, double h) {
    std::array<double, 4> x = x0;
    x[i] += h;
    const TyreState<double> d =
        CalcTyreDerivatives(p, compound, TyreState<double>{x[0], x[1], x[2], x[3]},
                            CalcTyreInputTerms(p, compound, in), kNoFlows, 250.0);
    return std::array<double, 4>{d.tread_temp, d.carcass_temp, d.wear, d.rim_temp};
  };
  const std::array<J, 4> exact = {dj.tread_temp, dj.carcass_temp, dj.wear, dj.rim_temp};
  for (int i = 0; i < 4; ++i) {
    const double h = i == 2 ? 1e-6 : 1e-4;
    const std::array<double, 4> up = at(i, h), down = at(i, -h);
    for (int k = 0; k < 4; ++k) {
      const double fd = (up[k] - down[k]) / (2.0 * h);
      EXPECT_NEAR(exact[k].v[i], fd, 1e-6 * (1.0 + std::abs(fd))) << "d" << k << "/dx" << i;
    }
  }
}

}  // namespace
}  // namespace hotlap::tyre
