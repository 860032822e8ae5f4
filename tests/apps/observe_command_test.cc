// End-to-end tests of `hotlap observe`: a log file in, one estimate line per input line out, the
// JSON summary; the stream through a pipe, one line at a time, answered line by line; MoTeC logs,
// `--lap N` and `--channel-map FILE` as replay takes them; the sensor lag; the live page
// (`--serve`), fed a line at a time and drawn in headless Chromium; refusals.

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "apps/run_hotlap.h"
#include "hotlap/common/csv.h"
#include "report/chromium.h"
#include "test_util.h"

namespace {

namespace fs = std::filesystem;
using hotlap::test::Contains;
using hotlap::test::ReadTextFile;

class ObserveCommandTest : public hotlap::test::CommandTest {
 protected:
  // One lap at 20 Hz from synth, sensors without lag.
  fs::path Log() {
    const fs::path log = dir() / "log.csv";
    if (!fs::exists(log)) {
      const auto r = Run("synth --laps 1 --rate-hz 20 --lag-s 0 --out " + log.string());
      EXPECT_EQ(r.exit_code, 0) << r.err;
    }
    return log;
  }
};

TEST_F(ObserveCommandTest, WritesOneEstimateLinePerInputLineAndASummary) {
  const fs::path log = Log(), est = dir() / "est.csv", json = dir() / "o.json";
  const auto r = Run("observe --telemetry " + log.string() + " --out " + est.string() + " --json " +
                     json.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const hotlap::CsvTable in = hotlap::ReadCsv(log), out = hotlap::ReadCsv(est);
  EXPECT_EQ(out.RowCount(), in.RowCount());
  EXPECT_EQ(out.Column("time_s"), in.Column("time_s"));
  for (const char* c : {"carcass_temp_fl_C", "carcass_temp_fl_sd_C", "wear_rr_mm", "wear_rr_sd_mm",
                        "disc_temp_rl_C", "disc_temp_rl_sd_C", "calliper_temp_fr_sd_C"}) {
    EXPECT_GE(out.ColumnIndex(c), 0) << c;
  }
  // The carcass estimate follows the log's carcass channel (its truth plus noise; never read).
  const auto& carcass = out.Column("carcass_temp_fl_C");
  const auto& logged = in.Column("carcass_temp_fl_C");
  EXPECT_NEAR(carcass.back(), logged.back(), 2.0);
  EXPECT_TRUE(Contains(r.out, "mean NIS"));
  EXPECT_TRUE(Contains(r.out, "0 disagreement warning(s)"));
  const nlohmann::json j = Json(json);
  EXPECT_EQ(j["command"], "observe");
  EXPECT_EQ(j["samples"], in.RowCount());
  EXPECT_TRUE(j["corners"]["fl"].contains("carcass_temp_sd_C"));
  const nlohmann::json& tread = j["corners"]["fl"]["sensors"]["tread_temp"];
  EXPECT_EQ(tread["readings"], in.RowCount());
  EXPECT_EQ(tread["used"].get<long>() + tread["rejected"].get<long>() + 1, in.RowCount());
  EXPECT_EQ(tread["nis_bounds95"].size(), 2u);
  EXPECT_FALSE(j["corners"]["fl"]["sensors"].contains("carcass_temp"));
  EXPECT_TRUE(j["disagreements"].is_array());
}

TEST_F(ObserveCommandTest, AnswersAStreamLineByLine) {
  const std::vector<std::string> lines = [&] {
    std::vector<std::string> out;
    std::string text = ReadTextFile(Log());
    size_t from = 0;
    while (from < text.size()) {
      const size_t end = text.find('\n', from);
      const std::string line = text.substr(from, end - from);
      if (!line.empty() && line[0] != '#') out.push_back(line);
      from = end == std::string::npos ? text.size() : end + 1;
    }
    return out;
  }();
  ASSERT_GT(lines.size(), 30u);
  int to_child[2], from_child[2];
  ASSERT_EQ(pipe(to_child), 0);
  ASSERT_EQ(pipe(from_child), 0);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    dup2(to_child[0], 0);
    dup2(from_child[1], 1);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 2);
    close(to_child[1]);
    close(from_child[0]);
    execl(HOTLAP_BINARY, HOTLAP_BINARY, "observe", "--telemetry", "-", "--out", "-",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  close(to_child[0]);
  close(from_child[1]);
  std::signal(SIGPIPE, SIG_IGN);
  std::string received;
  // Reads until `count` lines have arrived in total, or fails after 20 s.
  const auto wait_for_lines = [&](size_t count) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (static_cast<size_t>(std::count(received.begin(), received.end(), '\n')) < count) {
      pollfd p{from_child[0], POLLIN, 0};
      const int left = static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                            deadline - std::chrono::steady_clock::now())
                                            .count());
      if (left <= 0 || poll(&p, 1, left) <= 0) return false;
      char buffer[4096];
      const ssize_t n = read(from_child[0], buffer, sizeof buffer);
      if (n <= 0) return false;
      received.append(buffer, static_cast<size_t>(n));
    }
    return true;
  };
  const auto send = [&](const std::string& line) {
    const std::string text = line + "\n";
    return write(to_child[1], text.data(), text.size()) == static_cast<ssize_t>(text.size());
  };
  // The header and the first line answer with the estimate header and the first estimate (the
  // first line is read before the output starts, so a refused log leaves nothing); then each
  // line with one estimate line, before the next is sent (nothing buffered beyond the line).
  ASSERT_TRUE(send(lines[0]));
  ASSERT_TRUE(send(lines[1]));
  ASSERT_TRUE(wait_for_lines(2)) << "no header and first estimate back";
  const size_t fed = 30;
  for (size_t k = 2; k <= fed; ++k) {
    ASSERT_TRUE(send(lines[k]));
    ASSERT_TRUE(wait_for_lines(k + 1)) << "no estimate for line " << k;
    EXPECT_EQ(std::count(received.begin(), received.end(), '\n'), static_cast<long>(k + 1));
  }
  close(to_child[1]);
  // At the end of input the summary follows on standard error; the estimates are complete.
  char buffer[4096];
  ssize_t n;
  while ((n = read(from_child[0], buffer, sizeof buffer)) > 0) received.append(buffer, n);
  close(from_child[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(std::count(received.begin(), received.end(), '\n'), static_cast<long>(fed + 1));
  EXPECT_EQ(received.substr(0, received.find(',')), "time_s");
}

TEST_F(ObserveCommandTest, RefusesBadInputWithExitTwo) {
  const fs::path log = Log();
  auto r = Run("observe --telemetry " + log.string() + " --out " + (dir() / "e.csv").string() +
               " --config " + (dir() / "missing.yaml").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(Contains(r.err, "missing.yaml"));
  hotlap::test::WriteTextFile(dir() / "short.csv", "time_s,speed_mps\n0,10\n");
  r = Run("observe --telemetry " + (dir() / "short.csv").string() + " --out " +
          (dir() / "e2.csv").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(Contains(r.err, "fx_fl"));
  EXPECT_FALSE(fs::exists(dir() / "e2.csv"));  // refused at the first line: no file
  r = Run("observe --telemetry - --out " + (dir() / "e3.csv").string() + " </dev/null");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(Contains(r.err, "no header"));
  EXPECT_FALSE(fs::exists(dir() / "e3.csv"));
  // Refused further in (an impossible speed 20 rows down): the unfinished file is removed.
  std::vector<std::string> lines;
  {
    const std::string text = hotlap::test::ReadTextFile(log);
    for (size_t at = 0, end; at < text.size(); at = end + 1) {
      end = text.find('\n', at);
      lines.push_back(text.substr(at, end - at));
    }
  }
  size_t h = 0;
  while (lines.at(h).rfind("time_s,", 0) != 0) ++h;
  int speed = 0;
  for (size_t at = 0; lines[h].compare(at, 10, "speed_mps,") != 0;
       at = lines[h].find(',', at) + 1) {
    ++speed;
  }
  std::string& row = lines.at(h + 20);
  size_t cell = 0;
  for (int k = 0; k < speed; ++k) cell = row.find(',', cell) + 1;
  row.replace(cell, row.find(',', cell) - cell, "-50");
  std::string text;
  for (const std::string& l : lines) text += l + "\n";
  hotlap::test::WriteTextFile(dir() / "bad.csv", text);
  r = Run("observe --telemetry " + (dir() / "bad.csv").string() + " --out " +
          (dir() / "e4.csv").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(Contains(r.err, "impossible")) << r.err;
  EXPECT_FALSE(fs::exists(dir() / "e4.csv"));
}

// A MoTeC i2 export is observed as the hotlap CSV of the same numbers: read whole through the
// channel map, its estimates are those of the equivalent CSV read a line at a time; `--lap N`
// keeps that lap's rows (from the export's beacons, from the CSV's lap column) and starts the
// filter there.
TEST_F(ObserveCommandTest, ObservesAMotecExportAndOneLapOfIt) {
  const fs::path motec = hotlap::test::SourcePath("tests/data/motec/darlington_i2.csv");
  const fs::path same = hotlap::test::SourcePath("tests/data/motec/darlington_i2_equivalent.csv");
  const fs::path a = dir() / "motec.csv", b = dir() / "same.csv", json = dir() / "lap.json";
  auto r = Run("observe --telemetry " + motec.string() + " --out " + a.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = Run("observe --telemetry " + same.string() + " --out " + b.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const hotlap::CsvTable whole = hotlap::ReadCsv(a), lines = hotlap::ReadCsv(b);
  ASSERT_EQ(whole.RowCount(), 291u);
  ASSERT_EQ(whole.columns, lines.columns);
  for (size_t i = 0; i < whole.columns.size(); ++i) {
    for (size_t k = 0; k < whole.RowCount(); ++k) {
      ASSERT_NEAR(whole.values[i][k], lines.values[i][k],
                  1e-6 * (1.0 + std::abs(lines.values[i][k])))
          << whole.columns[i] << " row " << k;
    }
  }
  // The disc readings moved the disc estimate: it is not the car file's starting value.
  EXPECT_NEAR(whole.Column("disc_temp_fl_C").front(), 350.0, 1.0);

  const fs::path lap_a = dir() / "lap2_motec.csv", lap_b = dir() / "lap2_same.csv";
  r = Run("observe --telemetry " + motec.string() + " --lap 2 --out " + lap_a.string() +
          " --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = Run("observe --telemetry " + same.string() + " --lap 2 --out " + lap_b.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const hotlap::CsvTable lap = hotlap::ReadCsv(lap_a), lap_same = hotlap::ReadCsv(lap_b);
  ASSERT_EQ(lap.RowCount(), 97u);
  EXPECT_NEAR(lap.Column("time_s").front(), 9.7, 1e-9);
  EXPECT_NEAR(lap.Column("time_s").back(), 19.3, 1e-9);
  EXPECT_EQ(lap.Column("disc_temp_rr_C"), lap_same.Column("disc_temp_rr_C"));
  EXPECT_EQ(lap.Column("carcass_temp_fl_sd_C"), lap_same.Column("carcass_temp_fl_sd_C"));
  // The lap starts the filter afresh: its first disc band is the sensor's alone (0.5 degC),
  // wider than the whole log's at 9.7 s after 97 readings.
  size_t at = 0;
  while (std::abs(whole.Column("time_s")[at] - 9.7) > 1e-9) ++at;
  EXPECT_NEAR(lap.Column("disc_temp_fl_sd_C").front(), 0.5, 1e-9);
  EXPECT_LT(whole.Column("disc_temp_fl_sd_C")[at], 0.4);
  const nlohmann::json j = Json(json);
  EXPECT_EQ(j["lap"], 2);
  EXPECT_EQ(j["samples"], 97);
}

TEST_F(ObserveCommandTest, RefusesALapThatIsNotThereABadChannelMapAndLapsOnAStream) {
  const fs::path motec = hotlap::test::SourcePath("tests/data/motec/darlington_i2.csv");
  const fs::path out = dir() / "e.csv";
  auto r = Run("observe --telemetry " + motec.string() + " --lap 7 --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(Contains(r.err, "lap 7: no such lap; the log has laps 1 to 3")) << r.err;
  EXPECT_FALSE(fs::exists(out));
  const fs::path map =
      hotlap::test::WriteTextFile(dir() / "map.yaml", "channels:\n  Ground Speed: speed\n");
  r = Run("observe --telemetry " + motec.string() + " --channel-map " + map.string() + " --out " +
          out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(Contains(r.err, "missing column")) << r.err;
  EXPECT_TRUE(Contains(r.err, "map.yaml")) << r.err;
  EXPECT_FALSE(fs::exists(out));
  r = Run("observe --telemetry - --lap 1 --out " + out.string() + " < " + Log().string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(Contains(r.err, "need a log file")) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

// `hotlap synth`'s default sensors lag by 0.2 s and its log says so (`# sensor_lag_s: 0.2`): the
// observer takes the lag from there and raises no disagreement; told there is none
// (`--sensor-lag-s 0`) it warns, as the readings trail the states during braking.
TEST_F(ObserveCommandTest, TakesTheSensorLagFromTheLogOrTheOption) {
  const fs::path log = dir() / "lagged.csv", est = dir() / "est.csv", json = dir() / "o.json";
  auto r = Run("synth --laps 1 --rate-hz 20 --out " + log.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = Run("observe --telemetry " + log.string() + " --out " + est.string() + " --json " +
          json.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.out,
                       "sensor lag: tread 0.2 s, disc 0.2 s, calliper 0.2 s (from the "
                       "log's sensor_lag_s)"))
      << r.out;
  EXPECT_TRUE(Contains(r.out, "0 disagreement warning(s)")) << r.out;
  nlohmann::json j = Json(json);
  EXPECT_EQ(j["sensor_lag_s"]["disc_temp"], 0.2);
  EXPECT_TRUE(j["disagreements"].empty());
  // Every sensor's mean NIS near 1 (about 630 readings each: 1 +- 0.06 at one sigma).
  for (const char* c : {"fl", "fr", "rl", "rr"}) {
    for (const auto& [name, sensor] : j["corners"][c]["sensors"].items()) {
      EXPECT_NEAR(sensor["mean_nis"].get<double>(), 1.0, 0.2) << c << " " << name;
    }
  }

  r = Run("observe --telemetry " + log.string() + " --out " + est.string() + " --json " +
          json.string() + " --sensor-lag-s 0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = Json(json);
  EXPECT_EQ(j["sensor_lag_s"]["tread_temp"], 0.0);
  EXPECT_EQ(j["sensor_lag_from"], "--sensor-lag-s");
  EXPECT_FALSE(j["disagreements"].empty());
  EXPECT_TRUE(Contains(r.err, "model and car disagree")) << r.err;
  EXPECT_FALSE(j["consistent"].get<bool>());
  EXPECT_GT(j["corners"]["fl"]["sensors"]["disc_temp"]["rejected"].get<long>(), 0);

  // A log whose sensor_lag_s line is not a time constant is refused.
  std::string text = ReadTextFile(log);
  text.replace(text.find("# sensor_lag_s: 0.2"), 19, "# sensor_lag_s: -1");
  hotlap::test::WriteTextFile(dir() / "bad.csv", text);
  r = Run("observe --telemetry " + (dir() / "bad.csv").string() + " --out " +
          (dir() / "e.csv").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(Contains(r.err, "sensor_lag_s")) << r.err;
  EXPECT_FALSE(fs::exists(dir() / "e.csv"));
}

// GET `path` from 127.0.0.1:`port`: the status code and the body (-1 if the request failed).
std::pair<int, std::string> HttpGet(int port, const std::string& path) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return {-1, ""};
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<uint16_t>(port));
  if (connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    close(fd);
    return {-1, ""};
  }
  const std::string request = "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";
  if (send(fd, request.data(), request.size(), MSG_NOSIGNAL) !=
      static_cast<ssize_t>(request.size())) {
    close(fd);
    return {-1, ""};
  }
  std::string response;
  char buffer[8192];
  for (;;) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 10000) <= 0) break;
    const ssize_t n = recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    response.append(buffer, static_cast<size_t>(n));
  }
  close(fd);
  const size_t body = response.find("\r\n\r\n");
  if (response.rfind("HTTP/1.1 ", 0) != 0 || body == std::string::npos) return {-1, response};
  return {std::stoi(response.substr(9, 3)), response.substr(body + 4)};
}

// `--serve 0` on a stream: the page's data grows line by line as the lines are fed (before the
// input ends, and not done until it has), the page itself draws the three charts of estimates and
// bands in headless Chromium with no script error and every row, and unknown paths are 404.
TEST_F(ObserveCommandTest, ServesALivePageOfTheEstimatesAsTheyArrive) {
  std::vector<std::string> lines;
  {
    const std::string text = ReadTextFile(Log());
    for (size_t at = 0, end; at < text.size(); at = end + 1) {
      end = text.find('\n', at);
      const std::string line = text.substr(at, end - at);
      if (!line.empty() && line[0] != '#') lines.push_back(line);
      if (end == std::string::npos) break;
    }
  }
  ASSERT_GT(lines.size(), 200u);
  const fs::path est = dir() / "est.csv", err = dir() / "serve.err";
  int to_child[2];
  ASSERT_EQ(pipe(to_child), 0);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    dup2(to_child[0], 0);
    close(to_child[1]);
    const int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(e, 2);
    execl(HOTLAP_BINARY, HOTLAP_BINARY, "observe", "--telemetry", "-", "--out", est.c_str(),
          "--serve", "0", "--serve-linger-s", "120", static_cast<char*>(nullptr));
    _exit(127);
  }
  close(to_child[0]);
  std::signal(SIGPIPE, SIG_IGN);
  const auto send_line = [&](const std::string& line) {
    const std::string text = line + "\n";
    return write(to_child[1], text.data(), text.size()) == static_cast<ssize_t>(text.size());
  };
  // Waits up to 20 s for `ready()`.
  const auto wait_for = [](const auto& ready) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!ready()) {
      if (std::chrono::steady_clock::now() > deadline) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
  };
  int port = 0;
  const auto rows_served = [&](bool* done) {
    const auto [code, body] = HttpGet(port, "/data?from=0");
    if (code != 200) return -1;
    const nlohmann::json j = nlohmann::json::parse(body);
    if (done != nullptr) *done = j["done"].get<bool>();
    return static_cast<int>(j["rows"].size());
  };
  // The header and 20 lines: the page is up and serves 20 rows, not done.
  for (size_t k = 0; k <= 20; ++k) ASSERT_TRUE(send_line(lines[k]));
  ASSERT_TRUE(wait_for([&] {
    const std::string text = fs::exists(err) ? ReadTextFile(err) : "";
    const size_t at = text.find("live page at http://127.0.0.1:");
    if (at == std::string::npos) return false;
    port = std::stoi(text.substr(at + 30));
    return true;
  })) << ReadTextFile(err);
  bool done = true;
  ASSERT_TRUE(wait_for([&] { return rows_served(&done) == 20; }));
  EXPECT_FALSE(done);
  // Ten more lines, ten more rows, still live.
  for (size_t k = 21; k <= 30; ++k) ASSERT_TRUE(send_line(lines[k]));
  ASSERT_TRUE(wait_for([&] { return rows_served(&done) == 30; }));
  EXPECT_FALSE(done);
  // The rest, and the end of the input: done, every row.
  for (size_t k = 31; k < lines.size(); ++k) ASSERT_TRUE(send_line(lines[k]));
  close(to_child[1]);
  const int all = static_cast<int>(lines.size()) - 1;
  ASSERT_TRUE(wait_for([&] { return rows_served(&done) == all && done; }));
  const auto [code, body] = HttpGet(port, "/data?from=" + std::to_string(all - 5));
  ASSERT_EQ(code, 200);
  const nlohmann::json tail = nlohmann::json::parse(body);
  EXPECT_EQ(tail["rows"].size(), 5u);
  EXPECT_EQ(tail["next"], all);
  const hotlap::CsvTable table = hotlap::ReadCsv(est);
  EXPECT_EQ(tail["columns"].get<std::vector<std::string>>(), table.columns);
  EXPECT_NEAR(tail["rows"][4][0].get<double>(), table.Column("time_s").back(), 1e-6);
  EXPECT_EQ(HttpGet(port, "/nope").first, 404);

  const auto status = hotlap::test::RenderUrlInChromium(
      "http://127.0.0.1:" + std::to_string(port) + "/", dir() / "chromium");
  EXPECT_TRUE(hotlap::test::RenderedCleanly(status, 3));
  if (status) {
    EXPECT_TRUE(Contains(status->dom, "data-rows=\"" + std::to_string(all) + "\"")) << status->text;
    EXPECT_TRUE(Contains(status->dom, "data-done=\"1\"")) << status->text;
  }
  kill(pid, SIGTERM);
  int wait_status = 0;
  waitpid(pid, &wait_status, 0);
}

}  // namespace
