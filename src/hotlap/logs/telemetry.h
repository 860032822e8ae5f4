#pragma once
/// @file
/// Telemetry channels: the column naming and unit layer of the CSV format (spec telemetry-csv.md)
/// over CsvTable.
///
/// How to use: `Telemetry::Read(path)` reads a log whose rows are ordered by strictly increasing
/// `time_s` (or by `distance_m` with `Read(path, "distance")`), converts every known channel to
/// the internal SI units below, and keeps unknown columns untouched. Ask for a channel by quantity
/// and corner, never by column name: `log.Channel("fx", Corner::kFrontLeft)` works whether the
/// file has `fx_fl_N` or `fx_fl_kN`.
///
/// Internal units: time s, distance m, speed m/s, forces N, slip_angle rad, slip_ratio 1,
/// temperatures KELVIN, wear mm, rolling_radius m, grip_factor 1, brake_power W, q1..q7 W.
///
/// Pitfalls: temperatures are written in C (the canonical file unit) but held in K; use
/// ConvertSiToCanonical() before writing. Channel() keeps empty cells as NaN; use
/// FilledChannel() where every row needs a value.

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hotlap/common/corner.h"
#include "hotlap/common/csv.h"

namespace hotlap {

struct ChannelLimits;  // telemetry_limits.h

/// A parsed column name `<quantity>[_<corner>][_<unit>]`.
struct ChannelName {
  /// A known quantity of the spec's table, e.g. "fx", "tread_temp", "q3".
  std::string quantity;
  /// The corner, or nullopt for a whole-car channel.
  std::optional<Corner> corner;
  /// The unit as written in the file, e.g. "kN"; "1" for a dimensionless channel.
  std::string unit;
};

/// Parses a column name against the known quantities of the spec (time, distance, speed, fx, fy,
/// fz, slip_angle, slip_ratio, ambient_temp, track_temp, tread_temp, carcass_temp, disc_temp,
/// calliper_temp, wear, rolling_radius, grip_factor, brake_power, q1..q7). Returns nullopt for an
/// unknown quantity and for names that do not follow the pattern `<quantity>[_<corner>]_<unit>`
/// (e.g. `time_of_day`, `tread_temp_fl_inner_C`): those columns are carried through untouched.
/// Throws InputError for a known quantity with an unknown or missing unit (e.g. `fx_fl_lbf`,
/// `speed`), or with a corner where the quantity has none (`time_fl_s`); the message names
/// `file_for_messages`, the column, the unit and the accepted units.
std::optional<ChannelName> ParseChannelName(std::string_view column,
                                            const std::filesystem::path& file_for_messages);

/// Canonical column name, e.g. ChannelColumn("tread_temp", Corner::kFrontLeft, "C") ==
/// "tread_temp_fl_C". Unit "1" (dimensionless) or "" is written without suffix: "slip_ratio_fr",
/// "grip_factor_fl".
std::string ChannelColumn(std::string_view quantity, std::optional<Corner> corner,
                          std::string_view unit);

/// The units a file may use for `quantity`, canonical first ("1" for a dimensionless quantity).
/// Throws std::invalid_argument for an unknown quantity (a programming error).
std::vector<std::string_view> AcceptedUnits(std::string_view quantity);

/// The canonical file unit of `quantity` (the first of AcceptedUnits()), e.g. "C" for
/// "tread_temp". Throws std::invalid_argument for an unknown quantity.
std::string_view CanonicalUnit(std::string_view quantity);

/// Converts a value from the internal SI unit of `quantity` to its canonical file unit, for
/// writing: K -> C for temperatures (minus 273.15); every other quantity's canonical unit is its
/// internal unit. NaN stays NaN. Throws std::invalid_argument for an unknown quantity.
double ConvertSiToCanonical(std::string_view quantity, double value_si);

/// How a log is read, beyond its path (the `--channel-map` and `--lap` options).
struct TelemetryReadOptions {
  /// The MoTeC channel map for a MoTeC i2 CSV export (motec_channel_map.h); empty: the shipped
  /// DataDir()/motec_channels.yaml.
  std::filesystem::path channel_map{};
  /// Keep only this lap's rows (the `lap` column; a MoTeC export's comes from its beacons, a
  /// `.ld` log's from its `.ldx` file's).
  std::optional<int> lap{};
  /// The time base of a MoTeC `.ld` log, Hz; nullopt: its fastest channel's rate
  /// (motec_ld_table.h).
  std::optional<double> ld_rate_hz{};
};

/// A telemetry log with every known channel converted to internal SI units on read:
/// time s, distance m, speed m/s (kph, mph converted), forces N (kN converted), slip_angle rad
/// (deg converted), slip_ratio 1, temperatures K (C converted: +273.15), wear mm (kept in mm),
/// rolling_radius m (mm converted), grip_factor 1, brake_power W (kW converted), q1..q7 W.
///
/// The accessors that take a quantity throw std::invalid_argument (a programming error) for a
/// quantity that is not in the spec's table, or a corner on `time` or `distance`.
class Telemetry {
 public:
  /// Reads and converts the file at `path` (see ReadCsv for the file rules). `index_quantity` is
  /// "time" (default) or "distance": that channel must exist, have no empty cells and be strictly
  /// increasing (the error names the file, the line and both values where it is not). Two columns
  /// of the same quantity and corner (e.g. `speed_mps` and `speed_kph`) are an InputError naming
  /// both.
  ///
  /// A MoTeC i2 CSV export (first record `"Format","MoTeC CSV File"`) or MoTeC `.ld` log
  /// (docs/telemetry-formats.md; ReadLogTable in log_table.h tells them apart) is read through
  /// `options.channel_map` into the same channels as a hotlap CSV of the same numbers; a missing
  /// channel's message then also names the MoTeC channels that map to it.
  /// `options.lap` keeps one lap's rows (SelectLap).
  static Telemetry Read(const std::filesystem::path& path, std::string_view index_quantity = "time",
                        const TelemetryReadOptions& options = {});

