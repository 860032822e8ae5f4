#include "hotlap/tyre/tyre_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/telemetry_limits.h"
#include "hotlap/common/units.h"

namespace hotlap::tyre {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr size_t kMaxPoints = 2'000'000;

bool IsFinite(const TyreForces<double>& f) {
  for (double x : {f.fx, f.fy, f.mz, f.mx, f.my}) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

void CheckFinite(const TyreForces<double>& f, const std::vector<double>& values) {
  if (!IsFinite(f)) {
    throw NumericalError(fmt::format("the tyre model gave a non-finite force at inputs {}",
                                     fmt::join(values, ", ")));
  }
}

void CheckCount(const std::vector<double>& values) {
  if (values.size() != OperatingPointInputs().size()) {
    throw InputError(fmt::format("a tyre operating point has {} inputs, not {}",
                                 OperatingPointInputs().size(), values.size()));
  }
}

}  // namespace

const std::vector<OperatingPointInput>& OperatingPointInputs() {
  using Op = TyreOperatingPoint<double>;
  static const std::vector<OperatingPointInput> v = {
      {"fz-N", "fz_N", &Op::fz, 1.0, 0.0},
      {"slip-angle-deg", "slip_angle_deg", &Op::slip_angle, kDeg, 0.0},
      {"slip-ratio", "slip_ratio", &Op::slip_ratio, 1.0, 0.0},
      {"camber-deg", "camber_deg", &Op::camber, kDeg, 0.0},
      {"speed-mps", "speed_mps", &Op::speed, 1.0, 0.0},
      {"pressure-kPa", "pressure_kPa", &Op::pressure, 1e3, 0.0},
      {"tread-temp-C", "tread_temp_C", &Op::tread_temp, 1.0, kZeroCelsius},
  };
  return v;
}

std::vector<double> DefaultOperatingPointValues() {
  return {4000.0, 0.0, 0.0, 0.0, 20.0, 0.0, 25.0};
}

void CheckOperatingPoint(const TyreOperatingPoint<double>& op, std::string_view where) {
  for (const OperatingPointInput& input : OperatingPointInputs()) {
    if (!std::isfinite(op.*input.field)) {
      throw InputError(fmt::format("{}{} is not a finite number", where, input.column));
    }
  }
  if (op.pressure < 0.0) {
    throw InputError(
        fmt::format("{}pressure_kPa = {:g}: a pressure is not negative (0: the "
                    "model's nominal pressure)",
                    where, op.pressure / 1e3));
  }
  // The telemetry readers' limits (common/telemetry_limits.h), and strictly above 0 K.
  if (!(op.tread_temp > 0.0) || IsRefused("tread_temp", op.tread_temp)) {
    throw InputError(
        fmt::format("{}tread_temp_C = {:g}: a tread is above absolute zero "
                    "(-273.15 degC) and below 2000 degC",
                    where, op.tread_temp - kZeroCelsius));
  }
  if (IsRefused("slip_angle", op.slip_angle)) {
    throw InputError(fmt::format("{}slip_angle_deg = {:g}: a slip angle is within +-90 deg", where,
                                 op.slip_angle / kDeg));
  }
}

TyreOperatingPoint<double> OperatingPointFrom(const std::vector<double>& values) {
  CheckCount(values);
  TyreOperatingPoint<double> op;
  const auto& inputs = OperatingPointInputs();
  for (size_t i = 0; i < inputs.size(); ++i) {
    op.*inputs[i].field = values[i] * inputs[i].scale + inputs[i].shift;
  }
  CheckOperatingPoint(op, "tyre operating point: ");
  return op;
}

GridAxis ParseGridAxis(const std::string& text) {
  const auto fail = [&](const std::string& why) -> GridAxis {
    std::vector<std::string> names;
    for (const OperatingPointInput& v : OperatingPointInputs()) names.push_back(v.name);
    throw InputError(fmt::format("sweep '{}': {}; write NAME=FROM:TO:STEP with NAME one of {}",
                                 text, why, fmt::join(names, ", ")));
  };
  const size_t eq = text.find('=');
  if (eq == std::string::npos) return fail("no '='");
  const std::string name = text.substr(0, eq);
  const auto& inputs = OperatingPointInputs();
  const auto it = std::find_if(inputs.begin(), inputs.end(),
                               [&](const OperatingPointInput& v) { return name == v.name; });
  if (it == inputs.end()) return fail("unknown input '" + name + "'");
  double from = 0, to = 0, step = 0;
  char tail = 0;
  if (std::sscanf(text.c_str() + eq + 1, "%lf:%lf:%lf%c", &from, &to, &step, &tail) != 3) {
    return fail("the range is not FROM:TO:STEP");
  }
  if (!(std::isfinite(from) && std::isfinite(to) && step > 0.0)) {
    return fail("FROM and TO must be finite and STEP > 0");
  }
  const double count = std::floor((to - from) / step + 1e-9) + 1.0;
  if (!(count >= 1.0)) return fail("TO is below FROM");
  if (count > 1e6) return fail("more than a million points");
  GridAxis axis;
  axis.input = static_cast<size_t>(it - inputs.begin());
  for (int i = 0; i < static_cast<int>(count); ++i) axis.values.push_back(from + i * step);
  return axis;
}

TyreForces<double> EvaluateTyrePoint(const TyreForceModel<double>& model,
                                     const TyreCompound* compound, double wear_mm,
                                     const std::vector<double>& values) {
  CheckCount(values);
  if (!(values[0] > 0.0))
    throw InputError(fmt::format("the load must be > 0 N, got {:g}", values[0]));
  const TyreOperatingPoint<double> op = OperatingPointFrom(values);
  const TyreForces<double> f =
      compound ? CalcTyreForcesWithGrip(model, *compound, op, wear_mm) : CalcTyreForces(model, op);
  CheckFinite(f, values);
  return f;
}

TyreGrid EvaluateTyreGrid(const TyreForceModel<double>& model, const TyreCompound* compound,
                          double wear_mm, const std::vector<double>& base,
                          const std::vector<GridAxis>& axes) {
  CheckCount(base);
  if (axes.empty() || axes.size() > 3) {
    throw InputError(fmt::format("a tyre grid sweeps one to three inputs, not {}", axes.size()));
  }
  size_t total = 1;
  for (size_t a = 0; a < axes.size(); ++a) {
    if (axes[a].input >= base.size() || axes[a].values.empty()) {
      throw InputError(fmt::format("sweep {} has no input or no values", a + 1));
    }
    for (size_t b = 0; b < a; ++b) {
      if (axes[b].input == axes[a].input) {
        throw InputError(fmt::format("sweep of '{}' repeats an input",
                                     OperatingPointInputs()[axes[a].input].name));
      }
    }
    total *= axes[a].values.size();
  }
  if (total > kMaxPoints) throw InputError(fmt::format("the sweep has {} points (max 2e6)", total));

  TyreGrid grid;
  for (const OperatingPointInput& v : OperatingPointInputs()) grid.names.push_back(v.column);
  for (const char* n : {"fx_N", "fy_N", "mz_Nm", "mx_Nm", "my_Nm"}) grid.names.push_back(n);
  grid.columns.resize(grid.names.size());
  std::vector<double> values = base;
  const size_t k = values.size();
  // Through the batch API in blocks (a Magic Formula evaluates several points per call, with the
  // same results as one by one).
  constexpr size_t kBlock = 1024;
  std::vector<TyreOperatingPoint<double>> ops;
  std::vector<TyreForces<double>> forces;
  bool load_error = false;
  for (size_t first = 0; first < total && !load_error; first += kBlock) {
    ops.clear();
    for (size_t n = first; n < std::min(total, first + kBlock); ++n) {
      size_t rest = n;  // the last axis varies fastest
      for (size_t j = axes.size(); j-- > 0;) {
        values[axes[j].input] = axes[j].values[rest % axes[j].values.size()];
        rest /= axes[j].values.size();
      }
      // (Reported after the points before it, as when evaluating one by one.)
      if (!(values[0] > 0.0)) {
        load_error = true;
        break;
      }
      for (size_t i = 0; i < k; ++i) grid.columns[i].push_back(values[i]);
      ops.push_back(OperatingPointFrom(values));
    }
    forces.resize(ops.size());
    CalcTyreForcesBatch(model, ops, forces);
    for (size_t j = 0; j < ops.size(); ++j) {
      TyreForces<double> f = forces[j];
      if (compound) f = ApplyGripFactor(f, compound->GripFactor(ops[j].tread_temp, wear_mm));
      if (!IsFinite(f)) {
        std::vector<double> point(k);
        for (size_t i = 0; i < k; ++i) point[i] = grid.columns[i][first + j];
        CheckFinite(f, point);
      }
      grid.columns[k].push_back(f.fx);
      grid.columns[k + 1].push_back(f.fy);
      grid.columns[k + 2].push_back(f.mz);
      grid.columns[k + 3].push_back(f.mx);
      grid.columns[k + 4].push_back(f.my);
      grid.peak_abs_fx = std::max(grid.peak_abs_fx, std::abs(f.fx));
      grid.peak_abs_fy = std::max(grid.peak_abs_fy, std::abs(f.fy));
      grid.peak_abs_mz = std::max(grid.peak_abs_mz, std::abs(f.mz));
    }
  }
  if (load_error) throw InputError("the sweep reaches a load <= 0 N");
  grid.points = total;
  return grid;
}

}  // namespace hotlap::tyre
