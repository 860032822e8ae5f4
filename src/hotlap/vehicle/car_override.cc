#include "hotlap/vehicle/car_override.h"

#include <algorithm>

#include <fmt/format.h>

#include "hotlap/common/corner.h"
#include "hotlap/common/error.h"
#include "hotlap/common/string_match.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::vehicle {

namespace fs = std::filesystem;

namespace {

// The car's sections whose second part is a corner.
constexpr std::array<std::string_view, 3> kCornerSections = {"tyres", "brakes", "tyre_forces"};

// A key an override may name or that names text: the car's scalars, those of each corner's files
// through the corner, and the derived keys.
struct Target {
  std::string key;
  std::string text;  // the file's text ("" for a derived key)
  bool number = false;
  fs::path file;        // the file that holds it (a derived key: the corner's brake file)
  bool absent = false;  // an optional number the file leaves out (AbsentOptionalTargets)
};

std::vector<std::string> SplitKey(std::string_view key) {
  std::vector<std::string> parts;
  size_t start = 0;
  while (true) {
    const size_t dot = key.find('.', start);
    parts.emplace_back(key.substr(start, dot == std::string_view::npos ? dot : dot - start));
    if (dot == std::string_view::npos) return parts;
    start = dot + 1;
  }
}

std::string JoinKey(const std::vector<std::string>& parts, size_t from, size_t to) {
  std::string out;
  for (size_t i = from; i < to; ++i) out += (i > from ? "." : "") + parts[i];
  return out;
}

// The scalars of a tyre or brake file a corner names, or none if it cannot be read (LoadCar says
// why).
std::vector<YamlScalarField> ScalarsOrNone(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return {};
  try {
    return ListYamlScalars(file);
  } catch (const InputError&) {
    return {};
  }
}

std::vector<Target> CarTargets(const fs::path& path) {
  std::vector<Target> out;
  for (const YamlScalarField& f : ListYamlScalars(path)) {
    const std::vector<std::string> parts = SplitKey(f.field);
    const bool corner_file = parts.size() == 2 && (parts[0] == "tyres" || parts[0] == "brakes") &&
                             ParseCorner(parts[1]).has_value();
    out.push_back({f.field, f.text, f.number && !corner_file, path});
    if (!corner_file) continue;
    const fs::path file = path.parent_path() / f.text;
    for (const YamlScalarField& g : ScalarsOrNone(file)) {
      out.push_back({f.field + "." + g.field, g.text, g.number, file});
    }
    if (parts[0] == "brakes") {
      out.push_back({f.field + "." + std::string(kDuctFactorKey), "", true, file});
    }
  }
  return out;
}

bool SameFile(const fs::path& a, const fs::path& b) {
  std::error_code ea, eb;
  const fs::path ca = fs::weakly_canonical(a, ea), cb = fs::weakly_canonical(b, eb);
  return !ea && !eb && ca == cb;
}

// The optional numbers the car's readers take when present and its files leave out (such as
// tyre_forces.<c>.rolling_radius_m of a car whose force models are .tir files): found by reading
// the car once with a YamlOptionalNumberProbe, so they are exactly what the readers accept.
// `targets` (CarTargets) tell which corner reaches which tyre or brake file. The car is read
// with `in_files`, overrides of keys the files hold (a car may read only with them); if that
// fails, `failure` says why (what the probe saw before still counts).
std::vector<Target> AbsentOptionalTargets(const fs::path& path, const std::vector<Target>& targets,
                                          const std::vector<CarOverride>& in_files = {},
                                          std::string* failure = nullptr) {
  YamlOptionalNumberProbe probe;
  try {
    (void)LoadCar(path, in_files);
  } catch (const std::exception& e) {
    if (failure) *failure = e.what();
  }
  std::vector<Target> out;
  const auto add = [&](const std::string& key, const fs::path& file) {
    if (std::none_of(out.begin(), out.end(), [&](const Target& t) { return t.key == key; })) {
      out.push_back({key, "", true, file, true});
    }
  };
  for (const YamlOptionalNumberProbe::Field& f : probe.absent()) {
    // A field inside a list ("key[2].x") has no dotted key to override.
    if (f.field.find('[') != std::string::npos) continue;
    if (SameFile(f.file, path)) {
      add(f.field, path);
      continue;
    }
    for (const Target& t : targets) {  // the corners whose tyre or brake file it is
      const std::vector<std::string> parts = SplitKey(t.key);
      if (parts.size() == 2 && (parts[0] == "tyres" || parts[0] == "brakes") &&
          ParseCorner(parts[1]) && !t.number && SameFile(path.parent_path() / t.text, f.file)) {
        add(t.key + "." + f.field, f.file);
      }
    }
  }
  return out;
}

std::string Label(const CarOverride& o) { return fmt::format("override '{}'", OverrideText(o)); }

// The keys of `targets` that are numbers and lie under `prefix` ("" for all), in order.
std::vector<std::string> NumberKeysUnder(const std::vector<Target>& targets,
                                         const std::string& prefix) {
  std::vector<std::string> keys;
  for (const Target& t : targets) {
    if (t.number && (prefix.empty() || t.key.starts_with(prefix + "."))) keys.push_back(t.key);
  }
  return keys;
}

// InputError for a key that names no number: a section, or a part that is not there.
[[noreturn]] void FailUnknown(const CarOverride& o, const std::vector<std::string>& parts,
                              const std::vector<Target>& targets, const fs::path& car_path) {
  // A key under `prefix` (a section), else the key `prefix` itself (a value), else null.
  const auto find = [&](const std::string& prefix) -> const Target* {
    for (const Target& t : targets) {
      if (t.key.starts_with(prefix + ".")) return &t;
    }
    for (const Target& t : targets) {
      if (t.key == prefix) return &t;
    }
    return nullptr;
  };
  // The longest leading parts of the key that some key starts with.
  size_t known = parts.size();
  while (known > 0 && !find(JoinKey(parts, 0, known))) --known;
  const std::string prefix = JoinKey(parts, 0, known);
  if (known == parts.size()) {  // a section (a number or text is a Target and not here)
    const std::vector<std::string> keys = NumberKeysUnder(targets, prefix);
    std::vector<std::string> shown(keys.begin(), keys.begin() + std::min<size_t>(keys.size(), 4));
    throw InputError(
        fmt::format("{}: '{}' is a section, not a number: give one of its keys, {}{}", Label(o),
                    prefix, keys.size() > shown.size() ? "e.g. " : "", QuotedList(shown),
                    keys.size() > shown.size() ? fmt::format(" ({} in all)", keys.size()) : ""));
  }
  // The suggestions come from under the deepest section named correctly, else from every key.
  std::string message, section;
  if (known == 0) {
    message = fmt::format("{}: unknown key: the car ({}) has no section or field '{}'", Label(o),
                          car_path.string(), parts[0]);
  } else {
    const Target* t = find(prefix);
    const bool leaf = t->key == prefix;
    message = fmt::format("{}: unknown key: '{}' ({}) {} '{}'", Label(o), prefix, t->file.string(),
                          leaf ? "is a value, not a section: it has no field" : "has no field",
                          parts[known]);
    section = leaf ? JoinKey(parts, 0, known - 1) : prefix;
  }
  std::vector<std::string> close = ClosestNames(o.key, NumberKeysUnder(targets, section));
  if (close.empty()) close = ClosestNames(o.key, NumberKeysUnder(targets, ""));
  if (!close.empty()) {
    // The nearest alone (all of them when they tie): a long key is near many others.
    const int best = EditDistance(o.key, close.front());
    std::erase_if(close, [&](const std::string& k) { return EditDistance(o.key, k) > best; });
    message += fmt::format(" (did you mean {}?)", QuotedList(close));
  }
  throw InputError(message);
}

}  // namespace

