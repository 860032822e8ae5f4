// XmlFile: pugixml's tree with the line of every element, and malformed XML reported as
// "FILE:LINE: XML: ..." from text and from files (the readers' error contract).

#include "hotlap/common/xml_file.h"

#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap {
namespace {

using test::Contains;

TEST(XmlFile, ElementsAttributesTextEntitiesAndLines) {
  const XmlFile xml = XmlFile::Parse(R"(<?xml version="1.0"?>
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
  const pugi::xml_node root = xml.root();
  EXPECT_STREQ(root.name(), "circuit");
  EXPECT_STREQ(root.attribute("format").value(), "discrete");
  EXPECT_STREQ(root.attribute("type").value(), "closed");
  EXPECT_TRUE(root.attribute("missing").empty());
  const pugi::xml_node length = root.first_element_by_path("header/track_length");
  EXPECT_STREQ(length.child_value(), "4634.15");
  EXPECT_EQ(xml.Line(root), 3);
  EXPECT_EQ(xml.Line(length), 4);
  EXPECT_EQ(xml.Line(root.child("data").child("empty")), 7);
  EXPECT_STREQ(root.first_element_by_path("data/x").child_value(), "1, 2,3");
  EXPECT_STREQ(root.first_element_by_path("data/note").child_value(), "a < b && c > d");
  EXPECT_TRUE(root.child("nothing").empty());
  EXPECT_EQ(xml.Line(root.child("nothing")), 0);
  EXPECT_EQ(xml.file(), "t.xml");
}

TEST(XmlFile, LinesCountFromTheFileStartWithCrLfAndBom) {
  const XmlFile xml = XmlFile::Parse("\xEF\xBB\xBF<a>\r\n\r\n  <b/>\r\n</a>\r\n", "crlf.xml");
  EXPECT_EQ(xml.Line(xml.root()), 1);
  EXPECT_EQ(xml.Line(xml.root().child("b")), 3);
}

// Each malformed text: the message names the file, the line and what is wrong.
TEST(XmlFile, MalformedXmlNamesFileAndLine) {
  const auto expect = [](const std::string& text, const std::string& line,
                         const std::string& needle) {
    try {
      XmlFile::Parse(text, "bad.xml");
      ADD_FAILURE() << "no error for " << text;
    } catch (const InputError& e) {
      EXPECT_TRUE(Contains(e.what(), "bad.xml:" + line + ": XML: ")) << text;
      EXPECT_TRUE(Contains(e.what(), needle)) << text;
    }
  };
  expect("<a>\n<b></a>", "2", "start-end tags mismatch: </a> does not close the element");
  expect("<a>\n<b>\n</c>\n</a>", "3", "</c> does not close");
  expect("<a>\n</a>\n</b>", "3", "</b> does not close");
  expect("<a>\ntext", "2", "start-end tags mismatch: an element is not closed by the end");
  expect("<a>\n<b>\n</b>", "3", "an element is not closed by the end of the file");
  expect("<a>\n  <b x=1></b></a>", "2", "error parsing element attribute at '1></b></a>'");
  expect("<a>\n<b/>\n</a", "3", "error parsing end element tag");
  expect("<a>\n<!-- never closed </a>", "2", "error parsing comment");
  expect("<a></a>\n<b></b>", "2", "element <b> after the root element <a>");
  expect("", "1", "no document element found");
  expect("  \n  text only", "2", "no document element found");
}

TEST(XmlFile, LoadReadsTheFileAndNamesItInErrors) {
  test::TempDir dir;
  const auto good = dir.Write("good.xml", "<car>\n  <mass>728</mass>\n</car>\n");
  const XmlFile xml = XmlFile::Load(good);
  EXPECT_STREQ(xml.root().child_value("mass"), "728");
  EXPECT_EQ(xml.file(), good);
  const auto bad = dir.Write("bad.xml", "<car>\n  <mass>728</mas>\n</car>\n");
  try {
    XmlFile::Load(bad);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), bad.string() + ":2: XML: start-end tags mismatch: </mas>"));
  }
  try {
    XmlFile::Load(dir.path() / "missing.xml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "cannot read '" + (dir.path() / "missing.xml").string()));
  }
}

}  // namespace
}  // namespace hotlap
