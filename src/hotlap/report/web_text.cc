#include "hotlap/report/web_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace hotlap::report {

namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD in UTF-8

/// Length of the valid UTF-8 sequence that starts at text[i], or 0 if it is not valid (overlong
/// forms, surrogates and code points above U+10FFFF are invalid).
size_t Utf8SequenceLength(std::string_view text, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b0 = byte(i);
  if (b0 < 0x80) return 1;
  size_t n = 0;
  uint32_t code = 0;
  if ((b0 & 0xE0) == 0xC0) {
    n = 2, code = b0 & 0x1F;
  } else if ((b0 & 0xF0) == 0xE0) {
    n = 3, code = b0 & 0x0F;
  } else if ((b0 & 0xF8) == 0xF0) {
    n = 4, code = b0 & 0x07;
  } else {
    return 0;
  }
  if (i + n > text.size()) return 0;
  for (size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3F);
  }
  constexpr uint32_t kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (code < kSmallest[n] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return n;
}

/// Calls `emit(sequence)` for every UTF-8 sequence of `text`, with U+FFFD for each invalid byte.
template <class Emit>
void ForEachCodePoint(std::string_view text, Emit emit) {
  for (size_t i = 0; i < text.size();) {
    const size_t n = Utf8SequenceLength(text, i);
    if (n == 0) {
      emit(kReplacement);
      ++i;
    } else {
      emit(text.substr(i, n));
      i += n;
    }
  }
}

}  // namespace

std::string EscapeHtml(std::string_view text) {
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  ForEachCodePoint(text, [&](std::string_view c) {
    switch (c[0]) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  });
  return out;
}

std::string JsonQuote(std::string_view text) {
  std::string out = "\"";
  out.reserve(text.size() + 2);
  ForEachCodePoint(text, [&](std::string_view c) {
    const auto u = static_cast<unsigned char>(c[0]);
    char buffer[8];
    if (c == "\xE2\x80\xA8" || c == "\xE2\x80\xA9") {  // line and paragraph separators
      out += c[2] == '\xA8' ? "\\u2028" : "\\u2029";
    } else if (c.size() > 1) {
      out += c;
    } else if (u == '"' || u == '\\') {
      out += '\\';
      out += c;
    } else if (u == '\n') {
      out += "\\n";
    } else if (u == '\t') {
      out += "\\t";
    } else if (u < 0x20 || u == '<' || u == '>' || u == '&' || u == 0x7F) {
      std::snprintf(buffer, sizeof buffer, "\\u%04x", u);
      out += buffer;
    } else {
      out += c;
    }
  });
  out += '"';
  return out;
}

int DecimalsFor(double span, double relative_resolution) {
  const double step = span * relative_resolution;
  if (!std::isfinite(step) || step <= 0.0) return 0;
  return std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 12);
}

void AppendCompactNumber(std::string& out, double value, int decimals) {
  if (!std::isfinite(value)) {
    out += "null";
    return;
  }
  char buffer[64];
  const bool huge = std::abs(value) >= 1e15;
  const auto result =
      huge ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 7)
           : std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed,
                           std::clamp(decimals, 0, 17));
  std::string_view text(buffer, result.ptr - buffer);
  if (!huge && text.find('.') != std::string_view::npos) {
    while (text.back() == '0') text.remove_suffix(1);
    if (text.back() == '.') text.remove_suffix(1);
  }
  if (text == "-0") text = "0";
  out += text;
}

std::string JsonNumberArray(std::span<const double> values, double relative_resolution) {
  double lo = INFINITY, hi = -INFINITY;
  for (double v : values) {
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  double span = hi - lo;
  if (std::isfinite(span) && span == 0.0) span = std::abs(hi);
  const int decimals = DecimalsFor(span, relative_resolution);
  std::string out = "[";
  out.reserve(values.size() * 7 + 2);
  for (size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out += ',';
    AppendCompactNumber(out, values[i], decimals);
  }
  out += ']';
  return out;
}

}  // namespace hotlap::report
