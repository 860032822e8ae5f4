#pragma once
/// @file
/// A tyre force model evaluated at one operating point or over a grid of up to three swept
/// inputs, with the inputs in the units files and command lines use (newtons, degrees, kPa,
/// degC): what `hotlap tyre eval` prints and writes, as a library call.
///
///   const tyre::TyreGrid g = tyre::EvaluateTyreGrid(
///       model, nullptr, 0.0, tyre::DefaultOperatingPointValues(),
///       {tyre::ParseGridAxis("slip-angle-deg=-10:10:0.5")});
///   // g.columns[k][i]: column g.names[k] at grid point i.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "hotlap/tyre/compound.h"
#include "hotlap/tyre/tyre_force_model.h"

namespace hotlap::tyre {

/// One input of the operating point as files and command lines name it, with its conversion to
/// SI: SI = value * scale + shift.
struct OperatingPointInput {
  const char* name;    ///< option and sweep name, e.g. "slip-angle-deg"
  const char* column;  ///< CSV column and JSON key, e.g. "slip_angle_deg"
  double TyreOperatingPoint<double>::*field;
  double scale;
  double shift;
};

/// The operating point's inputs, in the order every value vector of this file uses: fz-N,
/// slip-angle-deg, slip-ratio, camber-deg, speed-mps, pressure-kPa, tread-temp-C.
const std::vector<OperatingPointInput>& OperatingPointInputs();

/// Values of every input in its own units (`hotlap tyre eval`'s defaults): 4000 N, 0 deg, 0, 0
/// deg, 20 m/s, 0 kPa (the model's nominal pressure), 25 degC.
std::vector<double> DefaultOperatingPointValues();

/// InputError, its message starting with `where`, for an operating point no tyre is at: a value
/// that is not finite, a pressure below 0 (0 is the model's nominal one), a tread temperature not
/// above absolute zero or above 2000 degC, a slip angle beyond +-90 deg (UniTire at -300 degC gave
/// half as much grip again as at 25 degC before this was checked).
void CheckOperatingPoint(const TyreOperatingPoint<double>& op, std::string_view where);

/// The operating point (SI) of values ordered as OperatingPointInputs(). InputError if the count
/// is wrong or the point is not physical (CheckOperatingPoint).
TyreOperatingPoint<double> OperatingPointFrom(const std::vector<double>& values);

/// One swept input: its index in OperatingPointInputs() and its values (own units).
struct GridAxis {
  size_t input = 0;
  std::vector<double> values;
};

/// "NAME=FROM:TO:STEP" (NAME an input's name, STEP > 0, FROM <= TO, at most a million values):
/// FROM, FROM + STEP, ... up to TO. InputError naming the text and what is wrong otherwise.
GridAxis ParseGridAxis(const std::string& text);

/// A grid's table: the inputs' columns, then fx_N, fy_N, mz_Nm, mx_Nm, my_Nm, one row per point,
/// the last axis varying fastest.
struct TyreGrid {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  size_t points = 0;
  double peak_abs_fx = 0.0;  ///< N
  double peak_abs_fy = 0.0;  ///< N
  double peak_abs_mz = 0.0;  ///< N m
};

/// The model's forces (times the compound's grip factor g(T_tread) h(wear) if `compound` is not
/// null) at `values` (ordered as OperatingPointInputs()). InputError for a load <= 0 N or a wrong
/// count; NumericalError naming the inputs if a force is not finite.
TyreForces<double> EvaluateTyrePoint(const TyreForceModel<double>& model,
                                     const TyreCompound* compound, double wear_mm,
                                     const std::vector<double>& values);

/// The model over the grid of `axes` (one to three distinct inputs) about `base` (the other
/// inputs' values), through the model's batch evaluation. InputError for no axis or more than
/// three, a repeated input, more than two million points or a load <= 0 N; NumericalError naming
/// the inputs if a force is not finite.
TyreGrid EvaluateTyreGrid(const TyreForceModel<double>& model, const TyreCompound* compound,
                          double wear_mm, const std::vector<double>& base,
                          const std::vector<GridAxis>& axes);

}  // namespace hotlap::tyre
