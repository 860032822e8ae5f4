#pragma once
/// @file
/// One tyre force model chosen at load time (Magic Formula, brush or UniTire), and the thermal and
/// wear correction g(T_tread) h(wear) of spec section 4 applied to whichever it is.
///
/// How to use:
///
///   const tyre::TyreForceModel<double> model = tyre::LoadTyreForceModel("front.tir");
///   const tyre::TyreForces<double> f = tyre::CalcTyreForces(model, op);
///   // With the compound's grip: forces scaled by g(T_t) h(wear).
///   const auto fc = tyre::CalcTyreForcesWithGrip(model, compound, op, wear_mm);
///
/// The file decides the model: a `.tir` file is a Magic Formula, a YAML file names its model in
/// `model:` (`brush` or `unitire`). The choice is a std::variant, so evaluating it is a visit,
/// never a virtual call, and every alternative is templated on the scalar (cast a loaded model
/// with `Cast<Jet>()` to differentiate with respect to its parameters).

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "hotlap/common/scalar.h"
#include "hotlap/tyre/brush_model.h"
#include "hotlap/tyre/compound.h"
#include "hotlap/tyre/magic_formula.h"
#include "hotlap/tyre/tyre_force.h"
#include "hotlap/tyre/unitire.h"

namespace hotlap::tyre {

/// A Magic Formula model: its coefficients and how to evaluate them.
template <Scalar T>
struct MagicFormulaModel {
  MagicFormulaParams<T> params;
  MagicFormulaOptions options;
};

/// Which model and its parameters.
template <Scalar T>
using TyreForceParams = std::variant<MagicFormulaModel<T>, BrushParams<T>, UniTireParams<T>>;

/// A tyre force model as loaded from one file.
template <Scalar T>
struct TyreForceModel {
  std::string name;  ///< the file's name (YAML `name:`; a .tir's file name without extension)
  std::filesystem::path path;  ///< where it was loaded from
  TyreForceParams<T> params;

  /// "mf", "brush" or "unitire".
  std::string_view kind() const;

  /// The same model in another scalar type (derivative parts start at zero).
  template <Scalar U>
  TyreForceModel<U> Cast() const {
    TyreForceModel<U> out{name, path, {}};
    std::visit(
        [&](const auto& p) {
          using P = std::decay_t<decltype(p)>;
          if constexpr (std::is_same_v<P, MagicFormulaModel<T>>) {
            out.params = MagicFormulaModel<U>{p.params.template Cast<U>(), p.options};
          } else {
            out.params = p.template Cast<U>();
          }
        },
        params);
    return out;
  }
};

/// Loads `path`: `.tir` as a Magic Formula (evaluated as mfeval's useMode 111), `.yaml`/`.yml`
/// by its `model:` key. InputError naming the file for anything else, and as the loaders.
TyreForceModel<double> LoadTyreForceModel(const std::filesystem::path& path);

/// As above, and InputError unless the file holds `expected_kind` ("mf", "brush", "unitire").
TyreForceModel<double> LoadTyreForceModel(const std::filesystem::path& path,
                                          std::string_view expected_kind);

/// Steady-state forces and moments of whichever model at `op`.
template <Scalar T>
TyreForces<T> CalcTyreForces(const TyreForceModel<T>& model, const TyreOperatingPoint<T>& op);

/// CalcTyreForces(model, points[i]) into out[i] for every i, for doubles: a Magic Formula
/// evaluates several points at once (CalcMagicFormulaBatch, the same results bit for bit), the
/// other models one by one. std::invalid_argument unless `out` has the size of `points`.
void CalcTyreForcesBatch(const TyreForceModel<double>& model,
                         std::span<const TyreOperatingPoint<double>> points,
                         std::span<TyreForces<double>> out);

/// The correction of spec section 4 (000:35-36 as corrected): Fx, Fy and Mz multiplied by
/// `grip_factor` = g(T_t) h(wear). Mz is scaled with Fy because it is Fy times the pneumatic trail;
/// Mx and My (load-driven overturning and rolling resistance) are left as they are.
template <Scalar T>
TyreForces<T> ApplyGripFactor(const TyreForces<T>& forces, const T& grip_factor) {
  TyreForces<T> out = forces;
  out.fx = forces.fx * grip_factor;
  out.fy = forces.fy * grip_factor;
  out.mz = forces.mz * grip_factor;
  return out;
}

/// CalcTyreForces scaled by the compound's g(op.tread_temp) h(wear_mm). The temperature-dependent
/// models (brush, UniTire) also see op.tread_temp themselves; set the compound's grip cubic flat
/// or use CalcTyreForces if their own temperature factors should be the only ones.
template <Scalar T>
TyreForces<T> CalcTyreForcesWithGrip(const TyreForceModel<T>& model, const TyreCompound& compound,
                                     const TyreOperatingPoint<T>& op, const T& wear_mm) {
  return ApplyGripFactor(CalcTyreForces(model, op), compound.GripFactor(op.tread_temp, wear_mm));
}

}  // namespace hotlap::tyre
