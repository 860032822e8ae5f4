#pragma once
/// @file
/// Writing fitted parameters as a car that `hotlap replay --car` and the lap simulation load as
/// they are (docs/fitting.md, "The fitted car"):
///
///   OUT.yaml                  the car file, every line as in the original except the paths
///   OUT/tyres/{fl,fr,rl,rr}.yaml, OUT/brakes/{fl,fr,rl,rr}.yaml
///                             one file per corner, every line as in the original file except
///                             the fitted values, each with its source comment
///   OUT/tyres/<compound>, OUT/tyres/<force model files>
///                             copies of the files those refer to
///
/// so the fitted car is self-contained: it can be moved or archived as a folder and a file. Each
/// file is written atomically; the car file last. The result is then loaded with LoadCar and every
/// written value is compared with what was meant, so a file the loader would misread is an error
/// here, not later.

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "hotlap/ident/channel_fit.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::ident {

/// One value written into a fitted file.
struct FileEdit {
  std::string key;      ///< dotted key in the file, e.g. "heat_generation.p1"
  double value = 0.0;   ///< in the file's unit
  std::string comment;  ///< its source, e.g. "fitted 2026-11-22 to log.csv, std error 0.0002"
};

struct FittedCarEdits {
  std::array<std::vector<FileEdit>, 4> tyres;   ///< per corner (CornerIndex), tyre file keys
  std::array<std::vector<FileEdit>, 4> brakes;  ///< per corner (CornerIndex), brake file keys
  std::vector<std::string> header;  ///< comment lines put at the top of every edited file
};

/// Writes the fitted car at `car_path` (see the file comment) and returns every path written.
/// InputError if a file cannot be written or an edited key is not in its file; NumericalError if
/// the written car does not read back as meant (a bug).
std::vector<std::filesystem::path> WriteFittedCar(const vehicle::Car& car,
                                                  const std::filesystem::path& car_path,
                                                  const FittedCarEdits& edits);

/// The source comment of a fitted value: "fitted DATE to LOG: std error ..., 95% [lo, hi]" and
/// whether it is at its bound or not well determined; or that the data leave it undetermined.
std::string SourceComment(const std::string& date, const std::string& log,
                          const ParameterEstimate& estimate);

/// The edits that write the model parameters of `fit` (nuisance ones are left out), each key
/// prefixed with `key_prefix` (e.g. "heat_generation."), with their source comments.
std::vector<FileEdit> FileEditsOf(const FitResult& fit, const std::string& key_prefix,
                                  const std::string& date, const std::string& log);

/// Today's date as YYYY-MM-DD (local time), for source comments.
std::string TodayIsoDate();

/// A value as written into fitted files: 8 significant digits.
std::string FormatFileNumber(double value);

}  // namespace hotlap::ident
