// Shared helpers for the experiment tests: scenarios, LLM backends built
// from specs with small timeouts, and the apprentice binary run as a user
// runs it.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiment/experiment.h"
#include "llm/factory.h"

namespace apprentice::testing {

namespace fs = std::filesystem;

inline fs::path source_path(std::string_view relative) { return fs::path(APPRENTICE_SOURCE_DIR) / relative; }
inline fs::path shared_path(std::string_view relative) { return fs::path(APPRENTICE_SHARED_DIR) / relative; }
inline fs::path corpus_path() { return shared_path("data/stars-tidy-kitchen/goal_responses.jsonl"); }
inline bool have_corpus() { return fs::exists(corpus_path()); }
#define SKIP_WITHOUT_CORPUS()                                                                   \
  if (!::apprentice::testing::have_corpus())                                                    \
  GTEST_SKIP() << "no " << ::apprentice::testing::corpus_path() << " (../shared is not part of a clone)"

inline Scenario load_or_die(const fs::path& path) {
  auto scenario = load_scenario(path);
  if (!scenario) {
    ADD_FAILURE() << scenario.error().describe();
    std::abort();
  }
  return std::move(*scenario);
}

// Small enough that a failing server costs a test little time.
inline llm::LlmOptions fast_failing_options() {
  llm::LlmOptions options;
  options.connect_timeout = std::chrono::milliseconds(300);
  options.request_timeout = std::chrono::milliseconds(300);
  options.stall_timeout = std::chrono::milliseconds(300);
  options.max_retries = 1;
  options.backoff_initial = std::chrono::milliseconds(5);
  options.backoff_max = std::chrono::milliseconds(10);
  options.retry_after_cap = std::chrono::milliseconds(30);
  return options;
}

inline LlmFactory factory(std::string spec, llm::LlmOptions options = fast_failing_options()) {
  return [spec, options]() { return llm::make_llm_client(spec, options); };
}

inline ExperimentOptions experiment_options(LlmFactory llm = nullptr) {
  ExperimentOptions options;
  options.prompts_dir = source_path("data/prompts");
  options.llm = std::move(llm);
  return options;
}

// Runs one condition; fails the test if it does not run.
inline ConditionResult run(const Scenario& scenario, std::string_view condition_name,
                           const ExperimentOptions& options) {
  auto condition = parse_condition(condition_name);
  EXPECT_TRUE(condition.has_value());
  if (!condition) return {};
  auto result = run_condition(scenario, *condition, options);
  EXPECT_TRUE(result.has_value()) << condition_name << ": " << (result ? "" : result.error().describe());
  return result ? std::move(*result) : ConditionResult{};
}

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::string shell_quote(const std::string& arg) {
  std::string out = "'";
  for (char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

struct Invocation {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Runs the apprentice binary with `args` in `cwd`, stdin from /dev/null.
inline Invocation run_cli(const std::vector<std::string>& args, const fs::path& scratch,
                          const fs::path& cwd = fs::path(APPRENTICE_SOURCE_DIR)) {
  std::string command = "cd " + shell_quote(cwd.string()) + " && " + shell_quote(APPRENTICE_BINARY);
  for (const std::string& a : args) command += " " + shell_quote(a);
  const fs::path out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  command += " >" + shell_quote(out.string()) + " 2>" + shell_quote(err.string()) + " </dev/null";
  int status = std::system(command.c_str());
  Invocation result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_text(out);
  result.err = read_text(err);
  return result;
}

// A scratch directory per test, removed afterwards.
class ScratchTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "." + info->name();
    for (char& c : name)
      if (c == '/') c = '_';
    dir_ = fs::path(::testing::TempDir()) / "apprentice_experiment_tests" / name;
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

}  // namespace apprentice::testing