CarOverride ParseCarOverride(std::string_view text) {
  YamlOverride o = ParseYamlOverride(text, "chassis.mass_kg=1600");
  return {std::move(o.field), o.value};
}

std::vector<CarOverride> ParseCarOverrides(const std::vector<std::string>& texts) {
  std::vector<CarOverride> out;
  for (const std::string& t : texts) out.push_back(ParseCarOverride(t));
  return out;
}

std::string OverrideText(const CarOverride& o) { return fmt::format("{}={}", o.key, o.value); }

std::vector<std::string> OverrideKeys(const fs::path& path) {
  const YamlParseCache cache;  // each file parsed once (the probe reads them all again)
  std::vector<Target> targets = CarTargets(path);
  const std::vector<Target> optional = AbsentOptionalTargets(path, targets);
  targets.insert(targets.end(), optional.begin(), optional.end());
  return NumberKeysUnder(targets, "");
}

nlohmann::json OverridesJson(const std::vector<CarOverride>& overrides) {
  nlohmann::json j = nlohmann::json::object();
  for (const CarOverride& o : overrides) j[o.key] = o.value;
  return j;
}

std::string OverridesText(const std::vector<CarOverride>& overrides) {
  std::string out;
  for (const CarOverride& o : overrides) out += (out.empty() ? "" : ", ") + OverrideText(o);
  return out;
}

