#include "hotlap/common/yaml_reader.h"

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap {
namespace {

using test::Contains;

TEST(RangeTest, ContainsHonoursOpenAndClosedEnds) {
  EXPECT_TRUE(Range::Positive("kg").Contains(1e-300));
  EXPECT_FALSE(Range::Positive("kg").Contains(0.0));
  EXPECT_TRUE(Range::NonNegative("kg").Contains(0.0));
  EXPECT_FALSE(Range::NonNegative("kg").Contains(-1e-300));
  EXPECT_TRUE(Range::Closed(0, 1, "").Contains(1.0));
  EXPECT_FALSE(Range::Closed(0, 1, "").Contains(1.0 + 1e-15));
  EXPECT_FALSE(Range::OpenClosed(0, 1, "").Contains(0.0));
  EXPECT_TRUE(Range::OpenClosed(0, 1, "").Contains(1.0));
  EXPECT_TRUE(Range::Any("m").Contains(-1e300));
  EXPECT_FALSE(Range::Any("m").Contains(std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(Range::Any("m").Contains(std::numeric_limits<double>::quiet_NaN()));
}

TEST(RangeTest, DescribeSaysTheBoundsAndUnit) {
  EXPECT_EQ(Range::Positive("kg").Describe(), "> 0 kg");
  EXPECT_EQ(Range::NonNegative("mm").Describe(), ">= 0 mm");
  EXPECT_EQ(Range::Closed(0, 1, "").Describe(), "in [0, 1]");
  EXPECT_EQ(Range::OpenClosed(0, 90, "deg").Describe(), "in (0, 90] deg");
  EXPECT_EQ(Range::Any("m").Describe(), "a finite number m");
}

class YamlReaderTest : public ::testing::Test {
 protected:
  std::filesystem::path Write(const std::string& text) { return dir_.Write("f.yaml", text); }
  test::TempDir dir_;
};

TEST_F(YamlReaderTest, ReadsEveryKindOfField) {
  dir_.Write("other.yaml", "x: 1\n");
  const auto path = Write(
      "name: demo\n"
      "model: a\n"
      "mass_kg: 2.5\n"
      "plus: +3\n"
      "sci: 1e-3\n"
      "ref: other.yaml\n"
      "inner:\n"
      "  depth_mm: 4\n"
      "rows:\n"
      "  - {a: 1}\n"
      "  - {a: 2}\n");
  YamlReader y = YamlReader::Load(path);
  EXPECT_EQ(y.file(), path);
  EXPECT_EQ(y.String("name"), "demo");
  EXPECT_EQ(y.Choice("model", {"a", "b"}), "a");
  EXPECT_EQ(y.Number("mass_kg", Range::Positive("kg")), 2.5);
  EXPECT_EQ(y.Number("plus", Range::Any("")), 3.0);
  EXPECT_EQ(y.Number("sci", Range::Any("")), 1e-3);
  EXPECT_EQ(y.FilePath("ref"), dir_.path() / "other.yaml");
  EXPECT_FALSE(y.OptionalNumber("absent", Range::Any("")).has_value());
  EXPECT_FALSE(y.OptionalString("absent").has_value());
  EXPECT_TRUE(y.Has("inner"));
  EXPECT_FALSE(y.Has("absent"));
  YamlReader inner = y.Map("inner");
  EXPECT_EQ(inner.Number("depth_mm", Range::NonNegative("mm")), 4.0);
  inner.Finish();
  auto rows = y.MapList("rows", 2);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].Number("a", Range::Any("")), 2.0);
  EXPECT_NO_THROW(y.Finish());
}

TEST_F(YamlReaderTest, MissingFileAndBadSyntaxAndNonMapping) {
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { YamlReader::Load(dir_.path() / "nope.yaml"); }),
                       "no such file"));
  const auto bad = Write("a: 1\nb: [1, 2\nc: 3\n");
  const std::string m = test::InputErrorOf([&] { YamlReader::Load(bad); });
  EXPECT_TRUE(Contains(m, bad.string() + ":"));
  EXPECT_TRUE(Contains(m, "YAML syntax error"));
  const auto list = Write("- 1\n- 2\n");
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { YamlReader::Load(list); }), "expected a mapping"));
}

