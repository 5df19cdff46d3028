// Reading input files (scenarios, domains, corpora, cassettes, prompt
// templates) with limits, so that hostile input gets a clear error instead
// of a read that runs until memory runs out: /dev/zero, a directory, a file
// of gigabytes, a line of megabytes.
//
// The limits are documented in docs/cli.md ("Limits"); every reader of an
// outside file goes through here.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"

namespace apprentice {

// The most bytes an input file may hold: 64 MiB.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{64} << 20;
// The most bytes one line of an input file may hold: 1 MiB.
inline constexpr std::size_t kMaxInputLineBytes = std::size_t{1} << 20;

struct InputLimits {
  std::size_t max_file_bytes = kMaxInputFileBytes;
  std::size_t max_line_bytes = kMaxInputLineBytes;
};

// open(2) and flock(2), retried while a signal interrupts them (EINTR);
// otherwise as the system calls: -1 (or non-zero) with errno set.
int open_retrying(const std::filesystem::path& path, int flags, unsigned mode = 0);
int flock_retrying(int fd, int operation);

// Owns a file descriptor (-1: none) and closes it when destroyed.
class FileDescriptor {
 public:
  FileDescriptor() = default;
  explicit FileDescriptor(int fd) : fd_(fd) {}
  ~FileDescriptor();
  FileDescriptor(FileDescriptor&& other) noexcept : fd_(other.release()) {}
  FileDescriptor& operator=(FileDescriptor&& other) noexcept;
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  int get() const { return fd_; }
  int release() {
    int fd = fd_;
    fd_ = -1;
    return fd;
  }

 private:
  int fd_ = -1;
};

// The whole file, bytes as they are. Errors name the file and say why:
//   kNotFound      it does not exist
//   kInvalidInput  it is a directory; it is larger than max_file_bytes; a
//                  line is longer than max_line_bytes ("file:N: ...")
//   kIo            it cannot be opened or read, with the system's reason
//                  ("Permission denied")
// Devices and pipes are read up to the limit (/dev/zero is refused once it
// passes max_file_bytes).
Result<std::string> read_input_file(const std::filesystem::path& path, InputLimits limits = {});

// The file's lines, without their "\n" (or "\r\n"); the same checks.
Result<std::vector<std::string>> read_input_lines(const std::filesystem::path& path, InputLimits limits = {});

// "64 MiB", "1 MiB", "512 KiB", "100 bytes": a size for messages.
std::string describe_size(std::size_t bytes);

}  // namespace apprentice
