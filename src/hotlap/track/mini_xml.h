#pragma once
/// @file
/// A small XML reader for the data files the track module imports (fastest-lap circuits): elements,
/// attributes, character data, comments, CDATA, the five predefined entities and numeric character
/// references. No DTDs, namespaces or encodings other than UTF-8. Internal to the track module.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hotlap::track::internal {

/// One element with its attributes, its own character data and its child elements.
struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::string text;  ///< character data directly inside this element, entities decoded
  std::vector<XmlElement> children;
  int line = 0;  ///< 1-based line of the start tag

  /// First child element named `child`, or nullptr.
  const XmlElement* Child(std::string_view child) const;
  /// Value of attribute `key`, or nullopt.
  std::optional<std::string> Attribute(std::string_view key) const;
};

/// Parses a whole document and returns its root element. Throws InputError "FILE:LINE: ..." for
/// malformed XML (unclosed or mismatched tags, bad attributes, unknown entities, text after the
/// root, nesting deeper than 64).
XmlElement ParseXml(std::string_view text, const std::filesystem::path& file_for_messages);

}  // namespace hotlap::track::internal
