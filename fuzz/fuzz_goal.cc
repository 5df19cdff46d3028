// libFuzzer target for the goal reader (plan --goal, stored goals): any
// bytes, read against the tidy kitchen, give a goal or an error with a
// message; a goal formatted and read again is the same goal.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "fuzz_support.h"
#include "util/log.h"
#include "world/goal.h"
#include "world/scenario.h"

namespace {
std::optional<apprentice::Scenario> kitchen;
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  apprentice::configure_logging(apprentice::LogLevel::kQuiet);
  auto scenario = apprentice::load_scenario(apprentice::fuzz::source_dir() / "data/scenarios/tidy-kitchen.yaml");
  apprentice::fuzz::require(scenario.has_value());
  kitchen = std::move(*scenario);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace apprentice;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  const Domain& domain = *kitchen->world.domain;
  const Universe& universe = *kitchen->world.universe;
  auto goal = parse_goal(domain, universe, text);
  if (!goal) {
    fuzz::require(!goal.error().message.empty());
    return 0;
  }
  fuzz::require(!goal->literals.empty());
  auto again = parse_goal(domain, universe, format_goal(domain, universe, *goal));
  fuzz::require(again.has_value() && again->literals == goal->literals);
  return 0;
}
