// Shared helpers for the knowledge tests: the shipped scenarios, the
// ceramic-plate episode of the paper's walk-through, scratch directories,
// and a way to run the apprentice binary.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "knowledge/learning.h"
#include "knowledge/matcher.h"
#include "knowledge/rule.h"
#include "world/action.h"
#include "world/goal.h"
#include "world/scenario.h"

namespace apprentice::testing {

namespace fs = std::filesystem;

inline fs::path source_path(std::string_view relative) { return fs::path(APPRENTICE_SOURCE_DIR) / relative; }
inline fs::path scenario_path(std::string_view name) {
  return source_path("data/scenarios/" + std::string(name) + ".yaml");
}

// Loads a shipped scenario; aborts the test binary if it cannot (every
// test here needs it).
inline Scenario load_or_die(const fs::path& path) {
  auto scenario = load_scenario(path);
  if (!scenario) {
    ADD_FAILURE() << scenario.error().describe();
    std::abort();
  }
  return std::move(*scenario);
}
inline Scenario tidy_kitchen() { return load_or_die(scenario_path("tidy-kitchen")); }
inline Scenario tidy_kitchen_similar() { return load_or_die(scenario_path("tidy-kitchen-similar")); }

// "(open fridge1)" -> the Action, checked.
inline Action action(const World& world, std::string_view text) {
  auto parsed = parse_action(*world.domain, *world.universe, text);
  EXPECT_TRUE(parsed.has_value()) << text << ": " << (parsed ? "" : parsed.error().describe());
  return parsed ? *parsed : Action();
}

inline Goal goal(const World& world, std::string_view text) {
  auto parsed = parse_goal(*world.domain, *world.universe, text);
  EXPECT_TRUE(parsed.has_value()) << text << ": " << (parsed ? "" : parsed.error().describe());
  return parsed ? *parsed : Goal();
}

inline ObjectId object(const World& world, std::string_view id) {
  auto found = world.universe->find(id);
  EXPECT_TRUE(found.has_value()) << "no object " << id;
  return found.value_or(0);
}

// The state after executing `actions` in turn from `state` (each checked
// applicable).
inline State after(const World& world, State state, const std::vector<std::string>& actions) {
  for (const std::string& text : actions) {
    Action a = action(world, text);
    EXPECT_TRUE(is_applicable(*world.domain, state, a)) << text;
    state = apply(*world.domain, state, a);
  }
  return state;
}

// An episode from the instructor: each action's source is what the agent
// records for an instructed action.
inline Episode make_episode(const World& world, const State& initial, std::string_view object_id,
                            std::string_view goal_text, std::string_view subtask,
                            const std::vector<std::string>& actions) {
  Episode episode;
  episode.initial = initial;
  for (const std::string& text : actions) {
    episode.actions.push_back(action(world, text));
    episode.sources.push_back("instructor: \"" + text + "\"");
  }
  episode.goal = goal(world, goal_text);
  episode.object_of_interest = object(world, object_id);
  episode.subtask = std::string(subtask);
  episode.object_description =
      std::string(object_id) + " (" + world.universe->info(episode.object_of_interest).category + ")";
  return episode;
}

// The paper's walk-through: the ceramic plate on the table, cleared into
// the dishwasher, which must end closed.
inline constexpr std::string_view kCeramicPlateGoal = "(and (in ceramic-plate1 dishwasher1) (closed dishwasher1))";
inline Episode ceramic_plate_episode(const World& world) {
  return make_episode(world, world.state, "ceramic-plate1", kCeramicPlateGoal, "clear",
                      {"(open dishwasher1)", "(pick-up ceramic-plate1 table1)",
                       "(put-in ceramic-plate1 dishwasher1)", "(close dishwasher1)"});
}

inline std::vector<Rule> learn(const World& world, const Episode& episode, Generalization generalization) {
  return learn_policy_rules(*world.domain, *world.universe, episode, generalization);
}

inline RuleMatcher matcher_of(const World& world, const std::vector<Rule>& rules) {
  RuleMatcher matcher;
  for (const Rule& rule : rules) matcher.add(*world.domain, rule);
  return matcher;
}

inline std::vector<std::string> signatures(const World& world, const std::vector<Rule>& rules) {
  std::vector<std::string> out;
  for (const Rule& rule : rules) out.push_back(rule_signature(*world.domain, rule));
  return out;
}

// A fresh scratch directory for one test, removed by the destructor. In
// memory (/dev/shm) when `in_memory` and the machine has one: the store
// syncs every save, which costs most of a learning run's time on disk and
// nothing there. Crash tests keep the disk.
class ScratchDir {
 public:
  explicit ScratchDir(bool in_memory = false) {
    fs::path base = ::testing::TempDir();
    if (in_memory && ::access("/dev/shm", W_OK) == 0) base = "/dev/shm";
    std::string pattern = (base / "apprentice-knowledge-XXXXXX").string();
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    const char* made = ::mkdtemp(buffer.data());
    EXPECT_NE(made, nullptr) << "mkdtemp " << pattern;
    path_ = made ? fs::path(made) : fs::path(pattern);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const fs::path& path() const { return path_; }
  fs::path operator/(std::string_view name) const { return path_ / name; }

 private:
  fs::path path_;
};

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Invocation {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string shell_quote(const std::string& arg) {
  std::string out = "'";
  for (char c : arg) {
    if (c == '\'') out += "'\\''";
    else out += c;
  }
  return out + "'";
}

// Runs the apprentice binary with `args`, capturing its output in `dir`.
inline Invocation run_cli(const fs::path& dir, const std::vector<std::string>& args) {
  std::string command = shell_quote(APPRENTICE_BINARY);
  for (const std::string& a : args) command += " " + shell_quote(a);
  const fs::path out = dir / "cli-stdout.txt";
  const fs::path err = dir / "cli-stderr.txt";
  command += " >" + shell_quote(out.string()) + " 2>" + shell_quote(err.string()) + " </dev/null";
  int status = std::system(command.c_str());
  Invocation result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_text(out);
  result.err = read_text(err);
  return result;
}

}  // namespace apprentice::testing
