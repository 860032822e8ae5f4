#include "hotlap/ident/fitted_car.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <map>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "hotlap/brake/brake_thermal_fields.h"
#include "hotlap/common/atomic_file.h"
#include "hotlap/common/error.h"
#include "hotlap/common/read_file.h"
#include "hotlap/ident/yaml_text_edit.h"
#include "hotlap/tyre/tyre_thermal_fields.h"

namespace hotlap::ident {

namespace fs = std::filesystem;

namespace {

void WriteText(const fs::path& path, const std::string& text, std::vector<fs::path>* written) {
  std::error_code ec;
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
  if (ec) {
    throw InputError(
        fmt::format("cannot create folder {}: {}", path.parent_path().string(), ec.message()));
  }
  WriteFileAtomically(path, [&](std::ostream& out) { out << text; });
  written->push_back(path);
}

// Copies `source` to `target` unless an identical copy is there (corners share files).
void CopyFile(const fs::path& source, const fs::path& target, std::vector<fs::path>* written) {
  const std::string text = ReadWholeFile(source);
  if (std::find(written->begin(), written->end(), target) != written->end()) return;
  WriteText(target, text, written);
}

// Names for the copies in one folder: the same source file gets the same name, different sources
// with the same file name get a numbered one.
class CopyNames {
 public:
  explicit CopyNames(std::vector<std::string> taken) : taken_(std::move(taken)) {}
  std::string For(const fs::path& source) {
    const std::string key = fs::weakly_canonical(source).string();
    if (auto it = by_source_.find(key); it != by_source_.end()) return it->second;
    std::string name = source.filename().string();
    for (int i = 2; std::find(taken_.begin(), taken_.end(), name) != taken_.end(); ++i) {
      name = fmt::format("{}-{}{}", source.stem().string(), i, source.extension().string());
    }
    taken_.push_back(name);
    by_source_[key] = name;
    return name;
  }

 private:
  std::vector<std::string> taken_;
  std::map<std::string, std::string> by_source_;
};

// The value of a fitted key ("section.key") as LoadCar read it back, in the file's unit (the
// fitted parameters are stored as the file gives them); NaN for a key no fit writes.
double TyreValue(const tyre::TyreThermalParams<double>& p, const std::string& key) {
  const tyre::TyreThermalField* f = tyre::FindTyreThermalField(key);
  return f && f->fit ? f->Of(p) : std::nan("");
}

double BrakeValue(const brake::BrakeThermalParams<double>& p, const std::string& key) {
  const brake::BrakeThermalField* f = brake::FindBrakeThermalField(key);
  return f && f->fit ? f->Of(p) : std::nan("");
}

void CheckReadBack(double read, const FileEdit& e, const fs::path& file) {
  const double written = std::stod(FormatFileNumber(e.value));
  if (!(std::abs(read - written) <= 1e-12 * std::max(1.0, std::abs(written)))) {
    throw NumericalError(fmt::format("fitted file {} reads back {} = {:g}, not the {:g} written",
                                     file.string(), e.key, read, written));
  }
}

}  // namespace

std::string SourceComment(const std::string& date, const std::string& log,
                          const ParameterEstimate& estimate) {
  const ParameterEstimate& e = estimate;
  if (e.undetermined) {
    return fmt::format("fitted {} to {}: undetermined by the data (kept where the fit left it)",
                       date, log);
  }
  std::string verdict;
  if (e.at_bound) verdict = "; at its bound";
  if (!e.well_determined && !e.at_bound) verdict = "; not well determined";
  return fmt::format("fitted {} to {}: std error {:.3g}, 95% [{:.5g}, {:.5g}]{}", date, log,
                     e.std_error, e.ci_low, e.ci_high, verdict);
}

std::vector<FileEdit> FileEditsOf(const FitResult& fit, const std::string& key_prefix,
                                  const std::string& date, const std::string& log) {
  std::vector<FileEdit> edits;
  for (size_t i = 0; i < fit.parameters.size(); ++i) {
    if (fit.parameters[i].role != ParameterRole::kModel) continue;
    edits.push_back({key_prefix + fit.parameters[i].key, fit.estimates[i].value,
                     SourceComment(date, log, fit.estimates[i])});
  }
  return edits;
}

std::string TodayIsoDate() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm local{};
  localtime_r(&now, &local);
  return fmt::format("{:04d}-{:02d}-{:02d}", local.tm_year + 1900, local.tm_mon + 1, local.tm_mday);
}

