// The TidyBot benchmark's own scenario format (Wu et al., "TidyBot:
// Personalized Robot Assistance with Large Language Models", 2023: the
// `benchmark/scenarios.yml` of its repository; the development half is in
// ../shared/data/tidybot-benchmark/scenarios-dev.yml). Each scenario is one
// person's preferences in one room: the places things go (`receptacles`),
// a few shown placements (`seen_placements`), and objects never shown
// whose placements are the truth (`unseen_placements`), with the person's
// rule in one sentence (`annotator_notes`) and what the rule turns on
// (`tags`: category, attribute, function, subcategory, multiple categories).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "util/result.h"

namespace apprentice::benchmark {

// An object and the receptacle it goes to, in the benchmark's words.
using Placement = std::pair<std::string, std::string>;

struct TidyBotScenario {
  // The scenario's 1-based number in the whole benchmark (`benchmark_index`);
  // without that key, its position in the file.
  int index = 0;
  int line = 0;  // where it starts in the file, for messages
  std::string room;
  std::vector<std::string> receptacles;
  std::vector<std::string> seen_objects;
  std::vector<Placement> seen_placements;
  std::vector<std::string> unseen_objects;
  std::vector<Placement> unseen_placements;
  std::string note;  // annotator_notes: the person's rule, one sentence
  std::vector<std::string> tags;

  // Where the benchmark says `object` goes (seen or unseen); empty if nowhere.
  std::string destination(std::string_view object) const;
};

// Reads and checks a file of scenarios: a YAML list of mappings with the
// keys above (others are refused, so that a typo is caught). Checked: every
// placement names one of its scenario's objects and receptacles, every
// object is placed exactly once, and no object is both seen and unseen.
// Errors: kNotFound (no file), kInvalidInput with file:line:column and
// what was expected, kIo (unreadable).
Result<std::vector<TidyBotScenario>> load_tidybot_scenarios(const std::filesystem::path& path);
Result<std::vector<TidyBotScenario>> parse_tidybot_scenarios(std::string_view yaml_text,
                                                             const std::filesystem::path& source);

}  // namespace apprentice::benchmark
