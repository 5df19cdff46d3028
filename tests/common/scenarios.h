// Loading scenarios in tests: a scenario that does not load fails the test
// and aborts the binary, since every test that loads one needs it.
#pragma once

#include <filesystem>
#include <string_view>

#include "world/scenario.h"

namespace apprentice::testing {

// A scenario whose domain is named ("domain: kitchen") finds the shipped one.
Scenario load_or_die(const std::filesystem::path& path);
// A shipped scenario by name ("tidy-kitchen"), loaded or die.
Scenario shipped_scenario(std::string_view name);

}  // namespace apprentice::testing
