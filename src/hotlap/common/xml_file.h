#pragma once
/// @file
/// XML input through pugixml (Debian's libpugixml-dev), with the errors every hotlap reader gives:
/// "FILE:LINE: ..." for malformed XML and for the reader's own checks on elements.
///
/// How to use: `const XmlFile xml = XmlFile::Load(path);`, walk `xml.root()` with pugixml's API
/// (`child`, `attribute`, `child_value`, `first_element_by_path`), and name an element in an error
/// with `xml.Line(node)`. The document is parsed with pugixml's defaults: elements, attributes,
/// character data, CDATA, the predefined entities and character references; comments, processing
/// instructions and the DOCTYPE are skipped.

#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

#include <pugixml.hpp>

namespace hotlap {

/// A parsed XML document, the file it came from, and the line of each of its nodes.
class XmlFile {
 public:
  /// Reads and parses the file. Throws InputError "cannot read 'FILE': REASON" (ReadWholeFile) or
  /// "FILE:LINE: XML: WHAT" for malformed XML (pugixml's description, the closing tag of a
  /// mismatch, or a second root element).
  static XmlFile Load(const std::filesystem::path& path);

  /// Parses `text` as if read from `file_for_messages`; errors as Load's.
  static XmlFile Parse(std::string_view text, const std::filesystem::path& file_for_messages);

  /// The root element.
  pugi::xml_node root() const { return document_->document_element(); }

  /// The file named in messages.
  const std::filesystem::path& file() const { return file_; }

  /// 1-based line of the node's start tag; 0 for a node not parsed from the text.
  int Line(const pugi::xml_node& node) const;

 private:
  XmlFile(std::string_view text, const std::filesystem::path& file);
  int LineAt(std::ptrdiff_t offset) const;

  std::filesystem::path file_;
  std::unique_ptr<pugi::xml_document> document_;
  std::vector<std::ptrdiff_t> newlines_;  // offsets of the '\n' characters, ascending
};

}  // namespace hotlap
