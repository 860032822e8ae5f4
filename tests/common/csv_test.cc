#include "hotlap/common/csv.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <locale>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap {
namespace {

namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using test::Contains;
using test::ReadTextFile;

// A fresh folder per test (removed with everything in it at the end) and helpers on it.
class CsvTest : public ::testing::Test {
 protected:
  // The names of everything in the folder.
  std::vector<std::string> Listing() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

  // The message of the InputError that reading `text` throws ("" and a failure if none).
  std::string ReadError(const std::string& text, const std::string& name = "bad.csv") {
    const fs::path path = tmp_.Write(name, text);
    try {
      ReadCsv(path);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no InputError for:\n" << text;
    return "";
  }

  const test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
};

TEST_F(CsvTest, RoundTripKeepsValuesEmptyCellsAndMetadata) {
  const std::vector<std::pair<std::string, std::string>> metadata = {
      {"track", "darlington"}, {"source", "hotlap 0.3 qss, lap 2"}, {"a plain comment", ""}};
  const std::vector<std::string> columns = {"time_s", "fx_fl_N", "tread_temp_fl_C"};
  const std::vector<std::vector<double>> values = {
      {0.0, 0.1, 1.0 / 3.0, 1700000000.001},
      {-1234.56789012345, kNaN, 1e-310, 6.02214076e23},
      {kNaN, 85.0, -0.0, std::acos(-1.0) * 1e5},
  };
  const fs::path path = dir_ / "round.csv";
  WriteCsv(path, metadata, columns, values);

  const CsvTable table = ReadCsv(path);
  EXPECT_EQ(table.path, path);
  EXPECT_EQ(table.metadata, metadata);
  EXPECT_EQ(table.columns, columns);
  ASSERT_EQ(table.values.size(), 3u);
  ASSERT_EQ(table.RowCount(), 4u);
  for (size_t c = 0; c < values.size(); ++c) {
    ASSERT_EQ(table.values[c].size(), 4u);
    for (size_t r = 0; r < 4; ++r) {
      const double expected = values[c][r];
      const double got = table.values[c][r];
      if (std::isnan(expected)) {
        EXPECT_TRUE(std::isnan(got)) << "column " << c << " row " << r;
      } else {
        EXPECT_NEAR(got, expected, 1e-9 * std::abs(expected)) << "column " << c << " row " << r;
        EXPECT_EQ(got, expected) << "shortest round-trip text should be exact";
      }
    }
  }
  // 3 metadata lines and the header come first.
  EXPECT_EQ(table.line_numbers, (std::vector<int>{5, 6, 7, 8}));
}

TEST_F(CsvTest, WritesTheExpectedText) {
  const fs::path path = dir_ / "small.csv";
  WriteCsv(path, {{"track", "darlington"}, {"a note", ""}}, {"time_s", "x"},
           {{0.0, 0.1, 2.0}, {1.5, kNaN, -3e-7}});
  EXPECT_EQ(ReadTextFile(path), "# track: darlington\n# a note\ntime_s,x\n0,1.5\n0.1,\n2,-3e-07\n");
  // No temporary file is left beside it.
  EXPECT_EQ(Listing(), std::vector<std::string>{"small.csv"});
}

TEST_F(CsvTest, ReadsBomCrlfBlankLinesSpacesAndPlusSign) {
  const fs::path path = tmp_.Write("log.csv",
                                   "\xEF\xBB\xBF# track :  darlington \r\n"
                                   "#free text, no colon\r\n"
                                   "\r\n"
                                   " time_s , speed_mps ,note\r\n"
                                   "0, 1.5 ,\r\n"
                                   "   \r\n"
                                   "0.5,+2e1,-0.25\r\n"
                                   "1,,7");  // no line end at the end of the file
  const CsvTable table = ReadCsv(path);
  ASSERT_EQ(table.metadata.size(), 2u);
  EXPECT_EQ(table.metadata[0], (std::pair<std::string, std::string>{"track", "darlington"}));
  EXPECT_EQ(table.metadata[1], (std::pair<std::string, std::string>{"free text, no colon", ""}));
  EXPECT_EQ(table.columns, (std::vector<std::string>{"time_s", "speed_mps", "note"}));
  EXPECT_EQ(table.ColumnIndex("speed_mps"), 1);
  EXPECT_EQ(table.ColumnIndex("note"), 2);
  EXPECT_EQ(table.ColumnIndex("speed"), -1);
  EXPECT_EQ(&table.Column("note"), &table.values[2]);
  try {
    table.Column("speed");
    ADD_FAILURE() << "no error for a missing column";
  } catch (const InputError& e) {
    EXPECT_TRUE(test::Contains(e.what(), path.string()));
    EXPECT_TRUE(test::Contains(e.what(), "no column 'speed'"));
  }
  ASSERT_EQ(table.RowCount(), 3u);
  EXPECT_EQ(table.values[0], (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_EQ(table.values[1][0], 1.5);
  EXPECT_EQ(table.values[1][1], 20.0);
  EXPECT_TRUE(std::isnan(table.values[1][2]));
  EXPECT_TRUE(std::isnan(table.values[2][0]));
  EXPECT_EQ(table.values[2][1], -0.25);
  EXPECT_EQ(table.values[2][2], 7.0);
  // Blank lines count in the line numbers.
  EXPECT_EQ(table.line_numbers, (std::vector<int>{5, 7, 8}));
}

// A C++ locale with a decimal comma and digit grouping, as a German user might have.
struct DecimalComma : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
  char do_thousands_sep() const override { return '.'; }
  std::string do_grouping() const override { return "\3"; }
};

TEST_F(CsvTest, NumbersIgnoreTheGlobalLocale) {
  const std::locale saved =
      std::locale::global(std::locale(std::locale::classic(), new DecimalComma));
  const fs::path path = dir_ / "locale.csv";
  WriteCsv(path, {}, {"time_s", "x"}, {{0.0, 1.0}, {2.5, -12345.125}});
  const CsvTable table = ReadCsv(path);
  std::locale::global(saved);
  EXPECT_EQ(ReadTextFile(path), "time_s,x\n0,2.5\n1,-12345.125\n");
  EXPECT_EQ(table.values[1], (std::vector<double>{2.5, -12345.125}));
}

TEST_F(CsvTest, RowWithTooManyOrTooFewCellsNamesFileLineAndCounts) {
  std::string message = ReadError("time_s,a\n0,1\n\n1,2,3\n");
  EXPECT_TRUE(Contains(message, "bad.csv:4:"));
  EXPECT_TRUE(Contains(message, "3 cells"));
  EXPECT_TRUE(Contains(message, "has 2 columns"));
  message = ReadError("time_s,a,b\n0,1,2\n1,2\n");
  EXPECT_TRUE(Contains(message, "bad.csv:3:"));
  EXPECT_TRUE(Contains(message, "2 cells"));
  EXPECT_TRUE(Contains(message, "has 3 columns"));
}

TEST_F(CsvTest, NonFiniteCellsAreErrorsNamingFileLineAndColumn) {
  for (const std::string cell : {"nan", "NaN", "inf", "-inf", "Inf", "-INF", "infinity", "1e999"}) {
    const std::string message = ReadError("# x: y\ntime_s,speed_mps\n0,1\n1," + cell + "\n");
    EXPECT_TRUE(Contains(message,
                         "bad.csv:4: column 'speed_mps' (column 2): '" + cell + "' is not finite"));
  }
}

TEST_F(CsvTest, UnparsableCellsAreErrorsNamingFileLineAndColumn) {
  for (const std::string cell :
       {"abc", "1.2.3", "12abc", "1e", "0x10", "--1", "+-1", "1 2", "\"3\""}) {
    const std::string message = ReadError("time_s,fx_fl_N,b\n0,1,2\n1,2,3\n2," + cell + ",4\n");
    EXPECT_TRUE(Contains(message,
                         "bad.csv:4: column 'fx_fl_N' (column 2): '" + cell + "' is not a number"));
  }
}

TEST_F(CsvTest, TinyNumbersUnderflowToZero) {
  const CsvTable table = ReadCsv(tmp_.Write("tiny.csv", "time_s,x\n0,1e-400\n1,-1e-400\n"));
  EXPECT_EQ(table.values[1][0], 0.0);
  EXPECT_EQ(table.values[1][1], 0.0);
  EXPECT_TRUE(std::signbit(table.values[1][1]));
}

TEST_F(CsvTest, HeaderProblemsAreErrors) {
  std::string message = ReadError("# a: b\ntime_s,fx_fl_N,time_s\n0,1,2\n");
  EXPECT_TRUE(Contains(message, "bad.csv:2:"));
  EXPECT_TRUE(Contains(message, "'time_s' twice (columns 1 and 3)"));
  message = ReadError("time_s, ,x\n0,1,2\n");
  EXPECT_TRUE(Contains(message, "bad.csv:1:"));
  EXPECT_TRUE(Contains(message, "column 2 of the header has no name"));
}

TEST_F(CsvTest, FileWithoutHeaderOrRowsIsAnError) {
  EXPECT_TRUE(Contains(ReadError(""), "bad.csv: no header row"));
  EXPECT_TRUE(Contains(ReadError("\xEF\xBB\xBF\n\n"), "bad.csv: no header row"));
  EXPECT_TRUE(Contains(ReadError("# track: x\n# note\n"), "bad.csv: no header row"));
  EXPECT_TRUE(Contains(ReadError("# track: x\ntime_s,x\n\n"), "bad.csv: no data rows"));
}

TEST_F(CsvTest, CommentLineAfterTheHeaderIsAnError) {
  const std::string message = ReadError("time_s,x\n0,1\n# late: 2\n1,2\n");
  EXPECT_TRUE(Contains(message, "bad.csv:3:"));
  EXPECT_TRUE(Contains(message, "only allowed before the header (line 1)"));
}

TEST_F(CsvTest, UnreadableFileIsAnError) {
  const fs::path missing = dir_ / "missing.csv";
  try {
    ReadCsv(missing);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "cannot read '" + missing.string() + "'"));
    EXPECT_TRUE(Contains(e.what(), "No such file"));
  }
  fs::create_directories(dir_ / "folder.csv");
  try {
    ReadCsv(dir_ / "folder.csv");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "cannot read '" + (dir_ / "folder.csv").string() + "'"));
    EXPECT_TRUE(Contains(e.what(), "folder"));
  }
}

