// In-process servers for the protocol and fault tests, on 127.0.0.1 with an
// ephemeral port: an HTTP server (cpp-httplib) whose handlers the test sets,
// and a raw TCP server that misbehaves below HTTP (hangs, cuts a body short).
#pragma once

#include <httplib.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace apprentice::llm::testing {

class TestHttpServer {
 public:
  TestHttpServer();
  ~TestHttpServer();
  httplib::Server& server() { return server_; }
  // Call after registering handlers.
  void start();
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_); }
  // Blocks a handler for up to `limit`, returning early when the server is
  // being torn down, so that slow-server tests do not slow the teardown.
  void wait(std::chrono::milliseconds limit);

 private:
  httplib::Server server_;
  int port_ = 0;
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable released_;
  bool stopping_ = false;
};

class RawTcpServer {
 public:
  enum class Mode {
    kHang,     // accepts, reads the request, never answers
    kCutBody,  // answers 200 with Content-Length larger than the body sent, then closes
  };
  explicit RawTcpServer(Mode mode);
  ~RawTcpServer();
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_); }
  int connections() const { return connections_.load(); }

 private:
  void run();

  Mode mode_;
  int listen_fd_ = -1;
  int port_ = 0;
  std::atomic<bool> stopping_{false};
  std::atomic<int> connections_{0};
  std::vector<int> open_fds_;
  std::thread thread_;
};

}  // namespace apprentice::llm::testing