  /// The same from a table already in memory (e.g. columns handed over from Python): the rules of
  /// Read() from the channel names on, plus equal column lengths, unique names and at least one
  /// row (InputError naming `table.path`, the source's name, otherwise). Without line numbers,
  /// row i is reported as line i + 2, as if under a header line.
  static Telemetry FromTable(CsvTable table, std::string_view index_quantity = "time");

  /// The file it was read from.
  const std::filesystem::path& path() const { return path_; }
  /// The `# key: value` lines of the file, in order.
  const std::vector<std::pair<std::string, std::string>>& metadata() const { return metadata_; }
  /// Number of rows.
  size_t size() const { return line_numbers_.size(); }
  /// "time" or "distance", as given to Read().
  const std::string& index_quantity() const { return index_quantity_; }
  /// The index channel (s or m), strictly increasing, no NaN.
  const std::vector<double>& index() const { return Channel(index_quantity_); }

  /// True if the file has a column for this quantity and corner (exactly: a whole-car channel does
  /// not count for a corner).
  bool Has(std::string_view quantity, std::optional<Corner> corner = std::nullopt) const;

  /// SI values, NaN where the cell was empty. Throws InputError if absent: the message lists the
  /// expected column with its accepted units (e.g. "'fx_fl_N' or 'fx_fl_kN'") and the closest
  /// column names found in the file.
  const std::vector<double>& Channel(std::string_view quantity,
                                     std::optional<Corner> corner = std::nullopt) const;

  /// The column name as written in the file for this channel, e.g. "fx_fl_kN", for messages.
  /// Throws as Channel() if absent.
  const std::string& ColumnOf(std::string_view quantity,
                              std::optional<Corner> corner = std::nullopt) const;

  /// As Channel(), but with empty cells filled: linear interpolation in the index between the
  /// measured neighbours, constant extension before the first and after the last measured
  /// sample. Throws InputError naming the column if it has no value at all.
  std::vector<double> FilledChannel(std::string_view quantity,
                                    std::optional<Corner> corner = std::nullopt) const;

