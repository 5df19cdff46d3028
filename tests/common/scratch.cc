#include "common/scratch.h"

#include <unistd.h>

#include <fstream>
#include <vector>

namespace apprentice::testing {

namespace fs = std::filesystem;

ScratchDir::ScratchDir(bool in_memory) {
  fs::path base = ::testing::TempDir();
  if (in_memory && ::access("/dev/shm", W_OK) == 0) base = "/dev/shm";
  std::string pattern = (base / "apprentice-test-XXXXXX").string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  const char* made = ::mkdtemp(buffer.data());
  EXPECT_NE(made, nullptr) << "mkdtemp " << pattern;
  path_ = made ? fs::path(made) : fs::path(pattern);
}

ScratchDir::~ScratchDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

void ScratchTest::SetUp() {
  scratch_.emplace();
  dir_ = scratch_->path();
}

void ScratchTest::TearDown() { scratch_.reset(); }

fs::path ScratchTest::write(const std::string& name, const std::string& text) const {
  fs::path path = dir_ / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

}  // namespace apprentice::testing