TEST_F(CsvTest, MismatchedColumnsAreProgrammingErrorsAndWriteNothing) {
  const fs::path path = dir_ / "out.csv";
  EXPECT_THROW(WriteCsv(path, {}, {"a", "b"}, {{1.0}}), std::invalid_argument);
  EXPECT_THROW(WriteCsv(path, {}, {"a", "b"}, {{1.0, 2.0}, {1.0}}), std::invalid_argument);
  EXPECT_THROW(WriteCsv(path, {}, {"a", "b,c"}, {{1.0}, {2.0}}), std::invalid_argument);
  EXPECT_THROW(WriteCsv(path, {}, {"a", ""}, {{1.0}, {2.0}}), std::invalid_argument);
  EXPECT_THROW(WriteCsv(path, {{"a:b", "c"}}, {"a"}, {{1.0}}), std::invalid_argument);
  EXPECT_THROW(WriteCsv(path, {{"a", "b\nc"}}, {"a"}, {{1.0}}), std::invalid_argument);
  EXPECT_THROW(WriteCsv(path, {}, {"a"}, {{1.0, kNaN}}), std::invalid_argument);
  EXPECT_THROW(WriteCsv(path, {}, {"a", "b"}, {{1.0, 2.0}, {0.0, -HUGE_VAL}}), NumericalError);
  EXPECT_TRUE(Listing().empty());
}