std::string FormatFileNumber(double value) { return fmt::format("{:.8g}", value); }

std::vector<fs::path> WriteFittedCar(const vehicle::Car& car, const fs::path& car_path,
                                     const FittedCarEdits& edits) {
  std::vector<fs::path> written;
  const std::string stem = car_path.stem().string();
  const fs::path parts = car_path.parent_path() / stem;
  const std::string car_text = ReadWholeFile(car.path);
  YamlTextEditor car_edit(car_text, car.path.string());
  CopyNames tyre_names({"fl.yaml", "fr.yaml", "rl.yaml", "rr.yaml"});

  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    const std::string corner(CornerName(c));
    // Tyre file: the fitted values, and its compound beside it.
    const tyre::TyreFile& t = car.tyres[i];
    YamlTextEditor tyre_edit(ReadWholeFile(t.path), t.path.string());
    const std::string compound = tyre_names.For(t.compound_path);
    tyre_edit.SetValue("compound", compound);
    for (const FileEdit& e : edits.tyres[i]) {
      tyre_edit.SetValue(e.key, FormatFileNumber(e.value), e.comment);
    }
    std::vector<std::string> header = edits.header;
    header.push_back(fmt::format("Based on {}.", fs::absolute(t.path).lexically_normal().string()));
    tyre_edit.PrependComments(header);
    WriteText(parts / "tyres" / (corner + ".yaml"), tyre_edit.Text(), &written);
    CopyFile(t.compound_path, parts / "tyres" / compound, &written);
    car_edit.SetValue("tyres." + corner, stem + "/tyres/" + corner + ".yaml");

    // Brake file, one per corner now that each corner has its own values.
    const brake::BrakeFile& b = car.brakes[i];
    YamlTextEditor brake_edit(ReadWholeFile(b.path), b.path.string());
    for (const FileEdit& e : edits.brakes[i]) {
      brake_edit.SetValue(e.key, FormatFileNumber(e.value), e.comment);
    }
    header = edits.header;
    header.push_back(fmt::format("Based on {}.", fs::absolute(b.path).lexically_normal().string()));
    brake_edit.PrependComments(header);
    WriteText(parts / "brakes" / (corner + ".yaml"), brake_edit.Text(), &written);
    car_edit.SetValue("brakes." + corner, stem + "/brakes/" + corner + ".yaml");
  }

  // The vehicle sections' files (tyre force models), copied beside the tyre files.
  const YAML::Node root = YAML::Load(car_text);
  if (root["tyre_forces"]) {
    for (Corner c : kAllCorners) {
      const std::string corner(CornerName(c));
      const YAML::Node file = root["tyre_forces"][corner]["file"];
      if (!file) continue;
      const fs::path source = car.path.parent_path() / file.as<std::string>();
      const std::string name = tyre_names.For(source);
      CopyFile(source, parts / "tyres" / name, &written);
      car_edit.SetValue("tyre_forces." + corner + ".file", stem + "/tyres/" + name);
    }
  }
  std::vector<std::string> header = edits.header;
  header.push_back(fmt::format("Based on {}.", fs::absolute(car.path).lexically_normal().string()));
  car_edit.PrependComments(header);
  WriteText(car_path, car_edit.Text(), &written);

  // Read it back as every command will.
  const vehicle::Car fitted = vehicle::LoadCar(car_path);
  for (int i = 0; i < 4; ++i) {
    for (const FileEdit& e : edits.tyres[i]) {
      CheckReadBack(TyreValue(fitted.tyres[i].params, e.key), e, fitted.tyres[i].path);
    }
    for (const FileEdit& e : edits.brakes[i]) {
      CheckReadBack(BrakeValue(fitted.brakes[i].params, e.key), e, fitted.brakes[i].path);
    }
  }
  return written;
}

}  // namespace hotlap::ident
