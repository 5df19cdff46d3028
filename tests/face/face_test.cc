// The public face (face/apprentice.h): a spec and a world make a session
// that learns and performs, as every front end builds it.
#include "face/apprentice.h"

#include <algorithm>
#include <cstdlib>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/paths.h"
#include "common/scenarios.h"
#include "common/scratch.h"
#include "instructor/simulated_instructor.h"
#include "knowledge/store.h"
#include "knowledge/store_engine.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;
using testing::ScratchTest;

TEST(Face, TheDefaultSpecIsTheCliDefault) {
  AgentSpec spec = default_agent_spec();
  EXPECT_EQ(spec.condition, "inst+search4");
  EXPECT_EQ(spec.generalization, "full");
  EXPECT_EQ(spec.goal_repair, "all");
  EXPECT_TRUE(spec.use_rules);
  EXPECT_EQ(spec.max_reprompts, 1);
  EXPECT_TRUE(spec.knowledge.empty());
  EXPECT_EQ(spec.llm.goal_responses, 5);
}

TEST(Face, BadTextInTheSpecIsRefusedBeforeAnythingIsBuilt) {
  Scenario kitchen = testing::shipped_scenario("tidy-kitchen");
  AgentSpec spec = default_agent_spec();
  spec.condition = "inst+serch4";
  auto made = make_agent_session(spec, kitchen);
  ASSERT_FALSE(made);
  EXPECT_EQ(made.error().code, ErrorCode::kInvalidInput);
  spec = default_agent_spec();
  spec.generalization = "partial";
  EXPECT_FALSE(make_agent_session(spec, kitchen));
  spec = default_agent_spec();
  spec.goal_repair = "mend";
  EXPECT_FALSE(make_agent_session(spec, kitchen));
}

TEST(Face, AnLlmConditionWithoutAnLlmSaysHowToGiveOne) {
  ::unsetenv("APPRENTICE_LLM");
  AgentSpec spec = default_agent_spec();
  spec.condition = "inst+llm";
  auto made = make_agent_session(spec, testing::shipped_scenario("tidy-kitchen"));
  ASSERT_FALSE(made);
  EXPECT_EQ(made.error().code, ErrorCode::kInvalidInput);
  EXPECT_THAT(made.error().message, HasSubstr("needs an LLM"));
  EXPECT_THAT(made.error().message, HasSubstr("--llm SPEC"));
}

// Table 3's inst+search4 row, through the face: 40 instructions, 603 words.
TEST(Face, LearningWithTheSimulatedInstructorGivesTableThree) {
  Scenario kitchen = testing::shipped_scenario("tidy-kitchen");
  auto session = make_agent_session(default_agent_spec(), kitchen);
  ASSERT_TRUE(session) << session.error().describe();
  SimulatedInstructor teacher(kitchen);
  auto report = (*session)->learn(teacher);
  ASSERT_TRUE(report) << report.error().describe();
  EXPECT_FALSE(report->stopped);
  EXPECT_EQ(report->counts.instructions, 40);
  EXPECT_EQ(report->counts.words, 603);
  EXPECT_EQ(report->assertions_achieved, report->assertions_total);
  EXPECT_EQ(report->objects_done, 30);
  EXPECT_THAT(report->summary, HasSubstr("The task is learned: 35 of 35 parts of the goal are met, after 40 instructions."));
  EXPECT_THAT(report->summary, HasSubstr("Nothing was saved."));
  // Where each goal came from keeps its name in the JSON: the teacher's
  // first of a kind, then memory for the rest of that kind.
  std::set<std::string> learned_from;
  const nlohmann::json learned = nlohmann::json::parse(to_json(*report));
  for (const auto& o : learned["objects"]) learned_from.insert(o["goal_source"]);
  EXPECT_EQ(learned_from, (std::set<std::string>{"instructor", "memory"}));
  // Each object names the part it was dealt with in, by its verb and place.
  std::set<std::pair<std::string, std::string>> parts;
  for (const auto& o : learned["objects"]) parts.emplace(o["subtask"], o["part_place"]);
  EXPECT_EQ(parts, (std::set<std::pair<std::string, std::string>>{
                       {"clear", "table"}, {"store", "counter"}, {"unload", "dish-rack"}}));

  // Then alone, with what it learned.
  auto alone = (*session)->perform("");
  ASSERT_TRUE(alone) << alone.error().describe();
  EXPECT_EQ(alone->assertions_achieved, alone->assertions_total);
  EXPECT_TRUE(alone->agent.help_needed.empty());
  EXPECT_THAT(alone->summary, HasSubstr("Performed with learned knowledge alone: 35 of 35 parts of the goal are met (100.0%)"));
  nlohmann::json j = nlohmann::json::parse(to_json(*alone));
  EXPECT_EQ(j["instructions"], 0);
  EXPECT_EQ(j["assertions_achieved"], 35);
  EXPECT_EQ(j["actions"], alone->agent.actions_executed);
  EXPECT_TRUE(j["help_needed"].empty());
  for (const auto& o : j["objects"]) EXPECT_EQ(o["goal_source"], "memory") << o["object"];
}

