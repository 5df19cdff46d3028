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

// What is known of a thing against one clause's class.
struct ClauseEvidence {
  bool wordnet = false;         // a sense of the class word is among the thing's classes
  bool wordnet_parent = false;  // only the parent of a class word that names almost nothing of its own ("clothes")
  bool word_in_name = false;    // the class's own word is a word of the thing's name ("toy hammer")
  bool modifiers_in_name = false;  // every modifier said is in the thing's name ("plastic items": the plastic cup)
  bool modifiers_missing = false;  // some modifier said is not
  bool has_vectors = false;
  // Cosines of the class's words with the thing's name (the head weighted
  // more), its best single word, its head, and the best name of the
  // thing's WordNet classes up to kAncestorDepth steps above it.
  double name_cosine = 0;
  double word_cosine = 0;
  double head_cosine = 0;
  double class_cosine = 0;
  // The same over the classes above the thing's own senses (depth 1 and
  // up) of at most kNearClassMostKinds kinds: how near WordNet's account
  // of what the thing is lies to the class word, apart from its own name.
  double ancestor_cosine = 0;
  // WordNet knows both the class word (a physical class) and the thing's
  // head: its silence on the thing is then a "no", and the vectors, which
  // measure relatedness and not membership ("brushes" and a paint pot),
  // cannot make the thing a member alone.
  bool wordnet_knows_both = false;
  // WordNet or the name's own words put the thing in the class.
  bool sure() const;
  // Only the vectors put the thing in the class, against WordNet's silence
  // where it knows both words, and none of the classes WordNet puts the
  // thing in is named near the class word (ancestor_cosine below
  // kNearClassCosine), or one is but the thing's own name is not
  // (word_cosine below kFitCosine: "tools" and a glove's "sports
  // equipment"): a guess the person is asked to confirm.
  bool only_related() const;
  // Whether anything says the thing is in the clause's class at all: WordNet
  // (or the parent of a collective word), the class's word or every
  // modifier in its name, or a cosine of the class's words with one word of
  // its name or one of its WordNet classes of at least kFitCosine. A clause
  // for "everything else" fits everything.
  bool fits() const;
  bool said_a_class = false;  // the clause names a class or modifiers (not "everything else")
  bool modifiers_only = false;  // it names modifiers and no class: "paper things", "heavy items"
};

// The least cosine that counts as evidence of a class (the vectors of
// unrelated words are commonly 0.1 to 0.3 apart). Chosen on the TidyBot
// benchmark's development half: of the clauses neither WordNet nor the
// name put a thing in, those below 0.3 were the thing's own clause for 16
// and another's for 194 (docs/benchmarks.md, "A class rule only for what
// fits it").
inline constexpr double kFitCosine = 0.3;

// The least cosine of the class's words with the name of one of the
// WordNet classes above the thing that counts as WordNet's near agreement
// ("electronics" and a laptop's "computer"; not "brushes" and a paint
// pot's "container", nor "reference books" and printer paper's
// "material").
inline constexpr double kNearClassCosine = 0.5;
// Only classes of at most this many kinds count there: the vectors of
// general words ("material", 2,816 kinds; "device") lie near many class
// words, and say nothing of this thing ("computer" holds 33).
inline constexpr double kNearClassMostKinds = 200;

// A class word's senses weighed less than this (ConceptClass::weight) are
// its less usual ones: they put only a thing's first sense in the class.
inline constexpr double kUsualSenseWeight = 0.5;

// How many steps above a thing its WordNet classes' names count.
inline constexpr int kAncestorDepth = 4;

// A class said with words before its head that WordNet does not know as
// one noun ("light-colored clothes", "winter clothes", "plastic toys"), as
// its head's class ("clothes") with those words as modifiers: WordNet then
// speaks for the head, the name's words for the modifiers. Any other rule
// as it is.
ClassRule as_head_and_modifiers(const ClassRule& rule, const ConceptSource& concepts);

ClauseEvidence clause_evidence(const ClassRule& rule, const KindProfile& thing, const ConceptSource& concepts);

// The weights of the evidence in a clause's score, before the clauses
// compete in a softmax. Fitted on the TidyBot benchmark's development half
// by conditional logistic regression (each thing's clause among its rule's
// clauses, "none" held at 2), then sharpened by 1.5 (at a belief of 0.9,
// 96% of the things acted on were right on that half), with the
// modifiers' and the rest's weights kept as they were (too few rules of
// either to fit): docs/benchmarks.md, "Class membership, fitted".
struct SaidRuleWeights {
  double wordnet = 4.2;
  double wordnet_parent = 1.5;
  double word_in_name = 3.2;
  double modifier = 4.5;
  double name_vector = 3.5;
  double word_vector = 7.5;
  double head_vector = 0.9;
  double class_vector = 5.4;
  // The score of "everything else", and how much less a rule for the rest
  // scores when another clause is sure of the thing (by WordNet or its
  // name's words).
  double rest = 3.0;
  double rest_penalty = 7.5;
  // The most a person's rule for the rest proposes when another clause of
  // the rule fits the thing too (ClauseEvidence::fits), below what the
  // agent acts on alone; the rest of its share goes to the best such
  // clause: the person is asked rather than the rest's place taken
  // (docs/benchmarks.md, "The person's rule at a where-question").
  double rest_in_doubt = 0.7;
  // The score of "none of the clauses": a thing that fits no clause well
  // (or only one it is an exception to) is not pushed onto the others.
  double none = 2.0;
  // A class said with modifiers ("plastic toys") whose modifiers are not in
  // the thing's name scores this much less. (A rule of modifiers alone,
  // "heavy items", is then scored by the vectors.)
  double modifier_missing = 1.5;
  // An LLM's summary is read as a person's rule, but is less often what the
  // person meant: its clauses' scores count half (at 2/3, protocol A with
  // the LLM acted on 3.3% wrong on the development half; at 1/2, 3.0%).
  double llm_sharpness = 0.5;
  // The most a person's clause proposes for a thing it is only related to
  // (ClauseEvidence::only_related), below what the agent acts on alone: a
  // one-clause rule ("the brushes go in the sink") competes only with
  // "none", and the vectors put the paint pot, the sponge and the glue
  // stick near brushes; the person is asked instead.
  double only_related_at_most = 0.6;

  double score(const ClassRule& rule, const ClauseEvidence& evidence) const;
};

// The proposals of the rules of `source` for a thing, one per destination
// some rule names (most probable first); none when the source said none.
// A person's clause the thing does not fit (ClauseEvidence::fits) proposes
// nothing (its share is left to none of them): a class rule never goes to a
// thing it does not fit. One the thing is only related to proposes at most
// `only_related_at_most`: asked, never acted on alone. An LLM's summary's
// clauses are not held to it: on the development half, the summary's
// "textbooks" no longer spoke for the shelf for a soda can, which shifted
// the summary's belief enough that the LLM's wrong placement of it was
// acted on (a-alone+llm 3.0% → 3.3% wrong).
std::vector<DestinationProposal> said_rule_proposals(std::span<const ClassRule> rules, const KindProfile& thing,
                                                     RuleSource source, const ConceptSource& concepts,
                                                     const SaidRuleWeights& weights = {});

}  // namespace apprentice
