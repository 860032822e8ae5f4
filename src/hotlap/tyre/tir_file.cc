#include "hotlap/tyre/tir_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hotlap/common/atomic_file.h"
#include "hotlap/common/error.h"
#include "hotlap/common/read_file.h"
#include "hotlap/common/units.h"

namespace hotlap::tyre {

namespace {

std::string_view Trim(std::string_view s) {
  const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

std::string Upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string Lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// The whole number `s` (a leading '+' allowed), or nothing.
std::optional<double> ParseNumber(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return std::nullopt;
  // A Fortran-style exponent (1.2D+03, as files written by Fortran tools have it) is an E.
  std::string text(s);
  const size_t d = text.find_first_of("dD");
  if (d != std::string::npos && d > 0 && text.find_first_of("dD", d + 1) == std::string::npos) {
    text[d] = 'e';
  }
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + s.size(), value);
  if (ec != std::errc() || end != text.data() + s.size()) return std::nullopt;
  // from_chars reads "nan", "inf" and "infinity" too: not numbers a .tir file holds.
  if (!std::isfinite(value)) return std::nullopt;
  return value;
}

// `line` without a `$` or `!` comment that starts outside quotes.
std::string_view StripComment(std::string_view line) {
  char quote = 0;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '$' || c == '!') {
      return line.substr(0, i);
    }
  }
  return line;
}

// A row of a table section: whitespace-separated numbers only.
bool IsNumberRow(std::string_view s) {
  std::istringstream in{std::string(s)};
  std::string token;
  bool any = false;
  while (in >> token) {
    if (!ParseNumber(token)) return false;
    any = true;
  }
  return any;
}

bool IsKey(std::string_view key) {
  return !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
  });
}

struct UnitName {
  std::string_view name;
  double to_si;
};

// Accepted spellings of each [UNITS] entry (compared in lower case).
constexpr UnitName kLengthUnits[] = {
    {"meter", 1.0},     {"meters", 1.0},      {"metre", 1.0},        {"metres", 1.0},
    {"m", 1.0},         {"millimeter", 1e-3}, {"millimeters", 1e-3}, {"millimetre", 1e-3},
    {"mm", 1e-3},       {"centimeter", 1e-2}, {"centimeters", 1e-2}, {"cm", 1e-2},
    {"kilometer", 1e3}, {"km", 1e3},          {"inch", 0.0254},      {"inches", 0.0254},
    {"in", 0.0254},     {"foot", 0.3048},     {"feet", 0.3048},      {"ft", 0.3048}};
constexpr UnitName kForceUnits[] = {{"newton", 1.0},
                                    {"newtons", 1.0},
                                    {"n", 1.0},
                                    {"kilonewton", 1e3},
                                    {"kilonewtons", 1e3},
                                    {"kn", 1e3},
                                    {"pound_force", 4.4482216152605},
                                    {"lbf", 4.4482216152605},
                                    {"kilogram_force", kGravity},
                                    {"kgf", kGravity}};
constexpr UnitName kAngleUnits[] = {
    {"radian", 1.0},         {"radians", 1.0},         {"rad", 1.0},
    {"degree", kPi / 180.0}, {"degrees", kPi / 180.0}, {"deg", kPi / 180.0}};
constexpr UnitName kMassUnits[] = {{"kg", 1.0},         {"kilogram", 1.0},
                                   {"kilograms", 1.0},  {"gram", 1e-3},
                                   {"grams", 1e-3},     {"g", 1e-3},
                                   {"tonne", 1e3},      {"pound_mass", 0.45359237},
                                   {"lbm", 0.45359237}, {"slug", 14.593902937206}};
constexpr UnitName kTimeUnits[] = {
    {"second", 1.0}, {"seconds", 1.0}, {"s", 1.0},    {"sec", 1.0},     {"millisecond", 1e-3},
    {"ms", 1e-3},    {"minute", 60.0}, {"min", 60.0}, {"hour", 3600.0}, {"h", 3600.0}};
constexpr UnitName kPressureUnits[] = {
    {"pascal", 1.0},     {"pa", 1.0},  {"kilopascal", 1e3}, {"kpa", 1e3},
    {"megapascal", 1e6}, {"mpa", 1e6}, {"bar", 1e5},        {"psi", 6894.757293168361}};

