#include "hotlap/observe/live_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string_view>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::observe {

namespace {

// Sends all of `data`, giving up on an error or a peer that takes nothing for 2 s.
void SendAll(int fd, std::string_view data) {
  while (!data.empty()) {
    pollfd p{fd, POLLOUT, 0};
    if (::poll(&p, 1, 2000) <= 0) return;
    const ssize_t sent = ::send(fd, data.data(), data.size(), MSG_NOSIGNAL);
    if (sent <= 0) {
      if (sent < 0 && (errno == EINTR || errno == EAGAIN)) continue;
      return;
    }
    data.remove_prefix(static_cast<size_t>(sent));
  }
}

void Respond(int fd, int code, std::string_view reason, std::string_view type,
             std::string_view body) {
  const std::string head = fmt::format(
      "HTTP/1.1 {} {}\r\nContent-Type: {}\r\nContent-Length: {}\r\nCache-Control: no-store\r\n"
      "Connection: close\r\n\r\n",
      code, reason, type, body.size());
  SendAll(fd, head);
  SendAll(fd, body);
}

}  // namespace

LiveServer::LiveServer(int port, std::vector<std::string> columns) : columns_(std::move(columns)) {
  if (port < 0 || port > 65535) {
    throw InputError(
        fmt::format("live page on port {}: a port is 0 to 65535 (0: any free one)", port));
  }
  listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (listen_fd_ < 0) {
    throw InputError(
        fmt::format("live page on port {}: cannot open a socket: {}", port, std::strerror(errno)));
  }
  const int yes = 1;
  ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<uint16_t>(port));
  if (::bind(listen_fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
      ::listen(listen_fd_, 16) != 0) {
    const std::string reason = std::strerror(errno);
    ::close(listen_fd_);
    throw InputError(
        fmt::format("live page on port {}: cannot listen on 127.0.0.1:{}: {}", port, port, reason));
  }
  socklen_t length = sizeof address;
  ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&address), &length);
  port_ = ntohs(address.sin_port);
  thread_ = std::thread([this] { Run(); });
}

LiveServer::~LiveServer() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  if (listen_fd_ >= 0) ::close(listen_fd_);
}

void LiveServer::Add(const std::vector<double>& row) {
  const std::lock_guard<std::mutex> lock(mutex_);
  rows_.push_back(row);
}

void LiveServer::Finish() {
  const std::lock_guard<std::mutex> lock(mutex_);
  done_ = true;
}

void LiveServer::ServeFor(double seconds) const {
  if (seconds > 0.0) std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
}

void LiveServer::Run() {
  while (!stop_) {
    pollfd p{listen_fd_, POLLIN, 0};
    if (::poll(&p, 1, 100) <= 0) continue;
    const int fd = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
    if (fd < 0) continue;
    Handle(fd);
    ::close(fd);
  }
}

std::string LiveServer::DataJson(size_t from) {
  std::string out = "{\"columns\":[";
  for (size_t i = 0; i < columns_.size(); ++i) {
    if (i > 0) out += ',';
    out += '"' + columns_[i] + '"';
  }
  out += "],\"rows\":[";
  size_t next = from;
  bool done = false;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const size_t end = std::min(rows_.size(), from + kMaxRowsPerResponse);
    for (size_t k = from; k < end; ++k) {
      if (k > from) out += ',';
      out += '[';
      const std::vector<double>& row = rows_[k];
      for (size_t i = 0; i < row.size(); ++i) {
        if (i > 0) out += ',';
        out += std::isfinite(row[i]) ? fmt::format("{:.9g}", row[i]) : std::string("null");
      }
      out += ']';
    }
    next = std::max(from, end);
    done = done_ && next >= rows_.size();
  }
  out +=
      fmt::format("],\"from\":{},\"next\":{},\"done\":{}}}", from, next, done ? "true" : "false");
  return out;
}

