// The golden files' format (tests/language/golden/*.test), after DuckDB's
// .test files: one case per block of `key: value` lines, blocks separated
// by blank lines, `#` lines as comments.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "util/text.h"

namespace apprentice::language::testing {

struct GoldenBlock {
  std::size_t line = 0;  // where the block starts
  std::vector<std::string> comments;
  std::vector<std::pair<std::string, std::string>> fields;  // in file order
};

// Reads every block; a block of comments only is kept (a file's header).
inline std::vector<GoldenBlock> read_golden_blocks(const std::filesystem::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot read " << path;
  std::vector<GoldenBlock> blocks;
  GoldenBlock current;
  bool open = false;
  auto close = [&] {
    if (open) blocks.push_back(std::move(current));
    current = GoldenBlock{};
    open = false;
  };
  std::string text;
  for (std::size_t number = 1; std::getline(in, text); ++number) {
    std::string_view line = trim(text);
    if (line.empty()) {
      close();
      continue;
    }
    if (!open) current.line = number;
    open = true;
    if (line.front() == '#') {
      current.comments.emplace_back(line);
      continue;
    }
    auto colon = line.find(": ");
    current.fields.emplace_back(std::string(line.substr(0, colon)),
                                std::string(colon == std::string_view::npos ? "" : line.substr(colon + 2)));
  }
  close();
  return blocks;
}

}  // namespace apprentice::language::testing
