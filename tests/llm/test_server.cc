#include "llm/test_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstring>
#include <stdexcept>

namespace apprentice::llm::testing {

TestHttpServer::TestHttpServer() {
  port_ = server_.bind_to_any_port("127.0.0.1");
  if (port_ <= 0) throw std::runtime_error("cannot bind a test port");
}

void TestHttpServer::start() {
  thread_ = std::thread([this] { server_.listen_after_bind(); });
  while (!server_.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

TestHttpServer::~TestHttpServer() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  released_.notify_all();
  server_.stop();
  if (thread_.joinable()) thread_.join();
}

void TestHttpServer::wait(std::chrono::milliseconds limit) {
  std::unique_lock lock(mutex_);
  released_.wait_for(lock, limit, [this] { return stopping_; });
}

RawTcpServer::RawTcpServer(Mode mode) : mode_(mode) {
  listen_fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = 0;
  if (listen_fd_ < 0 || ::bind(listen_fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
      ::listen(listen_fd_, 8) != 0) {
    throw std::runtime_error("cannot open a raw test socket");
  }
  socklen_t length = sizeof address;
  ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&address), &length);
  port_ = ntohs(address.sin_port);
  thread_ = std::thread([this] { run(); });
}

RawTcpServer::~RawTcpServer() {
  stopping_ = true;
  thread_.join();
  for (int fd : open_fds_) ::close(fd);
  ::close(listen_fd_);
}

void RawTcpServer::run() {
  while (!stopping_) {
    pollfd waiting{listen_fd_, POLLIN, 0};
    if (::poll(&waiting, 1, 20) <= 0) continue;
    int fd = ::accept(listen_fd_, nullptr, nullptr);
    if (fd < 0) continue;
    ++connections_;
    // Read the request (headers and a small body arrive in one go locally).
    char buffer[65536];
    pollfd readable{fd, POLLIN, 0};
    if (::poll(&readable, 1, 500) > 0) (void)::recv(fd, buffer, sizeof buffer, 0);
    if (mode_ == Mode::kHang) {
      open_fds_.push_back(fd);
      continue;
    }
    const char* reply =
        "HTTP/1.1 200 OK\r\nContent-Type: application/json\r\nContent-Length: 400\r\n"
        "Connection: close\r\n\r\n{\"choices\":[{\"text\":\" The goal";
    (void)::send(fd, reply, std::strlen(reply), MSG_NOSIGNAL);
    ::close(fd);
  }
}

}  // namespace apprentice::llm::testing