TEST_F(YamlReaderTest, OutOfRangeNamesFileFieldValueAndRange) {
  const auto path = Write("inner:\n  mass_kg: -2\n");
  YamlReader y = YamlReader::Load(path);
  YamlReader inner = y.Map("inner");
  const std::string m = test::InputErrorOf([&] { inner.Number("mass_kg", Range::Positive("kg")); });
  EXPECT_EQ(m, path.string() + ": field 'inner.mass_kg': value -2 is out of range: must be > 0 kg");
}

TEST_F(YamlReaderTest, RejectsNonNumbers) {
  YamlReader y =
      YamlReader::Load(Write("a: abc\nb: 1.5kg\nc: .nan\nd: [1]\ne: \"\"\nf: 1e999\ng: 0x10\n"));
  const Range any = Range::Any("");
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { y.Number("a", any); }), "'abc' is not a number"));
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { y.Number("b", any); }), "'1.5kg' is not a number"));
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { y.Number("c", any); }), "field 'c'"));
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { y.Number("d", any); }), "expected a number"));
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { y.String("e"); }), "non-empty"));
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { y.Number("f", any); }), "field 'f'"));  // overflows
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { y.Number("g", any); }), "'0x10' is not a number"));
}

// A key with another unit suffix is a missing field plus a hint naming the key that was found.
TEST_F(YamlReaderTest, MissingFieldSuggestsTheKeyFound) {
  const auto path = Write("tread_mass_g: 900\n");
  YamlReader y = YamlReader::Load(path);
  const std::string m =
      test::InputErrorOf([&] { y.Number("tread_mass_kg", Range::Positive("kg")); });
  EXPECT_TRUE(Contains(m, path.string()));
  EXPECT_TRUE(Contains(m, "missing field 'tread_mass_kg'"));
  EXPECT_TRUE(Contains(m, "found 'tread_mass_g' instead"));
  EXPECT_TRUE(Contains(m, "> 0 kg"));
  // Nothing close: no suggestion.
  YamlReader z = YamlReader::Load(Write("completely_different: 1\n"));
  EXPECT_FALSE(Contains(test::InputErrorOf([&] { z.Number("p1", Range::Any("")); }), "found"));
}

TEST_F(YamlReaderTest, FinishRejectsUnreadKeysWithSuggestion) {
  const auto path = Write("emissivity: 0.9\nemisivity: 0.9\nextra: 1\n");
  YamlReader y = YamlReader::Load(path);
  y.Number("emissivity", Range::Closed(0, 1, ""));
  const std::string m = test::InputErrorOf([&] { y.Finish(); });
  EXPECT_TRUE(Contains(m, path.string() + ": unknown field 'emisivity'"));
  EXPECT_TRUE(Contains(m, "did you mean 'emissivity'"));
  EXPECT_TRUE(Contains(m, "1 more unknown field"));
}

TEST_F(YamlReaderTest, ChoiceFilePathMapAndListErrors) {
  const auto path =
      Write("model: c\nref: missing.yaml\nscalar: 3\nrows:\n  - {a: 1}\nbadrows:\n  - 1\n  - 2\n");
  YamlReader y = YamlReader::Load(path);
  const std::string choice = test::InputErrorOf([&] { y.Choice("model", {"a", "b"}); });
  EXPECT_TRUE(Contains(choice, "field 'model'"));
  EXPECT_TRUE(Contains(choice, "'c' is not allowed"));
  EXPECT_TRUE(Contains(choice, "'a'"));
  const std::string file = test::InputErrorOf([&] { y.FilePath("ref"); });
  EXPECT_TRUE(Contains(file, "field 'ref'"));
  EXPECT_TRUE(Contains(file, "does not exist"));
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { y.Map("scalar"); }), "expected a mapping"));
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { y.Map("absent"); }), "missing field 'absent'"));
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { y.MapList("rows", 2); }), "at least 2 entries"));
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { y.MapList("badrows", 1); }), "field 'badrows[0]'"));
}

