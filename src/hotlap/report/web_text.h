#pragma once
/// @file
/// Text for HTML pages and the JSON embedded in them: escaping user strings (titles, file names,
/// labels) and writing numbers compactly.
///
/// Pitfall: text that goes inside a <script> element must never contain "</script" or "<!--";
/// JsonQuote() escapes '<', '>' and '&' so that JSON it writes is always safe there, and numbers
/// never contain them.

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace hotlap::report {

/// `text` with & < > " ' replaced by character references, so it is safe as element content and
/// inside a quoted attribute value. Invalid UTF-8 bytes become U+FFFD.
std::string EscapeHtml(std::string_view text);

/// `text` as a JSON string literal, quotes included. '"', '\' and control characters are escaped
/// as JSON requires; '<', '>', '&', U+2028 and U+2029 as \uXXXX, so the result is also a valid
/// JavaScript literal that is safe inside an HTML <script> element. Invalid UTF-8 bytes become
/// U+FFFD.
std::string JsonQuote(std::string_view text);

/// The number of decimals that resolve `relative_resolution` times `span` (the range a series
/// covers; the largest magnitude when the range is 0): ceil(-log10(span * relative_resolution)),
/// clamped to [0, 12]. 0 when span is 0 or not finite.
int DecimalsFor(double span, double relative_resolution);

/// Appends `value` with at most `decimals` decimals and no trailing zeros ("85.2", "3", "-0.013";
/// "-0" becomes "0"); "null" (a gap in a chart) for NaN and infinities. Magnitudes of 1e15 and
/// more are written with 7 significant digits in exponent form.
void AppendCompactNumber(std::string& out, double value, int decimals);

/// `values` as a JSON array, each with DecimalsFor(range of the finite values,
/// `relative_resolution`) decimals: a chart of them is exact to that fraction of its range.
std::string JsonNumberArray(std::span<const double> values, double relative_resolution = 1e-4);

}  // namespace hotlap::report
