// Runs the apprentice binary at a pseudo-terminal, as a person at a
// keyboard runs it: the program's stdin, stdout and stderr are the
// terminal, which is its controlling terminal, so that line editing
// (libedit) is on, typed text is echoed, Ctrl-C (byte 3) sends SIGINT and
// Ctrl-D (byte 4) ends the input.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <vector>

namespace apprentice::testing {

class Terminal {
 public:
  // Starts `args` (args[0] is the program's path) in `cwd` (empty: the
  // test's working directory).
  explicit Terminal(const std::vector<std::string>& args, const std::string& cwd = "") {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    struct winsize size {};
    size.ws_row = 50;
    size.ws_col = 400;  // wide enough that no line wraps
    pid_ = forkpty(&master_, nullptr, nullptr, &size);
    if (pid_ == 0) {
      if (!cwd.empty() && chdir(cwd.c_str()) != 0) _exit(127);
      execv(argv[0], argv.data());
      _exit(127);
    }
    if (pid_ < 0) master_ = -1;
    signal(SIGPIPE, SIG_IGN);
  }
  Terminal(const Terminal&) = delete;
  Terminal& operator=(const Terminal&) = delete;
  ~Terminal() {
    if (pid_ > 0 && !waited_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (master_ >= 0) close(master_);
  }

  bool started() const { return pid_ > 0 && master_ >= 0; }

  // Types `text` as keys: "\r" is Enter, "\x03" Ctrl-C, "\x04" Ctrl-D.
  // As a person would, it types once the program is reading keys (line
  // editing has put the terminal in raw mode): text typed ahead would be
  // echoed twice, once by the terminal and once by the line editor.
  bool type(const std::string& text) {
    wait_for_raw_mode();
    size_t done = 0;
    while (done < text.size()) {
      ssize_t n = ::write(master_, text.data() + done, text.size() - done);
      if (n <= 0) return false;
      done += static_cast<size_t>(n);
    }
    return true;
  }

  // Reads until the screen (from `from` on) ends with `suffix`, the program
  // closes the terminal, or `limit` passes. Returns whether it does.
  bool read_until_ends_with(const std::string& suffix, std::chrono::milliseconds limit = std::chrono::seconds(30)) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (!ends_with(suffix)) {
      auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0 || !pump(static_cast<int>(left.count()))) return ends_with(suffix);
    }
    return true;
  }

  // Reads everything until the program exits, and returns its exit code
  // (-1 if it did not end within `limit` and was killed, or died of a
  // signal).
  int wait(std::chrono::milliseconds limit = std::chrono::seconds(30)) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    for (;;) {
      auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0 || !pump(static_cast<int>(left.count()))) break;
    }
    int status = 0;
    pid_t done = 0;
    while (std::chrono::steady_clock::now() < deadline && (done = waitpid(pid_, &status, WNOHANG)) == 0) usleep(10'000);
    waited_ = true;
    if (done != pid_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, &status, 0);
      return -1;
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  // Waits for the agent to ask: the screen, grown past `from`, ends with
  // the prompt. Returns the question (the last line starting with
  // "Agent: ", without that prefix), or "" if the program ended first.
  std::string next_question(size_t from, std::chrono::milliseconds limit = std::chrono::seconds(30)) {
    const std::string prompt = "\nInstructor: ";
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (screen_.size() <= from || !ends_with(prompt)) {
      auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0 || !pump(static_cast<int>(left.count()))) return "";
    }
    size_t end = screen_.size() - prompt.size();
    size_t start = screen_.rfind("\nAgent: ", end);
    start = start == std::string::npos ? 0 : start + 1;
    return screen_.substr(start + 7, end - start - 7);
  }

  // What the terminal showed, with the terminal's "\r\n" as "\n".
  const std::string& screen() const { return screen_; }

 private:
  void wait_for_raw_mode() {
    // On Linux the master side reports the terminal's settings.
    for (int i = 0; i < 500; ++i) {
      termios settings{};
      if (tcgetattr(master_, &settings) != 0 || (settings.c_lflag & ICANON) == 0) return;
      usleep(10'000);
    }
  }
  bool ends_with(const std::string& suffix) const {
    return screen_.size() >= suffix.size() && screen_.compare(screen_.size() - suffix.size(), suffix.size(), suffix) == 0;
  }
  // Reads what is available within `timeout_ms`; false once the terminal
  // is closed (the program ended), or on a timeout with nothing read.
  bool pump(int timeout_ms) {
    if (master_ < 0) return false;
    pollfd fd{master_, POLLIN, 0};
    if (poll(&fd, 1, timeout_ms) <= 0) return false;
    char buffer[4096];
    ssize_t n = read(master_, buffer, sizeof buffer);
    if (n <= 0) return false;  // EIO once the program has closed the terminal
    for (ssize_t i = 0; i < n; ++i)
      if (buffer[i] != '\r') screen_.push_back(buffer[i]);
    return true;
  }

  pid_t pid_ = -1;
  int master_ = -1;
  bool waited_ = false;
  std::string screen_;
};

}  // namespace apprentice::testing
