#include "hotlap/tyre/tir_file.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/tyre/magic_formula.h"
#include "test_util.h"

namespace hotlap::tyre {
namespace {

std::filesystem::path TirPath(const std::string& relative) {
  return test::SourcePath("tests/data/tir/" + relative);
}

// A small MF 6.1 file; tests edit it with test::ReplaceOnce.
const char* const kMinimal = R"($ a minimal file
[MDI_HEADER]
FILE_TYPE = 'tir'
[UNITS]
LENGTH = 'meter'
FORCE  = 'newton'
ANGLE  = 'radians'
MASS   = 'kg'
TIME   = 'second'
[MODEL]
FITTYP = 61   $Magic Formula version
LONGVL = 16.6
[DIMENSION]
UNLOADED_RADIUS = 0.3943
[VERTICAL]
FNOMIN = 6752
VERTICAL_STIFFNESS = 314931.2969
[OPERATING_CONDITIONS]
INFLPRES = 260000
[SLIP_ANGLE_RANGE]
ALPMAX = 0.96
[LATERAL_COEFFICIENTS]
PCY1 = 1.4759  $Shape factor Cfy for lateral forces
PKY1 = -28.3155
)";

// Expects ParseTirFile(text) to throw InputError whose message contains every part.
void ExpectParseError(const std::string& text, const std::vector<std::string>& parts) {
  try {
    ParseTirFile(text, "bad.tir");
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const InputError& e) {
    for (const auto& part : parts) EXPECT_TRUE(test::Contains(e.what(), part));
  }
}

TEST(TirFileTest, ReadsMf61File) {
  const TirFile tir = ReadTirFile(TirPath("mfeval/MagicFormula61_Parameters.tir"));
  EXPECT_EQ(tir.fittyp, 61);
  EXPECT_EQ(tir.params.version, MagicFormulaVersion::kMf61);
  EXPECT_EQ(tir.property_file_format, "USER");
  EXPECT_DOUBLE_EQ(tir.params.FNOMIN, 6752);
  EXPECT_DOUBLE_EQ(tir.params.UNLOADED_RADIUS, 0.3943);
  EXPECT_DOUBLE_EQ(tir.params.PCY1, 1.4759);
  EXPECT_DOUBLE_EQ(tir.params.RVY6, -27.5155);
  EXPECT_DOUBLE_EQ(tir.params.QSY8, -0.4);
  EXPECT_DOUBLE_EQ(tir.params.SSZ4, 0.0);
  EXPECT_DOUBLE_EQ(tir.params.NOMPRES, 260000);
  // Only the MF 5.2 coefficient is missing from an MF 6.1 file.
  EXPECT_EQ(tir.defaulted, std::vector<std::string>{"PHY3"});
  // Entries keep everything, including keys the model does not use.
  ASSERT_NE(tir.Find("belt_mass"), nullptr);
  EXPECT_EQ(tir.Find("BELT_MASS")->value, "7");
  EXPECT_EQ(tir.Find("BELT_MASS")->section, "INERTIA");
  EXPECT_EQ(tir.Find("TYRESIDE")->value, "RIGHT");
  EXPECT_TRUE(tir.Find("TYRESIDE")->quoted);
}

TEST(TirFileTest, Mf52FileTakesMfevalDefaults) {
  const TirFile tir = ReadTirFile(TirPath("mfeval/MagicFormula52_Parameters.tir"));
  EXPECT_EQ(tir.fittyp, 6);
  EXPECT_EQ(tir.params.version, MagicFormulaVersion::kMf52);
  EXPECT_DOUBLE_EQ(tir.params.PHY3, 0.006973);
  // Absent from the file: mfeval's readTIR defaults.
  for (const char* name : {"PKY4", "NOMPRES", "INFLPRES", "PRESMIN", "QSY7"}) {
    EXPECT_NE(std::find(tir.defaulted.begin(), tir.defaulted.end(), name), tir.defaulted.end())
        << name;
  }
  EXPECT_DOUBLE_EQ(tir.params.PKY4, 2.0);
  EXPECT_DOUBLE_EQ(tir.params.NOMPRES, 220000);
  EXPECT_DOUBLE_EQ(tir.params.PRESMIN, 10000);
  EXPECT_DOUBLE_EQ(tir.params.QSY7, 0.85);
  EXPECT_DOUBLE_EQ(tir.params.PKY6, -1.0);
}

TEST(TirFileTest, ReadsChronoFilesAsMf52) {
  // PAC2002 without FITTYP, CRLF line ends, [SHAPE] and load-curve tables.
  for (const char* name : {"HMMWV_Pac02Tire.tir", "Sedan_Pac02Tire.tir", "mf_185_80R14.tir"}) {
    const TirFile tir = ReadTirFile(TirPath(std::string("chrono/") + name));
    EXPECT_EQ(tir.fittyp, 0) << name;
    EXPECT_EQ(tir.params.version, MagicFormulaVersion::kMf52) << name;
    EXPECT_EQ(tir.property_file_format, "PAC2002") << name;
  }
  const TirFile hmmwv = ReadTirFile(TirPath("chrono/HMMWV_Pac02Tire.tir"));
  EXPECT_DOUBLE_EQ(hmmwv.params.INFLPRES, 800000);  // IP in [TIRE_CONDITIONS]
  EXPECT_DOUBLE_EQ(hmmwv.params.NOMPRES, 800000);   // IP_NOM
  EXPECT_DOUBLE_EQ(hmmwv.params.LFZO, 0.580904846);
  // MF-Tyre 5.0 (FITTYP 5) is read as MF 5.2.
  const TirFile big = ReadTirFile(TirPath("chrono/335_65R22_5_G275MSA_60psi.tir"));
  EXPECT_EQ(big.fittyp, 5);
  EXPECT_EQ(big.params.version, MagicFormulaVersion::kMf52);
  EXPECT_DOUBLE_EQ(big.params.FNOMIN, 21674);
  EXPECT_DOUBLE_EQ(big.params.VERTICAL_STIFFNESS, 5.6519e5);
  EXPECT_DOUBLE_EQ(big.params.KPUMAX, 0.0);
}

TEST(TirFileTest, KeysSectionsAndUnitsAreCaseInsensitiveAndCommentsIgnored) {
  std::string text = test::ReplaceOnce(kMinimal, "PCY1 = 1.4759", "pcy1 = +1.5 ! trailing");
  text = test::ReplaceOnce(text, "[LATERAL_COEFFICIENTS]", "[lateral_coefficients]  $ header");
  text = test::ReplaceOnce(text, "FILE_TYPE = 'tir'", "FILE_TYPE = 'a $ and ! inside'");
  text = test::ReplaceOnce(text, "LENGTH = 'meter'", "length = 'Meter'");
  const TirFile tir = ParseTirFile(text, "x.tir");
  EXPECT_DOUBLE_EQ(tir.params.PCY1, 1.5);
  EXPECT_EQ(tir.Find("PCY1")->section, "LATERAL_COEFFICIENTS");
  EXPECT_EQ(tir.Find("file_type")->value, "a $ and ! inside");
  EXPECT_EQ(tir.Find("PCY1")->line, 23);
}

TEST(TirFileTest, ConvertsUnitsToSi) {
  std::string text = test::ReplaceOnce(kMinimal, "LENGTH = 'meter'", "LENGTH = 'mm'");
  text = test::ReplaceOnce(text, "FORCE  = 'newton'", "FORCE  = 'kN'");
  text = test::ReplaceOnce(text, "ANGLE  = 'radians'", "ANGLE  = 'deg'");
  text = test::ReplaceOnce(text, "UNLOADED_RADIUS = 0.3943", "UNLOADED_RADIUS = 394.3");
  text = test::ReplaceOnce(text, "FNOMIN = 6752", "FNOMIN = 6.752");
  text = test::ReplaceOnce(text, "LONGVL = 16.6", "LONGVL = 16600");
  text = test::ReplaceOnce(text, "VERTICAL_STIFFNESS = 314931.2969",
                           "VERTICAL_STIFFNESS = 0.3149312969");              // kN/mm
  text = test::ReplaceOnce(text, "INFLPRES = 260000", "INFLPRES = 0.00026");  // kN/mm^2
  text = test::ReplaceOnce(text, "ALPMAX = 0.96", "ALPMAX = 55");
  const MagicFormulaParams<double> p = ParseTirFile(text, "units.tir").params;
  EXPECT_NEAR(p.UNLOADED_RADIUS, 0.3943, 1e-15);
  EXPECT_NEAR(p.FNOMIN, 6752, 1e-9);
  EXPECT_NEAR(p.LONGVL, 16.6, 1e-12);
  EXPECT_NEAR(p.VERTICAL_STIFFNESS, 314931.2969, 1e-6);
  EXPECT_NEAR(p.INFLPRES, 260000, 1e-6);
  EXPECT_NEAR(p.ALPMAX, DegToRad(55), 1e-15);
  EXPECT_DOUBLE_EQ(p.PCY1, 1.4759);    // dimensionless: never converted
  EXPECT_DOUBLE_EQ(p.PKY1, -28.3155);  // per rad by definition

  // An explicit PRESSURE unit wins over FORCE/LENGTH^2; TIME scales speeds.
  text = test::ReplaceOnce(kMinimal, "TIME   = 'second'", "TIME = 'hour'\nPRESSURE = 'bar'");
  text = test::ReplaceOnce(text, "INFLPRES = 260000", "INFLPRES = 2.6");
  text = test::ReplaceOnce(text, "LONGVL = 16.6", "LONGVL = 59760");
  const MagicFormulaParams<double> q = ParseTirFile(text, "units.tir").params;
  EXPECT_NEAR(q.INFLPRES, 260000, 1e-9);
  EXPECT_NEAR(q.LONGVL, 16.6, 1e-12);
}

TEST(TirFileTest, MissingFileNamesTheFile) {
  try {
    ReadTirFile("/nonexistent/folder/tyre.tir");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_TRUE(test::Contains(e.what(), "/nonexistent/folder/tyre.tir"));
  }
  try {
    LoadMagicFormula(test::SourcePath("tests/data/tir"));  // a folder
    FAIL();
  } catch (const InputError& e) {
    EXPECT_TRUE(test::Contains(e.what(), "folder"));
  }
}

TEST(TirFileTest, MalformedLinesNameFileAndLine) {
  ExpectParseError(test::ReplaceOnce(kMinimal, "PCY1 = 1.4759", "PCY1 1.4759"),
                   {"bad.tir:23:", "KEY = value"});
  ExpectParseError(test::ReplaceOnce(kMinimal, "PCY1 = 1.4759", "PCY1 = 1.4759 N"),
                   {"bad.tir:23:", "PCY1", "not a number"});
  ExpectParseError(test::ReplaceOnce(kMinimal, "PCY1 = 1.4759", "= 1.4759"), {"bad.tir:23:"});
  ExpectParseError(test::ReplaceOnce(kMinimal, "PCY1 = 1.4759", "PCY1 = 1.47x"),
                   {"bad.tir:23:", "PCY1", "not a number"});
  ExpectParseError(test::ReplaceOnce(kMinimal, "PCY1 = 1.4759", "PCY1 = '1.4759'"),
                   {"bad.tir:23:", "not a number"});
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity"}) {
    ExpectParseError(test::ReplaceOnce(kMinimal, "PCY1 = 1.4759", std::string("PCY1 = ") + bad),
                     {"bad.tir:23:", "PCY1", "not a number"});
  }
  ExpectParseError(test::ReplaceOnce(kMinimal, "PCY1 = 1.4759", "PCY1 = 1\nPCY1 = 2"),
                   {"bad.tir:24:", "PCY1", "twice", "23"});
  ExpectParseError(test::ReplaceOnce(kMinimal, "[MODEL]", "[MODEL"), {"bad.tir:10:", "]"});
  ExpectParseError(test::ReplaceOnce(kMinimal, "TYPE = 'tir'", "TYPE = 'tir"),
                   {"bad.tir:3:", "unterminated"});
  ExpectParseError(test::ReplaceOnce(kMinimal, "LENGTH = 'meter'", "LENGTH = 'furlong'"),
                   {"bad.tir:5:", "furlong", "'mm'"});
}

