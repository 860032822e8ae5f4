#pragma once
/// @file
/// The observer's live page (`hotlap observe --serve PORT`, docs/observer.md, "Live page"): a
/// minimal HTTP/1.1 server on plain POSIX sockets, in a thread of its own, bound to 127.0.0.1
/// only. It serves
/// - `GET /`: a self-contained HTML page (no outside script or font) whose inline script polls
///   `/data` and draws the tread, carcass and disc estimates of the four corners with their
///   1-sigma bands on canvases as they arrive;
/// - `GET /data?from=N`: JSON `{"columns": [...], "rows": [[...], ...], "from": N, "next": M,
///   "done": bool}`, the estimate rows N to M - 1 (at most kMaxRowsPerResponse; NaN as null),
///   `done` once the input has ended and every row has been handed out;
/// - anything else: 404; a request that is not a GET: 405.
///
/// How to use: construct with the port (0: any free one; port() says which) and the estimate
/// columns, Add() each row as it is written, Finish() at the end of the input, then (optionally)
/// ServeFor() to keep serving a while; the destructor stops the thread. The filter's thread only
/// appends under a mutex: a slow or stuck browser never holds up the estimates (each connection
/// is read with a 2 s limit and answered at once, one at a time).

#include <atomic>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace hotlap::observe {

class LiveServer {
 public:
  static constexpr size_t kMaxRowsPerResponse = 5000;

  /// Binds 127.0.0.1:`port` and starts serving. InputError naming the port and the system's
  /// reason if it cannot (in use, not allowed).
  LiveServer(int port, std::vector<std::string> columns);
  ~LiveServer();
  LiveServer(const LiveServer&) = delete;
  LiveServer& operator=(const LiveServer&) = delete;

  /// The port it listens on.
  int port() const { return port_; }
  void Add(const std::vector<double>& row);
  /// The input has ended: `/data` says done once the page has every row.
  void Finish();
  /// Blocks for `seconds` while the thread keeps serving (the page stays up after the input).
  void ServeFor(double seconds) const;
  /// Requests answered so far.
  long requests() const { return requests_; }

  /// The page served at `/` (exposed for tests).
  static std::string Page();

 private:
  void Run();
  void Handle(int fd);
  std::string DataJson(size_t from);

  std::vector<std::string> columns_;
  int listen_fd_ = -1;
  int port_ = 0;
  std::atomic<bool> stop_{false};
  std::atomic<long> requests_{0};
  std::mutex mutex_;
  std::vector<std::vector<double>> rows_;
  bool done_ = false;
  std::thread thread_;
};

}  // namespace hotlap::observe
