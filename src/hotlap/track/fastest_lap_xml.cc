#include "hotlap/track/fastest_lap_xml.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/xml_file.h"
#include "hotlap/track/sampled_track.h"

namespace hotlap::track {

namespace {

using pugi::xml_node;

// Reads values of the circuit's elements; every error names the file and the element's line.
class CircuitReader {
 public:
  explicit CircuitReader(const XmlFile& xml) : xml_(xml) {}

  [[noreturn]] void Fail(const xml_node& at, const std::string& what,
                         const std::string& message) const {
    throw InputError(
        fmt::format("{}:{}: {}: {}", xml_.file().string(), xml_.Line(at), what, message));
  }

  xml_node Child(const xml_node& parent, const std::string& name, const std::string& where) const {
    const xml_node child = parent.child(name.c_str());
    if (!child) Fail(parent, where, fmt::format("missing element <{}>", name));
    return child;
  }

  double Number(const xml_node& e, std::string_view text, const std::string& what) const {
    std::string_view t = text;
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.front()))) t.remove_prefix(1);
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.remove_suffix(1);
    double value = 0.0;
    const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (t.empty() || ec != std::errc() || p != t.data() + t.size() || !std::isfinite(value)) {
      Fail(e, what, fmt::format("'{}' is not a finite number", t));
    }
    return value;
  }

  // A comma-separated list of exactly `count` numbers.
  std::vector<double> List(const xml_node& e, const std::string& what, size_t count) const {
    std::vector<double> values;
    std::stringstream in(e.child_value());
    std::string cell;
    while (std::getline(in, cell, ',')) {
      values.push_back(Number(e, cell, fmt::format("{} value {}", what, values.size() + 1)));
    }
    if (values.size() != count) {
      Fail(e, what,
           fmt::format("{} values, but <data number_of_points=\"{}\">", values.size(), count));
    }
    return values;
  }

  void Attribute(const xml_node& e, const std::string& key, const std::string& expected) const {
    const pugi::xml_attribute value = e.attribute(key.c_str());
    if (!value || value.value() != expected) {
      Fail(e, fmt::format("<{}>", e.name()),
           fmt::format("attribute {}=\"{}\" is not supported: expected {}=\"{}\"", key,
                       value ? value.value() : "(missing)", key, expected));
    }
  }

 private:
  const XmlFile& xml_;
};

}  // namespace

Track LoadFastestLapCircuit(const std::filesystem::path& path) {
  const XmlFile xml = XmlFile::Load(path);
  const CircuitReader r(xml);
  const xml_node root = xml.root();
  if (std::string_view(root.name()) != "circuit") {
    r.Fail(root, "root element", fmt::format("<{}> is not a fastest-lap <circuit>", root.name()));
  }
  r.Attribute(root, "format", "discrete");
  r.Attribute(root, "type", "closed");

  const xml_node length_element =
      r.Child(r.Child(root, "header", "<circuit>"), "track_length", "<header>");
  const double length = r.Number(length_element, length_element.child_value(), "<track_length>");
  if (!(length > 0.0)) r.Fail(length_element, "<track_length>", "must be > 0 m");

  const xml_node data = r.Child(root, "data", "<circuit>");
  const pugi::xml_attribute count_text = data.attribute("number_of_points");
  if (!count_text) r.Fail(data, "<data>", "missing attribute number_of_points");
  const double count_value = r.Number(data, count_text.value(), "<data number_of_points>");
  if (!(count_value >= 20.0) || count_value != std::floor(count_value) || count_value > 1e6) {
    r.Fail(data, "<data number_of_points>", "must be a whole number of at least 20");
  }
  const size_t n = static_cast<size_t>(count_value);
  const xml_node centre = r.Child(data, "centerline", "<data>");
  const xml_node s_element = r.Child(data, "arclength", "<data>");
  const std::vector<double> s = r.List(s_element, "<arclength>", n);
  const std::vector<double> x = r.List(r.Child(centre, "x", "<centerline>"), "<centerline>/<x>", n);
  const std::vector<double> y = r.List(r.Child(centre, "y", "<centerline>"), "<centerline>/<y>", n);
  const std::vector<double> yaw = r.List(r.Child(data, "yaw", "<data>"), "<yaw>", n);
  const xml_node kappa_element = r.Child(data, "yaw_dot", "<data>");
  const std::vector<double> kappa = r.List(kappa_element, "<yaw_dot>", n);
  const xml_node nl_element = r.Child(data, "nl", "<data>");
  const xml_node nr_element = r.Child(data, "nr", "<data>");
  const std::vector<double> nl = r.List(nl_element, "<nl>", n);
  const std::vector<double> nr = r.List(nr_element, "<nr>", n);

  if (s[0] != 0.0) r.Fail(s_element, "<arclength>", fmt::format("starts at {:g}, not 0", s[0]));
  for (size_t i = 1; i < n; ++i) {
    if (!(s[i] > s[i - 1])) {
      r.Fail(s_element, "<arclength>",
             fmt::format("value {} ({:g}) does not increase from value {} ({:g})", i + 1, s[i], i,
                         s[i - 1]));
    }
  }
  if (!(s[n - 1] < length)) {
    r.Fail(s_element, "<arclength>",
           fmt::format("last value {:g} is not below <track_length> {:g}", s[n - 1], length));
  }
  for (size_t i = 0; i < n; ++i) {
    if (!(nl[i] > 0.0)) {
      r.Fail(nl_element, "<nl>", fmt::format("value {} ({:g}) must be > 0 m", i + 1, nl[i]));
    }
    if (!(nr[i] > 0.0)) {
      r.Fail(nr_element, "<nr>", fmt::format("value {} ({:g}) must be > 0 m", i + 1, nr[i]));
    }
  }

  // Mirror y (fastest-lap's y points right of x; hotlap's left): see the header comment.
  CurvatureSamples samples;
  samples.s_m = s;
  samples.length_m = length;
  samples.curvature_per_m.resize(n);
  for (size_t i = 0; i < n; ++i) samples.curvature_per_m[i] = -kappa[i];
  samples.width_left_m = nl;
  samples.width_right_m = nr;
  samples.start = {x[0], -y[0], 0.0, -yaw[0]};
  try {
    return TrackFromCurvature(path.stem().string(), samples);
  } catch (const NumericalError& e) {
    // Curvature that closes into no loop (a fraction of a turn) is a fault of the file.
    throw InputError(
        fmt::format("{}: no track can be built from this circuit: {}", path.string(), e.what()));
  }
}

}  // namespace hotlap::track