// `text` with the whole line that starts with `key` (the first after `after`) replaced by `to`
// ("" removes the line).
std::string ReplaceLine(const std::string& text, const std::string& key, const std::string& to,
                        const std::string& after = "") {
  const size_t at = text.find("\n" + key + " ", text.find(after));
  if (at == std::string::npos) throw std::runtime_error("test: no line " + key);
  const size_t end = text.find('\n', at + 1);
  return text.substr(0, at + 1) + (to.empty() ? "" : to + "\n") + text.substr(end + 1);
}

// `text` with the section `[name]` (header to the next header) moved to the end.
std::string MoveSectionToEnd(const std::string& text, const std::string& name) {
  const size_t at = text.find("[" + name + "]");
  const size_t end = text.find("\n[", at);
  return text.substr(0, at) + text.substr(end + 1) + "\n" + text.substr(at, end + 1 - at);
}

// As real tools write them: keys with empty values (some with a comment after), '$' and '!'
// comments anywhere and sections out of order load as the same file with those keys left out,
// with one warning listing the empty keys; forces agree exactly on a grid.
TEST(TirFileTest, EmptyValuesAndOddCommentsReadAsTheKeysAbsent) {
  const std::string original = test::ReadTextFile(TirPath("mfeval/MagicFormula61_Parameters.tir"));
  std::string removed = ReplaceLine(original, "ROAD_INCREMENT", "");
  removed = ReplaceLine(removed, "WIDTH", "");
  removed = ReplaceLine(removed, "INFLPRES", "");
  removed = ReplaceLine(removed, "MASS", "", "[INERTIA]");
  std::string odd = ReplaceLine(original, "ROAD_INCREMENT", "ROAD_INCREMENT           =");
  odd = ReplaceLine(odd, "WIDTH", "  WIDTH =    $ left empty by the fitting tool");
  odd = ReplaceLine(odd, "INFLPRES", "INFLPRES =! empty too");
  odd = ReplaceLine(odd, "MASS", "MASS                     =", "[INERTIA]");
  odd = test::ReplaceOnce(odd, "[VERTICAL]", "  $ an indented comment\n[VERTICAL]   ! trailing");
  odd = test::ReplaceOnce(odd, "\nPCY1 ", "\n! a comment line\nPCY1 ");
  odd = MoveSectionToEnd(odd, "MODEL");
  odd = MoveSectionToEnd(odd, "UNITS");
  ASSERT_NE(odd.find("[VERTICAL]   ! trailing"), std::string::npos);
  const TirFile a = ParseTirFile(odd, "odd.tir");
  const TirFile b = ParseTirFile(removed, "removed.tir");
  EXPECT_TRUE(b.warnings.empty()) << b.warnings.front();
  ASSERT_EQ(a.warnings.size(), 1u);
  EXPECT_TRUE(test::Contains(a.warnings[0],
                             "odd.tir: keys without a value, taken as absent "
                             "(defaults used): WIDTH, INFLPRES, MASS, "
                             "ROAD_INCREMENT"));  // file order: [MODEL] was moved last
  EXPECT_EQ(a.defaulted, b.defaulted);
  for (const auto& info : MagicFormulaParamTable()) {
    EXPECT_EQ(a.params.*info.field, b.params.*info.field) << info.name;
  }
  for (double fz : {1000.0, 4000.0, 8000.0}) {
    for (double alpha : {-0.2, -0.03, 0.0, 0.05, 0.2}) {
      for (double kappa : {-0.1, 0.0, 0.08}) {
        for (double camber : {0.0, 0.05}) {
          const TyreOperatingPoint<double> op{fz, kappa, alpha, camber, 20.0, 0.0, 0.0};
          const auto fa = CalcMagicFormula(a.params, op, {});
          const auto fb = CalcMagicFormula(b.params, op, {});
          EXPECT_EQ(fa.fx, fb.fx);
          EXPECT_EQ(fa.fy, fb.fy);
          EXPECT_EQ(fa.mz, fb.mz);
        }
      }
    }
  }
}