  /// Speed of one corner (m/s): `speed_<corner>` if present, else the whole-car `speed`; filled as
  /// FilledChannel(). Throws InputError listing both names if neither exists.
  std::vector<double> CornerSpeed(Corner corner) const;

  /// First non-empty value (SI) of a channel; nullopt if the channel is absent or entirely empty.
  std::optional<double> FirstValue(std::string_view quantity,
                                   std::optional<Corner> corner = std::nullopt) const;

  /// Columns whose quantity is unknown, as read (to carry through untouched), with their raw
  /// values (NaN where empty), in file order.
  const std::vector<std::pair<std::string, std::vector<double>>>& unknown_columns() const {
    return unknown_columns_;
  }

  /// What was done to values just outside their physical range (a wheel in the air's negative
  /// load, a speed signal's noise at standstill, a locked wheel's slip ratio past -1), one line
  /// per column naming the file, the column, the rows and the treatment (telemetry_limits.h).
  /// Values further out are refused by Read() and FromTable() instead.
  const std::vector<std::string>& warnings() const { return warnings_; }

  /// One column's treated values (a line of warnings()), for merging the warnings of a log read a
  /// line at a time into one per column (observe/stream_io.h).
  struct LimitTreatment {
    std::string file, column;
    size_t count = 0;  ///< values treated
    int first_line = 0, last_line = 0;
    std::string range;  ///< the values' range in the column's unit, e.g. "from -1e+04 to below 0 N"
    std::string treatment;  ///< e.g. "taken as 0 N: a wheel in the air"
    /// The warning's line: file, column, count, range, lines and treatment.
    std::string Message() const;
  };
  /// The treatments behind warnings(), in the same order.
  const std::vector<LimitTreatment>& treatments() const { return treatments_; }

  /// 1-based file line of row `row` (for messages). Throws std::out_of_range past the end.
  int LineOf(size_t row) const { return line_numbers_.at(row); }

 private:
  // One known channel: its column as written and its values in SI.
  struct StoredChannel {
    std::string column;
    std::vector<double> values;
  };

  Telemetry() = default;

  // The stored channel, or nullptr; checks the quantity and corner (std::invalid_argument).
  const StoredChannel* Find(std::string_view quantity, std::optional<Corner> corner) const;
  // Find(), or the InputError that lists the expected names and the closest found.
  const StoredChannel& Get(std::string_view quantity, std::optional<Corner> corner) const;
  // For a MoTeC export, " (the MoTeC channels that map to it ...)" for these channel keys; "".
  std::string SourceText(const std::vector<std::string>& keys) const;
  // Refuses values outside `limits` (InputError naming the file, line, column and value in the
  // column's unit) and sets those just outside the physical range to it, adding a warning.
  void ApplyLimits(const ChannelLimits& limits, const std::string& column, const std::string& unit,
                   double scale, double offset, std::vector<double>& values);
  // The channel's values with the NaN gaps filled (see FilledChannel).
  std::vector<double> Fill(const StoredChannel& channel) const;

  std::filesystem::path path_;
  std::vector<std::pair<std::string, std::string>> metadata_;
  // Every column of the file, for closest-name suggestions.
  std::vector<std::string> columns_;
  std::vector<int> line_numbers_;
  std::string index_quantity_;
  // Known channels keyed by "<quantity>" or "<quantity>_<corner>".
  std::map<std::string, StoredChannel, std::less<>> channels_;
  std::vector<std::pair<std::string, std::vector<double>>> unknown_columns_;
  std::vector<std::string> warnings_;
  std::vector<LimitTreatment> treatments_;
  // For a MoTeC export: channel key -> the MoTeC names that map to it, and the map's path.
  std::map<std::string, std::vector<std::string>, std::less<>> source_names_;
  std::filesystem::path channel_map_;
};

}  // namespace hotlap
