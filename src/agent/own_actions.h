// Internal to the agent: its own next action toward a goal, before anyone
// is asked (Algorithm 1's inner loop, ahead of the LLM and the teacher):
// the rest of a plan search found, else a rule learned, else search to the
// condition's depth. One per goal being worked on: it holds the plan being
// carried out and the state search last failed in, so that search is not
// run again until the state changes. It asks no one, says nothing and
// changes no world: the session carries the action out.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <string_view>

#include "knowledge/matcher.h"
#include "world/world.h"

namespace apprentice {

class OwnActions {
 public:
  // The ways the agent may find an action itself.
  struct Ways {
    const RuleMatcher* rules = nullptr;  // the rules learned; null: not used
    int search_depth = 0;                // iterative deepening to this depth; 0: none
    bool unbounded_search = false;       // greedy best-first search with no depth limit
  };
  struct Next {
    std::optional<Action> action;  // none: the agent has no action of its own here
    std::string source;            // with an action: "search" or "rule"
    bool searched = false;         // whether search ran for it
    std::uint64_t nodes = 0;       // the nodes that search expanded
  };
  // The next action toward `goal` for `object` in `world`'s state, during
  // `subtask`.
  Next next(const World& world, const Goal& goal, ObjectId object, std::string_view subtask, const Ways& ways);
  // The action last given could not be carried out: the rest of its plan
  // is stale.
  void drop_plan() { plan_.clear(); }

 private:
  std::deque<Action> plan_;
  std::optional<State> searched_in_;
};

}  // namespace apprentice