// Keys that are neither coefficients nor known keys of the format are kept and listed once in
// one warning; a value that is not a number is still an error naming the file and line.
TEST(TirFileTest, UnknownKeysAreWarnedNotRefused) {
  const std::string text = test::ReplaceOnce(
      kMinimal, "PCY1 = 1.4759", "PCY1 = 1.4759\nPKY11 = 3 $ misspelt\nMY_NOTE = 'x'\nPKY11 = 4");
  const TirFile tir = ParseTirFile(text, "x.tir");
  ASSERT_EQ(tir.warnings.size(), 1u);
  EXPECT_EQ(tir.warnings[0], "x.tir: unknown keys, not used: PKY11, MY_NOTE");
  EXPECT_EQ(tir.params.PCY1, 1.4759);
  EXPECT_TRUE(ParseTirFile(kMinimal, "x.tir").warnings.empty());
  ExpectParseError(test::ReplaceOnce(kMinimal, "PCY1 = 1.4759", "PCY1 = abc $ not a number"),
                   {"bad.tir:23:", "PCY1", "'abc'", "not a number"});
}

TEST(TirFileTest, UnsupportedOrMissingFittypIsAnError) {
  ExpectParseError(test::ReplaceOnce(kMinimal, "FITTYP = 61", "FITTYP = 52"),
                   {"bad.tir:11:", "FITTYP = 52", "61 (MF 6.1)"});
  ExpectParseError(test::ReplaceOnce(kMinimal, "FITTYP = 61", "FITTYP = 6.5"),
                   {"bad.tir:11:", "FITTYP"});
  ExpectParseError(test::ReplaceOnce(kMinimal, "FITTYP = 61", "USE_MODE = 4"),
                   {"bad.tir", "no FITTYP"});
  // Fuzz regressions (UBSan: a float converted to an int that cannot hold it): not numbers, or
  // numbers no int holds, are unsupported versions.
  for (const char* bad : {"nan", "-nan", "inf", "infinity", "1e300", "-3e9", "2147483648"}) {
    ExpectParseError(test::ReplaceOnce(kMinimal, "FITTYP = 61", std::string("FITTYP = ") + bad),
                     {"bad.tir:11:", "FITTYP", "not supported"});
  }
  // Quoted: text, not the version number, said so.
  ExpectParseError(test::ReplaceOnce(kMinimal, "FITTYP = 61", "FITTYP = '61'"),
                   {"bad.tir:11:", "FITTYP = '61' is quoted text", "(FITTYP = 61)"});
  // A file on disk: the message names it.
  test::TempDir dir;
  const auto path = dir.Write("v52.tir", test::ReplaceOnce(kMinimal, "FITTYP = 61", "FITTYP = 52"));
  try {
    LoadMagicFormula(path);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_TRUE(test::Contains(e.what(), path.string() + ":11:"));
  }
  // The accepted values.
  for (const auto& [fittyp, version] :
       {std::pair{"5", MagicFormulaVersion::kMf52}, std::pair{"6", MagicFormulaVersion::kMf52},
        std::pair{"21", MagicFormulaVersion::kMf52}, std::pair{"61", MagicFormulaVersion::kMf61},
        std::pair{"62", MagicFormulaVersion::kMf62}}) {
    const std::string text =
        test::ReplaceOnce(kMinimal, "FITTYP = 61", std::string("FITTYP = ") + fittyp);
    EXPECT_EQ(ParseTirFile(text, "x.tir").params.version, version) << fittyp;
  }
}

