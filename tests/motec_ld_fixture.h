#pragma once
/// @file
/// The MoTeC .ld twin of tests/data/motec/darlington_i2.csv, written by the library's .ld writer
/// into a test's folder: the same channels with the same names and units, each stored with its
/// own type, rate and scaling, and the export's Beacon Markers in a companion .ldx. The numbers
/// are the export's to within float32 precision (forces) and exactly (the integer channels, whose
/// scalings hold the export's decimals); the constant temperatures are logged at 1 and 2 Hz.

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "hotlap/logs/motec_channel_map.h"
#include "hotlap/logs/motec_csv.h"
#include "hotlap/logs/motec_ld_writer.h"
#include "test_util.h"

namespace hotlap::test {

/// Writes `dir`/darlington.ld and `dir`/darlington.ldx; returns the .ld path.
inline std::filesystem::path WriteDarlingtonLd(const std::filesystem::path& dir) {
  const std::filesystem::path csv = SourcePath("tests/data/motec/darlington_i2.csv");
  // An empty map: every channel as logged, in its own unit.
  const MotecTable export_table = ReadMotecCsv(csv, MotecChannelMap{});
  const CsvTable& t = export_table.table;
  std::vector<LdChannel> channels;
  std::string beacons;
  for (const auto& [key, value] : t.metadata) {
    if (key == "Beacon Markers") beacons = value;
  }
  for (size_t c = 1; c < export_table.channels.size(); ++c) {  // 0 is Time
    const MotecSourceChannel& source = export_table.channels[c];
    LdChannel ch;
    ch.name = source.name;
    ch.unit = source.unit;
    ch.rate_hz = 10;
    ch.type = LdDataType::kInt32;
    const std::string& n = ch.name;
    if (n == "Distance") {
      ch.scaling = {0, 1, 1, 2};
    } else if (n == "Ground Speed") {
      ch.scaling = {0, 1, 1, 3};
    } else if (n == "Air Temp" || n == "Track Temp") {
      ch.type = LdDataType::kInt16;
      ch.scaling = {0, 1, 1, 1};
      ch.rate_hz = 1;
    } else if (n.rfind("Brake Temp", 0) == 0) {
      ch.type = LdDataType::kInt16;
      ch.scaling = {0, 1, 1, 1};
      ch.rate_hz = 2;
    } else if (n.rfind("Tyre Force", 0) == 0) {
      ch.type = LdDataType::kFloat32;
      ch.scaling = {0, 10, 1, 0};
    } else if (n.rfind("Tyre Load", 0) == 0) {
      ch.scaling = {0, 1, 1, 4};
    } else if (n.rfind("Slip Angle", 0) == 0) {
      ch.scaling = {0, 1, 2, 4};
    } else if (n.rfind("Slip Ratio", 0) == 0) {
      ch.scaling = {0, 1, 1, 5};
    } else if (n == "G Force Lat") {
      ch.type = LdDataType::kFloat16;
    } else if (n == "Engine RPM") {
      ch.type = LdDataType::kInt16;
      ch.scaling = {4000, 2, 1, 0};
    }
    const size_t step = 10 / static_cast<size_t>(ch.rate_hz);  // the export is at 10 Hz
    for (size_t i = 0; i < t.values[c].size(); i += step) ch.values.push_back(t.values[c][i]);
    channels.push_back(std::move(ch));
  }
  LdMetadata m;
  m.venue = "Darlington";
  m.vehicle = "Gen7 #48";
  m.driver = "A. Driver";
  m.session = "Practice 1";
  m.date = "14/03/2026";
  m.time = "10:32:05";
  m.device_type = "M150";
  const std::filesystem::path ld = dir / "darlington.ld";
  WriteMotecLd(ld, m, channels);

  std::ostringstream ldx;
  ldx << "<?xml version=\"1.0\"?>\n<LDXFile Version=\"1.6\">\n <Layers>\n  <Layer>\n"
         "   <MarkerBlock>\n    <MarkerGroup Name=\"Beacons\" Index=\"3\">\n";
  std::istringstream times(beacons);
  double t_s = 0.0;
  while (times >> t_s) {
    ldx << "     <Marker Version=\"100\" ClassName=\"BCN\" Time=\"" << std::llround(t_s * 1e6)
        << "\"/>\n";
  }
  ldx << "    </MarkerGroup>\n   </MarkerBlock>\n  </Layer>\n </Layers>\n</LDXFile>\n";
  WriteTextFile(dir / "darlington.ldx", ldx.str());
  return ld;
}

}  // namespace hotlap::test
