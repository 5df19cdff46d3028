// Running the apprentice binary (APPRENTICE_BINARY) as a user runs it, with
// stdin from /dev/null and stdout and stderr captured.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace apprentice::testing {

struct Invocation {
  int exit_code = -1;  // -1 if it died of a signal
  std::string out;
  std::string err;
};

// The whole file, bytes as they are ("" if it cannot be read).
std::string read_text(const std::filesystem::path& path);
// `arg` quoted for /bin/sh.
std::string shell_quote(const std::string& arg);

// Runs the binary with `args` in the working directory `cwd` (the
// checkout by default; empty: the test's own). Its output goes through
// files in `scratch` (stdout.txt, stderr.txt), which must exist.
Invocation run_cli(const std::vector<std::string>& args, const std::filesystem::path& scratch,
                   const std::filesystem::path& cwd = APPRENTICE_SOURCE_DIR);

}  // namespace apprentice::testing