void LiveServer::Handle(int fd) {
  // The request head, read with a 2 s limit (a browser sends it at once).
  std::string request;
  char buffer[2048];
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (request.find("\r\n\r\n") == std::string::npos && request.size() < 8192) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return;
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) return;
    const ssize_t got = ::recv(fd, buffer, sizeof buffer, 0);
    if (got <= 0) return;
    request.append(buffer, static_cast<size_t>(got));
  }
  ++requests_;
  const size_t line_end = request.find("\r\n");
  const std::string_view line = std::string_view(request).substr(0, line_end);
  const size_t space = line.find(' ');
  const size_t space2 = space == std::string_view::npos ? space : line.find(' ', space + 1);
  if (space == std::string_view::npos || space2 == std::string_view::npos) {
    Respond(fd, 400, "Bad Request", "text/plain", "bad request\n");
    return;
  }
  const std::string_view method = line.substr(0, space);
  const std::string_view target = line.substr(space + 1, space2 - space - 1);
  if (method != "GET") {
    Respond(fd, 405, "Method Not Allowed", "text/plain", "only GET\n");
    return;
  }
  const size_t question = target.find('?');
  const std::string_view path = target.substr(0, question);
  const std::string_view query =
      question == std::string_view::npos ? std::string_view() : target.substr(question + 1);
  if (path == "/") {
    Respond(fd, 200, "OK", "text/html; charset=utf-8", Page());
  } else if (path == "/data") {
    size_t from = 0;
    if (query.substr(0, 5) == "from=") {
      for (char ch : query.substr(5)) {
        if (ch < '0' || ch > '9' || from > (size_t{1} << 40)) break;
        from = 10 * from + static_cast<size_t>(ch - '0');
      }
    }
    Respond(fd, 200, "OK", "application/json", DataJson(from));
  } else {
    Respond(fd, 404, "Not Found", "text/plain", "not found\n");
  }
}

