#include "hotlap/common/yaml_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/read_file.h"
#include "hotlap/common/string_match.h"

namespace hotlap {

namespace fs = std::filesystem;

bool Range::Contains(double x) const {
  if (!std::isfinite(x)) return false;
  const bool above = min_inclusive ? x >= min : x > min;
  const bool below = max_inclusive ? x <= max : x < max;
  return above && below;
}

std::string Range::Describe() const {
  const std::string u = unit.empty() || unit == "1" ? "" : " " + unit;
  const bool has_min = std::isfinite(min);
  const bool has_max = std::isfinite(max);
  if (has_min && !has_max) return fmt::format("{} {:g}{}", min_inclusive ? ">=" : ">", min, u);
  if (!has_min && has_max) return fmt::format("{} {:g}{}", max_inclusive ? "<=" : "<", max, u);
  if (!has_min && !has_max) return "a finite number" + u;
  return fmt::format("in {}{:g}, {:g}{}{}", min_inclusive ? "[" : "(", min, max,
                     max_inclusive ? "]" : ")", u);
}

YamlOverride ParseYamlOverride(std::string_view text, std::string_view example) {
  const size_t eq = text.find('=');
  if (eq == std::string_view::npos || eq == 0) {
    throw InputError(fmt::format("override '{}': expected KEY=VALUE, e.g. {} (docs/overrides.md)",
                                 text, example));
  }
  const std::string_view value = text.substr(eq + 1);
  const std::optional<double> number = ParseYamlNumber(value);
  if (!number) {
    throw InputError(fmt::format("override '{}': '{}' is not a finite number", text, value));
  }
  return {std::string(text.substr(0, eq)), *number, fmt::format("override '{}'", text)};
}

std::optional<double> ParseYamlNumber(std::string_view text) {
  double value = 0.0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  if (begin != end && *begin == '+') ++begin;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (begin == end || ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

// yaml-cpp's nodes of a file are a graph: an alias may point at the node that holds it (`&a [*a]`)
// or repeat a large node many times. The walk below stops at this depth and this many nodes.
constexpr int kMaxYamlDepth = 64;
constexpr long kMaxYamlNodes = 1000000;

namespace {

void CheckYamlNode(const YAML::Node& node, const fs::path& path, int depth, long& nodes) {
  const auto where = [&](const YAML::Node& n) {
    const YAML::Mark mark = n.Mark().is_null() ? node.Mark() : n.Mark();
    return fmt::format("{}:{}:{}", path.string(), mark.line + 1, mark.column + 1);
  };
  if (depth > kMaxYamlDepth) {
    throw InputError(fmt::format("{}: nested deeper than {} levels (or an alias that holds itself)",
                                 where(node), kMaxYamlDepth));
  }
  if (++nodes > kMaxYamlNodes) {
    throw InputError(fmt::format("{}: more than {} values (aliases repeating large parts?)",
                                 path.string(), kMaxYamlNodes));
  }
  if (node.IsMap()) {
    for (const auto& kv : node) {
      if (!kv.first.IsScalar()) {
        throw InputError(fmt::format("{}: a key must be a name, not {}", where(kv.first),
                                     kv.first.IsMap()        ? "a mapping"
                                     : kv.first.IsSequence() ? "a list"
                                                             : "empty"));
      }
      CheckYamlNode(kv.second, path, depth + 1, nodes);
    }
  } else if (node.IsSequence()) {
    for (const auto& item : node) CheckYamlNode(item, path, depth + 1, nodes);
  }
}

}  // namespace

void CheckYamlKeys(const YAML::Node& root, const fs::path& path) {
  long nodes = 0;
  CheckYamlNode(root, path, 0, nodes);
}

namespace {

thread_local YamlParseCache* current_cache = nullptr;

// The file's top-level mapping; InputError if it cannot be read or parsed, or is not a mapping,
// or has a key that is not a name (CheckYamlKeys).
YAML::Node ParseFileUncached(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    throw InputError(fmt::format("cannot read '{}': no such file", path.string()));
  }
  // A folder, an unreadable file: ReadWholeFile says which. A device or a pipe is read as it is.
  const std::string text = ReadWholeFile(path);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw InputError(fmt::format(
        "{}: the file is empty; expected a mapping of 'field: value' lines", path.string()));
  }
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(fmt::format("{}:{}:{}: YAML syntax error: {}", path.string(), e.mark.line + 1,
                                 e.mark.column + 1, e.msg));
  } catch (const YAML::Exception& e) {
    throw InputError(fmt::format("cannot read '{}': {}", path.string(), e.what()));
  }
  if (!root.IsMap()) {
    throw InputError(fmt::format("{}: expected a mapping of 'field: value' lines at the top level",
                                 path.string()));
  }
  CheckYamlKeys(root, path);
  return root;
}

}  // namespace

