#include "util/file.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace apprentice {

namespace {

tl::unexpected<Error> too_large(const std::filesystem::path& path, std::size_t limit) {
  return make_error(ErrorCode::kInvalidInput, path.string() + ": the file is larger than " + describe_size(limit) +
                                                  ", the limit for an input file");
}

tl::unexpected<Error> line_too_long(const std::filesystem::path& path, std::size_t line, std::size_t limit) {
  return make_error(ErrorCode::kInvalidInput, path.string() + ":" + std::to_string(line) + ": the line is longer than " +
                                                  describe_size(limit) + ", the limit for a line of an input file");
}

}  // namespace

int open_retrying(const std::filesystem::path& path, int flags, unsigned mode) {
  int fd = -1;
  do {
    fd = ::open(path.c_str(), flags, static_cast<mode_t>(mode));
  } while (fd < 0 && errno == EINTR);
  return fd;
}

int flock_retrying(int fd, int operation) {
  int result = 0;
  do {
    result = ::flock(fd, operation);
  } while (result != 0 && errno == EINTR);
  return result;
}

FileDescriptor::~FileDescriptor() {
  if (fd_ >= 0) ::close(fd_);
}

FileDescriptor& FileDescriptor::operator=(FileDescriptor&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = other.release();
  }
  return *this;
}

std::string describe_size(std::size_t bytes) {
  if (bytes >= (std::size_t{1} << 20) && bytes % (std::size_t{1} << 20) == 0)
    return std::to_string(bytes >> 20) + " MiB";
  if (bytes >= (std::size_t{1} << 10) && bytes % (std::size_t{1} << 10) == 0)
    return std::to_string(bytes >> 10) + " KiB";
  return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
}

Result<std::string> read_input_file(const std::filesystem::path& path, InputLimits limits) {
  const int fd = open_retrying(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    if (error == ENOENT) return make_error(ErrorCode::kNotFound, path.string() + ": no such file");
    if (error == ENOTDIR)
      return make_error(ErrorCode::kNotFound, path.string() + ": no such file (a part of the path is not a directory)");
    return make_error(ErrorCode::kIo, path.string() + ": cannot be opened: " + std::strerror(error));
  }
  FileDescriptor file(fd);
  struct stat info {};
  if (::fstat(fd, &info) != 0)
    return make_error(ErrorCode::kIo, path.string() + ": cannot be read: " + std::strerror(errno));
  if (S_ISDIR(info.st_mode)) return make_error(ErrorCode::kInvalidInput, path.string() + ": is a directory, not a file");
  if (S_ISREG(info.st_mode) && static_cast<std::uintmax_t>(info.st_size) > limits.max_file_bytes)
    return too_large(path, limits.max_file_bytes);

  std::string text;
  if (S_ISREG(info.st_mode)) text.reserve(static_cast<std::size_t>(info.st_size));
  constexpr std::size_t kChunk = std::size_t{1} << 16;
  // Lines are checked as they arrive, so that a stream without newlines
  // (/dev/zero) stops at the line limit.
  std::size_t line_start = 0, line_number = 1;
  for (;;) {
    const std::size_t before = text.size();
    // Never hold more than the limit and one chunk.
    if (before > limits.max_file_bytes) return too_large(path, limits.max_file_bytes);
    text.resize(before + kChunk);
    ssize_t n = ::read(fd, text.data() + before, kChunk);
    if (n < 0) {
      if (errno == EINTR) {
        text.resize(before);
        continue;
      }
      const int error = errno;
      if (error == EISDIR)
        return make_error(ErrorCode::kInvalidInput, path.string() + ": is a directory, not a file");
      return make_error(ErrorCode::kIo, path.string() + ": cannot be read: " + std::strerror(error));
    }
    text.resize(before + static_cast<std::size_t>(n));
    for (std::size_t at = before; at < text.size();) {
      const void* found = std::memchr(text.data() + at, '\n', text.size() - at);
      if (found == nullptr) break;
      const std::size_t newline = static_cast<std::size_t>(static_cast<const char*>(found) - text.data());
      if (newline - line_start > limits.max_line_bytes) return line_too_long(path, line_number, limits.max_line_bytes);
      line_start = newline + 1;
      ++line_number;
      at = newline + 1;
    }
    if (text.size() - line_start > limits.max_line_bytes) return line_too_long(path, line_number, limits.max_line_bytes);
    if (n == 0) break;
  }
  if (text.size() > limits.max_file_bytes) return too_large(path, limits.max_file_bytes);
  return text;
}

Result<std::vector<std::string>> read_input_lines(const std::filesystem::path& path, InputLimits limits) {
  auto text = read_input_file(path, limits);
  if (!text) return tl::unexpected(text.error());
  std::vector<std::string> lines;
  std::string_view rest(*text);
  while (!rest.empty()) {
    std::size_t end = rest.find('\n');
    std::string_view line = rest.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.emplace_back(line);
    if (end == std::string_view::npos) break;
    rest.remove_prefix(end + 1);
  }
  return lines;
}

}  // namespace apprentice