namespace {

// The live page: the charts' frame, then the script that polls /data and draws them.
constexpr const char* kPageHtml = R"html(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>hotlap observe: live estimates</title>
<style>
body { font-family: sans-serif; margin: 1em 2em; color: #222; }
canvas { display: block; margin: 0.5em 0 1.5em 0; border: 1px solid #ccc; }
.legend span { display: inline-block; margin-right: 1.5em; font-weight: bold; }
#hotlap-status { color: #555; }
</style>
</head>
<body>
<h1>hotlap observe: live estimates</h1>
<p>Mean and 1-sigma band of each corner's estimate, drawn as the estimates arrive
(docs/observer.md).</p>
<p class="legend"><span style="color:#1f77b4">fl</span><span style="color:#d62728">fr</span><span
style="color:#2ca02c">rl</span><span style="color:#9467bd">rr</span></p>
<canvas id="chart-tread_temp" width="900" height="220"></canvas>
<canvas id="chart-carcass_temp" width="900" height="220"></canvas>
<canvas id="chart-disc_temp" width="900" height="220"></canvas>
<p id="hotlap-status" data-expected="3" data-rendered="0" data-errors="0" data-rows="0"
data-done="0">waiting for estimates</p>
<script>
)html";

constexpr const char* kPageScript = R"js('use strict';
const QUANTITIES = [['tread_temp', 'tread temperature, degC'],
                    ['carcass_temp', 'carcass temperature, degC'],
                    ['disc_temp', 'disc temperature, degC']];
const CORNERS = ['fl', 'fr', 'rl', 'rr'];
const COLOURS = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd'];
let columns = null, rows = [], done = false, errors = 0, rendered = 0;
const messages = [];
window.addEventListener('error', e => { errors++; messages.push(String(e.message)); report(); });
function report() {
  const s = document.getElementById('hotlap-status');
  s.dataset.expected = QUANTITIES.length;
  s.dataset.rendered = rendered;
  s.dataset.errors = errors;
  s.dataset.rows = rows.length;
  s.dataset.done = done ? '1' : '0';
  s.textContent = rows.length + ' estimates' + (done ? ', input ended' : ', live') +
      (errors ? '; errors: ' + messages.join('; ') : '');
}
function draw() {
  if (!columns || rows.length === 0) return;
  const t = columns.indexOf('time_s');
  const n = rows.length;
  let drawn = 0;
  for (const [q, label] of QUANTITIES) {
    const canvas = document.getElementById('chart-' + q);
    const ctx = canvas.getContext('2d');
    const w = canvas.width, h = canvas.height;
    const left = 64, right = 12, top = 22, bottom = 28;
    const series = CORNERS.map(c => [columns.indexOf(q + '_' + c + '_C'),
                                     columns.indexOf(q + '_' + c + '_sd_C')]);
    // At most about two points per pixel.
    const step = Math.max(1, Math.floor(n / (2 * (w - left - right))));
    const idx = [];
    for (let k = 0; k < n; k += step) idx.push(k);
    if (idx[idx.length - 1] !== n - 1) idx.push(n - 1);
    const x0 = rows[0][t];
    const x1 = rows[n - 1][t] > x0 ? rows[n - 1][t] : x0 + 1;
    let y0 = Infinity, y1 = -Infinity;
    for (const k of idx) {
      for (const [m, s] of series) {
        const v = rows[k][m];
        if (m < 0 || v === null) continue;
        const sd = rows[k][s] || 0;
        y0 = Math.min(y0, v - sd);
        y1 = Math.max(y1, v + sd);
      }
    }
    if (!(y1 > y0)) { y0 = (isFinite(y0) ? y0 : 0) - 1; y1 = y0 + 2; }
    const X = v => left + (v - x0) / (x1 - x0) * (w - left - right);
    const Y = v => h - bottom - (v - y0) / (y1 - y0) * (h - top - bottom);
    ctx.clearRect(0, 0, w, h);
    series.forEach(([m, s], i) => {
      if (m < 0) return;
      const good = idx.filter(k => rows[k][m] !== null);
      if (good.length === 0) return;
      ctx.beginPath();
      good.forEach((k, j) => {
        const px = X(rows[k][t]), py = Y(rows[k][m] + (rows[k][s] || 0));
        if (j === 0) ctx.moveTo(px, py); else ctx.lineTo(px, py);
      });
      for (let j = good.length - 1; j >= 0; j--) {
        const k = good[j];
        ctx.lineTo(X(rows[k][t]), Y(rows[k][m] - (rows[k][s] || 0)));
      }
      ctx.closePath();
      ctx.globalAlpha = 0.25;
      ctx.fillStyle = COLOURS[i];
      ctx.fill();
      ctx.globalAlpha = 1;
      ctx.beginPath();
      good.forEach((k, j) => {
        if (j === 0) ctx.moveTo(X(rows[k][t]), Y(rows[k][m]));
        else ctx.lineTo(X(rows[k][t]), Y(rows[k][m]));
      });
      ctx.strokeStyle = COLOURS[i];
      ctx.lineWidth = 1.2;
      ctx.stroke();
    });
    ctx.strokeStyle = '#888';
    ctx.strokeRect(left, top, w - left - right, h - top - bottom);
    ctx.fillStyle = '#222';
    ctx.font = '12px sans-serif';
    ctx.fillText(label, left, 15);
    ctx.fillText(y1.toFixed(1), 4, top + 10);
    ctx.fillText(y0.toFixed(1), 4, h - bottom);
    ctx.fillText(x0.toFixed(1) + ' s', left, h - 8);
    ctx.fillText(x1.toFixed(1) + ' s', w - right - 70, h - 8);
    drawn++;
  }
  rendered = drawn;
}
async function poll() {
  try {
    const response = await fetch('/data?from=' + rows.length, {cache: 'no-store'});
    if (!response.ok) throw new Error('/data: HTTP ' + response.status);
    const page = await response.json();
    if (!columns) columns = page.columns;
    for (const r of page.rows) rows.push(r);
    done = page.done;
    draw();
  } catch (e) {
    errors++;
    messages.push(String(e));
  }
  report();
  if (!done && errors === 0) setTimeout(poll, 250);
}
report();
poll();
</script>
</body>
</html>
)js";

}  // namespace

std::string LiveServer::Page() { return std::string(kPageHtml) + kPageScript; }

}  // namespace hotlap::observe
