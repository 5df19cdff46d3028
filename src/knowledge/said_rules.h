// A person's rule (or an LLM's summary) applied to a thing: which of the
// classes said ("toys", "fruits", "plastic items", "other clothes",
// "everything else") the thing belongs to. The words of a rule are a
// person's, not a WordNet synset, so each clause is weighed by every
// evidence there is, and the clauses compete:
//   wordnet   1 when a sense of the class word is among the thing's classes
//             ("clothes": a t-shirt is clothing)
//   modifier  1 when every modifier said is a word of the thing's name
//             ("plastic items": the plastic cup)
//   vector    the cosine of the class's words with the thing's name (the
//             word vectors know "electronics" and a "Nintendo Switch")
// A rule for "the rest" ("other clothes", "everything else") takes what no
// other clause of its source takes well. The shares are a softmax over the
// clauses of the score below and of "none of them"; the proposal's
// confidence is that share times the rule's own confidence.
#pragma once

#include <span>
#include <vector>

#include "knowledge/concepts.h"
#include "knowledge/decision.h"
#include "knowledge/preferences.h"

namespace apprentice {

struct SaidRuleWeights {
  double wordnet = 3.0;
  double modifier = 3.0;
  double vector = 8.0;
  // The score of "everything else", and how much less a rule for the rest
  // scores when another clause is sure of the thing (by WordNet or its
  // name's words).
  double rest = 2.0;
  double rest_penalty = 5.0;
  // The score of "none of the clauses": a thing that fits no clause well
  // (or only one it is an exception to) is not pushed onto the others.
  double none = 2.0;
  // A class said with modifiers ("plastic toys") whose modifiers are not in
  // the thing's name scores this much less. (A rule of modifiers alone,
  // "heavy items", is then scored by the vectors.)
  double modifier_missing = 1.0;
};

// The proposals of the rules of `source` for a thing, one per destination
// some rule names (most probable first); none when the source said none.
std::vector<DestinationProposal> said_rule_proposals(std::span<const ClassRule> rules, const KindProfile& thing,
                                                     RuleSource source, const ConceptSource& concepts,
                                                     const SaidRuleWeights& weights = {});

}  // namespace apprentice