struct YamlParseCacheAccess {
  // The file's tree: the cache's where one is open (parsed on its first read), else parsed now.
  static YAML::Node Parse(const fs::path& path) {
    YamlParseCache* cache = current_cache;
    if (cache == nullptr) return ParseFileUncached(path);
    const fs::path key = path.lexically_normal();
    for (size_t i = 0; i < cache->parsed_.size(); ++i) {
      if (cache->parsed_[i] == key) return cache->trees_[i];
    }
    YAML::Node root = ParseFileUncached(path);
    cache->parsed_.push_back(key);
    cache->trees_.push_back(root);
    return root;
  }
};

YamlParseCache::YamlParseCache() : outer_(current_cache) {
  if (current_cache == nullptr) current_cache = this;
}

YamlParseCache::~YamlParseCache() {
  if (current_cache == this) current_cache = outer_;
}

YamlParseCache* YamlParseCache::Current() { return current_cache; }

namespace {

YAML::Node ParseFile(const fs::path& path) { return YamlParseCacheAccess::Parse(path); }

void ListScalars(const YAML::Node& map, const std::string& prefix,
                 std::vector<YamlScalarField>& out) {
  for (const auto& kv : map) {
    const std::string field = prefix + kv.first.as<std::string>();
    if (kv.second.IsMap()) {
      ListScalars(kv.second, field + ".", out);
    } else if (kv.second.IsScalar()) {
      out.push_back({field, kv.second.Scalar(), ParseYamlNumber(kv.second.Scalar()).has_value()});
    }
  }
}

std::vector<std::string> Split(const std::string& dotted) {
  std::vector<std::string> parts;
  size_t start = 0;
  while (true) {
    const size_t dot = dotted.find('.', start);
    parts.push_back(dotted.substr(start, dot == std::string::npos ? dot : dot - start));
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

// Checks that `o` names a number of `root` (the file's top-level mapping), or an absent one it may
// add to an existing mapping; the reader reads its value in place of the file's (the tree is not
// changed: it may be shared, YamlParseCache).
void CheckOverride(const YAML::Node& root, const fs::path& path, const YamlOverride& o) {
  const std::vector<std::string> parts = Split(o.field);
  YAML::Node node = root;
  std::string walked;
  for (size_t i = 0; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    const std::string here = walked.empty() ? part : walked + "." + part;
    const YAML::Node& parent = node;
    const YAML::Node child = parent[part];
    if (!child.IsDefined() && o.add_if_absent && i + 1 == parts.size() && parent.IsMap()) {
      return;  // an optional number the file leaves out
    }
    if (!child.IsDefined()) {
      std::vector<std::string> keys;
      for (const auto& kv : parent) keys.push_back(kv.first.as<std::string>());
      std::string message = fmt::format("{}: {} has no field '{}'", o.label, path.string(), here);
      const auto close = ClosestNames(part, keys);
      if (!close.empty()) {
        std::vector<std::string> full;
        for (const std::string& k : close) full.push_back(walked.empty() ? k : walked + "." + k);
        message += fmt::format(" (did you mean {}?)", QuotedList(full));
      }
      throw InputError(message);
    }
    if (i + 1 < parts.size()) {
      if (!child.IsMap()) {
        throw InputError(fmt::format("{}: {}: field '{}' is not a mapping: it has no field '{}'",
                                     o.label, path.string(), here, parts[i + 1]));
      }
      node.reset(child);  // rebinds the handle (plain assignment would overwrite the parent)
      walked = here;
      continue;
    }
    if (!child.IsScalar()) {
      throw InputError(fmt::format("{}: {}: field '{}' is a {}, not a number", o.label,
                                   path.string(), here, child.IsMap() ? "mapping" : "list"));
    }
    if (!ParseYamlNumber(child.Scalar())) {
      throw InputError(
          fmt::format("{}: {}: field '{}' holds '{}', not a number: only numbers can be overridden",
                      o.label, path.string(), here, child.Scalar()));
    }
  }
}

}  // namespace

std::vector<YamlScalarField> ListYamlScalars(const fs::path& path) {
  std::vector<YamlScalarField> out;
  ListScalars(ParseFile(path), "", out);
  return out;
}

YamlReader::YamlReader(YAML::Node node, fs::path file, std::string prefix,
                       std::shared_ptr<const std::vector<YamlOverride>> overrides)
    : node_(std::move(node)),
      file_(std::move(file)),
      prefix_(std::move(prefix)),
      overrides_(std::move(overrides)) {}

YamlReader YamlReader::Load(const fs::path& path) {
  return YamlReader(ParseFile(path), path, "", nullptr);
}

YamlReader YamlReader::Load(const fs::path& path, std::vector<YamlOverride> overrides) {
  YAML::Node root = ParseFile(path);
  if (overrides.empty()) return YamlReader(root, path, "", nullptr);
  for (size_t i = 0; i < overrides.size(); ++i) {
    for (size_t k = 0; k < i; ++k) {
      if (overrides[k].field == overrides[i].field) {
        throw InputError(fmt::format("{}: {}: field '{}' is already set by {}", overrides[i].label,
                                     path.string(), overrides[i].field, overrides[k].label));
      }
    }
    CheckOverride(root, path, overrides[i]);
  }
  return YamlReader(root, path, "",
                    std::make_shared<const std::vector<YamlOverride>>(std::move(overrides)));
}

std::string YamlReader::OverridePrefix(const std::string& path) const {
  if (!overrides_) return "";
  for (const YamlOverride& o : *overrides_) {
    if (o.field == path) return o.label + ": ";
  }
  std::string labels;
  for (const YamlOverride& o : *overrides_) labels += (labels.empty() ? "" : ", ") + o.label;
  return "with " + labels + ": ";
}

std::string YamlReader::Where(std::string_view key) const {
  return fmt::format("{}: field '{}{}'", file_.string(), prefix_, key);
}

void YamlReader::Fail(std::string_view key, const std::string& message) const {
  throw InputError(OverridePrefix(prefix_ + std::string(key)) + Where(key) + ": " + message);
}

const YamlOverride* YamlReader::OverrideOf(std::string_view key) const {
  if (!overrides_) return nullptr;
  const std::string path = prefix_ + std::string(key);
  for (const YamlOverride& o : *overrides_) {
    if (o.field == path) return &o;
  }
  return nullptr;
}

bool YamlReader::Has(std::string_view key) const {
  return node_[std::string(key)].IsDefined() || OverrideOf(key) != nullptr;
}

void YamlReader::FailMissing(std::string_view key, const std::string& expected) const {
  std::vector<std::string> unread;
  for (const auto& kv : node_) {
    const std::string k = kv.first.as<std::string>();
    if (std::find(read_keys_.begin(), read_keys_.end(), k) == read_keys_.end()) unread.push_back(k);
  }
  std::string message =
      fmt::format("{}: missing field '{}{}' ({})", file_.string(), prefix_, key, expected);
  const auto close = ClosestNames(key, unread);
  if (!close.empty()) {
    message += fmt::format(
        "; found {} instead (units are part of the key: a different unit "
        "suffix is not accepted)",
        QuotedList(close));
  }
  throw InputError(message);
}

YAML::Node YamlReader::Get(std::string_view key) {
  if (const YamlOverride* o = OverrideOf(key)) {
    read_keys_.emplace_back(key);
    return YAML::Node(fmt::format("{}", o->value));  // shortest text that reads back as the value
  }
  const YAML::Node& node = node_;  // const: a read never adds to the (perhaps shared) tree
  YAML::Node value = node[std::string(key)];
  if (!value.IsDefined()) FailMissing(key, "required");
  read_keys_.emplace_back(key);
  return value;
}

double YamlReader::ToNumber(const YAML::Node& node, std::string_view key) const {
  if (!node.IsScalar()) Fail(key, "expected a number");
  const std::string text = node.Scalar();
  double value = 0.0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  if (begin != end && *begin == '+') ++begin;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end) Fail(key, fmt::format("'{}' is not a number", text));
  if (!std::isfinite(value)) Fail(key, fmt::format("'{}' is not a finite number", text));
  return value;
}

void YamlReader::CheckRange(double value, std::string_view key, const Range& range) const {
  if (!range.Contains(value)) {
    Fail(key, fmt::format("value {:g} is out of range: must be {}", value, range.Describe()));
  }
}

double YamlReader::Number(std::string_view key, const Range& range) {
  if (!Has(key)) FailMissing(key, "a number " + range.Describe());
  const double value = ToNumber(Get(key), key);
  CheckRange(value, key, range);
  return value;
}

namespace {
thread_local YamlOptionalNumberProbe* current_probe = nullptr;
}  // namespace

YamlOptionalNumberProbe::YamlOptionalNumberProbe() : outer_(current_probe) { current_probe = this; }

YamlOptionalNumberProbe::~YamlOptionalNumberProbe() { current_probe = outer_; }

YamlOptionalNumberProbe* YamlOptionalNumberProbe::Current() { return current_probe; }

void YamlOptionalNumberProbe::Record(const fs::path& file, std::string field) {
  absent_.push_back({file, std::move(field)});
}

std::optional<double> YamlReader::OptionalNumber(std::string_view key, const Range& range) {
  if (!Has(key)) {
    if (YamlOptionalNumberProbe* probe = YamlOptionalNumberProbe::Current()) {
      probe->Record(file_, prefix_ + std::string(key));
    }
    return std::nullopt;
  }
  return Number(key, range);
}

std::string YamlReader::String(std::string_view key) {
  if (!Has(key)) FailMissing(key, "a text value");
  const YAML::Node value = Get(key);
  if (!value.IsScalar() || value.Scalar().empty()) Fail(key, "expected a non-empty text value");
  return value.Scalar();
}

std::optional<std::string> YamlReader::OptionalString(std::string_view key) {
  if (!Has(key)) return std::nullopt;
  return String(key);
}

std::string YamlReader::Choice(std::string_view key, const std::vector<std::string>& allowed) {
  if (!Has(key)) FailMissing(key, "one of " + QuotedList(allowed));
  const std::string value = String(key);
  if (std::find(allowed.begin(), allowed.end(), value) == allowed.end()) {
    Fail(key, fmt::format("'{}' is not allowed: must be one of {}", value, QuotedList(allowed)));
  }
  return value;
}

fs::path YamlReader::FilePath(std::string_view key) {
  const std::string text = String(key);
  const fs::path path = file_.parent_path() / text;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    Fail(key, fmt::format("file '{}' (resolved to '{}') does not exist", text, path.string()));
  }
  return path;
}

