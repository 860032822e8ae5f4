#include "hotlap/track/mini_xml.h"

#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::track::internal {
namespace {

using test::Contains;

TEST(MiniXmlTest, ElementsAttributesTextAndEntities) {
  const XmlElement root = ParseXml(R"(<?xml version="1.0"?>
<!-- a comment -->
<circuit format="discrete" type='closed'>
  <header><track_length units="m">4634.15</track_length></header>
  <data n="3">
    <x>1, 2,&#x33;</x>
    <empty/>
    <note>a &lt; b &amp;&amp; c &gt; d<![CDATA[ <raw> ]]></note>
  </data>
</circuit>
)",
                                   "t.xml");
  EXPECT_EQ(root.name, "circuit");
  EXPECT_EQ(root.Attribute("format"), "discrete");
  EXPECT_EQ(root.Attribute("type"), "closed");
  EXPECT_FALSE(root.Attribute("missing").has_value());
  EXPECT_EQ(root.Child("header")->Child("track_length")->text, "4634.15");
  EXPECT_EQ(root.Child("header")->Child("track_length")->line, 4);
  const XmlElement* data = root.Child("data");
  ASSERT_NE(data, nullptr);
  EXPECT_EQ(data->Child("x")->text, "1, 2,3");
  EXPECT_TRUE(data->Child("empty")->children.empty());
  EXPECT_EQ(data->Child("note")->text, "a < b && c > d <raw> ");
  EXPECT_EQ(root.Child("nothing"), nullptr);
}

TEST(MiniXmlTest, ErrorsNameFileAndLine) {
  const auto expect = [](const std::string& text, const std::string& needle) {
    try {
      ParseXml(text, "bad.xml");
      ADD_FAILURE() << "no error for " << text;
    } catch (const InputError& e) {
      EXPECT_TRUE(Contains(e.what(), "bad.xml:")) << e.what();
      EXPECT_TRUE(Contains(e.what(), needle)) << e.what();
    }
  };
  expect("<a>\n<b></a>", "</a> closes <b> (opened on line 2)");
  expect("<a>text", "element <a> is not closed");
  expect("<a x=1></a>", "attribute 'x' value not quoted");
  expect("<a>&nbsp;</a>", "unknown entity '&nbsp;'");
  expect("<a></a><b></b>", "unexpected content after the root element");
  expect("", "expected the root element");
  expect("<a><!-- never closed </a>", "unterminated comment");
  std::string deep;
  for (int i = 0; i < 100; ++i) deep += "<a>";
  expect(deep, "nested too deeply");
}

}  // namespace
}  // namespace hotlap::track::internal
