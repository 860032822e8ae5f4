// Escaping for HTML and embedded JSON, and compact numbers.

#include "hotlap/report/web_text.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace hotlap::report {
namespace {

TEST(EscapeHtmlTest, EscapesMarkupCharacters) {
  EXPECT_EQ(EscapeHtml("<script>alert(\"x\") & 'y'</script>"),
            "&lt;script&gt;alert(&quot;x&quot;) &amp; &#39;y&#39;&lt;/script&gt;");
  EXPECT_EQ(EscapeHtml("plain text 1.5 m/s"), "plain text 1.5 m/s");
}

TEST(EscapeHtmlTest, KeepsUtf8AndReplacesInvalidBytes) {
  EXPECT_EQ(EscapeHtml("85 \xC2\xB0"
                       "C Z\xC3\xBCrich \xF0\x9F\x8F\x81"),
            "85 \xC2\xB0"
            "C Z\xC3\xBCrich \xF0\x9F\x8F\x81");
  // A lone continuation byte, a truncated sequence, an overlong '/' and a surrogate.
  EXPECT_EQ(EscapeHtml("a\x80"
                       "b\xC3"),
            "a\xEF\xBF\xBD"
            "b\xEF\xBF\xBD");
  EXPECT_EQ(EscapeHtml("\xC0\xAF"), "\xEF\xBF\xBD\xEF\xBF\xBD");
  EXPECT_EQ(EscapeHtml("\xED\xA0\x80"), "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");
}

TEST(JsonQuoteTest, IsValidJsonThatRoundTrips) {
  const std::vector<std::string> texts = {"",
                                          "fl",
                                          "say \"hi\"",
                                          "back\\slash",
                                          "line\nbreak\ttab\rreturn",
                                          std::string("nul\0x", 5),
                                          "</script><!-- & -->",
                                          "85 \xC2\xB0"
                                          "C",
                                          "sep\xE2\x80\xA8"
                                          "ara\xE2\x80\xA9"
                                          "tors"};
  for (const std::string& text : texts) {
    const std::string quoted = JsonQuote(text);
    EXPECT_EQ(nlohmann::json::parse(quoted).get<std::string>(), text) << quoted;
  }
}

TEST(JsonQuoteTest, IsSafeInsideAScriptElement) {
  const std::string quoted = JsonQuote("</script><script>alert(1)</script><!--");
  EXPECT_EQ(quoted.find('<'), std::string::npos) << quoted;
  EXPECT_EQ(quoted.find('>'), std::string::npos) << quoted;
  EXPECT_EQ(JsonQuote("a&b"), "\"a\\u0026b\"");
  // JavaScript treats U+2028 and U+2029 as line ends in older engines; they are escaped.
  EXPECT_EQ(JsonQuote("\xE2\x80\xA8"), "\"\\u2028\"");
  EXPECT_EQ(JsonQuote("bad\xFF"), "\"bad\xEF\xBF\xBD\"");
}

TEST(CompactNumberTest, DropsTrailingZerosAndNegativeZero) {
  const auto format = [](double v, int decimals) {
    std::string out;
    AppendCompactNumber(out, v, decimals);
    return out;
  };
  EXPECT_EQ(format(85.2, 3), "85.2");
  EXPECT_EQ(format(3.0, 4), "3");
  EXPECT_EQ(format(-0.0001, 2), "0");
  EXPECT_EQ(format(-1.23456, 2), "-1.23");
  EXPECT_EQ(format(123456.7, 0), "123457");
  EXPECT_EQ(format(0.0234567, 6), "0.023457");
  EXPECT_EQ(format(NAN, 2), "null");
  EXPECT_EQ(format(INFINITY, 2), "null");
  EXPECT_EQ(format(2.5e20, 2), "2.5e+20");
}

TEST(CompactNumberTest, DecimalsFollowTheRange) {
  EXPECT_EQ(DecimalsFor(100.0, 1e-4), 2);  // temperatures: 0.01 K
  EXPECT_EQ(DecimalsFor(0.05, 1e-4), 6);   // wear in mm
  EXPECT_EQ(DecimalsFor(3e5, 1e-4), 0);    // brake power in W
  EXPECT_EQ(DecimalsFor(1.0, 1e-4), 4);    // exact powers of ten are not rounded up
  EXPECT_EQ(DecimalsFor(0.0, 1e-4), 0);
  EXPECT_EQ(DecimalsFor(NAN, 1e-4), 0);
  EXPECT_EQ(DecimalsFor(1e-30, 1e-4), 12);
}

TEST(JsonNumberArrayTest, ParsesBackWithinTheResolution) {
  std::vector<double> values;
  for (int i = 0; i <= 1000; ++i) values.push_back(60.0 + 40.0 * std::sin(0.01 * i) + 1e-7 * i);
  values[500] = NAN;
  const nlohmann::json parsed = nlohmann::json::parse(JsonNumberArray(values));
  ASSERT_EQ(parsed.size(), values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    if (std::isnan(values[i])) {
      EXPECT_TRUE(parsed[i].is_null());
    } else {
      EXPECT_NEAR(parsed[i].get<double>(), values[i], 0.5e-4 * 80.0 + 1e-12) << i;
    }
  }
  EXPECT_EQ(JsonNumberArray(std::vector<double>{}), "[]");
  EXPECT_EQ(JsonNumberArray(std::vector<double>{85.25, 85.25}), "[85.25,85.25]");
  EXPECT_EQ(JsonNumberArray(std::vector<double>{0.0, 0.0}), "[0,0]");
  EXPECT_EQ(JsonNumberArray(std::vector<double>{0.0, 0.1, 0.2}), "[0,0.1,0.2]");
}

}  // namespace
}  // namespace hotlap::report
