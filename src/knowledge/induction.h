// Inducing a person's class preferences from the examples taught, and
// proposing destinations for new things from the rules and the examples.
//
// Induction is Bayesian, over the classes a ConceptSource gives (WordNet's
// hypernyms): for each destination, every class above one of its examples
// is a hypothesis, weighed by how well it explains all of them. By the size
// principle (Tenenbaum and Griffiths 2001; Xu and Tenenbaum 2007) a class
// explains an example it covers with likelihood 1/size, so that the banana
// and the apple give "edible fruit" far more belief than "food" or "entity",
// while one example alone leaves the belief spread up the hierarchy. An
// example a class does not cover counts as an outlier (a small likelihood),
// so that one odd example does not sink a class the others share. A class
// that also covers things taught to go elsewhere is "the rest" of that class
// (rest: "other snacks") where a smaller class takes those things there,
// and otherwise has them as exceptions ("fruit, but not the pear"). Modifiers
// that every example of a destination has, and no example of another, make
// a rule of their own ("plastic").
#pragma once

#include <span>
#include <string>
#include <vector>

#include "knowledge/concepts.h"
#include "knowledge/decision.h"
#include "knowledge/preferences.h"

namespace apprentice {

// One thing taught: its kind and where it went.
struct PlacementExample {
  KindProfile thing;
  Destination destination;
};

struct InductionOptions {
  // The likelihood share of an example no class of a hypothesis explains.
  double outlier = 0.05;
  // How many kinds all classes together hold (the size of the root): an
  // outlier is explained with outlier / universe.
  double universe = 82115;
  // Rules kept per destination: at most this many, each with at least
  // min_confidence of the destination's belief.
  std::size_t max_rules_per_destination = 3;
  double min_confidence = 0.05;
};

// The class rules the examples support, per destination, most believed
// first, each with its evidence (the examples it covers) and its confidence
// (its share of the destination's belief). Modifier rules come first.
// `scope` is where the examples were taught.
std::vector<ClassRule> induce_rules(std::span<const PlacementExample> examples, const GoalScope& scope,
                                    const InductionOptions& options = {});

// Whether a rule covers a thing: its class is one of the thing's (by id; a
// rule with no id, by name), every modifier is in the thing's name,
// and the thing's kind is not one of its exceptions. A rest rule is checked
// as its class alone; whether another rule takes the thing is the caller's
// (rule_proposals). Returns the class's weight for the thing (0 when not
// covered).
double rule_covers(const ClassRule& rule, const KindProfile& thing);

// The destinations the rules of `source` propose for a thing, as one
// source's distribution over the destinations those rules name: each
// destination's share of
//   outlier / universe + sum over its covering rules of confidence * weight / size
// (the size principle's prediction: a small class that covers the thing
// predicts it more strongly than a large one; a modifier rule counts as a
// class of size 1). Rest rules count only when no other rule covers the
// thing, times the confidence of its strongest covering rule. Only
// destinations some rule covers are proposed; none when no rule covers the
// thing.
std::vector<DestinationProposal> rule_proposals(std::span<const ClassRule> rules, const KindProfile& thing, RuleSource source,
                                     const InductionOptions& options = {});

}  // namespace apprentice
