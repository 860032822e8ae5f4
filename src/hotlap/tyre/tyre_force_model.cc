#include "hotlap/tyre/tyre_force_model.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <stdexcept>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "hotlap/common/error.h"
#include "hotlap/tyre/tyre_force_params_io.h"

namespace hotlap::tyre {

namespace {

std::string Lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// The `model:` of a YAML file, read loosely (the model's own loader then reads it strictly).
std::string YamlModelKey(const std::filesystem::path& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path.string());
  } catch (const YAML::Exception& e) {
    throw InputError(fmt::format("{}: cannot read as YAML: {}", path.string(), e.what()));
  }
  if (!root.IsMap() || !root["model"] || !root["model"].IsScalar()) {
    throw InputError(fmt::format(
        "{}: field 'model' is missing; a tyre force file says `model: brush` or `model: unitire` "
        "(Magic Formula models are .tir files)",
        path.string()));
  }
  return root["model"].as<std::string>();
}

}  // namespace

template <Scalar T>
std::string_view TyreForceModel<T>::kind() const {
  switch (params.index()) {
    case 0:
      return "mf";
    case 1:
      return "brush";
    default:
      return "unitire";
  }
}

TyreForceModel<double> LoadTyreForceModel(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path)) {
    throw InputError(fmt::format("{}: tyre force file not found", path.string()));
  }
  const std::string ext = Lowercase(path.extension().string());
  if (ext == ".tir") {
    return {path.stem().string(), path,
            MagicFormulaModel<double>{LoadMagicFormula(path), MagicFormulaOptions{}}};
  }
  if (ext == ".yaml" || ext == ".yml") {
    const std::string model = YamlModelKey(path);
    if (model == "brush") {
      BrushParamsFile file = LoadBrushParams(path);
      return {file.name, path, file.params};
    }
    if (model == "unitire") {
      UniTireParamsFile file = LoadUniTireParams(path);
      return {file.name, path, file.params};
    }
    throw InputError(fmt::format(
        "{}: field 'model': '{}' is not a tyre force model; allowed: brush, unitire (Magic Formula "
        "models are .tir files)",
        path.string(), model));
  }
  throw InputError(fmt::format(
      "{}: unknown tyre force file type '{}'; expected a Magic Formula .tir or a .yaml file",
      path.string(), ext));
}

TyreForceModel<double> LoadTyreForceModel(const std::filesystem::path& path,
                                          std::string_view expected_kind) {
  TyreForceModel<double> model = LoadTyreForceModel(path);
  if (model.kind() != expected_kind) {
    throw InputError(fmt::format("{}: holds a '{}' tyre model, but '{}' was asked for",
                                 path.string(), model.kind(), expected_kind));
  }
  return model;
}

template <Scalar T>
TyreForces<T> CalcTyreForces(const TyreForceModel<T>& model, const TyreOperatingPoint<T>& op) {
  return std::visit(
      [&](const auto& p) -> TyreForces<T> {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, MagicFormulaModel<T>>) {
          return CalcMagicFormula(p.params, op, p.options);
        } else if constexpr (std::is_same_v<P, BrushParams<T>>) {
          return CalcBrushForces(p, op);
        } else {
          return CalcUniTireForces(p, op);
        }
      },
      model.params);
}

void CalcTyreForcesBatch(const TyreForceModel<double>& model,
                         std::span<const TyreOperatingPoint<double>> points,
                         std::span<TyreForces<double>> out) {
  if (const auto* mf = std::get_if<MagicFormulaModel<double>>(&model.params)) {
    CalcMagicFormulaBatch(mf->params, points, mf->options, out);
    return;
  }
  if (out.size() != points.size()) {
    throw std::invalid_argument(fmt::format(
        "CalcTyreForcesBatch: {} points but room for {} results", points.size(), out.size()));
  }
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = CalcTyreForces(model, points[i]);
}

#define HOTLAP_INSTANTIATE_TYRE_FORCE_MODEL(T) \
  template struct TyreForceModel<T>;           \
  template TyreForces<T> CalcTyreForces<T>(const TyreForceModel<T>&, const TyreOperatingPoint<T>&);
HOTLAP_FOR_EACH_SCALAR(HOTLAP_INSTANTIATE_TYRE_FORCE_MODEL)
// The optimal-control tyre element's scalar: tyre forces over (Fz, kappa, alpha).
HOTLAP_INSTANTIATE_TYRE_FORCE_MODEL(::hotlap::SecondOrder<3>)

}  // namespace hotlap::tyre