template <size_t N>
double UnitFactor(const TirEntry& entry, const UnitName (&units)[N], const std::string& file) {
  const std::string name = Lower(Trim(entry.value));
  for (const UnitName& u : units) {
    if (u.name == name) return u.to_si;
  }
  std::string allowed;
  for (const UnitName& u : units)
    allowed += (allowed.empty() ? "'" : ", '") + std::string(u.name) + "'";
  throw InputError(fmt::format("{}:{}: unit {} = '{}' is not known; allowed: {}", file, entry.line,
                               entry.key, entry.value, allowed));
}

TirUnits ReadUnits(const std::vector<TirEntry>& entries, const std::string& file) {
  TirUnits units;
  bool has_pressure = false;
  for (const TirEntry& e : entries) {
    if (e.section != "UNITS") continue;
    if (e.key == "LENGTH") {
      units.length = UnitFactor(e, kLengthUnits, file);
    } else if (e.key == "FORCE") {
      units.force = UnitFactor(e, kForceUnits, file);
    } else if (e.key == "ANGLE") {
      units.angle = UnitFactor(e, kAngleUnits, file);
    } else if (e.key == "MASS") {
      units.mass = UnitFactor(e, kMassUnits, file);
    } else if (e.key == "TIME") {
      units.time = UnitFactor(e, kTimeUnits, file);
    } else if (e.key == "PRESSURE") {
      units.pressure = UnitFactor(e, kPressureUnits, file);
      has_pressure = true;
    }
  }
  if (!has_pressure) units.pressure = units.force / (units.length * units.length);
  return units;
}

// Keys of the standard MF-Tyre / ADAMS / PAC2002 files that this reader knows and does not use
// (header, inertia, structural, contact, turn-slip and test-record keys); other keys outside the
// coefficient table are warned about, as a misspelt coefficient would be.
constexpr std::string_view kKnownUnusedKeys[] = {"FILE_TYPE",
                                                 "FILE_VERSION",
                                                 "FILE_FORMAT",
                                                 "FITTYP",
                                                 "PROPERTY_FILE_FORMAT",
                                                 "USE_MODE",
                                                 "USER_SUB_ID",
                                                 "N_TIRE_STATES",
                                                 "TYRESIDE",
                                                 "MESSAGES",
                                                 "FE_METHOD",
                                                 "CONTACT_MODEL",
                                                 "BELT_DYNAMICS",
                                                 "DYNAMIC_STIFFNESS",
                                                 "DYNAMIC_DAMPING",
                                                 "INFLATION_PRESSURE",
                                                 "IP",
                                                 "IP_NOM",
                                                 "MASS",
                                                 "IXX",
                                                 "IYY",
                                                 "BELT_MASS",
                                                 "BELT_IXX",
                                                 "BELT_IYY",
                                                 "GRAVITY",
                                                 "MBELT",
                                                 "LONGITUDINAL_STIFFNESS",
                                                 "LATERAL_STIFFNESS",
                                                 "YAW_STIFFNESS",
                                                 "FREQ_LONG",
                                                 "FREQ_LAT",
                                                 "FREQ_YAW",
                                                 "FREQ_WINDUP",
                                                 "DAMP_LONG",
                                                 "DAMP_LAT",
                                                 "DAMP_YAW",
                                                 "DAMP_WINDUP",
                                                 "DAMP_RESIDUAL",
                                                 "DAMP_VLOW",
                                                 "Q_BVX",
                                                 "Q_BVT",
                                                 "PCFX1",
                                                 "PCFX2",
                                                 "PCFX3",
                                                 "PCFY1",
                                                 "PCFY2",
                                                 "PCFY3",
                                                 "PCMZ1",
                                                 "VERTICAL_DAMPING",
                                                 "BOTTOM_OFFST",
                                                 "BOTTOM_STIFF",
                                                 "BOTTOMING_RADIUS",
                                                 "Q_RA1",
                                                 "Q_RA2",
                                                 "Q_RB1",
                                                 "Q_RB2",
                                                 "ELLIPS_SHIFT",
                                                 "ELLIPS_LENGTH",
                                                 "ELLIPS_HEIGHT",
                                                 "ELLIPS_ORDER",
                                                 "ELLIPS_MAX_STEP",
                                                 "ELLIPS_NWIDTH",
                                                 "ELLIPS_NLENGTH",
                                                 "ENV_C1",
                                                 "ENV_C2",
                                                 "Q_CAM",
                                                 "Q_CAM1",
                                                 "Q_CAM2",
                                                 "Q_CAM3",
                                                 "Q_FCY2",
                                                 "Q_FYS1",
                                                 "Q_FYS2",
                                                 "Q_FYS3",
                                                 "MC_CONTOUR_A",
                                                 "MC_CONTOUR_B",
                                                 "ROAD_INCREMENT",
                                                 "ROAD_DIRECTION",
                                                 "HMAX_LOCAL",
                                                 "TIME_SWITCH_INTEG",
                                                 "PDXP1",
                                                 "PDXP2",
                                                 "PDXP3",
                                                 "PKYP1",
                                                 "PDYP1",
                                                 "PDYP2",
                                                 "PDYP3",
                                                 "PDYP4",
                                                 "PHYP1",
                                                 "PHYP2",
                                                 "PHYP3",
                                                 "PHYP4",
                                                 "PECP1",
                                                 "PECP2",
                                                 "QDTP1",
                                                 "QCRP1",
                                                 "QCRP2",
                                                 "QBRP1",
                                                 "QDRP1",
                                                 "LGAX",
                                                 "LGAY",
                                                 "LGAZ",
                                                 "LGYR",
                                                 "LCZ",
                                                 "LKG",
                                                 "LIP",
                                                 "LSGKP",
                                                 "LSGAL",
                                                 "PTX1",
                                                 "PTX2",
                                                 "PTX3",
                                                 "PTX4",
                                                 "PTY1",
                                                 "PTY2",
                                                 "PTY3",
                                                 "QTZ1",
                                                 "QPX1",
                                                 "QPZ1",
                                                 "QPZ2",
                                                 "MFSAFE1",
                                                 "MFSAFE2",
                                                 "MFSAFE3",
                                                 "DATESTAMP",
                                                 "TEST_DEVICE",
                                                 "TEST_NUMBER",
                                                 "TYPE_TEST_NUMBER",
                                                 "CONSTRUCTION",
                                                 "TIRE_DASH",
                                                 "TIRE_DOT"};