YamlReader YamlReader::Map(std::string_view key) {
  if (!Has(key)) FailMissing(key, "a mapping");
  const YAML::Node value = Get(key);
  if (!value.IsMap()) Fail(key, "expected a mapping of 'field: value' lines");
  return YamlReader(value, file_, prefix_ + std::string(key) + ".", overrides_);
}

std::vector<YamlReader> YamlReader::MapList(std::string_view key, size_t min_items) {
  if (!Has(key)) FailMissing(key, "a list of mappings");
  const YAML::Node value = Get(key);
  if (!value.IsSequence() || value.size() < min_items) {
    Fail(key, fmt::format("expected a list of at least {} entries", min_items));
  }
  std::vector<YamlReader> items;
  for (size_t i = 0; i < value.size(); ++i) {
    const std::string item_key = fmt::format("{}[{}]", key, i);
    if (!value[i].IsMap()) Fail(item_key, "expected a mapping of 'field: value' pairs");
    items.push_back(YamlReader(value[i], file_, prefix_ + item_key + ".", overrides_));
  }
  return items;
}

void YamlReader::Finish() const {
  std::vector<std::string> unknown;
  for (const auto& kv : node_) {
    const std::string k = kv.first.as<std::string>();
    if (std::find(read_keys_.begin(), read_keys_.end(), k) == read_keys_.end())
      unknown.push_back(k);
  }
  // An override that adds a field this mapping's reader never took is unknown too.
  if (overrides_) {
    for (const YamlOverride& o : *overrides_) {
      if (!o.field.starts_with(prefix_)) continue;
      const std::string k = o.field.substr(prefix_.size());
      if (k.find('.') != std::string::npos) continue;
      const auto known = [&](const std::vector<std::string>& keys) {
        return std::find(keys.begin(), keys.end(), k) != keys.end();
      };
      if (!known(read_keys_) && !known(unknown)) unknown.push_back(k);
    }
  }
  if (unknown.empty()) return;
  std::string message =
      fmt::format("{}: unknown field '{}{}'", file_.string(), prefix_, unknown[0]);
  const auto close = ClosestNames(unknown[0], read_keys_);
  if (!close.empty()) message += fmt::format(" (did you mean {}?)", QuotedList(close));
  if (unknown.size() > 1)
    message += fmt::format(" and {} more unknown field(s)", unknown.size() - 1);
  throw InputError(message);
}

}  // namespace hotlap
