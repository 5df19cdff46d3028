#include "cmd_core.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <ostream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "face/apprentice.h"
#include "language/narration.h"
#include "search/greedy_best_first.h"
#include "search/iterative_deepening.h"
#include "search/unreachable.h"
#include "util/json.h"
#include "util/text.h"
#include "world/pddl.h"
#include "world/scenario.h"
#include "world/state_lookup.h"

namespace apprentice::cli {

namespace {

// Where each item is, as "on table1", "in fridge1" or "in hand": binary
// searches in the sorted facts, so that listing n items is n log n.
std::string location_of(const World& world, ObjectId item) {
  const Vocabulary& v = world.vocabulary;
  if (auto on = facts_about(world.state, v.on, item); !on.empty()) return "on " + world.universe->name(on.front().args[1]);
  if (auto in = facts_about(world.state, v.in, item); !in.empty()) return "in " + world.universe->name(in.front().args[1]);
  if (world.state.holds(Fact(v.holding, {item}))) return "in hand";
  return "nowhere";
}

// The goal a --goal option names: a PDDL conjunction, or "intent" for the
// conjunction of every goal assertion of the scenario's intent (the whole
// task, as the instructor wants it done).
Result<Goal> goal_of(const Scenario& scenario, const std::string& text) {
  if (text == kIntentGoal) return Goal(scenario.goal_assertions());
  if (std::string_view t = trim(text); !t.empty() && t.front() != '(')
    return make_error(ErrorCode::kInvalidInput,
                      "--goal " + apprentice::quoted(text) + " is not a goal: a goal is PDDL, such as (in ketchup1 fridge1) or "
                      "(and (in ketchup1 fridge1) (closed fridge1)), or 'intent' for the whole task; "
                      "'apprentice interpret' reads English");
  return parse_goal(*scenario.world.domain, *scenario.world.universe, text);
}

// The other objects of `id`'s category, in id order.
std::vector<std::string> look_alikes(const Universe& u, ObjectId id) {
  std::vector<std::string> out;
  for (ObjectId other : u.with_category(u.info(id).category))
    if (other != id) out.push_back(u.name(other));
  return out;
}

// The plan in PDDL, one action a line, and the search's figures on a
// ";;" line (--pddl).
void print_plan_pddl(const World& world, const PlanResult& result, bool greedy, std::ostream& out) {
  const SearchStatistics& s = result.statistics;
  for (const Action& a : result.plan) out << format_action(*world.domain, *world.universe, a) << "\n";
  out << ";; status " << to_string(result.status) << ", " << result.plan.size() << " steps, ";
  if (greedy) {
    out << "greedy best-first search, " << s.nodes_expanded << " nodes expanded, " << s.nodes_generated
        << " generated, " << s.states_registered << " states, heuristic " << s.initial_heuristic
        << " at the start, " << s.steps_removed << " steps removed afterwards, ";
  } else {
    out << s.nodes_expanded << " nodes expanded, " << s.nodes_generated << " generated, depth limit "
        << s.depth_limit_reached << ", ";
  }
  out << s.relevant_objects << " relevant objects, " << s.ground_actions << " ground actions, " << s.elapsed_ms
      << " ms\n";
}

// What the search found, and what it took, in one sentence: "Greedy
// best-first search found a plan of 4 steps in 3 ms: 12 nodes expanded
// and 40 generated, ...".
std::string plan_summary(const PlanResult& result, bool greedy, std::optional<int> depth) {
  const SearchStatistics& s = result.statistics;
  using language::count_phrase;
  std::string search = greedy ? "Greedy best-first search" : "Iterative deepening to depth " + std::to_string(*depth);
  std::ostringstream ms;
  ms << std::fixed << std::setprecision(1) << s.elapsed_ms;
  const std::string in = " in " + ms.str() + " ms";
  std::string found;
  switch (result.status) {
    case SearchStatus::kSolved:
      found = result.plan.empty()
                  ? "found" + in + " that the goal holds already, so no step is needed"
                  : "found a plan of " + count_phrase(static_cast<long long>(result.plan.size()), "step") + in;
      break;
    case SearchStatus::kExhausted: found = "found" + in + " that no plan reaches the goal"; break;
    case SearchStatus::kBudgetExhausted: found = "reached its limit without a plan" + in; break;
    case SearchStatus::kInProgress: found = "stopped without a plan" + in; break;
  }
  std::string how = count_phrase(static_cast<long long>(s.nodes_expanded), "node") + " expanded and " +
                    std::to_string(s.nodes_generated) + " generated";
  if (greedy) {
    how += ", " + count_phrase(static_cast<long long>(s.states_registered), "state");
    // -1: the start is a dead end, or the goal holds there; no value to give.
    if (s.initial_heuristic >= 0) how += ", a heuristic value of " + std::to_string(s.initial_heuristic) + " at the start";
    how += ", " + count_phrase(static_cast<long long>(s.steps_removed), "step") + " removed afterwards";
  }
  how += ", " + std::to_string(s.relevant_objects) + " of the objects relevant and " +
         count_phrase(static_cast<long long>(s.ground_actions), "ground action");
  return search + " " + found + ": " + how + ".";
}

}  // namespace

CommandResult run_world(const WorldOptions& options, std::ostream& out) {
  auto scenario = load_world(options.scenario);
  if (!scenario) return tl::unexpected(scenario.error());
  const World& world = scenario->world;
  const Universe& u = *world.universe;
  const Vocabulary& v = world.vocabulary;
  if (options.json) {
    nlohmann::json places = nlohmann::json::array(), items = nlohmann::json::array();
    for (const ObjectInfo& o : u.objects()) {
      ObjectId id = *u.find(o.id);
      nlohmann::json j{{"id", o.id}, {"category", o.category}, {"kind", std::string(to_string(o.kind))},
                       {"properties", o.properties}, {"look_alikes", look_alikes(u, id)}};
      if (o.kind == ObjectKind::kItem) {
        j["location"] = location_of(world, id);
        items.push_back(j);
      } else {
        if (world.state.holds(Fact(v.openable, {id}))) j["door"] = world.state.holds(Fact(v.closed, {id})) ? "closed" : "open";
        places.push_back(j);
      }
    }
    const nlohmann::json document{{"scenario", scenario->name}, {"location", world.location},
                                  {"hand", world.state.holds(Fact(v.handempty, std::initializer_list<ObjectId>{})) ? "empty" : "full"},
                                  {"places", places}, {"objects", items}};
    out << dump_json(document, 2) << "\n";
    return Outcome::kSuccess;
  }
  out << "Scenario " << scenario->name << ": the robot is in the " << world.location << ".\n";
  out << "Places:\n";
  auto properties = [&](ObjectId id) {
    std::string text;
    for (const std::string& p : u.info(id).properties) text += ", " + p;
    return text;
  };
  for (ObjectId p : u.of_kind(ObjectKind::kSurface)) out << "  " << u.name(p) << " (surface" << properties(p) << ")\n";
  for (ObjectId p : u.of_kind(ObjectKind::kReceptacle)) {
    out << "  " << u.name(p) << " (receptacle";
    if (world.state.holds(Fact(v.openable, {p})))
      out << ", door " << (world.state.holds(Fact(v.closed, {p})) ? "closed" : "open");
    out << properties(p) << ")\n";
  }
  out << "Objects:\n";
  for (ObjectId o : u.of_kind(ObjectKind::kItem)) {
    const std::string own = properties(o);
    out << "  " << u.name(o) << " " << location_of(world, o) << (own.empty() ? "" : " (" + own.substr(2) + ")") << "\n";
  }
  // Things of one kind, which a teacher tells apart by where they are or by
  // their properties ("the top drawer").
  std::vector<std::string> groups;
  std::set<std::string> seen;
  for (const ObjectInfo& o : u.objects()) {
    std::vector<std::string> alike = look_alikes(u, *u.find(o.id));
    if (alike.empty() || !seen.insert(o.category).second) continue;
    alike.insert(alike.begin(), o.id);
    groups.push_back(join(alike, ", "));
  }
  if (!groups.empty()) out << "Look-alikes (one kind of thing each): " << join(groups, "; ") << ".\n";
  return Outcome::kSuccess;
}

CommandResult run_plan(const PlanOptions& options, std::ostream& out, std::ostream& progress_out) {
  auto scenario = load_world(options.scenario);
  if (!scenario) return tl::unexpected(scenario.error());
  const World& world = scenario->world;
  auto goal = goal_of(*scenario, options.goal);
  if (!goal) return tl::unexpected(goal.error());
  SearchOptions search;
  if (options.depth) search.max_depth = *options.depth;
  if (options.node_limit) search.max_nodes = static_cast<std::uint64_t>(*options.node_limit);
  if (options.time_limit_s)
    search.max_time = std::chrono::milliseconds(static_cast<std::int64_t>(*options.time_limit_s * 1000.0));
  search.prune_irrelevant = !options.no_pruning;
  if (options.progress) {
    search.progress = [&progress_out](const SearchProgress& p) {
      progress_out << "searching: " << p.nodes_expanded << " nodes in " << std::fixed << std::setprecision(1)
                   << p.elapsed_ms / 1000.0 << " s (" << std::setprecision(0) << p.nodes_per_second
                   << " nodes/s), best heuristic value " << p.best_heuristic << std::defaultfloat
                   << std::setprecision(6) << "\n"
                   << std::flush;
    };
  }
  const bool greedy = !options.depth.has_value();
  PlanResult result = greedy ? find_greedy_plan(*world.domain, *world.universe, world.state, *goal, search)
                             : find_plan(*world.domain, *world.universe, world.state, *goal, search);
  for (const std::string& note : result.notes) spdlog::info("{}", note);
  const SearchStatistics& s = result.statistics;
  // Why a goal that no plan reaches can never hold, if one of its parts
  // cannot on its own: "The garbage can never be closed: it has no door,
  // so I cannot close it."
  std::string why_not;
  if (result.status == SearchStatus::kExhausted)
    why_not = language::never_holds(world, explain_unreachable(*world.domain, *world.universe, world.state, *goal));
  if (options.json) {
    nlohmann::json plan = nlohmann::json::array();
    for (const Action& a : result.plan) plan.push_back(format_action(*world.domain, *world.universe, a));
    nlohmann::json j{{"status", to_string(result.status)}, {"plan", plan},
                     {"planner", greedy ? "greedy-best-first" : "iterative-deepening"},
                     {"nodes_expanded", s.nodes_expanded}, {"nodes_generated", s.nodes_generated},
                     {"relevant_objects", s.relevant_objects}, {"ground_actions", s.ground_actions},
                     {"elapsed_ms", s.elapsed_ms}, {"relevance", result.notes}};
    if (!why_not.empty()) j["never_holds"] = why_not;
    if (greedy) {
      j["nodes_evaluated"] = s.nodes_evaluated;
      j["dead_ends"] = s.dead_ends;
      j["states_registered"] = s.states_registered;
      j["propositions"] = s.propositions;
      j["initial_heuristic"] = s.initial_heuristic;
      j["best_heuristic"] = s.best_heuristic;
      j["steps_removed"] = s.steps_removed;
      j["grounding_ms"] = s.grounding_ms;
    } else {
      j["depth_limit"] = s.depth_limit_reached;
    }
    out << dump_json(j, 2) << "\n";
  } else if (options.pddl) {
    print_plan_pddl(world, result, greedy, out);
  } else {
    out << language::plan_steps(world, result.plan) << plan_summary(result, greedy, options.depth) << "\n";
  }
  if (result.status == SearchStatus::kExhausted) {
    if (!why_not.empty())
      progress_out << "apprentice: " << why_not << "\n";
    else if (greedy)
      progress_out << "apprentice: no sequence of actions reaches the goal from this state, though each part of it "
                      "could hold on its own: its parts cannot all hold at once here\n";
    else
      progress_out << "apprentice: no plan of at most " << *options.depth
                << " steps reaches the goal; try a larger --depth, or leave --depth out for greedy best-first "
                   "search\n";
  }
  return result.status == SearchStatus::kSolved ? Outcome::kSuccess : Outcome::kGoalNotReached;
}

CommandResult run_export_pddl(const ExportPddlOptions& options, std::ostream& out) {
  auto scenario = load_world(options.scenario);
  if (!scenario) return tl::unexpected(scenario.error());
  const World& world = scenario->world;
  auto goal = goal_of(*scenario, options.goal);
  if (!goal) return tl::unexpected(goal.error());
  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (ec) return make_error(ErrorCode::kIo, options.out_dir + ": " + ec.message());
  const std::map<std::string, std::string> files = {
      {"domain.pddl", write_domain(*world.domain)},
      {"problem.pddl", write_problem(scenario->name, *world.domain, *world.universe, world.state, *goal)}};
  for (const auto& [name, text] : files) {
    std::filesystem::path path = std::filesystem::path(options.out_dir) / name;
    std::ofstream file(path, std::ios::binary);
    file << text;
    file.close();
    if (!file) return make_error(ErrorCode::kIo, path.string() + ": write failed");
    out << "wrote " << path.string() << "\n";
  }
  return Outcome::kSuccess;
}

}  // namespace apprentice::cli