// ", "-separated `names`.
std::string JoinNames(const std::vector<std::string>& names) {
  return fmt::format("{}", fmt::join(names, ", "));
}

// The entries of the file, in order; throws on a line that is none of the accepted kinds. Keys
// with an empty value go to `empty` instead (taken as absent, as MF-Tyre and mfeval take them).
std::vector<TirEntry> ParseEntries(std::string_view text, const std::string& file,
                                   std::vector<std::string>& empty) {
  std::vector<TirEntry> entries;
  std::string section;
  int line_no = 0;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view raw = text.substr(start, end - start);
    start = end + 1;
    ++line_no;
    std::string_view s = Trim(raw);
    if (s.empty() || s.front() == '$' || s.front() == '!') continue;
    const auto fail = [&](const std::string& what) {
      throw InputError(fmt::format("{}:{}: {} (line '{}')", file, line_no, what, s));
    };
    if (s.front() == '[') {
      const size_t close = s.find(']');
      if (close == std::string_view::npos) fail("section header without ']'");
      section = Upper(Trim(s.substr(1, close - 1)));
      if (!Trim(StripComment(s.substr(close + 1))).empty()) fail("text after the section header");
      continue;
    }
    s = Trim(StripComment(s));
    if (s.empty()) continue;
    const size_t eq = s.find('=');
    if (eq == std::string_view::npos) {
      // Table sections: a `{column names}` line and rows of numbers.
      if (s.front() == '{' || IsNumberRow(s)) continue;
      fail("expected KEY = value, a [SECTION], a comment ('$' or '!') or a row of numbers");
    }
    TirEntry e;
    e.section = section;
    e.key = Upper(Trim(s.substr(0, eq)));
    e.line = line_no;
    if (!IsKey(e.key)) fail("'" + e.key + "' is not a key (letters, digits and '_')");
    std::string_view value = Trim(s.substr(eq + 1));
    if (value.empty()) {
      empty.push_back(e.key);
      continue;
    }
    if (value.front() == '\'' || value.front() == '"') {
      if (value.size() < 2 || value.back() != value.front()) fail("unterminated string");
      value = value.substr(1, value.size() - 2);
      e.quoted = true;
    }
    e.value = std::string(value);
    entries.push_back(std::move(e));
  }
  return entries;
}