// Numbers with a Fortran-style exponent (D for E), as Fortran tools write them, are read; two
// exponents are not numbers.
TEST(TirFileTest, ReadsFortranStyleExponents) {
  const TirFile a =
      ParseTirFile(test::ReplaceOnce(kMinimal, "FNOMIN = 6752", "FNOMIN = 6.752D+03"), "x.tir");
  const TirFile b =
      ParseTirFile(test::ReplaceOnce(kMinimal, "FNOMIN = 6752", "FNOMIN = 6752.0d0"), "x.tir");
  const TirFile c = ParseTirFile(kMinimal, "x.tir");
  EXPECT_EQ(a.params.FNOMIN, c.params.FNOMIN);
  EXPECT_EQ(b.params.FNOMIN, c.params.FNOMIN);
  ExpectParseError(test::ReplaceOnce(kMinimal, "FNOMIN = 6752", "FNOMIN = 6.7D+0D3"),
                   {"bad.tir:16:", "FNOMIN"});
}

TEST(TirFileTest, TableListsEveryFieldOnce) {
  const auto table = MagicFormulaParamTable();
  std::set<std::string_view> names;
  std::vector<double MagicFormulaParams<double>::*> fields;  // member pointers have no '<'
  for (const auto& info : table) {
    EXPECT_TRUE(names.insert(info.name).second) << info.name;
    EXPECT_EQ(std::find(fields.begin(), fields.end(), info.field), fields.end()) << info.name;
    fields.push_back(info.field);
    EXPECT_FALSE(info.section.empty()) << info.name;
  }
  // CastFields (FieldsOf) covers every field: give each a distinct value and cast there and back.
  MagicFormulaParams<double> p;
  double value = 1.0;
  for (const auto& info : table) p.*info.field = (value += 1.0);
  p.version = MagicFormulaVersion::kMf52;
  const MagicFormulaParams<double> back = p.Cast<Jet2>().Cast<double>();
  EXPECT_EQ(back.version, MagicFormulaVersion::kMf52);
  for (const auto& info : table) EXPECT_EQ(back.*info.field, p.*info.field) << info.name;
}

