// `apprentice benchmark tidybot` as a user runs it: the table, --json, and
// the conventions of docs/cli.md for bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/paths.h"
#include "common/process.h"
#include "common/scratch.h"
#include "tidybot_fixtures.h"

namespace apprentice::benchmark {
namespace {

using apprentice::testing::run_cli;
using ::testing::HasSubstr;
using ::testing::StartsWith;

class TidyBotCli : public apprentice::testing::ScratchTest {};

TEST_F(TidyBotCli, PrintsTheTableAndTheJson) {
  const auto file = write("two.yml", testing::kTwoScenarios);
  auto table = run_cli({"benchmark", "tidybot", "--scenarios", file.string(), "--settings", "a-alone, b-teacher"}, dir_);
  EXPECT_EQ(table.exit_code, 0) << table.err;
  EXPECT_THAT(table.out, HasSubstr("TidyBot benchmark: 2 scenarios"));
  EXPECT_THAT(table.out, HasSubstr("b-teacher"));
  EXPECT_THAT(table.out, ::testing::Not(HasSubstr("a-teacher ")));
  auto json = run_cli({"benchmark", "tidybot", "--scenarios", file.string(), "--settings", "a-teacher", "--only", "9",
                       "--json"},
                      dir_);
  ASSERT_EQ(json.exit_code, 0) << json.err;
  auto parsed = nlohmann::json::parse(json.out);
  ASSERT_EQ(parsed["settings"].size(), 1u);
  EXPECT_EQ(parsed["settings"][0]["objects"], 1);
  EXPECT_EQ(parsed["settings"][0]["right"], 1);
  EXPECT_EQ(parsed["settings"][0]["scenarios"][0]["index"], 9);
}

TEST_F(TidyBotCli, BadInputIsOnePlainLineAndExitTwo) {
  const auto file = write("two.yml", testing::kTwoScenarios);
  const auto broken = write("broken.yml", "- room: [unclosed\n");
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const Case cases[] = {
      {{"benchmark", "tidybot", "--scenarios", (dir_ / "missing.yml").string()}, "missing.yml"},
      {{"benchmark", "tidybot", "--scenarios", broken.string()}, "broken.yml:"},
      {{"benchmark", "frobnicate", "--scenarios", file.string()}, "is not a benchmark"},
      {{"benchmark", "tidybot", "--scenarios", file.string(), "--settings", "c-alone"}, "unknown setting"},
      {{"benchmark", "tidybot", "--scenarios", file.string(), "--only", "3"}, "has no scenario 3"},
      {{"benchmark", "tidybot", "--scenarios", file.string(), "--settings", "a-alone+llm"}, "needs an LLM"},
      {{"benchmark", "tidybot"}, "--scenarios is required"},
  };
  for (const Case& c : cases) {
    auto run = run_cli(c.args, dir_);
    EXPECT_EQ(run.exit_code, 2) << c.message << "\n" << run.err;
    EXPECT_THAT(run.err, StartsWith("apprentice: ")) << c.message;
    EXPECT_THAT(run.err, HasSubstr(c.message));
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  }
}

}  // namespace
}  // namespace apprentice::benchmark
