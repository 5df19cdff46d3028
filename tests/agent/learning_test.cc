// Learning runs of the agent (Algorithm 1) with the simulated instructor on
// the paper's kitchen: the Table 3 figures of the instructed conditions,
// goals asked once per kind of object, a world that changes only through
// the simulator, and knowledge that is kept and suffices to perform the
// task again alone.
#include <map>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "agent_fixtures.h"
#include "common/scratch.h"
#include "knowledge/store.h"
#include "util/text.h"

namespace apprentice {
namespace {

using testing::LearningRun;
using testing::learn;
using testing::load_or_die;
using testing::source_path;

bool is_goal_description(const std::string& reply) { return starts_with_ignoring_case(reply, "If the object is "); }

std::vector<std::string> instructor_lines(const LearningRun& run) {
  std::vector<std::string> out;
  for (const TranscriptLine& line : run.transcript)
    if (line.speaker == "Instructor") out.push_back(line.text);
  return out;
}

class Learning : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    kitchen_ = new Scenario(load_or_die(source_path("data/scenarios/tidy-kitchen.yaml")));
  }
  static void TearDownTestSuite() {
    delete kitchen_;
    kitchen_ = nullptr;
  }
  static Scenario* kitchen_;
};
Scenario* Learning::kitchen_ = nullptr;

TEST_F(Learning, InstSearch4MatchesThePapersRowExactly) {
  LearningRun run = learn(*kitchen_, "inst+search4");
  ASSERT_TRUE(run.report.has_value()) << run.report.error().describe();
  EXPECT_TRUE(run.report->task_finished);
  EXPECT_EQ(run.total, 35);
  EXPECT_EQ(run.achieved, 35);  // completion 100%
  EXPECT_EQ(run.counts.instructions, 40);
  EXPECT_EQ(run.counts.words, 603);
  EXPECT_EQ(run.counts.yes_no, 0);
  // 14 task-structure instructions of 76 words, and one goal description
  // for each of the 26 (subtask, category) goal types.
  int structure = 0, structure_words = 0, goals = 0;
  for (const std::string& reply : instructor_lines(run)) {
    if (is_goal_description(reply)) {
      ++goals;
    } else {
      ++structure;
      structure_words += count_words(reply);
    }
  }
  EXPECT_EQ(structure, 14);
  EXPECT_EQ(structure_words, 76);
  EXPECT_EQ(goals, 26);
  EXPECT_EQ(run.report->goals_learned, 26);
  // Search found every action: the agent never asked for one.
  for (const Question& q : run.questions) {
    EXPECT_NE(q.kind, QuestionKind::kNextAction) << q.text;
  }
  EXPECT_GT(run.report->search_nodes, 0u);
}

TEST_F(Learning, InstructionAloneCompletesTheTask) {
  LearningRun run = learn(*kitchen_, "instruction");
  ASSERT_TRUE(run.report.has_value()) << run.report.error().describe();
  EXPECT_EQ(run.achieved, run.total);  // completion 100%
  EXPECT_EQ(run.counts.yes_no, 0);
  EXPECT_EQ(run.report->search_nodes, 0u);
  EXPECT_EQ(run.report->searches, 0);
  // The same 40 instructions as with search, plus the action commands the
  // learned rules could not supply (the paper, without rules of this
  // generality, reports 76 instructions and 757 words).
  int goals = 0, actions = 0;
  for (std::size_t i = 0; i < run.questions.size(); ++i) {
    if (run.questions[i].kind == QuestionKind::kNextAction) ++actions;
  }
  for (const std::string& reply : instructor_lines(run)) goals += is_goal_description(reply) ? 1 : 0;
  EXPECT_EQ(goals, 26);
  EXPECT_GT(actions, 0);
  EXPECT_EQ(run.counts.instructions, 40 + actions);
  EXPECT_GT(run.counts.words, 603);
  EXPECT_GT(run.report->rule_actions, 0) << "rules learned on one object should act for later ones";
  ::testing::Test::RecordProperty("instructions", run.counts.instructions);
  ::testing::Test::RecordProperty("words", run.counts.words);
  std::printf("instruction: %d instructions, %d words, %d yes/no, %d action commands\n", run.counts.instructions,
              run.counts.words, run.counts.yes_no, actions);
}

