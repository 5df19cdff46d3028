#include "cmd_rules.h"


#include "agent/class_rule_knowledge.h"
#include "agent/concept_source.h"
#include "agent/goal_proposals.h"
#include "agent/understanding.h"
#include "knowledge/store.h"
#include "language/narration.h"
#include "util/json.h"
#include "util/text.h"

namespace apprentice::cli {

namespace {

nlohmann::json rule_json(const ClassRule& rule) {
  return nlohmann::json{{"text", say_class_rule(rule)},
                        {"subject", rule_subject(rule)},
                        {"destination", rule_destination(rule)},
                        {"evidence", rule.evidence},
                        {"exceptions", rule.exceptions},
                        {"source", std::string(rule_source_name(rule.source))},
                        {"said", rule.said},
                        {"confidence", rule.confidence},
                        {"task", rule.scope.task}};
}

}  // namespace

// Below this, an induced rule is one guess among several for the same
// things (the examples of a kids' room gave "placental", 11%, beside
// "stuffed animals"): listed only when asked for.
constexpr double kListedInducedConfidence = 0.5;

void print_class_rules(const Knowledge& knowledge, const ConceptSource& concepts, bool all, std::ostream& out) {
  std::vector<ClassRule> rules = class_rules_in_use(knowledge, concepts);
  std::size_t weaker = 0;
  if (!all)
    weaker = std::erase_if(rules, [](const ClassRule& rule) {
      return rule.source == RuleSource::kInduced && rule.confidence < kListedInducedConfidence;
    });
  if (!rules.empty() || weaker > 0) {
    out << "\nFor things I was never taught, I generalize:\n";
    for (const ClassRule& rule : rules) out << "  " << say_class_rule(rule) << "\n";
    if (weaker > 0)
      out << "  (and " << language::count_phrase(static_cast<long long>(weaker), "weaker guess", "weaker guesses")
          << " from the examples, less than even odds each; --all lists them)\n";
  }
  if (!knowledge.forgotten_rules.empty()) {
    out << "\nYou told me to forget these, and I do not use them:\n";
    for (const ClassRule& rule : knowledge.forgotten_rules.all()) out << "  " << say_class_rule(rule) << "\n";
  }
}

nlohmann::json class_rules_json(const Knowledge& knowledge, const ConceptSource& concepts) {
  nlohmann::json rules = nlohmann::json::array(), forgotten = nlohmann::json::array();
  for (const ClassRule& rule : class_rules_in_use(knowledge, concepts)) rules.push_back(rule_json(rule));
  for (const ClassRule& rule : knowledge.forgotten_rules.all()) forgotten.push_back(rule_json(rule));
  return nlohmann::json{{"class_rules", rules}, {"forgotten_rules", forgotten}};
}

CommandResult forget_class_rules(const KnowledgeOptions& options, const Domain& domain, std::ostream& out) {
  if (!options.to.empty() || !options.from.empty())
    return make_error(ErrorCode::kInvalidInput, "--to is for 'knowledge export' and --from for 'knowledge import'");
  Understanding understanding;
  LexicalConcepts concepts(understanding.lexicon(), understanding.vectors());
  const std::string household = options.household.empty() ? std::string(kDefaultHousehold) : options.household;
  auto forgotten = forget_rules_named(options.knowledge, household, domain, join(options.what, " "), concepts);
  if (!forgotten) return tl::unexpected(forgotten.error());
  if (options.json) {
    nlohmann::json rules = nlohmann::json::array();
    for (const ClassRule& rule : *forgotten) rules.push_back(rule_json(rule));
    out << dump_json(nlohmann::json{{"forgotten_rules", rules}}, 2) << "\n";
    return Outcome::kSuccess;
  }
  out << "I forgot that " << say_class_rule(forgotten->front())
      << ". I will not use it again, even where the goals suggest it, and will ask where such things go.\n";
  return Outcome::kSuccess;
}

}  // namespace apprentice::cli
