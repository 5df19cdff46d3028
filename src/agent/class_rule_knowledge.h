// The class rules an agent holds, as `apprentice knowledge`, `forget` and
// the Python module see them, and keeping them in the store.
//
// Two kinds are kept (knowledge/store_engine.h, Knowledge::class_rules):
//   - a person's rules, stored the moment they are said and read back, and
//     used in every later session of the same task (or of any task, when
//     said before one);
//   - the rules induced from the goals (knowledge/induction.h), stored with
//     their evidence when a session ends. The agent induces them anew from
//     the goals it loads, which gives the same rules; forgetting a goal
//     takes its evidence away.
// A rule the person forgets goes on the store's forgotten list and is never
// used again, however the goals would induce it, until it is said again.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "knowledge/concepts.h"
#include "knowledge/store.h"
#include "knowledge/store_engine.h"

namespace apprentice {

// Every class rule the agent would use with `knowledge`: the stored rules
// other than induced ones (a person's, first), then those the goals induce,
// none forgotten. Each once (by class_rule_key).
std::vector<ClassRule> class_rules_in_use(const Knowledge& knowledge, const ConceptSource& concepts);

// The rules of `rules` that a phrase names, for "forget": the phrase is
// what the rule is about ("fruit", "edible fruit", "plastic things", "other
// clothes", "everything else"), optionally followed by where it goes ("fruit
// on the coffee table", "fruit goes on the coffee table"); "the rule that"
// and "the rule about" may come first. A class named by its last words
// matches ("fruit" names "edible fruit"), and a plural its singular.
std::vector<ClassRule> rules_named(std::span<const ClassRule> rules, std::string_view phrase);

// What a rule is about, in English: rule_subject (agent/goal_proposals.h).
// Where it sends things, in English: "on the coffee table", "in the left
// storage box".
std::string rule_destination(const ClassRule& rule);

// Forgets `rule` in `knowledge` (out of class_rules, onto forgotten_rules)
// and in `store` when there is one. Errors: the store's.
Status forget_rule(Knowledge& knowledge, KnowledgeStore* store, const ClassRule& rule);

// Forgets, in `household` of the store at `location` (SQLite or
// PostgreSQL), the rules in
// use that `what` names (rules_named): what `apprentice knowledge forget`
// and the Python module's forget_rule do. The same rule kept in several
// scopes is forgotten in each. Returns the rules forgotten. Errors:
//   kInvalidInput  `what` is empty, names no rule in use (the message
//                  says what the rules are about), or names rules that say
//                  different things (it lists them and says how to say
//                  which);
//   those of opening, loading and writing the store.
Result<std::vector<ClassRule>> forget_rules_named(const std::string& location, const std::string& household,
                                                  const Domain& domain, std::string_view what,
                                                  const ConceptSource& concepts);

// Keeps the rules the goals of `knowledge` induce, with their evidence, in
// `knowledge` and in `store` (when there is one): each saved (replacing
// the stored rule under its key), and the induced rules stored before that
// the goals no longer give removed. Forgotten rules are not kept. Errors:
// the store's.
Status keep_induced_rules(Knowledge& knowledge, KnowledgeStore* store, const ConceptSource& concepts);

}  // namespace apprentice