// The (subtask, category) a goal question is about.
using GoalType = std::pair<std::string, std::string>;

// For every goal type, the objects the agent asked a goal question about
// (a request for a goal description or a proposed goal to confirm).
std::map<GoalType, std::set<ObjectId>> goal_questions(const Scenario& scenario, const LearningRun& run) {
  std::map<GoalType, std::set<ObjectId>> out;
  for (const Question& q : run.questions) {
    bool about_goal = (q.kind == QuestionKind::kSubtaskStep || q.kind == QuestionKind::kConfirmGoal) && q.object;
    if (!about_goal) continue;
    out[{q.subtask, scenario.world.universe->info(*q.object).category}].insert(*q.object);
  }
  return out;
}

void expect_goals_asked_once_per_kind(const Scenario& scenario, const LearningRun& run, std::size_t goal_types) {
  auto asked = goal_questions(scenario, run);
  EXPECT_EQ(asked.size(), goal_types);
  for (const auto& [type, objects] : asked)
    EXPECT_EQ(objects.size(), 1u) << "asked about the goal of " << objects.size() << " objects of kind "
                                  << type.second << " in " << type.first;
  // And never twice for a description of the same object.
  std::map<ObjectId, int> descriptions;
  for (const Question& q : run.questions)
    if (q.kind == QuestionKind::kSubtaskStep && q.object) ++descriptions[*q.object];
  for (const auto& [object, n] : descriptions)
    EXPECT_EQ(n, 1) << "asked " << n << " times for the goal of " << scenario.world.universe->name(object);
}

TEST_F(Learning, NeverAsksTwiceForAGoalOfTheSameKind) {
  // The kitchen has two ceramic-plates, soda-cans, granola-bars and
  // ceramic-bowls: the second of each reuses the goal learned on the first.
  for (const char* condition : {"instruction", "inst+search4"}) {
    SCOPED_TRACE(condition);
    LearningRun run = learn(*kitchen_, condition);
    ASSERT_TRUE(run.report.has_value());
    expect_goals_asked_once_per_kind(*kitchen_, run, 26);
    int from_memory = 0;
    for (const ObjectReport& o : run.report->objects) from_memory += o.goal_source == GoalSource::kMemory ? 1 : 0;
    EXPECT_EQ(from_memory, 4);
  }
}

TEST_F(Learning, NeverAsksTwiceForAGoalWithTheLlmEither) {
  SKIP_WITHOUT_CORPUS();
  for (const char* condition : {"inst+llm", "inst+search2+llm", "inst+search4+llm", "search4+llm"}) {
    SCOPED_TRACE(condition);
    auto advisor = testing::corpus_advisor();
    ASSERT_NE(advisor, nullptr);
    LearningRun run = learn(*kitchen_, condition, advisor.get());
    ASSERT_TRUE(run.report.has_value());
    auto asked = goal_questions(*kitchen_, run);
    for (const auto& [type, objects] : asked) {
      EXPECT_EQ(objects.size(), 1u) << type.second << " in " << type.first;
    }
    if (std::string_view(condition) != "search4+llm") {
      EXPECT_EQ(run.achieved, run.total);
    }
  }
}

TEST_F(Learning, TheWorldChangesOnlyThroughTheSimulator) {
  for (const char* condition : {"instruction", "inst+search4"}) {
    SCOPED_TRACE(condition);
    LearningRun run = learn(*kitchen_, condition);
    ASSERT_TRUE(run.report.has_value());
    const World& world = kitchen_->world;
    // Replaying the simulator's history from the initial state gives the
    // final state, every action applicable where it was taken...
    std::vector<State> trajectory{world.state};
    for (const Action& a : run.history) {
      ASSERT_TRUE(is_applicable(*world.domain, trajectory.back(), a))
          << format_action(*world.domain, *world.universe, a);
      trajectory.push_back(apply(*world.domain, trajectory.back(), a));
    }
    EXPECT_EQ(trajectory.back(), run.final_state);
    EXPECT_EQ(static_cast<int>(run.history.size()), run.report->actions_executed);
    // ...and every world the instructor was shown lies on that trajectory,
    // in order: nothing else moved anything between two actions.
    std::size_t at = 0;
    for (const State& seen : run.states_at_questions) {
      while (at < trajectory.size() && !(trajectory[at] == seen)) ++at;
      ASSERT_LT(at, trajectory.size()) << "the instructor saw a state the simulator never had";
    }
  }
}

