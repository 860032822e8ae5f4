#pragma once
/// @file
/// Strict reading of YAML parameter files.
///
/// How to use: open a file with YamlReader::Load, read each field with the typed getters, each
/// with the range it must lie in, then call Finish(): any key that was not read is an error (a
/// misspelt key or a key with a unit this field does not take is never silently ignored).
/// Units live in the key (`tread_mass_kg`); a key with the wrong unit suffix therefore shows up
/// as a missing field plus an unknown key, and the message says both. Every message names the
/// file, the field (dotted path), the value and the allowed range.
///
/// Overrides: YamlReader::Load can replace numbers of the file before it is read (a car parameter
/// set by its dotted key, vehicle/car_override.h), so an overridden value meets the very checks a
/// value in the file would; messages about an overridden field start with its override's label.

#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace hotlap {

/// The allowed interval of a number, with its unit for messages.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_inclusive = true;
  bool max_inclusive = true;
  std::string unit;

  static Range Positive(std::string unit) { return {0.0, kInf, false, true, std::move(unit)}; }
  static Range NonNegative(std::string unit) { return {0.0, kInf, true, true, std::move(unit)}; }
  static Range Closed(double lo, double hi, std::string unit) {
    return {lo, hi, true, true, std::move(unit)};
  }
  /// (lo, hi]: lower bound excluded.
  static Range OpenClosed(double lo, double hi, std::string unit) {
    return {lo, hi, false, true, std::move(unit)};
  }
  static Range Any(std::string unit) { return {-kInf, kInf, true, true, std::move(unit)}; }

  bool Contains(double x) const;
  /// "> 0 kg", "in [0, 1]", "in (0, 1] 1", ...
  std::string Describe() const;

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
};

/// One number of a YAML file replaced before the file is read.
struct YamlOverride {
  std::string field;   ///< dotted path through the file's mappings, e.g. "chassis.mass_kg"
  double value = 0.0;  ///< in the field's own unit, as the file writes it
  std::string label;   ///< how messages name it, e.g. "override 'chassis.mass_kg=1600'"
  /// The field may be missing from the file (an optional number the reader takes when present,
  /// as YamlOptionalNumberProbe finds them): it is then added to its mapping, which must exist.
  bool add_if_absent = false;
};

/// While one lives on a thread, every YamlReader::OptionalNumber on that thread that finds its
/// field missing records the file and the field's dotted path: the optional numbers a reader
/// would take, which an override may then set (vehicle/car_override.h). Probes nest (the inner
/// one records).
class YamlOptionalNumberProbe {
 public:
  struct Field {
    std::filesystem::path file;
    std::string field;  ///< dotted path, e.g. "tyre_forces.rl.rolling_radius_m"
  };
  YamlOptionalNumberProbe();
  ~YamlOptionalNumberProbe();
  YamlOptionalNumberProbe(const YamlOptionalNumberProbe&) = delete;
  YamlOptionalNumberProbe& operator=(const YamlOptionalNumberProbe&) = delete;
  const std::vector<Field>& absent() const { return absent_; }
  /// The probe of this thread, or null.
  static YamlOptionalNumberProbe* Current();
  void Record(const std::filesystem::path& file, std::string field);

 private:
  std::vector<Field> absent_;
  YamlOptionalNumberProbe* outer_;
};

/// While one lives on a thread, every YAML file read on that thread (YamlReader::Load,
/// ListYamlScalars) is parsed once: a second read of the same path takes the tree parsed first.
/// Nothing changes a parsed tree (overrides are applied as the reader reads, not written into
/// it), so one tree serves every reader of its file, with or without overrides. Caches nest (the
/// outermost one holds the trees). Loading a car opens one (vehicle::LoadCar), so its files, which
/// the override keys, the optional-number probe and the readers all read, are each parsed once.
class YamlParseCache {
 public:
  YamlParseCache();
  ~YamlParseCache();
  YamlParseCache(const YamlParseCache&) = delete;
  YamlParseCache& operator=(const YamlParseCache&) = delete;
  /// The outermost cache of this thread, or null.
  static YamlParseCache* Current();
  /// The files parsed through this cache so far, each once, in the order first read.
  const std::vector<std::filesystem::path>& parsed() const { return parsed_; }

 private:
  friend struct YamlParseCacheAccess;
  std::vector<std::filesystem::path> parsed_;
  std::vector<YAML::Node> trees_;  // by parsed_'s index
  YamlParseCache* outer_;
};

/// One scalar of a YAML file: its dotted path through the file's mappings (lists are not
/// entered), its text, and whether that text reads as a number (as YamlReader reads numbers).
struct YamlScalarField {
  std::string field;
  std::string text;
  bool number = false;
};