// What standard readers (MF-Tyre, mfeval) expect of each line: a '$' or '!' comment, a
// [SECTION], or KEY = a finite number or a quoted string, never an empty value.
void ExpectStandardLines(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '$' || line[0] == '!' || line[0] == '[') continue;
    const size_t eq = line.find('=');
    ASSERT_NE(eq, std::string::npos) << name << ": " << line;
    std::string value = line.substr(eq + 1, line.find('$') - eq - 1);
    value.erase(0, value.find_first_not_of(' '));
    value.erase(value.find_last_not_of(' ') + 1);
    ASSERT_FALSE(value.empty()) << name << ": " << line;
    if (value.front() == '\'') continue;
    size_t used = 0;
    const double number = std::stod(value, &used);
    EXPECT_EQ(used, value.size()) << name << ": " << line;
    EXPECT_TRUE(std::isfinite(number)) << name << ": " << line;
  }
}

TEST(TirFileTest, WriterRoundTripsExactly) {
  test::TempDir dir;
  for (const char* name :
       {"mfeval/MagicFormula52_Parameters.tir", "mfeval/MagicFormula61_Parameters.tir",
        "mfeval/MagicFormula62_Parameters.tir", "chrono/HMMWV_Pac02Tire.tir"}) {
    const MagicFormulaParams<double> original = LoadMagicFormula(TirPath(name));
    const auto path = dir.path() / "written.tir";
    WriteTirFile(path, original);
    const TirFile back = ReadTirFile(path);
    EXPECT_TRUE(back.defaulted.empty()) << name;
    EXPECT_TRUE(back.warnings.empty()) << name << ": " << back.warnings.front();
    ExpectStandardLines(test::ReadTextFile(path), name);
    EXPECT_EQ(back.params.version, original.version) << name;
    for (const auto& info : MagicFormulaParamTable()) {
      EXPECT_EQ(back.params.*info.field, original.*info.field) << name << " " << info.name;
    }
    const TyreOperatingPoint<double> op{original.FNOMIN, 0.05, 0.05, 0.02, 20.0, 0.0, 0.0};
    const auto a = CalcMagicFormula(original, op, {});
    const auto b = CalcMagicFormula(back.params, op, {});
    EXPECT_EQ(a.fx, b.fx);
    EXPECT_EQ(a.mz, b.mz);
  }
  // A folder that does not exist: InputError naming the path, nothing written.
  try {
    WriteTirFile(dir.path() / "missing" / "x.tir", MagicFormulaDefaults());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_TRUE(test::Contains(e.what(), "x.tir"));
  }
}

}  // namespace
}  // namespace hotlap::tyre
