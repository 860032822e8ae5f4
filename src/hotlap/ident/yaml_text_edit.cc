#include "hotlap/ident/yaml_text_edit.h"

#include <algorithm>
#include <cctype>
#include <utility>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::ident {

namespace {

bool IsKeyChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.';
}

}  // namespace

YamlTextEditor::YamlTextEditor(const std::string& text, std::string file_for_messages)
    : file_(std::move(file_for_messages)) {
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = text.find('\n', start);
    if (end == std::string::npos) {
      lines_.push_back({text.substr(start), {}, 0});
      trailing_newline_ = false;
      break;
    }
    lines_.push_back({text.substr(start, end - start), {}, 0});
    start = end + 1;
  }
  Index();
}

void YamlTextEditor::Index() {
  // Stack of (indent, key) for the block mappings enclosing the current line.
  std::vector<std::pair<size_t, std::string>> stack;
  for (Line& line : lines_) {
    line.path.clear();
    const std::string& t = line.text;
    const size_t indent = t.find_first_not_of(' ');
    if (indent == std::string::npos || t[indent] == '#' || t[indent] == '-') continue;
    size_t k = indent;
    while (k < t.size() && IsKeyChar(t[k])) ++k;
    if (k == indent || k >= t.size() || t[k] != ':') continue;
    while (!stack.empty() && stack.back().first >= indent) stack.pop_back();
    std::string path;
    for (const auto& [i, key] : stack) path += key + ".";
    path += t.substr(indent, k - indent);
    line.path = path;
    line.value_at = k + 1;
    stack.emplace_back(indent, t.substr(indent, k - indent));
  }
}

void YamlTextEditor::Split(const std::string& line, size_t from, size_t* value_begin,
                           size_t* value_end, size_t* comment) {
  char quote = 0;
  *comment = std::string::npos;
  for (size_t i = from; i < line.size(); ++i) {
    const char c = line[i];
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '#' && (i == from || line[i - 1] == ' ' || line[i - 1] == '\t')) {
      *comment = i;
      break;
    }
  }
  const size_t stop = *comment == std::string::npos ? line.size() : *comment;
  size_t b = from;
  while (b < stop && (line[b] == ' ' || line[b] == '\t')) ++b;
  size_t e = stop;
  while (e > b && (line[e - 1] == ' ' || line[e - 1] == '\t')) --e;
  *value_begin = b;
  *value_end = e;
}

bool YamlTextEditor::FindInFlow(const std::string& line, size_t from, std::string_view key,
                                size_t* begin, size_t* end) {
  size_t vb = 0, ve = 0, comment = 0;
  Split(line, from, &vb, &ve, &comment);
  if (vb >= ve || line[vb] != '{') return false;
  for (size_t i = vb + 1; i < ve; ++i) {
    if (line.compare(i, key.size(), key) != 0) continue;
    const char before = line[i - 1];
    if (before != '{' && before != ',' && before != ' ') continue;
    size_t j = i + key.size();
    if (j >= ve || line[j] != ':') continue;
    ++j;
    while (j < ve && line[j] == ' ') ++j;
    size_t k = j;
    while (k < ve && line[k] != ',' && line[k] != '}') ++k;
    while (k > j && line[k - 1] == ' ') --k;
    *begin = j;
    *end = k;
    return true;
  }
  return false;
}

bool YamlTextEditor::Has(std::string_view dotted_key) const {
  for (const Line& line : lines_) {
    if (line.path == dotted_key) return true;
  }
  const size_t dot = dotted_key.rfind('.');
  if (dot == std::string_view::npos) return false;
  for (const Line& line : lines_) {
    size_t b = 0, e = 0;
    if (line.path == dotted_key.substr(0, dot) &&
        FindInFlow(line.text, line.value_at, dotted_key.substr(dot + 1), &b, &e)) {
      return true;
    }
  }
  return false;
}

void YamlTextEditor::SetValue(std::string_view dotted_key, const std::string& value,
                              const std::string& comment) {
  for (Line& line : lines_) {
    if (line.path != dotted_key) continue;
    std::string& t = line.text;
    size_t vb = 0, ve = 0, hash = 0;
    Split(t, line.value_at, &vb, &ve, &hash);
    if (vb >= ve || t[vb] == '{' || t[vb] == '[') {
      throw InputError(fmt::format("{}: '{}' is not a single value; cannot write a fitted value",
                                   file_, dotted_key));
    }
    std::string out = t.substr(0, line.value_at) + " " + value;
    if (!comment.empty()) {
      // Keep the comment's column where there was one, at least two spaces after the value.
      const size_t column = hash == std::string::npos ? 0 : hash;
      out += std::string(column > out.size() + 1 ? column - out.size() : 2, ' ') + "# " + comment;
    } else if (hash != std::string::npos) {
      const size_t column = std::max(hash, out.size() + 2);
      out += std::string(column - out.size(), ' ') + t.substr(hash);
    }
    t = out;
    return;
  }
  const size_t dot = dotted_key.rfind('.');
  if (dot != std::string_view::npos) {
    for (Line& line : lines_) {
      size_t b = 0, e = 0;
      if (line.path != dotted_key.substr(0, dot) ||
          !FindInFlow(line.text, line.value_at, dotted_key.substr(dot + 1), &b, &e)) {
        continue;
      }
      line.text.replace(b, e - b, value);
      if (!comment.empty()) {
        line.text += fmt::format("  # {}: {}", dotted_key.substr(dot + 1), comment);
      }
      return;
    }
  }
  throw InputError(
      fmt::format("{}: no value '{}' to write a fitted value into", file_, dotted_key));
}

void YamlTextEditor::PrependComments(const std::vector<std::string>& comment_lines) {
  std::vector<Line> head;
  for (const std::string& c : comment_lines) head.push_back({"# " + c, {}, 0});
  lines_.insert(lines_.begin(), head.begin(), head.end());
}

std::string YamlTextEditor::Text() const {
  std::string out;
  for (size_t i = 0; i < lines_.size(); ++i) {
    out += lines_[i].text;
    if (i + 1 < lines_.size() || trailing_newline_) out += '\n';
  }
  return out;
}

}  // namespace hotlap::ident