MagicFormulaVersion ReadVersion(TirFile& tir, const std::string& file) {
  const TirEntry* pff = tir.Find("PROPERTY_FILE_FORMAT");
  if (pff != nullptr) tir.property_file_format = pff->value;
  const TirEntry* fittyp = tir.Find("FITTYP");
  if (fittyp == nullptr) {
    if (Upper(tir.property_file_format) == "PAC2002") return MagicFormulaVersion::kMf52;
    throw InputError(file +
                     ": no FITTYP (the Magic Formula version) in [MODEL], and "
                     "PROPERTY_FILE_FORMAT is not 'PAC2002'; add FITTYP = 6 (MF 5.2), 61 (MF 6.1) "
                     "or 62 (MF 6.2)");
  }
  const std::optional<double> number = fittyp->quoted ? std::nullopt : ParseNumber(fittyp->value);
  // Converted only where an int holds it (a float beyond it, like NaN before ParseNumber refused
  // it, is undefined behaviour: found by fuzzing, 2026-11-27).
  const int value = number && std::abs(*number) < 1e9 ? static_cast<int>(*number) : -1;
  tir.fittyp = value;
  if (number && *number == value) {
    switch (value) {
      case 5:
      case 6:
      case 21:
        return MagicFormulaVersion::kMf52;
      case 61:
        return MagicFormulaVersion::kMf61;
      case 62:
        return MagicFormulaVersion::kMf62;
      default:
        break;
    }
  }
  if (fittyp->quoted) {
    throw InputError(
        fmt::format("{}:{}: FITTYP = '{}' is quoted text; it is the Magic Formula "
                    "version number: write it without quotes (FITTYP = {})",
                    file, fittyp->line, fittyp->value, fittyp->value));
  }
  throw InputError(
      fmt::format("{}:{}: FITTYP = {} is not supported; supported: 5, 6 or 21 (MF 5.2), 61 (MF "
                  "6.1), 62 (MF 6.2)",
                  file, fittyp->line, fittyp->value));
}

// Fills the coefficients from the entries, converting to SI.
void ReadParams(TirFile& tir, const std::string& file) {
  const auto table = MagicFormulaParamTable();
  std::unordered_map<std::string_view, size_t> index;
  for (size_t i = 0; i < table.size(); ++i) index.emplace(table[i].name, i);
  std::vector<const TirEntry*> given(table.size(), nullptr);
  const auto set = [&](const TirEntry& e, size_t i) {
    const MagicFormulaParamInfo& info = table[i];
    if (given[i] != nullptr) {
      throw InputError(fmt::format("{}:{}: {} is given twice (lines {} and {})", file, e.line,
                                   info.name, given[i]->line, e.line));
    }
    const std::optional<double> value = e.quoted ? std::nullopt : ParseNumber(e.value);
    if (!value) {
      throw InputError(
          fmt::format("{}:{}: {} = '{}' is not a number", file, e.line, e.key, e.value));
    }
    given[i] = &e;
    tir.params.*info.field = *value * tir.units.ToSi(info.quantity);
  };
  for (const TirEntry& e : tir.entries) {
    if (e.section == "UNITS") continue;  // LENGTH, ..., MASS there are units
    const auto it = index.find(e.key);
    if (it != index.end()) set(e, it->second);
  }
  // PAC2002's names for the pressures.
  for (const auto& [alias, name] : {std::pair{"IP", "INFLPRES"}, std::pair{"IP_NOM", "NOMPRES"}}) {
    const TirEntry* e = tir.Find(alias);
    const size_t i = index.at(name);
    if (e != nullptr && given[i] == nullptr) set(*e, i);
  }
  for (size_t i = 0; i < table.size(); ++i) {
    if (given[i] == nullptr) tir.defaulted.emplace_back(table[i].name);
  }
}