TEST_F(CsvTest, FailedWriteLeavesTheOldFileAndNoTemporary) {
  const fs::path path = tmp_.Write("out.csv", "time_s\n1\n");
  EXPECT_THROW(WriteCsv(path, {}, {"a", "b"}, {{1.0, 2.0}, {1.0}}), std::invalid_argument);
  EXPECT_EQ(ReadTextFile(path), "time_s\n1\n");
  EXPECT_EQ(Listing(), std::vector<std::string>{"out.csv"});
}

TEST_F(CsvTest, WriteThatFailsOnRenameLeavesNoFile) {
  // A non-empty folder under the target name: the temporary is written, the rename fails.
  fs::create_directories(dir_ / "out.csv");
  tmp_.Write("out.csv/keep", "x");
  EXPECT_THROW(WriteCsv(dir_ / "out.csv", {}, {"a"}, {{1.0}}), InputError);
  EXPECT_EQ(Listing(), std::vector<std::string>{"out.csv"});
  EXPECT_TRUE(fs::is_directory(dir_ / "out.csv"));
  // And into a folder that does not exist.
  EXPECT_THROW(WriteCsv(dir_ / "nowhere" / "out.csv", {}, {"a"}, {{1.0}}), InputError);
  EXPECT_EQ(Listing(), std::vector<std::string>{"out.csv"});
}

}  // namespace
}  // namespace hotlap