TEST_F(YamlReaderTest, FailNamesFileAndDottedField) {
  const auto path = Write("outer:\n  inner:\n    x: 1\n");
  YamlReader y = YamlReader::Load(path);
  YamlReader inner = y.Map("outer").Map("inner");
  EXPECT_EQ(inner.Where("x"), path.string() + ": field 'outer.inner.x'");
  EXPECT_EQ(test::InputErrorOf([&] { inner.Fail("x", "too big"); }),
            path.string() + ": field 'outer.inner.x': too big");
}

// Overrides replace numbers before the getters read them, so the usual checks apply to the new
// values; messages about an overridden field start with its label.
TEST_F(YamlReaderTest, OverridesReplaceNumbersBeforeReading) {
  const auto path = Write(
      "name: demo\n"
      "mass_kg: 2.5\n"
      "outer: {inner: {depth_mm: 4, width_mm: 3}}\n");
  YamlReader y = YamlReader::Load(path, {{"mass_kg", 7.25, "override 'm=7.25'"},
                                         {"outer.inner.depth_mm", 1e-5, "override 'd'"}});
  EXPECT_EQ(y.String("name"), "demo");
  EXPECT_EQ(y.Number("mass_kg", Range::Positive("kg")), 7.25);
  YamlReader outer = y.Map("outer");
  YamlReader inner = outer.Map("inner");
  EXPECT_EQ(inner.Number("depth_mm", Range::Positive("mm")), 1e-5);
  EXPECT_EQ(inner.Number("width_mm", Range::Positive("mm")), 3.0);
  EXPECT_EQ(test::InputErrorOf([&] { inner.Fail("depth_mm", "too deep"); }),
            "override 'd': " + path.string() + ": field 'outer.inner.depth_mm': too deep");
  // Another field of a file with overrides: the message lists them all.
  EXPECT_EQ(test::InputErrorOf([&] { inner.Fail("width_mm", "wider than deep"); }),
            "with override 'm=7.25', override 'd': " + path.string() +
                ": field 'outer.inner.width_mm': wider than deep");

  YamlReader out_of_range = YamlReader::Load(path, {{"mass_kg", -1, "override 'mass_kg=-1'"}});
  EXPECT_EQ(test::InputErrorOf([&] { out_of_range.Number("mass_kg", Range::Positive("kg")); }),
            "override 'mass_kg=-1': " + path.string() +
                ": field 'mass_kg': value -1 is out of range: must be > 0 kg");
  // Without overrides the messages are as before.
  YamlReader plain = YamlReader::Load(path, {});
  EXPECT_EQ(test::InputErrorOf([&] { plain.Fail("mass_kg", "x"); }),
            path.string() + ": field 'mass_kg': x");
}

