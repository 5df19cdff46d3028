// Internal to the agent: acting toward one goal, Algorithm 1's inner loop.
//
// The next action comes from the agent's own ways first (agent/
// own_actions.h: the plan being carried out, a rule learned, search to the
// condition's depth), then from the LLM, then from the teacher. Each is
// carried out in the world until the goal holds, the agent gives up, or
// the teacher says to leave the thing. What was done, and where each action
// came from, is kept in the goal's work (teaching::InProgress), from which
// the rules an episode teaches are learned once the goal holds.
//
// The actor asks no one and says nothing itself: the session, which holds
// the dialogue and the world, does that through `ActingHelp`. So the loop
// is tested with a help of the test's own (tests/agent/actor_test.cc).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "agent/curriculum.h"
#include "agent/flow.h"
#include "agent/own_actions.h"
#include "knowledge/learning.h"
#include "world/world.h"

namespace apprentice {

// Who else may say the next action, and the hands that carry one out.
class ActingHelp {
 public:
  virtual ~ActingHelp() = default;
  // The LLM's next action toward the goal of `work`, or none; `advice`
  // gets its words as said back in the report ("\"open fridge\" (confirmed)").
  virtual Flow<std::optional<Action>> llm_action(teaching::InProgress& work, std::string& advice) = 0;
  // The teacher's next action, or none: the teacher said to leave the
  // thing, or gave nothing usable (`work.report.note` says which).
  virtual Flow<std::optional<Action>> instructor_action(teaching::InProgress& work, std::string& advice) = 0;
  // Carries `action` out in the world; an error when it cannot be done there.
  virtual Status carry_out(const Action& action) = 0;
  // `action`, advised, could not be carried out: the teacher is told.
  virtual void could_not_do(const Action& action) = 0;
};

// Who the actor may turn to, and how long it keeps trying alone.
struct ActingPolicy {
  OwnActions::Ways own;         // the agent's own ways: its rules, search
  bool ask_llm = false;         // the LLM is asked when the agent has no action
  bool ask_instructor = false;  // then the teacher is
  // The actions the agent takes toward one goal before it gives up. Past
  // it, a teacher who is a person (`ask_only_teacher_past_bound`) is asked
  // for every further action instead.
  int max_actions = 0;
  bool ask_only_teacher_past_bound = false;
};

// How acting toward a goal ended.
enum class Acted {
  kAchieved,       // the goal holds
  kGaveUp,         // past the bound with no one to ask
  kNoWay,          // no source had an action
  kLeftByTeacher,  // the teacher said to leave the thing, or gave nothing usable
};

// What the actor did over a session, for the report.
struct ActingCounts {
  int searches = 0;
  std::uint64_t search_nodes = 0;
  int rule_actions = 0;  // actions chosen by a learned rule
  int actions_executed = 0;
};

class Actor {
 public:
  // Acts toward `work.goal` in `world` (which `help.carry_out` changes)
  // during the subtask `subtask`, until it holds or no one has an action.
  // Each action carried out is added to `work` with its source; a reason
  // for not achieving the goal goes in `work.report.note`.
  Flow<Acted> achieve(const World& world, teaching::InProgress& work, std::string_view subtask,
                      const ActingPolicy& policy, ActingHelp& help);

  const ActingCounts& counts() const { return counts_; }

 private:
  // The next action from the agent's own ways, then the LLM; none when
  // neither has one. `source` says which gave it.
  Flow<std::optional<Action>> own_or_llm_action(const World& world, teaching::InProgress& work,
                                                std::string_view subtask, const ActingPolicy& policy,
                                                ActingHelp& help, OwnActions& own, std::string& source);

  ActingCounts counts_;
};

// The rules an achieved goal teaches (Algorithm 3's chunks): none when no
// action was taken or every action already came from a rule. `object_text`
// describes the object for the rules' provenance.
std::vector<Rule> rules_taught(const World& world, const teaching::InProgress& work, std::string_view subtask,
                               const std::string& object_text, Generalization generalization);

}  // namespace apprentice