// One warning naming every key outside the coefficient table and the known unused keys.
void WarnUnknownKeys(TirFile& tir) {
  std::unordered_set<std::string_view> known(std::begin(kKnownUnusedKeys),
                                             std::end(kKnownUnusedKeys));
  for (const MagicFormulaParamInfo& info : MagicFormulaParamTable()) known.insert(info.name);
  std::vector<std::string> unknown;
  for (const TirEntry& e : tir.entries) {
    if (e.section == "UNITS" || known.contains(e.key)) continue;
    if (std::find(unknown.begin(), unknown.end(), e.key) == unknown.end()) {
      unknown.push_back(e.key);
    }
  }
  if (unknown.empty()) return;
  tir.warnings.push_back(
      fmt::format("{}: unknown keys, not used: {}", tir.path.string(), JoinNames(unknown)));
}

}  // namespace

double TirUnits::ToSi(TirQuantity quantity) const {
  switch (quantity) {
    case TirQuantity::kNone:
      return 1.0;
    case TirQuantity::kLength:
      return length;
    case TirQuantity::kForce:
      return force;
    case TirQuantity::kAngle:
      return angle;
    case TirQuantity::kSpeed:
      return length / time;
    case TirQuantity::kPressure:
      return pressure;
    case TirQuantity::kStiffness:
      return force / length;
  }
  return 1.0;
}

const TirEntry* TirFile::Find(std::string_view key) const {
  const std::string upper = Upper(key);
  for (auto it = entries.rbegin(); it != entries.rend(); ++it) {
    if (it->key == upper) return &*it;
  }
  return nullptr;
}

TirFile ParseTirFile(std::string_view text, const std::filesystem::path& path) {
  const std::string file = path.string();
  TirFile tir;
  tir.path = path;
  std::vector<std::string> empty;
  tir.entries = ParseEntries(text, file, empty);
  if (!empty.empty()) {
    tir.warnings.push_back(fmt::format(
        "{}: keys without a value, taken as absent (defaults used): {}", file, JoinNames(empty)));
  }
  tir.units = ReadUnits(tir.entries, file);
  tir.params = MagicFormulaDefaults();
  tir.params.version = ReadVersion(tir, file);
  ReadParams(tir, file);
  WarnUnknownKeys(tir);
  return tir;
}

TirFile ReadTirFile(const std::filesystem::path& path) {
  return ParseTirFile(ReadWholeFile(path), path);
}

std::string FormatTirFile(const MagicFormulaParams<double>& params, std::string_view comment) {
  const auto line = [](std::string_view key, const std::string& value, std::string_view note) {
    std::string out = fmt::format("{:<24} = {:<24}", key, value);
    if (!note.empty()) out += fmt::format(" ${}", note);
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out + "\n";
  };
  const auto header = [](std::string_view section) {
    return fmt::format("${:-^79}\n[{}]\n", "", section);
  };
  int fittyp = 61;
  if (params.version == MagicFormulaVersion::kMf52) fittyp = 6;
  if (params.version == MagicFormulaVersion::kMf62) fittyp = 62;

  std::string out = "[MDI_HEADER]\n";
  out += line("FILE_TYPE", "'tir'", "");
  out += line("FILE_VERSION", "3.0", "");
  out += line("FILE_FORMAT", "'ASCII'", "");
  out += fmt::format("! {} coefficients written by hotlap; SI units\n",
                     MagicFormulaVersionName(params.version));
  while (!comment.empty()) {
    const size_t end = comment.find('\n');
    out += fmt::format("! {}\n", comment.substr(0, end));
    comment = end == std::string_view::npos ? std::string_view{} : comment.substr(end + 1);
  }
  out += header("UNITS");
  out += line("LENGTH", "'meter'", "");
  out += line("FORCE", "'newton'", "");
  out += line("ANGLE", "'radians'", "");
  out += line("MASS", "'kg'", "");
  out += line("TIME", "'second'", "");
  std::string_view section;
  for (const MagicFormulaParamInfo& info : MagicFormulaParamTable()) {
    if (info.section != section) {
      section = info.section;
      out += header(section);
      if (section == "MODEL") {
        out += line("FITTYP", std::to_string(fittyp), "Magic Formula version number");
        out += line("PROPERTY_FILE_FORMAT", "'USER'", "");
      }
    }
    // fmt's shortest representation reads back to the same double.
    out += line(info.name, fmt::format("{}", params.*info.field), info.description);
  }
  return out;
}

void WriteTirFile(const std::filesystem::path& path, const MagicFormulaParams<double>& params,
                  std::string_view comment) {
  const std::string text = FormatTirFile(params, comment);
  WriteFileAtomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace hotlap::tyre
