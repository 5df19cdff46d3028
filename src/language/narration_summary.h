// The end of a session in English, part of the agent's narration
// (narration.h): after teaching, how much of the scenario's intent holds and
// what is not done; after performing alone, what it took and where help
// would have been needed. Front ends print these as they are (the CLI) or
// hand them on (the Python module's report "summary").
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "world/scenario.h"

namespace apprentice::language {

// Each goal assertion of `scenario`'s intent that does not hold in `now`, in
// English, once, with how many times it occurs. Look-alikes are named by
// where they were at the start ("the glass tumbler from the dish rack should
// be in the cupboard").
std::vector<std::pair<std::string, int>> unmet_assertions(const Scenario& scenario, const World& now);

struct TeachingEnd {
  bool finished = false;  // the instructor said the task was done
  int instructions = 0;
  // The knowledge store's file, when there is one.
  std::optional<std::string> store;
  // Without a store, how to keep what is taught ("apprentice teach
  // --scenario S --knowledge FILE"); empty: only that nothing was saved.
  std::string how_to_keep;
};

// How much of a world's goal holds, in a person's words: "28 of 30 parts of
// the goal are met" ("1 of 14 parts of the goal is met"). A part is one goal
// assertion of the scenario's intent (the experiment's term).
std::string goal_parts_met(long long achieved, long long total);

// "The task is learned: 28 of 30 parts of the goal are met, after 40
// instructions.", a "Not done: ..." line per unmet assertion, then where
// the knowledge is kept, or that nothing was saved. One line each, each
// ending in a newline.
std::string teaching_summary(const Scenario& scenario, const State& end, const TeachingEnd& how);

struct PerformanceEnd {
  bool measured = false;  // the scenario has an intent
  int achieved = 0;
  int total = 0;
  double completion = 0;  // percent
  int actions = 0;
  unsigned long long search_nodes = 0;
  std::vector<std::string> renamed;     // "took 'beaker' for 'mug'" (transfer)
  std::vector<std::string> analogies;
  std::vector<std::string> help_needed;
  // The parts of the world's intent not met, as unmet_assertions says them.
  std::vector<std::pair<std::string, int>> unmet;
};

// "Performed with learned knowledge alone: 30 of 30 parts of the goal are
// met (100.0%), 44 actions, 0 instructions, 0 search nodes, 0 LLM calls.", what
// was carried over from other worlds, where help would have been needed
// ("No help was needed."), and a "Not done: ..." line per part of the
// intent not met (with no help asked for, that what was learned says
// otherwise). One line each.
std::string performance_summary(const PerformanceEnd& how);

}  // namespace apprentice::language