CarOverridePlan PlanCarOverrides(const fs::path& path, const std::vector<CarOverride>& overrides) {
  CarOverridePlan plan;
  if (overrides.empty()) return plan;
  for (size_t i = 0; i < overrides.size(); ++i) {
    for (size_t k = 0; k < i; ++k) {
      if (overrides[k].key == overrides[i].key) {
        throw InputError(fmt::format("{}: the key '{}' is given twice (first as {})",
                                     Label(overrides[i]), overrides[i].key,
                                     OverrideText(overrides[k])));
      }
    }
  }
  std::vector<Target> targets = CarTargets(path);
  bool probed = false;
  std::string probe_failure;
  for (const CarOverride& o : overrides) {
    const std::vector<std::string> parts = SplitKey(o.key);
    if (std::any_of(parts.begin(), parts.end(), [](const std::string& p) { return p.empty(); })) {
      throw InputError(fmt::format(
          "{}: '{}' is not a dotted key (parts joined by single dots, e.g. chassis.mass_kg)",
          Label(o), o.key));
    }
    if (parts.size() >= 2 &&
        std::find(kCornerSections.begin(), kCornerSections.end(), parts[0]) !=
            kCornerSections.end() &&
        !ParseCorner(parts[1])) {
      throw InputError(fmt::format("{}: '{}' is not a corner: must be 'fl', 'fr', 'rl' or 'rr'",
                                   Label(o), parts[1]));
    }
    auto it = std::find_if(targets.begin(), targets.end(),
                           [&](const Target& t) { return t.key == o.key; });
    if (it == targets.end() && !probed) {
      // Not in the files: perhaps an optional number they leave out.
      probed = true;
      // Read with the overrides of the files' own keys (no probe then: no recursion).
      std::vector<CarOverride> in_files;
      for (const CarOverride& k : overrides) {
        if (std::any_of(targets.begin(), targets.end(),
                        [&](const Target& t) { return t.key == k.key && t.number; })) {
          in_files.push_back(k);
        }
      }
      const std::vector<Target> optional =
          AbsentOptionalTargets(path, targets, in_files, &probe_failure);
      targets.insert(targets.end(), optional.begin(), optional.end());
      it = std::find_if(targets.begin(), targets.end(),
                        [&](const Target& t) { return t.key == o.key; });
    }
    if (it == targets.end() && !probe_failure.empty()) {
      // The optional numbers could not all be found: the car does not read as its files are.
      throw InputError(fmt::format(
          "{}: '{}' is not in the car's files, and the car does not read (with the overrides of "
          "keys they hold) to tell whether it is an optional number: {}",
          Label(o), o.key, probe_failure));
    }
    if (it == targets.end()) FailUnknown(o, parts, targets, path);
    if (!it->number) {
      throw InputError(
          fmt::format("{}: '{}' is text ('{}' in {}), not a number: only numbers can be overridden",
                      Label(o), o.key, it->text, it->file.string()));
    }
    const bool corner_file = parts[0] == "tyres" || parts[0] == "brakes";
    if (!corner_file) {
      plan.car.push_back({o.key, o.value, Label(o), it->absent});
      continue;
    }
    const int corner = CornerIndex(*ParseCorner(parts[1]));
    const std::string field = JoinKey(parts, 2, parts.size());
    if (parts[0] == "brakes" && field == kDuctFactorKey) {
      if (!(o.value > 0.0)) {
        throw InputError(
            fmt::format("{}: value {} is out of range: must be > 0 (the factor on the disc's and "
                        "calliper's convective conductance)",
                        Label(o), o.value));
      }
      plan.duct_factor[corner] = o.value;
    } else {
      (parts[0] == "tyres" ? plan.tyres : plan.brakes)[corner].push_back(
          {field, o.value, Label(o), it->absent});
    }
  }
  return plan;
}

}  // namespace hotlap::vehicle
