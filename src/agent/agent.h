// The task-learning agent: Algorithm 1 of the paper, extended with learned
// policy rules.
//
// For each subtask the instructor names, while objects remain at its place,
// the agent chooses one. It retrieves a goal it knows for that kind of
// object, or acquires one (from the LLM, confirmed by the instructor where
// there is one, or from the instructor). Then, until the goal holds, it
// takes the next action from: a plan already found; its learned rules;
// search, to the condition's depth; the LLM; the instructor. When the goal
// holds it learns rules from what it did. Everything learned is stored the
// moment it is learned, when a store is attached.
//
// The world changes only through the Simulator, by the actions the agent
// executes.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "agent/condition.h"
#include "agent/goal_proposals.h"
#include "agent/goal_repair.h"
#include "agent/llm_advisor.h"
#include "agent/report.h"
#include "agent/understanding.h"
#include "instructor/dialogue.h"
#include "knowledge/learning.h"
#include "knowledge/store.h"
#include "world/simulator.h"

namespace apprentice {

struct AgentOptions {
  Condition condition;
  Generalization generalization = Generalization::kFull;
  // Consult learned policy rules before search and before asking.
  bool use_rules = true;
  // Give up on an object after this many actions (a bad goal or bad
  // advice). With a person teaching, the agent asks the person instead of
  // giving up, and only what the person says is done.
  int max_actions_per_object = 30;
  // Re-ask an instructor that is not a person (Instructor::is_person) at
  // most this many times after a reply the agent cannot use; the question
  // then goes unanswered and the report says so. A person is asked again
  // until they answer or end the session.
  int max_retries = 3;
  // LLM goals: which analysis and repair steps run (agent/goal_repair.h).
  GoalRepairOptions goal_repair;
  // LLM goals: re-prompts with the rejected answers per object (when
  // goal_repair.reprompt), before the instructor is asked.
  int max_reprompts = 1;
  // The paper's behaviour: offer LLM responses the agent cannot ground, and
  // without an instructor take the most probable one even so. Otherwise
  // only usable ones are offered, and without an instructor the best usable
  // one is taken.
  bool offer_ungrounded = false;
  // Where a thing goes that no goal is known for: when the agent acts
  // alone, asks yes/no, or asks where (knowledge/decision.h,
  // agent/goal_proposals.h).
  DecisionPolicy decision = default_decision_policy();
  // For a kind this household never taught, what the store's other
  // households chose is one of the decision's sources
  // (knowledge/fleet_prior.h, Knowledge::fleet).
  bool fleet_prior = true;
};

// Ownership: the agent owns its options, knowledge and understanding (by
// value). `store` and `llm` are borrowed and must outlive the agent; the
// simulator and dialogue are lent for one call. Not thread-safe: one
// thread uses an agent at a time (separate agents may run in parallel).
class TaskLearningAgent {
 public:
  // `store` may be null (nothing persisted); `llm` may be null unless the
  // condition uses the LLM (checked: a bug aborts).
  TaskLearningAgent(AgentOptions options, Knowledge knowledge, Understanding understanding,
                    KnowledgeStore* store, LlmAdvisor* llm);

  // Learns and performs the task the instructor teaches (Algorithm 1),
  // saying what it understood and what it did, and answering the
  // teacher's commands (help, status, undo, forget, quit). Errors:
  // kCancelled when the instructor leaves (end of input or "quit"; what was
  // learned is kept); kIo/kDataLoss if the store cannot be written.
  Result<AgentReport> learn(Simulator& simulator, Dialogue& dialogue);

  // Performs a task it has learned, with learned knowledge alone: no
  // instructor, search or LLM. Reports where it would have needed help.
  // Errors: kNotFound when no such task was learned (with an empty name:
  // unless exactly one was).
  Result<AgentReport> perform(Simulator& simulator, const std::string& task_name);

  const Knowledge& knowledge() const { return knowledge_; }

  // The learned task a name stands for: the task of that name, or the one
  // a teacher saying the name would have taught ("clean living room" finds
  // "tidy living room", language::task_name_as_read); with an empty name,
  // the only task when exactly one was learned. Null when none.
  const TaskKnowledge* find_task(const std::string& name) const;

  // Watches `store` (borrowed; it must outlive the agent; null: none) for
  // what other robots learn while this one runs: before each object it
  // takes the store's news (KnowledgeStore::news), goals of its household
  // and the fleet's rules, and says once per kind, naming the robot that
  // learned it, "Robot kitchen-2 just learned where the ketchup goes."
  // (AgentReport::news).
  void watch(KnowledgeStore* store) { watched_ = store; }

 private:
  class Session;
  friend class Session;

  AgentOptions options_;
  Knowledge knowledge_;
  Understanding understanding_;
  KnowledgeStore* store_;
  LlmAdvisor* llm_;
  KnowledgeStore* watched_ = nullptr;
};

}  // namespace apprentice