// The report's enums keep the names the JSON had when they were strings.
TEST(Face, GoalSourcesKeepTheirNamesInTheJson) {
  const std::vector<std::pair<GoalSource, std::string>> sources = {
      {GoalSource::kNone, ""},          {GoalSource::kMemory, "memory"},   {GoalSource::kInstructor, "instructor"},
      {GoalSource::kLlm, "llm"},        {GoalSource::kAnalogy, "analogy"}, {GoalSource::kLikeness, "likeness"},
      {GoalSource::kRule, "rule"},      {GoalSource::kPersonRule, "person's rule"},
      {GoalSource::kFleet, "fleet"},    {GoalSource::kDecision, "decision"}};
  SessionReport report;
  for (const auto& [source, name] : sources) {
    ObjectReport object;
    object.object = "thing";
    object.goal_source = source;
    report.agent.objects.push_back(object);
  }
  nlohmann::json j = nlohmann::json::parse(to_json(report));
  ASSERT_EQ(j["objects"].size(), sources.size());
  for (std::size_t i = 0; i < sources.size(); ++i) EXPECT_EQ(j["objects"][i]["goal_source"], sources[i].second);
}

TEST(Face, PerformingWithNothingLearnedNamesWhatIsMissing) {
  auto session = make_agent_session(default_agent_spec(), testing::shipped_scenario("tidy-kitchen"));
  ASSERT_TRUE(session);
  auto alone = (*session)->perform("tidy kitchen");
  ASSERT_FALSE(alone);
  EXPECT_EQ(alone.error().code, ErrorCode::kNotFound);
  EXPECT_THAT(alone.error().message, HasSubstr("the agent holds no learned task yet"));
}

class FaceStore : public ScratchTest {};

// What one session keeps in its store, the next one starts from.
TEST_F(FaceStore, TheStoreIsOwnedAndKeptAcrossSessions) {
  Scenario kitchen = testing::shipped_scenario("tidy-kitchen");
  AgentSpec spec = default_agent_spec();
  spec.knowledge = (dir_ / "kitchen.sqlite").string();
  {
    auto session = make_agent_session(spec, kitchen);
    ASSERT_TRUE(session) << session.error().describe();
    ASSERT_EQ((*session)->store_path(), dir_ / "kitchen.sqlite");
    SimulatedInstructor teacher(kitchen);
    auto report = (*session)->learn(teacher);
    ASSERT_TRUE(report);
    EXPECT_THAT(report->summary, HasSubstr("What you taught me is kept in " + spec.knowledge + "."));
  }
  spec.condition = "knowledge-only";
  spec.store_access = StoreAccess::kReadOnly;
  auto again = make_agent_session(spec, kitchen);
  ASSERT_TRUE(again) << again.error().describe();
  EXPECT_EQ((*again)->knowledge().tasks.size(), 1u);
  auto alone = (*again)->perform("tidy kitchen");
  ASSERT_TRUE(alone) << alone.error().describe();
  EXPECT_EQ(alone->assertions_achieved, alone->assertions_total);
}

