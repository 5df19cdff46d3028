#include "knowledge/likeness.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "util/cosine.h"
#include "util/text.h"

namespace apprentice {

namespace {

bool shares_a_modifier(const KindProfile& a, const KindProfile& b) {
  return std::any_of(a.modifiers.begin(), a.modifiers.end(), [&](const std::string& m) {
    return std::find(b.modifiers.begin(), b.modifiers.end(), m) != b.modifiers.end();
  });
}

// The words feature of every destination: each word of the thing's name is
// matched to its likeliest word among a destination's examples (the
// highest cosine), and the destinations are scored by the weighted mean of
// those matches, each word weighted by how much its matches differ from
// one destination to another (a word that matches everywhere alike tells
// nothing: "shirt" where every example is clothing), plus a little, and the
// last word (the head) twice. So "clean shorts" goes where "clean t-shirt"
// went and not where "dirty socks" did, though all are clothes.
std::vector<double> word_scores(std::span<const PlacementExample> examples, const KindProfile& thing,
                                const std::vector<LikenessFeatures>& destinations) {
  const std::size_t n = thing.word_vectors.size();
  std::vector<double> out(destinations.size(), 0.0);
  if (n == 0) return out;
  std::vector<std::vector<double>> best(destinations.size(), std::vector<double>(n, -1.0));
  for (const PlacementExample& e : examples) {
    auto d = std::find_if(destinations.begin(), destinations.end(),
                          [&](const LikenessFeatures& f) { return f.destination == e.destination; });
    if (d == destinations.end()) continue;
    std::vector<double>& mine = best[static_cast<std::size_t>(d - destinations.begin())];
    for (std::size_t i = 0; i < n; ++i)
      for (const std::vector<float>& u : e.thing.word_vectors) mine[i] = std::max(mine[i], cosine(thing.word_vectors[i], u));
  }
  std::vector<double> weight(n, 0.0);
  double total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double high = -1, low = 1;
    for (const std::vector<double>& b : best) {
      high = std::max(high, b[i]);
      low = std::min(low, b[i]);
    }
    weight[i] = (high - low) + 0.1;
    if (i + 1 == n) weight[i] *= 2;
    total += weight[i];
  }
  for (std::size_t d = 0; d < destinations.size(); ++d)
    for (std::size_t i = 0; i < n; ++i) out[d] += weight[i] * best[d][i] / total;
  return out;
}

}  // namespace

std::vector<LikenessFeatures> likeness_features(std::span<const PlacementExample> examples, const KindProfile& thing,
                                                std::span<const ClassRule> rules, const ConceptSource& concepts) {
  std::vector<LikenessFeatures> out;
  std::vector<std::vector<std::pair<double, std::string>>> by_name;
  for (const PlacementExample& e : examples) {
    auto it = std::find_if(out.begin(), out.end(), [&](const LikenessFeatures& f) { return f.destination == e.destination; });
    std::size_t i = static_cast<std::size_t>(it - out.begin());
    if (it == out.end()) {
      out.push_back(LikenessFeatures{e.destination, {}, {}});
      out.back().values[0] = -1;
      out.back().values[2] = -1;
      by_name.emplace_back();
    }
    LikenessFeatures& f = out[i];
    const double name = cosine(thing.vector, e.thing.vector);
    f.values[0] = std::max(f.values[0], name);
    f.values[1] += name;
    f.values[2] = std::max(f.values[2], cosine(thing.head_vector, e.thing.head_vector));
    if (!thing.modifier_vector.empty() && !e.thing.modifier_vector.empty())
      f.values[3] = std::max(f.values[3], cosine(thing.modifier_vector, e.thing.modifier_vector));
    if (shares_a_modifier(thing, e.thing)) f.values[4] = 1;
    if (!thing.head.empty() && thing.head == e.thing.head) f.values[5] = 1;
    by_name[i].emplace_back(name, e.thing.kind);
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i].values[1] /= static_cast<double>(by_name[i].size());
    out[i].values[7] = -1;
    std::stable_sort(by_name[i].begin(), by_name[i].end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (const auto& [similarity, kind] : by_name[i]) out[i].nearest.push_back(kind);
  }
  std::vector<double> words = word_scores(examples, thing, out);
  for (std::size_t i = 0; i < out.size(); ++i)
    if (!thing.word_vectors.empty()) out[i].values[7] = words[i];
  // The class feature: the thing's likeness to the names of the classes
  // induced for each destination.
  std::map<std::string, std::vector<float>> class_vectors;
  for (const ClassRule& rule : rules) {
    if (rule.class_name.empty()) continue;
    auto f = std::find_if(out.begin(), out.end(), [&](const LikenessFeatures& x) { return x.destination == rule.destination; });
    if (f == out.end()) continue;
    auto [it, fresh] = class_vectors.try_emplace(rule.class_name);
    if (fresh) it->second = concepts.vector_of(rule.class_name);
    f->values[6] = std::max(f->values[6], rule.confidence * cosine(thing.vector, it->second));
  }
  return out;
}

std::vector<DestinationProposal> likeness_proposals(std::span<const PlacementExample> examples, const KindProfile& thing,
                                                    std::span<const ClassRule> rules, const ConceptSource& concepts,
                                                    const LikenessWeights& weights) {
  std::vector<LikenessFeatures> features = likeness_features(examples, thing, rules, concepts);
  std::vector<DestinationProposal> out;
  if (features.empty() || thing.vector.empty()) return out;
  std::vector<double> scores;
  for (const LikenessFeatures& f : features) {
    double s = 0;
    for (std::size_t k = 0; k < kLikenessFeatures; ++k) s += weights.weights[k] * f.values[k];
    scores.push_back(s);
  }
  double elsewhere = 0;
  for (std::size_t k = 0; k < kLikenessFeatures; ++k) elsewhere += weights.weights[k] * weights.elsewhere[k];
  const double top = std::max(*std::max_element(scores.begin(), scores.end()), elsewhere);
  double total = std::exp(elsewhere - top);
  for (double& s : scores) total += s = std::exp(s - top);
  for (std::size_t i = 0; i < features.size(); ++i) {
    DestinationProposal p;
    p.destination = features[i].destination;
    p.confidence = scores[i] / total;
    p.source = ProposalSource::kSimilarity;
    p.evidence = features[i].nearest;
    if (p.evidence.size() > 2) p.evidence.resize(2);
    p.reason = "like the " + join(p.evidence, " and the ");
    out.push_back(std::move(p));
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const DestinationProposal& a, const DestinationProposal& b) { return a.confidence > b.confidence; });
  return out;
}

}  // namespace apprentice
