// The fall-off cache: a round trip bit for bit, another key or a damaged file read as nothing, a
// folder that cannot be made refused with its name, and the car's key telling its files and
// overrides apart.

#include "hotlap/race/fall_off_cache.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/vehicle/car.h"
#include "test_util.h"

namespace hotlap::race {
namespace {

namespace fs = std::filesystem;

FallOff Example() {
  FallOff f;
  f.lap_time_s = {31.2, 30.1 + 1e-13, 30.123456789012345};
  f.heat_only_lap_time_s = {31.2, 30.1, 30.1};
  f.fuel_s_per_kg = 0.0043999999999999997;
  f.reference_fuel_kg = 25.0;
  f.restart_penalty_s = 3.5731234567;
  f.set_laps.resize(3);
  f.set_laps[1].tread_temp = {350.1, 360.2, 351.3, 362.4};
  f.set_laps[2].wear_mm = {0.1, 0.2, 0.3, 1.0 / 3.0};
  f.set_laps[2].pressure = {170e3, 400e3, 190e3, 370e3};
  f.right_stop_after_laps = {1, 3};
  f.right_stop_lap_time_s = {{31.5, 30.2, 30.3}, {31.6, 30.4, 30.5}};
  return f;
}

class FallOffCacheTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("hotlap_cache_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(FallOffCacheTest, WhatIsWrittenIsReadBackBitForBitUnderItsKeyOnly) {
  const FallOff f = Example();
  SideStopCheck check{.before = 2,
                      .after = 3,
                      .driven_s = {1.0 / 3.0, 2, 3},
                      .fall_off_s = {1, 2, 3.25},
                      .max_abs_difference_s = 0.25,
                      .mean_difference_s = -1e-17};
  const fs::path file = FallOffCacheFile(dir_ / "nested", "the key\nwith a line end");
  WriteCachedFallOff(file, "the key\nwith a line end", f, check);
  std::optional<SideStopCheck> back_check;
  const std::optional<FallOff> back =
      ReadCachedFallOff(file, "the key\nwith a line end", &back_check);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->lap_time_s, f.lap_time_s);
  EXPECT_EQ(back->heat_only_lap_time_s, f.heat_only_lap_time_s);
  EXPECT_EQ(back->fuel_s_per_kg, f.fuel_s_per_kg);
  EXPECT_EQ(back->reference_fuel_kg, f.reference_fuel_kg);
  EXPECT_EQ(back->restart_penalty_s, f.restart_penalty_s);
  ASSERT_EQ(back->set_laps.size(), 3u);
  EXPECT_EQ(back->set_laps[1].tread_temp, f.set_laps[1].tread_temp);
  EXPECT_EQ(back->set_laps[2].wear_mm, f.set_laps[2].wear_mm);
  EXPECT_EQ(back->set_laps[2].pressure, f.set_laps[2].pressure);
  EXPECT_EQ(back->right_stop_after_laps, f.right_stop_after_laps);
  EXPECT_EQ(back->right_stop_lap_time_s, f.right_stop_lap_time_s);
  ASSERT_TRUE(back_check.has_value());
  EXPECT_EQ(back_check->driven_s, check.driven_s);
  EXPECT_EQ(back_check->fall_off_s, check.fall_off_s);
  EXPECT_EQ(back_check->mean_difference_s, check.mean_difference_s);
  // Another key, even one that hashes to the same file, is not this fall-off.
  EXPECT_FALSE(ReadCachedFallOff(file, "another key").has_value());
  EXPECT_NE(FallOffCacheFile(dir_, "a"), FallOffCacheFile(dir_, "b"));
  // Written without a check: read back without one.
  WriteCachedFallOff(file, "k", f);
  back_check = check;
  ASSERT_TRUE(ReadCachedFallOff(file, "k", &back_check).has_value());
  EXPECT_FALSE(back_check.has_value());
}

TEST_F(FallOffCacheTest, AMissingOrDamagedFileIsReadAsNothing) {
  const fs::path file = FallOffCacheFile(dir_, "k");
  EXPECT_FALSE(ReadCachedFallOff(file, "k").has_value());
  WriteCachedFallOff(file, "k", Example());
  std::string text;
  {
    std::ifstream in(file);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  for (size_t cut : {text.size() / 2, text.size() - 4}) {
    std::ofstream(file, std::ios::trunc) << text.substr(0, cut);
    EXPECT_FALSE(ReadCachedFallOff(file, "k").has_value()) << cut;
  }
  std::ofstream(file, std::ios::trunc)
      << text.substr(0, text.find("lap_time_s")) << "lap_time_s 3 1 x 3\n";
  EXPECT_FALSE(ReadCachedFallOff(file, "k").has_value());
}

TEST_F(FallOffCacheTest, AFolderThatCannotBeMadeIsRefusedByName) {
  fs::create_directories(dir_);
  std::ofstream(dir_ / "plain") << "a file, not a folder";
  try {
    WriteCachedFallOff(dir_ / "plain" / "sub" / "x.txt", "k", Example());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("plain"), std::string::npos) << e.what();
  }
}

TEST_F(FallOffCacheTest, TheCarsKeyChangesWithAFileByteOrAnOverride) {
  fs::create_directories(dir_);
  fs::copy(test::Gen7Dir(), dir_ / "car", fs::copy_options::recursive);
  const vehicle::Car car = vehicle::LoadCar(dir_ / "car" / "car.yaml");
  const std::string key = CarFilesKey(car);
  EXPECT_EQ(CarFilesKey(vehicle::LoadCar(dir_ / "car" / "car.yaml")), key);
  EXPECT_NE(CarFilesKey(vehicle::LoadCar(dir_ / "car" / "car.yaml",
                                         {{.key = "chassis.mass_kg", .value = 1600.0}})),
            key);
  std::ofstream(dir_ / "car" / "tyres" / "compound.yaml", std::ios::app) << "# a comment\n";
  EXPECT_NE(CarFilesKey(vehicle::LoadCar(dir_ / "car" / "car.yaml")), key);
  vehicle::Car in_code = car;
  in_code.path.clear();
  EXPECT_NE(CarFilesKey(in_code).find("no files"), std::string::npos);
}

}  // namespace
}  // namespace hotlap::race
