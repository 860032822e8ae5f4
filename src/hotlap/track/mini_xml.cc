#include "hotlap/track/mini_xml.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::track::internal {

namespace {

constexpr int kMaxDepth = 64;

class Parser {
 public:
  Parser(std::string_view text, const std::filesystem::path& file) : text_(text), file_(file) {}

  XmlElement Document() {
    SkipMisc();
    if (AtEnd() || Peek() != '<') Fail("expected the root element");
    XmlElement root = Element(0);
    SkipMisc();
    if (!AtEnd()) Fail("unexpected content after the root element");
    return root;
  }

 private:
  bool AtEnd() const { return pos_ >= text_.size(); }
  char Peek() const { return text_[pos_]; }
  bool StartsWith(std::string_view s) const { return text_.substr(pos_, s.size()) == s; }

  [[noreturn]] void Fail(const std::string& message) const {
    const int line = 1 + static_cast<int>(std::count(
                             text_.begin(), text_.begin() + std::min(pos_, text_.size()), '\n'));
    throw InputError(fmt::format("{}:{}: XML: {}", file_.string(), line, message));
  }

  int Line() const {
    return 1 + static_cast<int>(std::count(text_.begin(), text_.begin() + pos_, '\n'));
  }

  void SkipSpace() {
    while (!AtEnd() && std::isspace(static_cast<unsigned char>(Peek()))) ++pos_;
  }

  // Skips `open` ... `close`, failing if `close` never comes.
  void SkipPast(std::string_view close, const char* what) {
    const size_t end = text_.find(close, pos_);
    if (end == std::string_view::npos) Fail(fmt::format("unterminated {}", what));
    pos_ = end + close.size();
  }

  // White space, comments, processing instructions and a DOCTYPE outside the root.
  void SkipMisc() {
    for (;;) {
      SkipSpace();
      if (StartsWith("<?")) {
        SkipPast("?>", "processing instruction");
      } else if (StartsWith("<!--")) {
        SkipPast("-->", "comment");
      } else if (StartsWith("<!DOCTYPE")) {
        SkipPast(">", "DOCTYPE");
      } else {
        return;
      }
    }
  }

  std::string Name() {
    const size_t start = pos_;
    while (!AtEnd()) {
      const char c = Peek();
      if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ||
          c == ':' || static_cast<unsigned char>(c) >= 0x80) {
        ++pos_;
      } else {
        break;
      }
    }
    if (pos_ == start) Fail("expected a name");
    return std::string(text_.substr(start, pos_ - start));
  }

  // Decodes entities in raw character data.
  std::string Decode(std::string_view raw) const {
    std::string out;
    out.reserve(raw.size());
    for (size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] != '&') {
        out += raw[i];
        continue;
      }
      const size_t semi = raw.find(';', i);
      if (semi == std::string_view::npos) Fail("'&' without ';'");
      const std::string_view entity = raw.substr(i + 1, semi - i - 1);
      if (entity == "lt") {
        out += '<';
      } else if (entity == "gt") {
        out += '>';
      } else if (entity == "amp") {
        out += '&';
      } else if (entity == "quot") {
        out += '"';
      } else if (entity == "apos") {
        out += '\'';
      } else if (entity.size() > 1 && entity[0] == '#') {
        const bool hex = entity[1] == 'x';
        unsigned code = 0;
        const std::string_view digits = entity.substr(hex ? 2 : 1);
        const auto [p, ec] =
            std::from_chars(digits.data(), digits.data() + digits.size(), code, hex ? 16 : 10);
        if (ec != std::errc() || p != digits.data() + digits.size() || code == 0 || code > 0x7f) {
          Fail(fmt::format("unsupported character reference '&{};' (ASCII only)", entity));
        }
        out += static_cast<char>(code);
      } else {
        Fail(fmt::format("unknown entity '&{};'", entity));
      }
      i = semi;
    }
    return out;
  }

  XmlElement Element(int depth) {
    if (depth > kMaxDepth) Fail("elements nested too deeply");
    XmlElement e;
    e.line = Line();
    ++pos_;  // '<'
    e.name = Name();
    for (;;) {  // attributes
      SkipSpace();
      if (AtEnd()) Fail(fmt::format("unterminated start tag <{}>", e.name));
      if (StartsWith("/>")) {
        pos_ += 2;
        return e;
      }
      if (Peek() == '>') {
        ++pos_;
        break;
      }
      std::string key = Name();
      SkipSpace();
      if (AtEnd() || Peek() != '=') Fail(fmt::format("attribute '{}' without '='", key));
      ++pos_;
      SkipSpace();
      if (AtEnd() || (Peek() != '"' && Peek() != '\'')) {
        Fail(fmt::format("attribute '{}' value not quoted", key));
      }
      const char quote = Peek();
      const size_t end = text_.find(quote, pos_ + 1);
      if (end == std::string_view::npos) Fail(fmt::format("unterminated attribute '{}'", key));
      e.attributes.emplace_back(std::move(key), Decode(text_.substr(pos_ + 1, end - pos_ - 1)));
      pos_ = end + 1;
    }
    for (;;) {  // content
      const size_t lt = text_.find('<', pos_);
      if (lt == std::string_view::npos) Fail(fmt::format("element <{}> is not closed", e.name));
      e.text += Decode(text_.substr(pos_, lt - pos_));
      pos_ = lt;
      if (StartsWith("</")) {
        pos_ += 2;
        const std::string closing = Name();
        if (closing != e.name) {
          Fail(fmt::format("</{}> closes <{}> (opened on line {})", closing, e.name, e.line));
        }
        SkipSpace();
        if (AtEnd() || Peek() != '>') Fail(fmt::format("unterminated end tag </{}>", closing));
        ++pos_;
        return e;
      }
      if (StartsWith("<!--")) {
        SkipPast("-->", "comment");
      } else if (StartsWith("<![CDATA[")) {
        const size_t start = pos_ + 9;
        SkipPast("]]>", "CDATA section");
        e.text += text_.substr(start, pos_ - 3 - start);
      } else if (StartsWith("<?")) {
        SkipPast("?>", "processing instruction");
      } else {
        e.children.push_back(Element(depth + 1));
      }
    }
  }

  std::string_view text_;
  const std::filesystem::path& file_;
  size_t pos_ = 0;
};

}  // namespace

const XmlElement* XmlElement::Child(std::string_view child) const {
  for (const XmlElement& c : children) {
    if (c.name == child) return &c;
  }
  return nullptr;
}

std::optional<std::string> XmlElement::Attribute(std::string_view key) const {
  for (const auto& [k, v] : attributes) {
    if (k == key) return v;
  }
  return std::nullopt;
}

XmlElement ParseXml(std::string_view text, const std::filesystem::path& file_for_messages) {
  return Parser(text, file_for_messages).Document();
}

}  // namespace hotlap::track::internal
