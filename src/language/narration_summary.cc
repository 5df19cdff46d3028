#include "language/narration_summary.h"

#include <algorithm>
#include <cstdio>

#include "language/narration.h"

namespace apprentice::language {

std::vector<std::pair<std::string, int>> unmet_assertions(const Scenario& scenario, const World& now) {
  const Universe& u = *now.universe;
  std::vector<std::pair<std::string, int>> unmet;
  for (const Literal& l : scenario.goal_assertions()) {
    if (now.state.satisfies(l)) continue;
    std::string sentence = expected_fact(now, l);
    if (l.fact.arity > 0 && u.info(l.fact.args[0]).kind == ObjectKind::kItem) {
      ObjectId item = l.fact.args[0];
      std::string name = spoken_name(now, item);
      std::string from = spoken_location(scenario.world, item);
      std::size_t space = from.find(' ');
      std::vector<ObjectId> alike = u.with_category(u.info(item).category);
      bool elsewhere = std::any_of(alike.begin(), alike.end(), [&](ObjectId other) {
        return spoken_location(scenario.world, other) != from;
      });
      if (elsewhere && space != std::string::npos && sentence.rfind(name, 0) == 0)
        sentence.insert(name.size(), " from" + from.substr(space));
    }
    auto same = std::find_if(unmet.begin(), unmet.end(), [&](const auto& entry) { return entry.first == sentence; });
    if (same == unmet.end()) unmet.emplace_back(sentence, 1);
    else ++same->second;
  }
  return unmet;
}

std::string goal_parts_met(long long achieved, long long total) {
  return std::to_string(achieved) + " of " + count_phrase(total, "part") + " of the goal " +
         (achieved == 1 ? "is" : "are") + " met";
}

std::string teaching_summary(const Scenario& scenario, const State& end, const TeachingEnd& how) {
  std::vector<Literal> assertions = scenario.goal_assertions();
  int achieved = 0;
  for (const Literal& l : assertions)
    if (end.satisfies(l)) ++achieved;
  std::string out = how.finished ? "The task is learned" : "Stopped";
  const std::string instructions = count_phrase(how.instructions, "instruction");
  if (assertions.empty()) out += ", after " + instructions + ".\n";
  else
    out += ": " + goal_parts_met(achieved, static_cast<long long>(assertions.size())) + ", after " + instructions +
           ".\n";
  World now = scenario.world;
  now.state = end;
  for (const auto& [sentence, times] : unmet_assertions(scenario, now))
    out += "Not done: " + sentence + (times > 1 ? " (" + std::to_string(times) + " of them)" : std::string()) + ".\n";
  if (how.store) out += "What you taught me is kept in " + *how.store + ".\n";
  else if (how.how_to_keep.empty()) out += "Nothing was saved.\n";
  else out += "Nothing was saved. To keep what you teach, give a knowledge store: " + how.how_to_keep + ".\n";
  return out;
}

std::string performance_summary(const PerformanceEnd& how) {
  std::string out = "Performed with learned knowledge alone: ";
  if (how.measured) {
    char percent[32];
    std::snprintf(percent, sizeof percent, "%.1f", how.completion);
    out += goal_parts_met(how.achieved, how.total) + " (" + percent + "%), ";
  }
  out += count_phrase(how.actions, "action") + ", 0 instructions, " +
         count_phrase(static_cast<long long>(how.search_nodes), "search node") + ", 0 LLM calls.\n";
  for (const std::string& note : how.renamed) out += "From another world: I " + note + ".\n";
  for (const std::string& note : how.analogies) out += "By analogy: I " + note + ".\n";
  // Each said once, with how many things it is about ("(3 of them)").
  std::vector<std::pair<std::string, int>> helps;
  for (const std::string& help : how.help_needed) {
    auto same = std::find_if(helps.begin(), helps.end(), [&](const auto& h) { return h.first == help; });
    if (same == helps.end()) helps.emplace_back(help, 1);
    else ++same->second;
  }
  for (const auto& [help, times] : helps)
    out += "Would need help: " + help + (times > 1 ? " (" + std::to_string(times) + " of them)" : std::string()) + "\n";
  for (const auto& [sentence, times] : how.unmet)
    out += "Not done: " + sentence + (times > 1 ? " (" + std::to_string(times) + " of them)" : std::string()) + ".\n";
  if (how.help_needed.empty())
    out += how.unmet.empty() ? "No help was needed.\n"
                             : "I asked for no help: what I learned says to do otherwise. Teach it again to change it.\n";
  return out;
}

}  // namespace apprentice::language
