// `hotlap replay --report`: writes one self-contained HTML report of the replayed log that renders
// in headless Chromium (all charts drawn, no script errors; Debian's chromium is a test
// dependency, see scripts/install-deps.sh --test) and agrees with the channels CSV.

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hotlap/common/csv.h"
#include "report/chromium.h"
#include "test_util.h"

namespace {

namespace fs = std::filesystem;
using hotlap::test::Contains;
using hotlap::test::ReadTextFile;

const fs::path kExampleLog = fs::path(HOTLAP_SOURCE_DIR) / "data/telemetry/darlington_example.csv";

class ReplayReportTest : public ::testing::Test {
 protected:
  // Runs hotlap with `args`; returns the exit code, stdout and stderr in out_ and err_.
  int Run(const std::string& args) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const int status = std::system(
        (std::string(HOTLAP_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string())
            .c_str());
    out_ = ReadTextFile(out);
    err_ = ReadTextFile(err);
    return WEXITSTATUS(status);
  }

  const hotlap::test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
  std::string out_, err_;
};

TEST_F(ReplayReportTest, WritesAReportThatRendersAndMatchesTheChannels) {
  const fs::path csv = dir_ / "out.csv", html = dir_ / "replay report.html";
  ASSERT_EQ(Run("replay --telemetry " + kExampleLog.string() + " --out " + csv.string() +
                " --report '" + html.string() + "'"),
            0)
      << err_;
  EXPECT_TRUE(Contains(out_, "wrote " + html.string()));
  const std::string page = ReadTextFile(html);
  EXPECT_TRUE(Contains(page, "<title>hotlap replay: darlington_example.csv</title>"));
  EXPECT_TRUE(Contains(page, "Chart.js v3"));  // embedded, so the file works offline
  EXPECT_LT(page.size(), 1'000'000u);

  // The summary table holds the rows the command printed.
  const hotlap::CsvTable table = hotlap::ReadCsv(csv);
  for (const char* corner : {"fl", "fr", "rl", "rr"}) {
    const size_t line = out_.find(std::string("\n") + corner + " ");
    ASSERT_NE(line, std::string::npos) << out_;
    const std::string tread = out_.substr(out_.find_first_not_of(' ', line + 4), 20);
    EXPECT_TRUE(Contains(page, "<td>" + std::string(corner) + "</td><td class=\"num\">" +
                                   tread.substr(0, tread.find(' '))));
  }

  // The tread chart's lines are the CSV's columns (to 1e-4 of their range).
  const std::string open = "<script type=\"application/json\" id=\"hotlap-data\">";
  const size_t begin = page.find(open) + open.size();
  const nlohmann::json data =
      nlohmann::json::parse(page.substr(begin, page.find("</script>", begin) - begin));
  ASSERT_EQ(data["charts"].size(), 7u);
  const nlohmann::json& tread = data["charts"][0];
  EXPECT_EQ(tread["link"], "time");
  for (size_t k = 0; k < 4; ++k) {
    const nlohmann::json& s = tread["series"][k];
    const auto& column =
        table.values[table.ColumnIndex("tread_temp_" + s["label"].get<std::string>() + "_C")];
    const nlohmann::json& y = data["arrays"][s["y"].get<int>()];
    ASSERT_EQ(y.size(), column.size());
    const double range = *std::max_element(column.begin(), column.end()) -
                         *std::min_element(column.begin(), column.end());
    for (size_t i = 0; i < column.size(); i += 97) {
      EXPECT_NEAR(y[i].get<double>(), column[i], 1e-4 * range) << s["label"] << " " << i;
    }
  }

  const auto status = hotlap::test::RenderInChromium(html, dir_);
  EXPECT_TRUE(hotlap::test::RenderedCleanly(status, 7));
}

TEST_F(ReplayReportTest, MissingReportFolderFailsBeforeWork) {
  const fs::path csv = dir_ / "out.csv";
  EXPECT_EQ(Run("replay --telemetry " + kExampleLog.string() + " --out " + csv.string() +
                " --report " + (dir_ / "nope" / "r.html").string()),
            2);
  EXPECT_TRUE(Contains(err_, "--report"));
  EXPECT_TRUE(Contains(err_, "does not exist"));
  EXPECT_FALSE(fs::exists(csv));
}

}  // namespace
