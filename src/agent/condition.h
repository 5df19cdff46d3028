// An experimental condition: which knowledge sources the agent may use.
// Conditions are data, named as in the paper's Table 3.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"

namespace apprentice {

struct Condition {
  std::string name;         // "inst+search4"
  bool instruction = true;  // the instructor answers goal and action questions
  int search_depth = 0;     // iterative deepening to this depth; 0: none
  // "search" without a depth: greedy best-first search with no depth
  // limit (search/greedy_best_first.h), which plans whole tasks.
  bool unbounded_search = false;
  bool llm = false;
};

// Parses "instruction", "inst+search4", "search4+llm", "inst+llm",
// "inst+search2+llm", "inst+search4+llm", "inst+search": '+'-separated
// parts, each "instruction" or "inst", "search<depth>", "search" (no depth
// limit), or "llm".
Result<Condition> parse_condition(std::string_view name);

// The paper's six conditions, in Table 3's order.
std::vector<std::string> paper_condition_names();

}  // namespace apprentice
