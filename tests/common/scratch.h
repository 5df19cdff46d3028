// Scratch directories for tests: ScratchDir (a fresh mkdtemp directory,
// removed by its destructor) and ScratchTest (a fixture with one directory
// per test).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

namespace apprentice::testing {

class ScratchDir {
 public:
  // In memory (/dev/shm) when `in_memory` and the machine has one: the
  // knowledge store syncs every save, which costs most of a learning run's
  // time on disk and nothing there. Crash tests keep the disk.
  explicit ScratchDir(bool in_memory = false);
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(std::string_view name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

// A fixture whose dir_ is empty at the start of each test and removed after.
class ScratchTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  // Writes `text` to dir_/name and returns the path.
  std::filesystem::path write(const std::string& name, const std::string& text) const;
  std::filesystem::path dir_;

 private:
  std::optional<ScratchDir> scratch_;
};

}  // namespace apprentice::testing
