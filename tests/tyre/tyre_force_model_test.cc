#include "hotlap/tyre/tyre_force_model.h"

#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/tyre/tyre_params_io.h"
#include "test_util.h"

namespace hotlap::tyre {
namespace {

const std::filesystem::path kTir =
    test::SourcePath("tests/data/tir/mfeval/MagicFormula61_Parameters.tir");
const std::filesystem::path kBrush = test::SourcePath("data/tyres/brush_example.yaml");
const std::filesystem::path kUniTire = test::SourcePath("data/tyres/unitire_example.yaml");

TyreOperatingPoint<double> Point() {
  TyreOperatingPoint<double> op;
  op.fz = 4000.0;
  op.slip_ratio = 0.03;
  op.slip_angle = 0.04;
  op.speed = 20.0;
  op.tread_temp = 300.0;
  return op;
}

TEST(TyreForceModelTest, TheFileChoosesTheModel) {
  EXPECT_EQ(LoadTyreForceModel(kTir).kind(), "mf");
  EXPECT_EQ(LoadTyreForceModel(kBrush).kind(), "brush");
  EXPECT_EQ(LoadTyreForceModel(kUniTire).kind(), "unitire");
}

// The variant dispatches to the model's own function: same numbers as calling it directly.
TEST(TyreForceModelTest, DispatchMatchesDirectCalls) {
  const TyreOperatingPoint<double> op = Point();
  const TyreForceModel<double> mf = LoadTyreForceModel(kTir);
  const TyreForces<double> direct = CalcMagicFormula(LoadMagicFormula(kTir), op, {});
  const TyreForces<double> via = CalcTyreForces(mf, op);
  EXPECT_EQ(via.fx, direct.fx);
  EXPECT_EQ(via.fy, direct.fy);
  EXPECT_EQ(via.mz, direct.mz);
  const TyreForceModel<double> ut = LoadTyreForceModel(kUniTire);
  EXPECT_EQ(CalcTyreForces(ut, op).fy,
            CalcUniTireForces(std::get<UniTireParams<double>>(ut.params), op).fy);
  // Every model: a positive slip angle pushes to the right, a positive slip ratio drives.
  for (const auto& path : {kTir, kBrush, kUniTire}) {
    const TyreForces<double> f = CalcTyreForces(LoadTyreForceModel(path), op);
    EXPECT_LT(f.fy, 0.0) << path;
    EXPECT_GT(f.fx, 0.0) << path;
  }
}

TEST(TyreForceModelTest, GripFactorScalesForcesAndAligningMomentOnly) {
  const TyreForces<double> f{100.0, -200.0, 3.0, -4.0, 5.0};
  const TyreForces<double> s = ApplyGripFactor(f, 0.9);
  EXPECT_DOUBLE_EQ(s.fx, 90.0);
  EXPECT_DOUBLE_EQ(s.fy, -180.0);
  EXPECT_DOUBLE_EQ(s.mz, 4.5);
  EXPECT_DOUBLE_EQ(s.mx, 3.0);
  EXPECT_DOUBLE_EQ(s.my, -4.0);
}

// g(T) h(wear) from the Gen-7 compound: off its optimum and worn, the forces drop by exactly that.
TEST(TyreForceModelTest, WithGripUsesTheCompoundsFactor) {
  const TyreCompound compound = LoadTyreCompound(test::Gen7Dir() / "tyres/compound.yaml");
  const TyreForceModel<double> model = LoadTyreForceModel(kTir);
  TyreOperatingPoint<double> op = Point();
  op.tread_temp = 330.0;
  const double factor = compound.GripFactor(330.0, 2.0);
  ASSERT_LT(factor, 0.99);
  const TyreForces<double> plain = CalcTyreForces(model, op);
  const TyreForces<double> worn = CalcTyreForcesWithGrip(model, compound, op, 2.0);
  EXPECT_NEAR(worn.fy, factor * plain.fy, 1e-9 * std::abs(plain.fy));
  EXPECT_NEAR(worn.fx, factor * plain.fx, 1e-9 * std::abs(plain.fx));
}

// A cast model gives the same values, and derivatives with respect to the inputs.
TEST(TyreForceModelTest, CastModelsEvaluateOnJets) {
  for (const auto& path : {kTir, kBrush, kUniTire}) {
    const TyreForceModel<double> model = LoadTyreForceModel(path);
    const TyreForceModel<Jet2> jet_model = model.Cast<Jet2>();
    EXPECT_EQ(jet_model.kind(), model.kind());
    const TyreOperatingPoint<double> op = Point();
    TyreOperatingPoint<Jet2> opj{Jet2(op.fz),        Jet2(op.slip_ratio, 0), Jet2(op.slip_angle, 1),
                                 Jet2(op.camber),    Jet2(op.speed),         Jet2(op.pressure),
                                 Jet2(op.tread_temp)};
    const TyreForces<Jet2> fj = CalcTyreForces(jet_model, opj);
    const TyreForces<double> f = CalcTyreForces(model, op);
    EXPECT_NEAR(fj.fy.a, f.fy, 1e-9 * std::abs(f.fy)) << path;
    const double h = 1e-6;
    TyreOperatingPoint<double> up = op, down = op;
    up.slip_angle += h;
    down.slip_angle -= h;
    const double dfy = (CalcTyreForces(model, up).fy - CalcTyreForces(model, down).fy) / (2 * h);
    test::ExpectNearDerivative(fj.fy.v[1], dfy, std::abs(f.fy), path.string());
  }
}

TEST(TyreForceModelTest, BadFilesGiveClearErrors) {
  const auto message = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const test::TempDir dir;
  EXPECT_TRUE(
      test::Contains(message([&] { LoadTyreForceModel(dir.path() / "none.tir"); }), "not found"));
  const auto txt = test::WriteTextFile(dir.path() / "tyre.txt", "x");
  EXPECT_TRUE(test::Contains(message([&] { LoadTyreForceModel(txt); }), "unknown tyre force file"));
  const auto no_model = test::WriteTextFile(dir.path() / "a.yaml", "name: a\n");
  EXPECT_TRUE(test::Contains(message([&] { LoadTyreForceModel(no_model); }), "'model'"));
  const auto other = test::WriteTextFile(dir.path() / "b.yaml", "name: b\nmodel: stock_car\n");
  EXPECT_TRUE(
      test::Contains(message([&] { LoadTyreForceModel(other); }), "allowed: brush, unitire"));
  EXPECT_TRUE(test::Contains(message([&] { LoadTyreForceModel(kTir, "unitire"); }),
                             "holds a 'mf' tyre model"));
}

}  // namespace
}  // namespace hotlap::tyre
