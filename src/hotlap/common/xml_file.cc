#include "hotlap/common/xml_file.h"

#include <algorithm>
#include <cctype>
#include <string>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/read_file.h"

namespace hotlap {

namespace {

// The name at `offset` (a tag's name: up to white space, '>', '/' or the end).
std::string_view NameAt(std::string_view text, size_t offset) {
  size_t end = offset;
  while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end])) &&
         text[end] != '>' && text[end] != '/' && text[end] != '<') {
    ++end;
  }
  return text.substr(offset, end - offset);
}

// pugixml's description of a failed parse, with what stands at the offset.
std::string Describe(const pugi::xml_parse_result& result, std::string_view text) {
  std::string what = result.description();
  if (!what.empty()) what[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(what[0])));
  const size_t at = static_cast<size_t>(std::max<std::ptrdiff_t>(result.offset, 0));
  if (result.status == pugi::status_end_element_mismatch) {
    // pugixml points at the name of a wrong end tag, or at the last character when the text
    // ends with elements still open.
    if (at >= 2 && at < text.size() && text.substr(at - 2, 2) == "</") {
      return fmt::format("{}: </{}> does not close the element open there", what, NameAt(text, at));
    }
    return what + ": an element is not closed by the end of the file";
  }
  if (at >= text.size()) return what + " at the end of the file";
  const std::string_view rest = text.substr(at, std::min<size_t>(24, text.find('\n', at) - at));
  return fmt::format("{} at '{}'", what, rest);
}

}  // namespace

XmlFile XmlFile::Load(const std::filesystem::path& path) {
  return XmlFile(ReadWholeFile(path), path);
}

XmlFile XmlFile::Parse(std::string_view text, const std::filesystem::path& file_for_messages) {
  return XmlFile(text, file_for_messages);
}

XmlFile::XmlFile(std::string_view text, const std::filesystem::path& file)
    : file_(file), document_(std::make_unique<pugi::xml_document>()) {
  for (size_t i = text.find('\n'); i != std::string_view::npos; i = text.find('\n', i + 1)) {
    newlines_.push_back(static_cast<std::ptrdiff_t>(i));
  }
  // load_buffer copies the text; node offsets (offset_debug) are offsets into it.
  const pugi::xml_parse_result result = document_->load_buffer(text.data(), text.size());
  if (!result) {
    throw InputError(fmt::format("{}:{}: XML: {}", file_.string(), LineAt(result.offset),
                                 Describe(result, text)));
  }
  // pugixml reads fragments; a data file has exactly one root element.
  int roots = 0;
  for (const pugi::xml_node& node : document_->children()) {
    if (node.type() != pugi::node_element || ++roots == 1) continue;
    throw InputError(fmt::format("{}:{}: XML: element <{}> after the root element <{}>",
                                 file_.string(), Line(node), node.name(), root().name()));
  }
}

int XmlFile::Line(const pugi::xml_node& node) const {
  const std::ptrdiff_t offset = node.offset_debug();
  return offset < 0 ? 0 : LineAt(offset);
}

int XmlFile::LineAt(std::ptrdiff_t offset) const {
  return 1 + static_cast<int>(std::lower_bound(newlines_.begin(), newlines_.end(), offset) -
                              newlines_.begin());
}

}  // namespace hotlap
