#include "cmd_core.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <ostream>
#include <set>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "face/apprentice.h"
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

// The other objects of `id`'s category, in id order.
std::vector<std::string> look_alikes(const Universe& u, ObjectId id) {
  std::vector<std::string> out;
  for (ObjectId other : u.with_category(u.info(id).category))
    if (other != id) out.push_back(u.name(other));
  return out;
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
  PlanRequest request;
  request.goal = options.goal;
  request.depth = options.depth;
  request.node_limit = options.node_limit;
  request.time_limit_s = options.time_limit_s;
  request.pruning = !options.no_pruning;
  if (options.progress)
    request.progress = [&progress_out](const std::string& line) { progress_out << line << "\n" << std::flush; };
  auto found = plan(*scenario, request);
  if (!found) return tl::unexpected(found.error());
  for (const std::string& note : found->notes) spdlog::info("{}", note);
  out << (options.json ? found->json : options.pddl ? found->pddl : found->text);
  if (!found->why_not.empty()) progress_out << "apprentice: " << found->why_not << "\n";
  return found->solved ? Outcome::kSuccess : Outcome::kGoalNotReached;
}

CommandResult run_export_pddl(const ExportPddlOptions& options, std::ostream& out) {
  auto scenario = load_world(options.scenario);
  if (!scenario) return tl::unexpected(scenario.error());
  const World& world = scenario->world;
  auto goal = parse_goal_or_intent(*scenario, options.goal);
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