// Within a YamlParseCache a file is parsed once: a second read takes the first tree (the file
// changed on disk in between is not read again), and a read with overrides leaves that tree as
// the file has it for the next reader.
TEST_F(YamlReaderTest, ACacheParsesEachFileOnceAndOverridesLeaveItsTreeAlone) {
  const auto path = Write("mass_kg: 2.5\nouter: {depth_mm: 4}\n");
  {
    const YamlParseCache cache;
    YamlReader first = YamlReader::Load(
        path, {{"mass_kg", 7.25, "override 'm'"}, {"outer.width_mm", 3.0, "override 'w'", true}});
    EXPECT_EQ(first.Number("mass_kg", Range::Positive("kg")), 7.25);
    EXPECT_EQ(first.Map("outer").OptionalNumber("width_mm", Range::Positive("mm")), 3.0);
    Write("mass_kg: 9\nouter: {depth_mm: 4}\n");  // not read again inside the cache
    YamlReader second = YamlReader::Load(path);
    EXPECT_EQ(second.Number("mass_kg", Range::Positive("kg")), 2.5);
    YamlReader outer = second.Map("outer");
    EXPECT_FALSE(outer.Has("width_mm"));  // the override did not add it to the tree
    EXPECT_EQ(outer.Number("depth_mm", Range::Positive("mm")), 4.0);
    outer.Finish();
    second.Finish();
    {
      const YamlParseCache inner;  // nested: the outer one holds
      EXPECT_EQ(YamlParseCache::Current(), &cache);
      EXPECT_EQ(YamlReader::Load(path).Number("mass_kg", Range::Positive("kg")), 2.5);
    }
    ASSERT_EQ(cache.parsed().size(), 1u);
    EXPECT_EQ(cache.parsed()[0], path.lexically_normal());
  }
  EXPECT_EQ(YamlParseCache::Current(), nullptr);
  EXPECT_EQ(YamlReader::Load(path).Number("mass_kg", Range::Positive("kg")), 9.0);
}

// An optional number the file leaves out: a probe finds it where the reader asks for it, and an
// override marked add_if_absent puts it into its mapping (which must be there).
TEST_F(YamlReaderTest, OptionalNumbersLeftOutAreProbedAndCanBeAdded) {
  const auto path = Write("outer: {depth_mm: 4}\n");
  const auto read = [](YamlReader y) {
    YamlReader outer = y.Map("outer");
    const double depth = outer.Number("depth_mm", Range::Positive("mm"));
    const std::optional<double> width = outer.OptionalNumber("width_mm", Range::Positive("mm"));
    outer.Finish();
    return std::pair{depth, width};
  };
  {
    YamlOptionalNumberProbe probe;
    EXPECT_EQ(read(YamlReader::Load(path, {})).second, std::nullopt);
    ASSERT_EQ(probe.absent().size(), 1u);
    EXPECT_EQ(probe.absent()[0].file, path);
    EXPECT_EQ(probe.absent()[0].field, "outer.width_mm");
  }
  EXPECT_EQ(YamlOptionalNumberProbe::Current(), nullptr);  // gone with its scope
  const auto [depth, width] =
      read(YamlReader::Load(path, {{"outer.width_mm", 2.5, "override 'w'", true}}));
  EXPECT_EQ(depth, 4.0);
  EXPECT_EQ(width, 2.5);
  // Without the mark, or where the mapping itself is missing, it is refused as before.
  EXPECT_TRUE(Contains(test::InputErrorOf([&] {
                         YamlReader::Load(path, {{"outer.width_mm", 2.5, "override 'w'"}});
                       }),
                       "has no field 'outer.width_mm'"));
  EXPECT_TRUE(Contains(test::InputErrorOf([&] {
                         YamlReader::Load(path, {{"inner.width_mm", 2.5, "override 'w'", true}});
                       }),
                       "has no field 'inner'"));
  // Added under a name the reader does not know, it is an unknown field of the file.
  EXPECT_TRUE(
      Contains(test::InputErrorOf([&] {
                 read(YamlReader::Load(path, {{"outer.wdth_mm", 2.5, "override 'w'", true}}));
               }),
               "unknown field 'outer.wdth_mm'"));
}

