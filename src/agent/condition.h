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
  int search_depth = 0;     // 0: no search
  bool llm = false;
};

// Parses "instruction", "inst+search4", "search4+llm", "inst+llm",
// "inst+search2+llm", "inst+search4+llm": '+'-separated parts, each
// "instruction" or "inst", "search<depth>", or "llm".
Result<Condition> parse_condition(std::string_view name);

// The paper's six conditions, in Table 3's order.
std::vector<std::string> paper_condition_names();

}  // namespace apprentice
