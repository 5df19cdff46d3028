// The agent's own next action (agent/own_actions.h).
#include "agent/own_actions.h"

#include "search/greedy_best_first.h"
#include "search/iterative_deepening.h"

namespace apprentice {

OwnActions::Next OwnActions::next(const World& world, const Goal& goal, ObjectId object, std::string_view subtask,
                                  const Ways& ways) {
  Next out;
  if (!plan_.empty()) {
    out.action = plan_.front();
    plan_.pop_front();
    out.source = "search";
    return out;
  }
  if (ways.rules != nullptr) {
    MatchQuery query{&world.state, &goal, object, subtask};
    if (auto proposal = ways.rules->select(*world.domain, *world.universe, query)) {
      out.action = proposal->action;
      out.source = "rule";
      return out;
    }
  }
  if ((ways.search_depth > 0 || ways.unbounded_search) && searched_in_ != world.state) {
    SearchOptions options;
    options.max_depth = ways.search_depth;
    PlanResult result = ways.unbounded_search
                            ? find_greedy_plan(*world.domain, *world.universe, world.state, goal, options)
                            : find_plan(*world.domain, *world.universe, world.state, goal, options);
    out.searched = true;
    out.nodes = result.statistics.nodes_expanded;
    searched_in_ = world.state;
    if (result.status == SearchStatus::kSolved && !result.plan.empty()) {
      plan_.assign(result.plan.begin() + 1, result.plan.end());
      out.action = result.plan.front();
      out.source = "search";
    }
  }
  return out;
}

}  // namespace apprentice
