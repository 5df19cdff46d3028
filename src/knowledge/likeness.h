// Proposing a destination for a new thing by its likeness to the things
// taught: the source "similarity" of knowledge/decision.h. It generalizes
// the agent's analogies across worlds (agent/transfer.h) from WordNet's
// hierarchy to the word vectors, which know brands and compounds WordNet
// lacks ("Skittles", "Kleenex tissue box"), and weighs what the names share:
// their heads ("fork" and "fork") and their modifiers ("plastic" and
// "plastic", "muddy" and "soiled").
//
// For each destination it scores the thing by features of its examples:
//   name      the highest cosine of the whole names' vectors
//   mean      the mean of those cosines
//   head      the highest cosine of the heads' vectors
//   modifier  the highest cosine of the modifiers' vectors (both have some)
//   shared    1 when some example has one of its modifiers
//   same_head 1 when some example has its head
//   class     the highest cosine of its vector with the name of a class
//             induced for the destination ("candy" for the Reese's and the
//             Life Savers), times that rule's confidence
//   words     each word of its name matched to the nearest word of the
//             destination's examples, weighted by how much the matches
//             differ between destinations (so modifiers count where the
//             examples split by them: "clean" and "dirty" clothes)
// and proposes the softmax of the weighted sum over the destinations. The
// weights were chosen on the TidyBot benchmark's development half
// (bench/bench_preferences.cc --weights; docs/benchmarks.md, "Words that
// split the examples"): the words feature carries most of the weight, the
// mean, head and same-head features none (a shared head pulled the clay
// pot to the copper pot where the examples split by material).
#pragma once

#include <array>
#include <span>
#include <vector>

#include "knowledge/concepts.h"
#include "knowledge/decision.h"
#include "knowledge/induction.h"

namespace apprentice {

inline constexpr std::size_t kLikenessFeatures = 8;

struct LikenessWeights {
  // In the order of the features above.
  std::array<double, kLikenessFeatures> weights = {4.0, 0.0, 0.0, 1.0, 2.0, 0.0, 0.0, 20.0};
  // The features of "somewhere else": a place no example went to, as like
  // the thing as unrelated names are (their cosines near 0.3). Without it a
  // lone destination would get all the belief, however unlike its
  // examples the thing is (the paper plate is no ketchup).
  std::array<double, kLikenessFeatures> elsewhere = {0.3, 0.3, 0.3, 0.0, 0.0, 0.0, 0.0, 0.3};
};

// Each destination's features for one thing (the rows of the fit). `rules`
// are the rules induced from the same examples, for the class feature; its
// class names' vectors come from `concepts`.
struct LikenessFeatures {
  Destination destination;
  std::array<double, kLikenessFeatures> values{};
  // Its examples, most like the thing first (by the whole names' cosine).
  std::vector<std::string> nearest;
};
std::vector<LikenessFeatures> likeness_features(std::span<const PlacementExample> examples, const KindProfile& thing,
                                                std::span<const ClassRule> rules, const ConceptSource& concepts);

// The proposals, one per destination with examples, most probable first;
// none without examples. The softmax includes "somewhere else"
// (LikenessWeights::elsewhere), whose share is not proposed.
std::vector<DestinationProposal> likeness_proposals(std::span<const PlacementExample> examples, const KindProfile& thing,
                                                    std::span<const ClassRule> rules, const ConceptSource& concepts,
                                                    const LikenessWeights& weights = {});

}  // namespace apprentice
