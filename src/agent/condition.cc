#include "agent/condition.h"

#include <charconv>

namespace apprentice {

Result<Condition> parse_condition(std::string_view name) {
  Condition condition;
  condition.name = std::string(name);
  condition.instruction = false;
  std::string_view rest = name;
  bool any = false;
  // `more`: a '+' was read, so a part must follow ("inst+" is malformed).
  bool more = !rest.empty();
  while (more) {
    std::size_t plus = rest.find('+');
    std::string_view part = rest.substr(0, plus);
    more = plus != std::string_view::npos;
    rest = more ? rest.substr(plus + 1) : std::string_view();
    any = true;
    if (part == "instruction" || part == "inst") {
      condition.instruction = true;
    } else if (part == "llm") {
      condition.llm = true;
    } else if (part == "search") {
      condition.unbounded_search = true;
    } else if (part.substr(0, 6) == "search") {
      std::string_view digits = part.substr(6);
      int depth = 0;
      auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), depth);
      if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() || depth < 1 || depth > 16)
        return make_error(ErrorCode::kInvalidInput, "condition " + std::string(name) +
                                                        ": expected search<depth> with a depth from 1 to 16, not " +
                                                        std::string(part));
      condition.search_depth = depth;
    } else {
      return make_error(ErrorCode::kInvalidInput,
                        "condition " + std::string(name) + ": expected parts instruction (or inst), search<depth>, "
                        "search or llm joined by '+', not '" + std::string(part) + "'");
    }
  }
  if (!any) return make_error(ErrorCode::kInvalidInput, "empty condition name");
  if (!condition.instruction && !condition.llm)
    return make_error(ErrorCode::kInvalidInput, "condition " + std::string(name) +
                                                    ": without instruction or an LLM nothing can supply goals");
  return condition;
}

std::vector<std::string> paper_condition_names() {
  return {"instruction", "inst+search4", "search4+llm", "inst+llm", "inst+search2+llm", "inst+search4+llm"};
}

}  // namespace apprentice
