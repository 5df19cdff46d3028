// A person's rule, as read (language/rule_reader.h), as the class rules of
// the preference model (knowledge/preferences.h): one rule per class and
// place. The same for an LLM's summary, which is read as a person's rule.
//
//   "toys"              -> class "toys"                  (the words as said; the
//                          model's ConceptSource finds the class)
//   "stuffed animals"   -> class "stuffed animals"
//   "heavy items"       -> class "", modifiers {heavy}   (a general head:
//   "plastic things"    -> class "", modifiers {plastic}  item, thing, object, ...)
//   "other clothes"     -> class "clothes", rest
//   "everything else"   -> class "", rest
//
// A clause that names several places ("the drawers") gives a rule for
// each, its confidence shared among them. A clause about one particular
// thing ("the sweater in the basket") gives none: it is a goal.
#pragma once

#include <string>
#include <vector>

#include "knowledge/preferences.h"
#include "language/rule_in_reply.h"
#include "language/rule_reader.h"
#include "world/world.h"

namespace apprentice {

// How sure each source is of what it states, before the decision weighs
// them (knowledge/decision.h; prefs calibrates these on data): a person's
// own rule; a rule read from the LLM's summary; the LLM's placement of one
// thing.
inline constexpr double kPersonRuleConfidence = 0.95;
inline constexpr double kLlmRuleConfidence = 0.8;
// The LLM's placements were right for 90% of the unseen objects by its own
// summary, and 97% by the person's note, on the TidyBot benchmark's
// development half (docs/benchmarks.md).
inline constexpr double kLlmPlacementConfidence = 0.85;
inline constexpr double kLlmPlacementByPersonConfidence = 0.97;


// The rules `reading` states, from `source`, said as `said`, for `scope`
// (empty fields: anywhere). Each has `confidence` (shared among the places
// of its clause).
std::vector<ClassRule> class_rules_of(const World& world, const language::RuleReading& reading, RuleSource source,
                                      const std::string& said, const GoalScope& scope, double confidence);

// Where a place of this world is, as a destination: in it or on it, told
// apart by its properties where the world has several of its category.
Destination destination_at(const World& world, ObjectId place);

}  // namespace apprentice