TEST_F(YamlReaderTest, OverrideOfAFieldThatIsNoNumberIsRefused) {
  const auto path = Write("name: demo\nouter: {depth_mm: 4}\nrows: [1, 2]\n");
  const auto error = [&](const std::string& field) {
    return test::InputErrorOf([&] { YamlReader::Load(path, {{field, 1.0, "override 'X'"}}); });
  };
  EXPECT_EQ(error("outer.depht_mm"), "override 'X': " + path.string() +
                                         " has no field 'outer.depht_mm' (did you mean "
                                         "'outer.depth_mm'?)");
  EXPECT_TRUE(Contains(error("name"), "field 'name' holds 'demo', not a number"));
  EXPECT_TRUE(Contains(error("outer"), "field 'outer' is a mapping, not a number"));
  EXPECT_TRUE(Contains(error("rows"), "field 'rows' is a list, not a number"));
  EXPECT_TRUE(Contains(error("name.x"), "field 'name' is not a mapping: it has no field 'x'"));
  EXPECT_TRUE(Contains(test::InputErrorOf([&] {
                         YamlReader::Load(path, {{"outer.depth_mm", 1, "override 'A'"},
                                                 {"outer.depth_mm", 2, "override 'B'"}});
                       }),
                       "override 'B': " + path.string() +
                           ": field 'outer.depth_mm' is already set by override 'A'"));
}

TEST_F(YamlReaderTest, ListsTheScalarsAndReadsNumbersAsTheGettersDo) {
  const auto path = Write("name: demo\nmass_kg: +2.5\nouter: {inner: {n: 1e-3}}\nrows: [1]\n");
  const std::vector<YamlScalarField> fields = ListYamlScalars(path);
  ASSERT_EQ(fields.size(), 3u);
  EXPECT_EQ(fields[0].field, "name");
  EXPECT_FALSE(fields[0].number);
  EXPECT_EQ(fields[1].field, "mass_kg");
  EXPECT_TRUE(fields[1].number);
  EXPECT_EQ(fields[2].field, "outer.inner.n");
  EXPECT_EQ(fields[2].text, "1e-3");
  EXPECT_EQ(ParseYamlNumber("+2.5"), 2.5);
  EXPECT_EQ(ParseYamlNumber("-1e3"), -1000.0);
  for (const char* bad : {"", "+", "2.5kg", "nan", "inf", "0x10", " 1"}) {
    EXPECT_FALSE(ParseYamlNumber(bad).has_value()) << bad;
  }
}

// Found by fuzz/compound_yaml_fuzz and brake_yaml_fuzz: a key that is not a name (YAML's complex
// keys, `? [a, b]: 1`, or an empty key) escaped as yaml-cpp's TypedBadConversion from the message
// code; now every key is checked when the file is loaded.
TEST_F(YamlReaderTest, KeyThatIsNotANameIsAnInputError) {
  for (const std::string keys : {"? [a, b]\n: 1\n", "? {a: 1}\n: 2\n", "~: 1\n",
                                 "outer:\n  ? [x]\n  : 1\n", "rows:\n  - {? [y]: 1}\n"}) {
    const auto path = Write("name: x\n" + keys);
    try {
      YamlReader::Load(path);
      ADD_FAILURE() << "no error for:\n" << keys;
    } catch (const InputError& e) {
      EXPECT_TRUE(Contains(e.what(), "a key must be a name")) << e.what();
    }
    EXPECT_THROW(ListYamlScalars(path), InputError) << keys;
  }
}

TEST_F(YamlReaderTest, AliasesThatHoldThemselvesOrExplodeAreRefused) {
  // yaml-cpp takes the alias as the node that holds it (a cycle); the walk meets it as depth.
  try {
    YamlReader::Load(Write("name: x\na: &x [1, *x]\n"));
    ADD_FAILURE() << "an alias that holds itself accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "an alias that holds itself")) << e.what();
  }
  std::string laughs = "name: x\nl0: &l0 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]\n";
  for (int i = 1; i <= 7; ++i) {
    laughs += fmt::format("l{}: &l{} [", i, i);
    for (int k = 0; k < 10; ++k) laughs += fmt::format("{}*l{}", k == 0 ? "" : ", ", i - 1);
    laughs += "]\n";
  }
  try {
    YamlReader::Load(Write(laughs));
    ADD_FAILURE() << "10^7 values by aliases accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "more than 1000000 values")) << e.what();
  }
}

}  // namespace
}  // namespace hotlap
