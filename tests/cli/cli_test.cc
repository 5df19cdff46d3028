// End-to-end tests of the apprentice binary: output and exit codes of the
// world, plan and export-pddl subcommands (0 ok, 1 goal not reached, 2 bad
// input), run as a user would run them.
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/paths.h"
#include "common/process.h"
#include "common/scratch.h"
#include "search/iterative_deepening.h"
#include "world/pddl.h"

namespace apprentice {
namespace {

using ::testing::EndsWith;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

namespace fs = std::filesystem;

constexpr const char* kKetchupGoal = "(and (in ketchup1 fridge1) (closed fridge1))";

std::string source(std::string_view relative) { return testing::source_path(relative).string(); }
std::string tidy_kitchen() { return source("data/scenarios/tidy-kitchen.yaml"); }

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

using testing::Invocation;

class Cli : public testing::ScratchTest {
 protected:
  Invocation run(const std::vector<std::string>& args) const { return testing::run_cli(args, dir_, fs::path()); }
};

TEST_F(Cli, PlanSaysTheFourStepKetchupPlanInSentences) {
  Invocation r = run({"plan", "--scenario", tidy_kitchen(), "--goal", kKetchupGoal});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 5u) << r.out;
  EXPECT_THAT(std::vector<std::string>(lines.begin(), lines.begin() + 4),
              ElementsAre("1. Open the fridge.", "2. Pick up the ketchup.", "3. Put the ketchup in the fridge.",
                          "4. Close the fridge."));
  EXPECT_THAT(lines[4], StartsWith("Greedy best-first search found a plan of 4 steps in "));
  EXPECT_THAT(lines[4], HasSubstr(" nodes expanded and "));
  EXPECT_THAT(lines[4], EndsWith(" ground actions."));
  EXPECT_THAT(r.out, Not(HasSubstr("(")));  // no PDDL without --pddl
  EXPECT_EQ(r.err, "");
}

TEST_F(Cli, PlanInPddlWithPddl) {
  Invocation r = run({"plan", "--scenario", tidy_kitchen(), "--goal", kKetchupGoal, "--pddl"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 5u) << r.out;
  EXPECT_THAT(std::vector<std::string>(lines.begin(), lines.begin() + 4),
              ElementsAre("(open fridge1)", "(pick-up ketchup1 table1)", "(put-in ketchup1 fridge1)", "(close fridge1)"));
  EXPECT_THAT(lines[4], StartsWith(";; status solved, 4 steps, "));
  EXPECT_THAT(lines[4], HasSubstr("nodes expanded"));
  EXPECT_EQ(r.err, "");
}

TEST_F(Cli, PlanWithDepthTwoIsExhaustedAndExitsOne) {
  Invocation r = run({"plan", "--scenario", tidy_kitchen(), "--goal", kKetchupGoal, "--depth", "2"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.out, StartsWith("Iterative deepening to depth 2 found in "));
  EXPECT_THAT(r.out, HasSubstr(" ms that no plan reaches the goal: "));
  Invocation pddl = run({"plan", "--scenario", tidy_kitchen(), "--goal", kKetchupGoal, "--depth", "2", "--pddl"});
  EXPECT_THAT(pddl.out, StartsWith(";; status exhausted, 0 steps, "));
  EXPECT_THAT(pddl.out, HasSubstr("depth limit 2"));
  EXPECT_EQ(r.err,
            "apprentice: no plan of at most 2 steps reaches the goal; try a larger --depth, or leave --depth out "
            "for greedy best-first search\n");
}

TEST_F(Cli, PlanWithATinyNodeBudgetStopsAndExitsOne) {
  Invocation r = run({"plan", "--scenario", tidy_kitchen(), "--goal", kKetchupGoal, "--max-nodes", "3", "--json"});
  EXPECT_EQ(r.exit_code, 1);
  auto json = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(json.is_discarded()) << r.out;
  EXPECT_EQ(json["status"], "budget-exhausted");
  EXPECT_EQ(json["nodes_expanded"], 3);
}

TEST_F(Cli, PlanJson) {
  Invocation r = run({"plan", "--scenario", tidy_kitchen(), "--goal", kKetchupGoal, "--json", "--depth", "4"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto json = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(json.is_discarded()) << r.out;
  EXPECT_EQ(json["status"], "solved");
  EXPECT_EQ(json["plan"], nlohmann::json({"(open fridge1)", "(pick-up ketchup1 table1)", "(put-in ketchup1 fridge1)",
                                          "(close fridge1)"}));
  EXPECT_GT(json["nodes_expanded"].get<int>(), 0);
  EXPECT_EQ(json["depth_limit"], 4);
  EXPECT_EQ(json["planner"], "iterative-deepening");
  EXPECT_EQ(json["relevant_objects"], 12);
  EXPECT_TRUE(json["elapsed_ms"].is_number());
}

TEST_F(Cli, PlanWithoutDepthUsesGreedyBestFirstSearch) {
  Invocation r = run({"plan", "--scenario", tidy_kitchen(), "--goal", kKetchupGoal, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto json = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(json.is_discarded()) << r.out;
  EXPECT_EQ(json["planner"], "greedy-best-first");
  EXPECT_EQ(json["plan"].size(), 4u);
  EXPECT_FALSE(json.contains("depth_limit"));
  EXPECT_EQ(json["initial_heuristic"], 3);
  EXPECT_EQ(json["relevant_objects"], 12);
  EXPECT_THAT(json["relevance"][0].get<std::string>(), HasSubstr("12 of 41 objects can matter to the goal"));
}

TEST_F(Cli, PlanTheWholeIntent) {
  Invocation r = run({"plan", "--scenario", tidy_kitchen(), "--goal", "intent", "--pddl"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> lines = lines_of(r.out);
  ASSERT_FALSE(lines.empty());
  EXPECT_THAT(lines.back(), StartsWith(";; status solved, "));
  EXPECT_GE(lines.size() - 1, 70u);  // the optimum
  EXPECT_LE(lines.size() - 1, 77u);
  // export-pddl writes the same goal: 35 assertions.
  Invocation e = run({"export-pddl", "--scenario", tidy_kitchen(), "--goal", "intent", "--out", dir_.string()});
  ASSERT_EQ(e.exit_code, 0) << e.err;
  auto domain = read_domain_file(dir_ / "domain.pddl");
  ASSERT_TRUE(domain.has_value()) << domain.error().describe();
  auto problem = parse_problem(*domain, testing::read_text(dir_ / "problem.pddl"), "problem.pddl");
  ASSERT_TRUE(problem.has_value()) << problem.error().describe();
  EXPECT_EQ(problem->goal.literals.size(), 35u);
}

TEST_F(Cli, PlanLimitsStopTheSearchAndExitOne) {
  // Unsatisfiable, and the relaxation cannot tell: unpruned search would run for long.
  const char* impossible = "(and (in ketchup1 fridge1) (in ketchup1 pantry1))";
  Invocation timed = run({"plan", "--scenario", tidy_kitchen(), "--goal", impossible, "--no-pruning", "--json",
                          "--time-limit", "0.2"});
  EXPECT_EQ(timed.exit_code, 1);
  EXPECT_EQ(nlohmann::json::parse(timed.out)["status"], "budget-exhausted");
  Invocation counted = run({"plan", "--scenario", tidy_kitchen(), "--goal", impossible, "--no-pruning", "--json",
                            "--node-limit", "50"});
  EXPECT_EQ(counted.exit_code, 1);
  auto json = nlohmann::json::parse(counted.out);
  EXPECT_EQ(json["status"], "budget-exhausted");
  EXPECT_EQ(json["nodes_expanded"], 50);
  EXPECT_EQ(run({"plan", "--scenario", tidy_kitchen(), "--goal", kKetchupGoal, "--time-limit", "0"}).exit_code, 2);
  // With pruning the same goal is proved impossible: exhausted, exit 1.
  Invocation proved = run({"plan", "--scenario", tidy_kitchen(), "--goal", impossible, "--json"});
  EXPECT_EQ(proved.exit_code, 1);
  EXPECT_EQ(nlohmann::json::parse(proved.out)["status"], "exhausted");
}

TEST_F(Cli, PlanProgressGoesToTheTerminalOnly) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1) to give a terminal";
  const std::string plan = testing::shell_quote(APPRENTICE_BINARY) + " plan --scenario " + testing::shell_quote(tidy_kitchen()) +
                           " --goal '(and (in ketchup1 fridge1) (in ketchup1 pantry1))' --no-pruning --time-limit 1.6";
  const fs::path out = dir_ / "terminal.txt";
  const std::string command = "script -qec " + testing::shell_quote(plan) + " /dev/null > " + testing::shell_quote(out.string()) +
                              " 2>&1 </dev/null";
  ASSERT_EQ(std::system(command.c_str()) == -1, false);
  const std::string text = testing::read_text(out);
  EXPECT_THAT(text, HasSubstr("searching: "));
  EXPECT_THAT(text, HasSubstr(" nodes/s), best heuristic value "));
  EXPECT_THAT(text, HasSubstr("Greedy best-first search reached its limit without a plan in "));
  // Not a terminal: no progress lines.
  Invocation piped = run({"plan", "--scenario", tidy_kitchen(), "--goal", "(and (in ketchup1 fridge1) (in ketchup1 pantry1))",
                          "--no-pruning", "--time-limit", "1.2"});
  EXPECT_EQ(piped.err, "");
}

TEST_F(Cli, PlanVerboseSaysWhatPruningDid) {
  Invocation kitchen = run({"-v", "plan", "--scenario", tidy_kitchen(), "--goal", kKetchupGoal});
  ASSERT_EQ(kitchen.exit_code, 0) << kitchen.err;
  EXPECT_THAT(kitchen.err, HasSubstr("relevance: 12 of 41 objects can matter to the goal; 29 pruned"));
  Invocation stacked = run({"-v", "plan", "--scenario", source("data/scenarios/stacked-dishes.yaml"), "--goal",
                            "(in ceramic-plate1 cupboard1)"});
  ASSERT_EQ(stacked.exit_code, 0) << stacked.err;
  EXPECT_THAT(stacked.err, HasSubstr("are kept because they can interact with others"));
  EXPECT_THAT(stacked.err, HasSubstr("because unstack changes (covered ?bottom)"));
  Invocation tower = run({"-v", "plan", "--scenario", source("data/scenarios/dish-tower.yaml"), "--goal", "intent"});
  ASSERT_EQ(tower.exit_code, 0) << tower.err;
  EXPECT_THAT(tower.err, HasSubstr("0 pruned"));
}

TEST_F(Cli, PlanWithoutPruningFindsTheSamePlan) {
  // A short goal: unpruned search of the whole kitchen is slow under the sanitizers.
  const char* goal = "(on ketchup1 counter1)";
  Invocation pruned = run({"plan", "--scenario", tidy_kitchen(), "--goal", goal, "--json"});
  Invocation full = run({"plan", "--scenario", tidy_kitchen(), "--goal", goal, "--json", "--no-pruning"});
  ASSERT_EQ(full.exit_code, 0) << full.err;
  auto a = nlohmann::json::parse(pruned.out);
  auto b = nlohmann::json::parse(full.out);
  EXPECT_EQ(a["plan"], b["plan"]);
  EXPECT_EQ(b["relevant_objects"], 41);
  EXPECT_GT(b["nodes_generated"].get<int>(), a["nodes_generated"].get<int>());
}

TEST_F(Cli, PlanIsDeterministic) {
  Invocation a = run({"plan", "--scenario", tidy_kitchen(), "--goal", "(and (in mug2 cupboard1) (closed cupboard1))", "--json"});
  Invocation b = run({"plan", "--scenario", tidy_kitchen(), "--goal", "(and (in mug2 cupboard1) (closed cupboard1))", "--json"});
  ASSERT_EQ(a.exit_code, 0) << a.err;
  auto ja = nlohmann::json::parse(a.out);
  auto jb = nlohmann::json::parse(b.out);
  EXPECT_EQ(ja["plan"], jb["plan"]);
  EXPECT_EQ(ja["nodes_expanded"], jb["nodes_expanded"]);
  EXPECT_EQ(ja["plan"][1], "(pick-up-from mug2 dish-rack1)");
}

TEST_F(Cli, BrokenScenarioExitsTwoWithFileAndLine) {
  std::string text = testing::read_text(tidy_kitchen());
  // Point the domain at the shipped file, then break the ketchup's place.
  text.replace(text.find("domain: ../domains/kitchen.pddl"), 31, "domain: " + source("data/domains/kitchen.pddl"));
  const std::string ketchup = "{category: ketchup, at: table1}";
  std::size_t at = text.find(ketchup);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, ketchup.size(), "{category: ketchup, at: shelf1}");
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
  fs::path path = write("broken.yaml", text);

  Invocation r = run({"plan", "--scenario", path.string(), "--goal", kKetchupGoal});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");  // nothing half-loaded is used
  EXPECT_THAT(r.err, HasSubstr(path.string() + ":" + std::to_string(line) + ":"));
  EXPECT_THAT(r.err, HasSubstr("there is no place 'shelf1'"));
  // The same for world and export-pddl.
  Invocation w = run({"world", "--scenario", path.string()});
  EXPECT_EQ(w.exit_code, 2);
  EXPECT_EQ(w.out, "");
  EXPECT_THAT(w.err, HasSubstr(path.string() + ":" + std::to_string(line) + ":"));
  Invocation e = run({"export-pddl", "--scenario", path.string(), "--goal", kKetchupGoal, "--out", (dir_ / "out").string()});
  EXPECT_EQ(e.exit_code, 2);
  EXPECT_FALSE(fs::exists(dir_ / "out" / "problem.pddl"));
}

TEST_F(Cli, YamlSyntaxErrorExitsTwoWithFileAndLine) {
  fs::path path = write("syntax.yaml", "name: x\ndomain: d.pddl\nplaces:\n  - {category: table, kind: surface}}\n");
  Invocation r = run({"world", "--scenario", path.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr(path.string() + ":4:"));
  EXPECT_EQ(r.out, "");
}

TEST_F(Cli, MissingScenarioFileExitsTwo) {
  const std::string missing = (dir_ / "no-such-scenario.yaml").string();
  Invocation r = run({"plan", "--scenario", missing, "--goal", kKetchupGoal});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr(missing));
  EXPECT_THAT(r.err, HasSubstr("no such file"));
  EXPECT_EQ(r.out, "");
}

TEST_F(Cli, MissingDomainFileExitsTwo) {
  std::string text = testing::read_text(tidy_kitchen());
  text.replace(text.find("domain: ../domains/kitchen.pddl"), 31, "domain: nowhere.pddl");
  fs::path path = write("nodomain.yaml", text);
  Invocation r = run({"world", "--scenario", path.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr(path.string() + ":5:"));
  EXPECT_THAT(r.err, HasSubstr("nowhere.pddl: no such file"));
}

TEST_F(Cli, BadGoalExitsTwo) {
  Invocation unknown = run({"plan", "--scenario", tidy_kitchen(), "--goal", "(in ketchup9 fridge1)"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_THAT(unknown.err, HasSubstr("goal:1:5: expected an object; there is no ketchup9"));
  EXPECT_EQ(unknown.out, "");
  Invocation syntax = run({"plan", "--scenario", tidy_kitchen(), "--goal", "(in ketchup1 fridge1"});
  EXPECT_EQ(syntax.exit_code, 2);
  EXPECT_THAT(syntax.err, HasSubstr("goal:1:"));
  EXPECT_THAT(syntax.err, HasSubstr("expected ')'"));
  Invocation typed = run({"export-pddl", "--scenario", tidy_kitchen(), "--goal", "(in ketchup1 table1)", "--out",
                   (dir_ / "out").string()});
  EXPECT_EQ(typed.exit_code, 2);
  EXPECT_THAT(typed.err, HasSubstr("table1 is a surface"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "domain.pddl"));
}

TEST_F(Cli, BadFlagsExitTwo) {
  EXPECT_EQ(run({"plan", "--scenario", tidy_kitchen()}).exit_code, 2);  // --goal is required
  EXPECT_EQ(run({"plan", "--scenario", tidy_kitchen(), "--goal", kKetchupGoal, "--depth", "-1"}).exit_code, 2);
  EXPECT_EQ(run({"plan", "--scenario", tidy_kitchen(), "--goal", kKetchupGoal, "--depth", "deep"}).exit_code, 2);
  EXPECT_EQ(run({"plan", "--scenario", tidy_kitchen(), "--goal", kKetchupGoal, "--max-nodes", "0"}).exit_code, 2);
  EXPECT_EQ(run({"world"}).exit_code, 2);
  EXPECT_EQ(run({"no-such-command"}).exit_code, 2);
  EXPECT_EQ(run({}).exit_code, 2);
}

TEST_F(Cli, HelpExitsZeroForEverySubcommand) {
  Invocation top = run({"--help"});
  EXPECT_EQ(top.exit_code, 0);
  for (const char* sub : {"world", "plan", "export-pddl"}) EXPECT_THAT(top.out, HasSubstr(sub));
  const std::vector<std::pair<std::string, std::vector<std::string>>> expected = {
      {"world", {"--scenario", "--json"}},
      {"plan", {"--scenario", "--goal", "--depth", "--node-limit", "--time-limit", "--no-pruning", "--json"}},
      {"export-pddl", {"--scenario", "--goal", "--out"}},
  };
  for (const auto& [sub, flags] : expected) {
    Invocation r = run({sub, "--help"});
    EXPECT_EQ(r.exit_code, 0) << sub;
    for (const std::string& flag : flags) EXPECT_THAT(r.out, HasSubstr(flag)) << sub;
  }
}

TEST_F(Cli, WorldPrintsPlacesAndObjects) {
  Invocation r = run({"world", "--scenario", tidy_kitchen()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("Scenario tidy-kitchen: the robot is in the kitchen."));
  EXPECT_THAT(r.out, HasSubstr("  table1 (surface)\n"));
  EXPECT_THAT(r.out, HasSubstr("  fridge1 (receptacle, door closed)\n"));
  EXPECT_THAT(r.out, HasSubstr("  sink1 (receptacle)\n"));
  EXPECT_THAT(r.out, HasSubstr("  ketchup1 on table1\n"));
  EXPECT_THAT(r.out, HasSubstr("  mug2 in dish-rack1\n"));
  // The world never shows the instructor's intent.
  EXPECT_THAT(r.out, ::testing::Not(HasSubstr("intent")));
  // Things of one kind are listed together, to be told apart.
  EXPECT_THAT(r.out, HasSubstr("Look-alikes (one kind of thing each): "));
  EXPECT_THAT(r.out, HasSubstr("mug1, mug2"));
}

// A goal learned for one of two look-alikes names it by its property in
// `knowledge --pddl` as in English: the top drawer, not any drawer.
TEST_F(Cli, KnowledgeInPddlNamesTheLookAlikeAGoalNames) {
  Invocation taught = run({"experiment", source("data/scenarios/party-cleanup.yaml"), "--conditions", "instruction",
                           "--knowledge-out", (dir_ / "out").string(), "-q"});
  ASSERT_EQ(taught.exit_code, 0) << taught.err;
  const std::string store = (dir_ / "out" / "instruction.sqlite").string();
  Invocation pddl = run({"knowledge", "--knowledge", store, "--pddl"});
  ASSERT_EQ(pddl.exit_code, 0) << pddl.err;
  EXPECT_THAT(pddl.out, HasSubstr("the object is a remote-control at the coffee-table\n"
                                  "Then the goal is (in ?o [top drawer]) and (closed [top drawer])"));
  EXPECT_THAT(pddl.out, HasSubstr("(in ?o [bottom drawer]) and (closed [bottom drawer])"));
  Invocation english = run({"knowledge", "--knowledge", store});
  EXPECT_THAT(english.out, HasSubstr("the remote control goes in the top drawer, and the top drawer ends closed."));
}

// `knowledge` speaks English: where each goal and rule came from names no
// PDDL action ("(close dishwasher1)"), no variable and no object id; the
// PDDL is for --pddl.
TEST_F(Cli, KnowledgeInEnglishHasNoPddl) {
  Invocation taught = run({"experiment", tidy_kitchen(), "--conditions", "inst+search4", "--knowledge-out",
                           (dir_ / "out").string(), "-q"});
  ASSERT_EQ(taught.exit_code, 0) << taught.err;
  const std::string store = (dir_ / "out" / "inst+search4.sqlite").string();
  Invocation english = run({"knowledge", "--knowledge", store});
  ASSERT_EQ(english.exit_code, 0) << english.err;
  EXPECT_THAT(english.out, HasSubstr("(learned on the ceramic plate from my own search, which chose to close the "
                                     "dishwasher)"));
  const std::regex pddl_atom(R"(\((open|close|pick-up|pick-up-from|put-in|put-on|in|on|closed) [^)]*\))");
  const std::regex object_id(R"(\b[a-z]+(-[a-z]+)*[0-9]+\b)");
  std::istringstream lines(english.out);
  for (std::string line; std::getline(lines, line);) {
    EXPECT_FALSE(std::regex_search(line, pddl_atom)) << line;
    EXPECT_FALSE(std::regex_search(line, object_id)) << line;
    EXPECT_THAT(line, Not(HasSubstr("?o")));
  }
  Invocation pddl = run({"knowledge", "--knowledge", store, "--pddl"});
  EXPECT_THAT(pddl.out, HasSubstr("from search: (close dishwasher1)"));
}

TEST_F(Cli, WorldShowsPropertiesAndLookAlikes) {
  const std::string playroom = source("data/scenarios/playroom.yaml");
  Invocation text = run({"world", "--scenario", playroom});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  Invocation r = run({"world", "--scenario", playroom, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto json = nlohmann::json::parse(r.out);
  int with_properties = 0;
  for (const char* part : {"places", "objects"})
    for (const auto& o : json[part]) {
      ASSERT_TRUE(o["properties"].is_array() && o["look_alikes"].is_array()) << o.dump();
      for (const auto& p : o["properties"]) {
        ++with_properties;
        EXPECT_THAT(text.out, HasSubstr(p.get<std::string>())) << o.dump();
      }
      for (const auto& other : o["look_alikes"]) EXPECT_NE(other, o["id"]);
    }
  EXPECT_GT(with_properties, 0);
}

TEST_F(Cli, WorldJsonParses) {
  Invocation r = run({"world", "--scenario", tidy_kitchen(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto json = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(json.is_discarded()) << r.out;
  EXPECT_EQ(json["scenario"], "tidy-kitchen");
  EXPECT_EQ(json["location"], "kitchen");
  EXPECT_EQ(json["hand"], "empty");
  ASSERT_TRUE(json["places"].is_array());
  ASSERT_TRUE(json["objects"].is_array());
  EXPECT_EQ(json["places"].size(), 11u);
  EXPECT_EQ(json["objects"].size(), 30u);
  EXPECT_FALSE(json.contains("intent"));
  bool found_ketchup = false, found_fridge = false;
  for (const auto& o : json["objects"]) {
    EXPECT_TRUE(o.contains("id") && o.contains("category") && o.contains("location"));
    if (o["id"] == "ketchup1") {
      found_ketchup = true;
      EXPECT_EQ(o["category"], "ketchup");
      EXPECT_EQ(o["location"], "on table1");
    }
  }
  for (const auto& p : json["places"]) {
    if (p["id"] == "fridge1") {
      found_fridge = true;
      EXPECT_EQ(p["kind"], "receptacle");
      EXPECT_EQ(p["door"], "closed");
    }
    if (p["id"] == "sink1") {
      EXPECT_FALSE(p.contains("door"));
    }
  }
  EXPECT_TRUE(found_ketchup);
  EXPECT_TRUE(found_fridge);
}

TEST_F(Cli, ExportPddlRoundTrips) {
  const fs::path out = dir_ / "pddl";
  Invocation r = run({"export-pddl", "--scenario", tidy_kitchen(), "--goal", kKetchupGoal, "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("wrote " + (out / "domain.pddl").string()));
  EXPECT_THAT(r.out, HasSubstr("wrote " + (out / "problem.pddl").string()));

  auto domain = read_domain_file(out / "domain.pddl");
  ASSERT_TRUE(domain.has_value()) << domain.error().describe();
  EXPECT_EQ(domain->name, "kitchen");
  EXPECT_EQ(domain->actions.size(), 6u);
  auto problem_text = read_text_file(out / "problem.pddl");
  ASSERT_TRUE(problem_text.has_value());
  auto problem = parse_problem(*domain, *problem_text, (out / "problem.pddl").string());
  ASSERT_TRUE(problem.has_value()) << problem.error().describe();
  EXPECT_EQ(problem->universe.size(), 41u);
  EXPECT_EQ(problem->goal.literals.size(), 2u);

  // The planner finds the same four-step plan on the re-read problem.
  PlanResult result = find_plan(*domain, problem->universe, problem->init, problem->goal, {});
  ASSERT_EQ(result.status, SearchStatus::kSolved);
  std::vector<std::string> steps;
  for (const Action& a : result.plan) steps.push_back(format_action(*domain, problem->universe, a));
  EXPECT_THAT(steps, ElementsAre("(open fridge1)", "(pick-up ketchup1 table1)", "(put-in ketchup1 fridge1)",
                                 "(close fridge1)"));
  EXPECT_EQ(result.statistics.relevant_objects, 12u);
}

TEST_F(Cli, ExportPddlIntoAnUnwritablePlaceFails) {
  // A regular file where the output directory should be.
  fs::path blocker = write("blocker", "not a directory");
  Invocation r = run({"export-pddl", "--scenario", tidy_kitchen(), "--goal", kKetchupGoal, "--out", (blocker / "sub").string()});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_THAT(r.err, HasSubstr((blocker / "sub").string()));
}

TEST_F(Cli, TidyKitchen35Plans) {
  Invocation r = run({"plan", "--scenario", source("data/scenarios/tidy-kitchen-35.yaml"), "--goal",
               "(and (in ketchup1 fridge1) (closed fridge1))", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["plan"].size(), 4u);
}

}  // namespace
}  // namespace apprentice
