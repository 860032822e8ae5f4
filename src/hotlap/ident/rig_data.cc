#include "hotlap/ident/rig_data.h"

#include <cmath>
#include <map>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/error.h"
#include "hotlap/common/string_match.h"
#include "hotlap/common/telemetry_limits.h"
#include "hotlap/common/units.h"

namespace hotlap::ident {

namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

// A rig column: quantity, its accepted units and their conversions to SI (value * scale + shift).
struct UnitConversion {
  const char* unit;  // "" for dimensionless (no suffix)
  double scale;
  double shift;
};
struct RigColumn {
  const char* quantity;
  bool required;
  std::vector<UnitConversion> units;  // canonical first
};

const std::vector<RigColumn>& RigColumns() {
  static const std::vector<RigColumn> columns = {
      {"slip_angle", true, {{"deg", kDegToRad, 0.0}, {"rad", 1.0, 0.0}}},
      {"fz", true, {{"N", 1.0, 0.0}, {"kN", 1e3, 0.0}}},
      {"fy", true, {{"N", 1.0, 0.0}, {"kN", 1e3, 0.0}}},
      {"mz", true, {{"Nm", 1.0, 0.0}, {"kNm", 1e3, 0.0}}},
      {"tread_temp", true, {{"C", 1.0, kZeroCelsius}, {"K", 1.0, 0.0}}},
      {"slip_ratio", false, {{"", 1.0, 0.0}}},
      {"fx", false, {{"N", 1.0, 0.0}, {"kN", 1e3, 0.0}}},
      {"camber", false, {{"deg", kDegToRad, 0.0}, {"rad", 1.0, 0.0}}},
      {"speed", false, {{"mps", 1.0, 0.0}, {"kph", 1.0 / 3.6, 0.0}}},
  };
  return columns;
}

std::string ColumnName(const RigColumn& c, const UnitConversion& u) {
  return u.unit[0] == '\0' ? std::string(c.quantity) : fmt::format("{}_{}", c.quantity, u.unit);
}

}  // namespace

std::vector<RigSample> ReadRigCsv(const std::filesystem::path& path) {
  const CsvTable table = ReadCsv(path);
  const std::string file = path.string();

  // Match every column of the file to a rig quantity and unit.
  std::vector<std::string> known_names;
  for (const RigColumn& c : RigColumns()) {
    for (const UnitConversion& u : c.units) known_names.push_back(ColumnName(c, u));
  }
  std::map<std::string, std::pair<int, const UnitConversion*>> found;  // quantity -> column
  for (size_t i = 0; i < table.columns.size(); ++i) {
    const std::string& name = table.columns[i];
    bool matched = false;
    for (const RigColumn& c : RigColumns()) {
      for (const UnitConversion& u : c.units) {
        if (name != ColumnName(c, u)) continue;
        if (found.count(c.quantity) != 0) {
          throw InputError(fmt::format("{}: columns '{}' and '{}' are both {}", file,
                                       table.columns[found[c.quantity].first], name, c.quantity));
        }
        found[c.quantity] = {static_cast<int>(i), &u};
        matched = true;
      }
    }
    if (!matched) {
      const std::vector<std::string> close = ClosestNames(name, known_names);
      throw InputError(
          fmt::format("{}: unknown rig column '{}'{}; rig columns are {}", file, name,
                      close.empty() ? "" : " (did you mean " + QuotedList(close) + "?)",
                      QuotedList(known_names)));
    }
  }
  for (const RigColumn& c : RigColumns()) {
    if (c.required && found.count(c.quantity) == 0) {
      throw InputError(fmt::format("{}: required rig column '{}' is missing (units: {})", file,
                                   ColumnName(c, c.units.front()), c.quantity));
    }
  }

  const size_t rows = table.RowCount();
  // The SI value of `quantity` in `row`, or nullopt if that column is absent or the cell empty.
  const auto value = [&](const char* quantity, size_t row) -> std::optional<double> {
    const auto it = found.find(quantity);
    if (it == found.end()) return std::nullopt;
    const double v = table.values[it->second.first][row];
    if (std::isnan(v)) return std::nullopt;
    return v * it->second.second->scale + it->second.second->shift;
  };
  const auto required = [&](const char* quantity, size_t row) {
    const std::optional<double> v = value(quantity, row);
    if (!v) {
      throw InputError(fmt::format("{}:{}: column '{}' is empty; every rig row needs it", file,
                                   table.line_numbers[row],
                                   table.columns[found.at(quantity).first]));
    }
    return *v;
  };
  std::vector<RigSample> samples(rows);
  for (size_t r = 0; r < rows; ++r) {
    RigSample& s = samples[r];
    s.slip_angle = required("slip_angle", r);
    s.fz = required("fz", r);
    s.fy = required("fy", r);
    s.mz = required("mz", r);
    s.tread_temp = required("tread_temp", r);
    s.slip_ratio = value("slip_ratio", r).value_or(0.0);
    s.camber = value("camber", r).value_or(0.0);
    s.speed = value("speed", r).value_or(kRigSpeed);
    s.fx = value("fx", r);
    // Physically impossible values (telemetry_limits.h), as a log's are refused.
    for (const auto& [quantity, v] : {std::pair<const char*, double>{"slip_angle", s.slip_angle},
                                      {"fz", s.fz},
                                      {"tread_temp", s.tread_temp},
                                      {"slip_ratio", s.slip_ratio},
                                      {"speed", s.speed}}) {
      const auto column = found.find(quantity);
      if (column != found.end() && IsRefused(quantity, v)) {
        const UnitConversion& u = *column->second.second;
        throw InputError(fmt::format("{}:{}: '{}' is {:g}{}{}: impossible ({})", file,
                                     table.line_numbers[r], table.columns[column->second.first],
                                     (v - u.shift) / u.scale, u.unit[0] == '\0' ? "" : " ", u.unit,
                                     LimitsOf(quantity)->reason));
      }
    }
    if (!(s.fz > 0.0)) {
      throw InputError(fmt::format("{}:{}: column '{}': load {:g} N must be > 0", file,
                                   table.line_numbers[r], table.columns[found.at("fz").first],
                                   s.fz));
    }
    if (!(s.tread_temp > 0.0)) {
      throw InputError(fmt::format("{}:{}: tread temperature {:g} K is below absolute zero", file,
                                   table.line_numbers[r], s.tread_temp));
    }
  }
  return samples;
}

void WriteRigCsv(const std::filesystem::path& path,
                 const std::vector<std::pair<std::string, std::string>>& metadata,
                 const std::vector<RigSample>& samples) {
  bool has_fx = false;
  for (const RigSample& s : samples) has_fx = has_fx || s.fx.has_value();
  std::vector<std::string> names = {"slip_angle_deg", "slip_ratio",   "camber_deg", "speed_mps",
                                    "fz_N",           "tread_temp_C", "fy_N",       "mz_Nm"};
  if (has_fx) names.push_back("fx_N");
  std::vector<std::vector<double>> values(names.size());
  for (const RigSample& s : samples) {
    values[0].push_back(s.slip_angle / kDegToRad);
    values[1].push_back(s.slip_ratio);
    values[2].push_back(s.camber / kDegToRad);
    values[3].push_back(s.speed);
    values[4].push_back(s.fz);
    values[5].push_back(s.tread_temp - kZeroCelsius);
    values[6].push_back(s.fy);
    values[7].push_back(s.mz);
    if (has_fx) values[8].push_back(s.fx.value_or(std::nan("")));
  }
  WriteCsv(path, metadata, names, values);
}

}  // namespace hotlap::ident