/// The number `text` reads as in a parameter file (an optional '+', then std::from_chars' format;
/// finite only), or nullopt.
std::optional<double> ParseYamlNumber(std::string_view text);

/// "KEY=VALUE" as a command line's `--set` gives it: the override of the number at the dotted
/// path KEY by VALUE (read as ParseYamlNumber reads it), labelled "override 'KEY=VALUE'".
/// InputError without '=', with an empty key, or with a value that is not a finite number; the
/// message shows `example` (e.g. "chassis.mass_kg=1600").
YamlOverride ParseYamlOverride(std::string_view text, std::string_view example);

/// Checks what every reader of a YAML file takes for granted: every key of every mapping in
/// `root` is a name (a scalar; not a mapping, a list or empty, as YAML's `? [a, b]: 1` allows),
/// nesting is at most 64 deep (so an alias that holds itself, `&a [*a]`, is refused) and there are
/// at most a million values. InputError "FILE:LINE:COLUMN: ..." otherwise. YamlReader::Load does
/// this; a reader that loads YAML itself calls it.
void CheckYamlKeys(const YAML::Node& root, const std::filesystem::path& path);

/// Every scalar of the file at `path`, in file order; InputError as YamlReader::Load.
std::vector<YamlScalarField> ListYamlScalars(const std::filesystem::path& path);

/// A mapping node of one YAML file, read strictly.
class YamlReader {
 public:
  /// Parses `path`; InputError if it cannot be read or parsed, or is not a mapping.
  static YamlReader Load(const std::filesystem::path& path);
  /// Parses `path` and reads the numbers `overrides` name in place of the file's, each of which
  /// must be a number in the file (InputError starting with its label otherwise: a field the file
  /// does not have, with the closest ones it has; a text value; a mapping; a field given twice)
  /// or an absent one it may add (YamlOverride::add_if_absent). The getters then check the new
  /// values as the file's own (the parsed tree itself is not changed), and every message about an
  /// overridden field starts with that override's label (about another field of a file with
  /// overrides: with all their labels, as a check across fields may fail because of one).
  static YamlReader Load(const std::filesystem::path& path, std::vector<YamlOverride> overrides);

  /// Required number within `range`.
  double Number(std::string_view key, const Range& range);
  /// Optional number within `range`.
  std::optional<double> OptionalNumber(std::string_view key, const Range& range);
  /// Required non-empty string.
  std::string String(std::string_view key);
  std::optional<std::string> OptionalString(std::string_view key);
  /// Required string that must be one of `allowed`.
  std::string Choice(std::string_view key, const std::vector<std::string>& allowed);
  /// Required path, relative to this file's folder; the file must exist.
  std::filesystem::path FilePath(std::string_view key);
  /// Required nested mapping.
  YamlReader Map(std::string_view key);
  /// Required list of at least `min_items` mappings (a table written as `- {a_mm: 1, b: 2}` rows);
  /// read each one strictly and call its Finish().
  std::vector<YamlReader> MapList(std::string_view key, size_t min_items);
  bool Has(std::string_view key) const;

  /// Errors on any key that was never read, with the closest expected names.
  void Finish() const;

  /// "FILE: field 'a.b'" for messages about `key`.
  std::string Where(std::string_view key) const;
  /// Throws InputError "FILE: field 'a.b': message".
  [[noreturn]] void Fail(std::string_view key, const std::string& message) const;

  const std::filesystem::path& file() const { return file_; }

 private:
  YamlReader(YAML::Node node, std::filesystem::path file, std::string prefix,
             std::shared_ptr<const std::vector<YamlOverride>> overrides);
  // "LABEL: " for a message about the field at `path` (the whole dotted path) when overrides
  // were applied; "" otherwise.
  std::string OverridePrefix(const std::string& path) const;
  YAML::Node Get(std::string_view key);  // marks as read; fails if missing
  // The override of the field `key` of this mapping, or null.
  const YamlOverride* OverrideOf(std::string_view key) const;
  [[noreturn]] void FailMissing(std::string_view key, const std::string& expected) const;
  double ToNumber(const YAML::Node& node, std::string_view key) const;
  void CheckRange(double value, std::string_view key, const Range& range) const;

  YAML::Node node_;
  std::filesystem::path file_;
  std::string prefix_;  // "" at top level, "outer.inner." below
  std::vector<std::string> read_keys_;
  std::shared_ptr<const std::vector<YamlOverride>> overrides_;  // null without overrides
};

}  // namespace hotlap
