// Helpers for the agent tests: an instructor wrapper that keeps every
// question, and one learning run with the simulated instructor. Paths and
// scenario loading come from tests/common.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agent/agent.h"
#include "common/paths.h"
#include "common/scenarios.h"
#include "instructor/simulated_instructor.h"
#include "llm/factory.h"
#include "world/scenario.h"
#include "world/simulator.h"

namespace apprentice::testing {

// Passes questions on to `inner` and keeps them, with the world as it was.
class RecordingInstructor final : public Instructor {
 public:
  explicit RecordingInstructor(Instructor& inner) : inner_(inner) {}
  Result<std::string> answer(const Question& question, const World& world) override {
    questions.push_back(question);
    states.push_back(world.state);
    return inner_.answer(question, world);
  }
  void hear(std::string_view statement) override {
    heard.emplace_back(statement);
    inner_.hear(statement);
  }
  std::vector<Question> questions;
  std::vector<State> states;
  std::vector<std::string> heard;

 private:
  Instructor& inner_;
};

// The goals of tests/agent/data/two-objects.yaml in the script's words.
inline constexpr const char* kKetchupGoal =
    "If the object is a ketchup then the goal is that the object is in the fridge and the fridge is closed.";
inline constexpr const char* kPaperPlateGoal =
    "If the object is a paper-plate then the goal is that the object is in the garbage.";

// An instructor whose replies come from a function of the question (what
// a program or a person would answer); nullopt ends the session as end of
// input does. `person` says whether the agent must never give up on it.
class CallbackInstructor final : public Instructor {
 public:
  using Reply = std::function<std::optional<std::string>(const Question&, const World&)>;
  CallbackInstructor(Reply reply, bool person) : reply_(std::move(reply)), person_(person) {}
  Result<std::string> answer(const Question& question, const World& world) override {
    questions.push_back(question);
    auto reply = reply_(question, world);
    if (!reply) return make_error(ErrorCode::kCancelled, "end of input");
    return *reply;
  }
  void hear(std::string_view statement) override { heard.emplace_back(statement); }
  void observe(const Action& action, const World& world) override { observed.emplace_back(action, world.state); }
  bool is_person() const override { return person_; }

  std::vector<Question> questions;
  std::vector<std::string> heard;
  std::vector<std::pair<Action, State>> observed;  // each action as it happened, with the world after it

 private:
  Reply reply_;
  bool person_;
};

// Replies from a list, in order, then end of input.
inline CallbackInstructor::Reply replies(std::vector<std::string> lines) {
  auto next = std::make_shared<std::size_t>(0);
  return [lines = std::move(lines), next](const Question&, const World&) -> std::optional<std::string> {
    if (*next >= lines.size()) return std::nullopt;
    return lines[(*next)++];
  };
}

// One learning run with the simulated instructor.
struct LearningRun {
  Result<AgentReport> report = make_error(ErrorCode::kCancelled, "not run");
  DialogueCounts counts;
  std::vector<TranscriptLine> transcript;
  std::string transcript_text;
  std::vector<Question> questions;
  std::vector<State> states_at_questions;
  State final_state;
  std::vector<Action> history;
  int achieved = 0;
  int total = 0;
  Knowledge knowledge;
  LlmTotals llm;
};

inline std::unique_ptr<LlmAdvisor> corpus_advisor() {
  auto client = llm::make_llm_client("corpus:" + corpus_path().string(), llm::LlmOptions{});
  EXPECT_TRUE(client.has_value()) << (client ? "" : client.error().describe());
  if (!client) return nullptr;
  auto templates = llm::PromptTemplates::load(source_path("data/prompts"));
  EXPECT_TRUE(templates.has_value()) << (templates ? "" : templates.error().describe());
  if (!templates) return nullptr;
  return std::make_unique<LlmAdvisor>(std::move(*client), std::move(*templates));
}

// `start`: what the agent knows before (empty by default).
inline LearningRun learn(const Scenario& scenario, std::string_view condition_name, LlmAdvisor* llm = nullptr,
                         KnowledgeStore* store = nullptr, Knowledge start = {}) {
  LearningRun run;
  auto condition = parse_condition(condition_name);
  EXPECT_TRUE(condition.has_value());
  if (!condition) return run;
  AgentOptions options;
  options.condition = *condition;
  TaskLearningAgent agent(options, std::move(start), Understanding(), store, llm);
  Simulator simulator(scenario.world);
  SimulatedInstructor simulated(scenario);
  RecordingInstructor instructor(simulated);
  Dialogue dialogue(instructor);
  run.report = agent.learn(simulator, dialogue);
  run.counts = dialogue.counts();
  run.transcript = dialogue.transcript();
  run.transcript_text = dialogue.transcript_text();
  run.questions = instructor.questions;
  run.states_at_questions = instructor.states;
  run.final_state = simulator.state();
  run.history = simulator.history();
  run.total = static_cast<int>(scenario.goal_assertions().size());
  for (const Literal& l : scenario.goal_assertions())
    if (simulator.state().satisfies(l)) ++run.achieved;
  run.knowledge = agent.knowledge();
  if (llm) run.llm = llm->totals();
  return run;
}

}  // namespace apprentice::testing