// Live: a running agent takes in what other robots of its household
// learned after it started (the store's news), and says so once, naming
// each robot.
TEST_F(FaceStore, ARunningAgentSeesWhatAnotherRobotLearnedSinceItStarted) {
  Scenario kitchen = testing::shipped_scenario("tidy-kitchen");
  const std::string store = (dir_ / "fleet.sqlite").string();
  AgentSpec spec = default_agent_spec();
  spec.knowledge = store;
  spec.household = "smiths";
  {
    auto teaching = make_agent_session(spec, kitchen);
    ASSERT_TRUE(teaching) << teaching.error().describe();
    SimulatedInstructor teacher(kitchen);
    ASSERT_TRUE((*teaching)->learn(teacher));
  }
  auto taught = load_knowledge_read_only(store, *kitchen.world.domain, "smiths");
  ASSERT_TRUE(taught) << taught.error().describe();
  // The joneses' robot knows everything but two kinds' goals.
  const std::string kind = taught->goals.all().front().key.category;
  std::string other_kind;
  for (const GoalKnowledge& g : taught->goals.all())
    if (g.key.category != kind && other_kind.empty()) other_kind = g.key.category;
  ASSERT_FALSE(other_kind.empty());
  std::vector<GoalKnowledge> kinds_goals, other_kinds_goals;
  {
    auto joneses = KnowledgeStore::open(store, StoreAccess::kReadWrite, "joneses");
    ASSERT_TRUE(joneses) << joneses.error().describe();
    ASSERT_TRUE(joneses->save_task(taught->tasks.front()));
    for (const GoalKnowledge& g : taught->goals.all()) {
      if (g.key.category == kind) kinds_goals.push_back(g);
      else if (g.key.category == other_kind) other_kinds_goals.push_back(g);
      else ASSERT_TRUE(joneses->save_goal(g));
    }
  }
  spec.household = "joneses";
  spec.condition = "knowledge-only";
  spec.store_access = StoreAccess::kReadOnly;
  auto running = make_agent_session(spec, kitchen);
  ASSERT_TRUE(running) << running.error().describe();
  for (const GoalKnowledge& g : kinds_goals) ASSERT_EQ((*running)->knowledge().goals.find(g.key), nullptr);
  // Two other robots of the household learn those kinds now.
  {
    auto robot2 = KnowledgeStore::open(store, StoreAccess::kReadWrite, "joneses", "kitchen-2");
    ASSERT_TRUE(robot2) << robot2.error().describe();
    for (const GoalKnowledge& g : kinds_goals) ASSERT_TRUE(robot2->save_goal(g));
    auto robot3 = KnowledgeStore::open(store, StoreAccess::kReadWrite, "joneses", "Robot 3");
    ASSERT_TRUE(robot3) << robot3.error().describe();
    for (const GoalKnowledge& g : other_kinds_goals) ASSERT_TRUE(robot3->save_goal(g));
  }
  auto alone = (*running)->perform("tidy kitchen");
  ASSERT_TRUE(alone) << alone.error().describe();
  EXPECT_TRUE(alone->agent.help_needed.empty()) << alone->agent.help_needed.front();
  EXPECT_EQ(alone->assertions_achieved, alone->assertions_total);
  auto spoken = [](std::string category) {
    std::replace(category.begin(), category.end(), '-', ' ');
    return category;
  };
  const std::vector<std::string> said{"Robot kitchen-2 just learned where the " + spoken(kind) + " goes.",
                                      "Robot 3 just learned where the " + spoken(other_kind) + " goes."};
  EXPECT_EQ(alone->agent.news, said);
  EXPECT_EQ(nlohmann::json::parse(to_json(*alone))["news"], nlohmann::json::array({said[0], said[1]}));
  // Said once: a second run of the same session has nothing new to say.
  auto again = (*running)->perform("tidy kitchen");
  ASSERT_TRUE(again);
  EXPECT_TRUE(again->agent.news.empty());
}

TEST_F(FaceStore, AStoreThatIsNotOneIsRefused) {
  AgentSpec spec = default_agent_spec();
  spec.knowledge = write("not-a-store.sqlite", "this is not SQLite\n").string();
  auto made = make_agent_session(spec, testing::shipped_scenario("tidy-kitchen"));
  ASSERT_FALSE(made);
  EXPECT_NE(made.error().code, ErrorCode::kInvalidInput);
}

// "domain: kitchen" names the shipped domain from a world in any folder.
TEST_F(FaceStore, AWorldElsewhereNamesAShippedDomainByName) {
  std::string yaml = [] {
    std::ifstream in(testing::source_path("tests/agent/data/two-objects.yaml"));
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }();
  const std::size_t at = yaml.find("domain:");
  ASSERT_NE(at, std::string::npos);
  yaml.replace(at, yaml.find('\n', at) - at, "domain: kitchen");
  const std::filesystem::path world = write("elsewhere.yaml", yaml);
  auto loaded = load_world(world);
  ASSERT_TRUE(loaded) << loaded.error().describe();
  EXPECT_EQ(std::filesystem::weakly_canonical(loaded->domain_path),
            std::filesystem::weakly_canonical(testing::source_path("data/domains/kitchen.pddl")));
  // Without the shipped domains to look in, the name is a file beside it.
  auto alone = load_scenario(world);
  ASSERT_FALSE(alone);
  EXPECT_EQ(alone.error().code, ErrorCode::kNotFound);
  // A domain of that name beside the world is preferred.
  write("kitchen", "not a domain");
  auto beside = load_world(world);
  ASSERT_FALSE(beside);
  EXPECT_EQ(beside.error().code, ErrorCode::kInvalidInput);
}

// One way to find data/: from the test binary inside the build tree, the
// checkout's; $APPRENTICE_DATA wins when set.
TEST(Face, DataDirIsFoundFromTheCodeAndCanBeChosen) {
  ::unsetenv("APPRENTICE_DATA");
  EXPECT_EQ(std::filesystem::weakly_canonical(data_dir()), std::filesystem::weakly_canonical(testing::source_path("data")));
  ::setenv("APPRENTICE_DATA", "/somewhere/else", 1);
  EXPECT_EQ(data_dir(), std::filesystem::path("/somewhere/else"));
  ::unsetenv("APPRENTICE_DATA");
}

TEST(Face, TheWordsForATeacherAreTheScriptsWords) {
  Scenario kitchen = testing::shipped_scenario("tidy-kitchen");
  EXPECT_EQ(words::task_name("tidy kitchen"), "Tidy kitchen.");
  EXPECT_EQ(words::repeat(), "Repeat.");
  EXPECT_EQ(words::done(), "You are done.");
  const Subtask& first = kitchen.task.subtasks.front();
  EXPECT_THAT(words::repeat_while(kitchen.world, first.places), HasSubstr("Repeat the following tasks while an object is "));
}

}  // namespace
}  // namespace apprentice
