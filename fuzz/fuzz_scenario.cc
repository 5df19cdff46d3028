// libFuzzer target for the scenario loader: any bytes, read as a scenario
// file in data/scenarios (so that `domain: ../domains/kitchen.pddl` finds
// the kitchen), give a scenario or an error with a message, never a crash,
// a sanitizer report or a hang.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_support.h"
#include "util/log.h"
#include "world/scenario.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  apprentice::configure_logging(apprentice::LogLevel::kQuiet);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace apprentice;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  auto scenario = parse_scenario(text, fuzz::source_dir() / "data/scenarios/fuzz-input.yaml");
  if (!scenario) {
    fuzz::require(!scenario.error().message.empty());
    return 0;
  }
  // What a loaded scenario promises its users.
  fuzz::require(scenario->world.domain != nullptr && scenario->world.universe != nullptr);
  for (const Literal& l : scenario->goal_assertions()) fuzz::require(l.fact.predicate < scenario->world.domain->predicates.size());
  return 0;
}
