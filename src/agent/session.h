// Internal to the agent: the state of one run (learn or perform).
#pragma once

#include <deque>
#include <set>

#include "agent/agent.h"

namespace apprentice {

class TaskLearningAgent::Session {
 public:
  Session(TaskLearningAgent& agent, Simulator& simulator, Dialogue* dialogue, bool learning);

  Result<AgentReport> learn_task();
  Result<AgentReport> perform_task(const TaskKnowledge& task);

 private:
  // The subtask being worked on.
  struct Current {
    std::string verb;
    ObjectId place = 0;
  };

  // Task structure (agent.cc).
  Result<std::string> ask(QuestionKind kind, std::string text, std::optional<ObjectId> object = std::nullopt,
                          std::optional<Goal> goal = std::nullopt, std::optional<Action> action = std::nullopt);
  Status run_first_iteration(const Current& current);
  Status run_loop(const Current& current);
  std::optional<ObjectId> next_object(ObjectId place);
  Status handle_object(const Current& current, ObjectId object, ObjectReport& report);
  Status remember_task();

  // Goals (agent_goals.cc).
  Result<std::optional<Goal>> acquire_goal(const Current& current, ObjectId object, ObjectReport& report);
  Result<std::optional<Goal>> goal_from_llm(const Current& current, ObjectId object, ObjectReport& report);
  Result<std::optional<Goal>> goal_from_instructor(const Current& current, ObjectId object, ObjectReport& report);
  Status learn_goal(const Current& current, ObjectId object, const Goal& goal, const std::string& source);
  GoalKey goal_key(const Current& current, ObjectId object) const;
  llm::TaskContext llm_context(const Current& current, ObjectId object) const;

  // Actions (agent_actions.cc).
  Result<bool> achieve(const Current& current, ObjectId object, const Goal& goal, ObjectReport& report);
  Result<std::optional<Action>> action_from_llm(const Current& current, ObjectId object, const Goal& goal);
  Result<std::optional<Action>> action_from_instructor(const Current& current, ObjectId object, const Goal& goal);
  Status learn_rules(const Current& current, ObjectId object, const Goal& goal);

  const World& world() const { return simulator_.world(); }
  std::string describe_object(ObjectId object) const;

  TaskLearningAgent& agent_;
  Simulator& simulator_;
  Dialogue* dialogue_;  // null when performing alone
  bool learning_;
  AgentReport report_;
  TaskKnowledge task_;
  std::string task_verb_;
  std::string subtask_verb_;  // the subtask being worked on, once there is one
  std::set<ObjectId> evaluated_;
  // The actions executed towards the current goal, and where each came from.
  State episode_start_;
  std::vector<Action> episode_actions_;
  std::vector<std::string> episode_sources_;
  std::vector<std::string> llm_steps_;  // the steps so far, as the LLM prompt shows them
  std::string advice_;  // the words of the last action advised by the LLM or the instructor
};

}  // namespace apprentice