TEST_F(Learning, WhatIsLearnedPerformsTheTaskAloneInOneShot) {
  LearningRun run = learn(*kitchen_, "inst+search4");
  ASSERT_TRUE(run.report.has_value());
  for (const char* file : {"data/scenarios/tidy-kitchen.yaml", "data/scenarios/tidy-kitchen-similar.yaml"}) {
    SCOPED_TRACE(file);
    Scenario scenario = load_or_die(source_path(file));
    AgentOptions options;
    options.condition = Condition{"knowledge-only", false, 0, false};
    TaskLearningAgent agent(options, run.knowledge, Understanding(), nullptr, nullptr);
    Simulator simulator(scenario.world);
    auto report = agent.perform(simulator, "tidy kitchen");
    ASSERT_TRUE(report.has_value()) << report.error().describe();
    EXPECT_THAT(report->help_needed, ::testing::IsEmpty());
    EXPECT_EQ(report->search_nodes, 0u);
    int achieved = 0;
    for (const Literal& l : scenario.goal_assertions()) achieved += simulator.state().satisfies(l) ? 1 : 0;
    EXPECT_EQ(achieved, static_cast<int>(scenario.goal_assertions().size()));
  }
}

TEST_F(Learning, EverythingLearnedIsStoredAsItIsLearned) {
  testing::ScratchDir scratch;
  const std::filesystem::path& dir = scratch.path();
  {
    auto store = KnowledgeStore::open(dir / "k.sqlite");
    ASSERT_TRUE(store.has_value()) << store.error().describe();
    LearningRun run = learn(*kitchen_, "inst+search4", nullptr, &*store);
    ASSERT_TRUE(run.report.has_value());
  }
  auto store = KnowledgeStore::open(dir / "k.sqlite");
  ASSERT_TRUE(store.has_value());
  auto knowledge = store->load(*kitchen_->world.domain);
  ASSERT_TRUE(knowledge.has_value()) << knowledge.error().describe();
  EXPECT_EQ(knowledge->goals.size(), 26u);
  EXPECT_GT(knowledge->rules.size(), 0u);
  ASSERT_EQ(knowledge->tasks.size(), 1u);
  EXPECT_EQ(knowledge->tasks[0].name, "tidy kitchen");
  EXPECT_EQ(knowledge->tasks[0].subtasks.size(), 3u);
  std::filesystem::remove_all(dir);
}

// The simulated instructor, until it leaves after `replies` replies.
class LeavingInstructor final : public Instructor {
 public:
  LeavingInstructor(const Scenario& scenario, int replies) : inner_(scenario), left_(replies) {}
  Result<std::string> answer(const Question& question, const World& world) override {
    if (left_-- <= 0) return make_error(ErrorCode::kCancelled, "end of input");
    return inner_.answer(question, world);
  }

 private:
  SimulatedInstructor inner_;
  int left_;
};

TEST_F(Learning, AnInstructorWhoLeavesEndsTheRunAndKeepsWhatWasLearned) {
  testing::ScratchDir scratch;
  const std::filesystem::path& dir = scratch.path();
  auto store = KnowledgeStore::open(dir / "k.sqlite");
  ASSERT_TRUE(store.has_value());
  AgentOptions options;
  options.condition = *parse_condition("inst+search4");
  TaskLearningAgent agent(options, Knowledge{}, Understanding(), &*store, nullptr);
  Simulator simulator(kitchen_->world);
  // Task name, loop, subtask, first goal, "You are done.", "Repeat.", two
  // more goals: then gone.
  LeavingInstructor instructor(*kitchen_, 8);
  Dialogue dialogue(instructor);
  auto report = agent.learn(simulator, dialogue);
  ASSERT_FALSE(report.has_value());
  EXPECT_EQ(report.error().code, ErrorCode::kCancelled);
  EXPECT_EQ(agent.knowledge().goals.size(), 3u);
  auto stored = store->load(*kitchen_->world.domain);
  ASSERT_TRUE(stored.has_value());
  EXPECT_EQ(stored->goals.size(), 3u);
  EXPECT_EQ(stored->tasks.size(), 1u);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace apprentice
