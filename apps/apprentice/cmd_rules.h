// The class rules of `apprentice knowledge`: listed in English with their
// evidence and source, as JSON, and `knowledge forget WHAT`.
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

#include "cmd_agent.h"
#include "knowledge/concepts.h"
#include "knowledge/store_engine.h"

namespace apprentice::cli {

// "For things I was never taught, I generalize:" and one line per rule in
// use (agent/class_rule_knowledge.h), then the rules forgotten; nothing
// when there are neither. Of the rules induced from the goals only those
// at least even odds sure are listed, with how many are not, unless `all`;
// a person's and the LLM's rules always are.
void print_class_rules(const Knowledge& knowledge, const ConceptSource& concepts, bool all, std::ostream& out);

// {"class_rules": [...], "forgotten_rules": [...]}: each rule's English,
// what it is about, where it goes, its evidence, source, sentence,
// confidence and scope.
nlohmann::json class_rules_json(const Knowledge& knowledge, const ConceptSource& concepts);

// `knowledge forget WHAT`: forgets the rule WHAT names, in the store, for
// good. Errors (kInvalidInput, exit 2): no WHAT; WHAT names no rule held,
// or rules that differ (it says which).
CommandResult forget_class_rules(const KnowledgeOptions& options, const Domain& domain, std::ostream& out);

}  // namespace apprentice::cli
