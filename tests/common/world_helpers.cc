#include "common/world_helpers.h"

#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "common/paths.h"

namespace apprentice::testing {

Scenario load_or_die(const std::filesystem::path& path) {
  // "domain: kitchen" names a shipped domain, as the program's data folder does.
  auto scenario = load_scenario(path, {source_path("data/domains")});
  if (!scenario) {
    ADD_FAILURE() << scenario.error().describe();
    std::abort();
  }
  return std::move(*scenario);
}

Scenario shipped_scenario(std::string_view name) { return load_or_die(scenario_path(name)); }

ObjectId object(const World& world, std::string_view id) {
  auto found = world.universe->find(id);
  EXPECT_TRUE(found.has_value()) << "no object " << id;
  return found.value_or(0);
}

Action action(const World& world, std::string_view text) {
  auto parsed = parse_action(*world.domain, *world.universe, text);
  EXPECT_TRUE(parsed.has_value()) << text << ": " << (parsed ? "" : parsed.error().describe());
  return parsed ? *parsed : Action();
}

Goal goal(const World& world, std::string_view text) {
  auto parsed = parse_goal(*world.domain, *world.universe, text);
  EXPECT_TRUE(parsed.has_value()) << text << ": " << (parsed ? "" : parsed.error().describe());
  return parsed ? *parsed : Goal();
}

}  // namespace apprentice::testing
