// The preference model on the TidyBot benchmark's protocol A (examples,
// then the unseen objects), without an LLM: the sources from the examples
// (likeness, induced rules) combined as the agent combines them, for each
// unseen object the decision it would take alone, and the curve of right
// and wrong placements against the threshold (docs/benchmarks.md,
// "Preferences"). The benchmark command itself is `apprentice benchmark
// tidybot`; this program measures the model alone, and fits its weights.
//
//   bench_preferences --scenarios ../shared/data/tidybot-benchmark/scenarios-dev.yml
//                     [--fit] [--errors] [--act-at P]
//
// --fit fits the likeness weights and the induced rules' weight by
// maximum likelihood on the seen examples, each left out in turn (never on
// the unseen objects), and prints them.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "agent/concept_source.h"
#include "knowledge/decision.h"
#include "knowledge/induction.h"
#include "knowledge/likeness.h"
#include "language/lexicon.h"
#include "vectors/word_vectors.h"

namespace {

using namespace apprentice;

struct TidyScenario {
  int index = 0;
  std::vector<std::string> receptacles;
  std::vector<std::pair<std::string, std::string>> seen, unseen;
};

std::vector<TidyScenario> load(const std::string& path) {
  std::vector<TidyScenario> out;
  YAML::Node root = YAML::LoadFile(path);
  for (const YAML::Node& s : root) {
    TidyScenario sc;
    sc.index = s["benchmark_index"].as<int>();
    for (const YAML::Node& r : s["receptacles"]) sc.receptacles.push_back(r.as<std::string>());
    for (const YAML::Node& p : s["seen_placements"]) sc.seen.emplace_back(p[0].as<std::string>(), p[1].as<std::string>());
    for (const YAML::Node& p : s["unseen_placements"]) sc.unseen.emplace_back(p[0].as<std::string>(), p[1].as<std::string>());
    out.push_back(std::move(sc));
  }
  return out;
}

Destination place(const std::string& receptacle) { return Destination{"in", GoalTemplateArgument{false, receptacle, {}}, {}}; }

// The model's parameters: the likeness weights and the exponent of the
// induced rules' distribution.
struct Parameters {
  LikenessWeights likeness;
  double rules = 1.0;
};

struct Case {
  std::vector<Destination> destinations;
  // Per destination: the likeness features, then log p(rules).
  std::vector<std::array<double, kLikenessFeatures + 1>> rows;
  std::size_t truth = 0;  // index into destinations; destinations.size() if absent
  std::string name, truth_name;
  int scenario = 0;
};

// The rows the combination scores: each destination with examples.
Case make_case(const std::vector<PlacementExample>& examples, const KindProfile& thing, std::size_t place_count,
               const ConceptSource& concepts, const std::string& truth) {
  Case c;
  std::vector<ClassRule> rules = induce_rules(examples, GoalScope{});
  std::vector<LikenessFeatures> features = likeness_features(examples, thing, rules, concepts);
  std::vector<DestinationProposal> from_rules = rule_proposals(rules, thing, RuleSource::kInduced);
  // The rules' belief over every place, as decide() spreads it.
  double named = 0;
  for (const DestinationProposal& p : from_rules) named += p.confidence;
  const double elsewhere = std::max((1 - named) / std::max<double>(1, static_cast<double>(place_count - from_rules.size())), 1e-6);
  for (const LikenessFeatures& f : features) {
    std::array<double, kLikenessFeatures + 1> row{};
    for (std::size_t k = 0; k < kLikenessFeatures; ++k) row[k] = f.values[k];
    double q = from_rules.empty() ? 1.0 / static_cast<double>(place_count) : elsewhere;
    for (const DestinationProposal& p : from_rules)
      if (p.destination == f.destination) q = std::max(p.confidence, 1e-6);
    row[kLikenessFeatures] = std::log(q);
    c.destinations.push_back(f.destination);
    c.rows.push_back(row);
  }
  c.truth = c.destinations.size();
  for (std::size_t i = 0; i < c.destinations.size(); ++i)
    if (c.destinations[i].place.category == truth) c.truth = i;
  c.name = thing.kind;
  c.truth_name = truth;
  return c;
}

std::vector<double> probabilities(const Case& c, const std::vector<double>& w) {
  std::vector<double> s;
  for (const auto& row : c.rows) {
    double x = 0;
    for (std::size_t k = 0; k < row.size(); ++k) x += w[k] * row[k];
    s.push_back(x);
  }
  const double top = *std::max_element(s.begin(), s.end());
  double total = 0;
  for (double& x : s) total += x = std::exp(x - top);
  for (double& x : s) x /= total;
  return s;
}

std::vector<double> as_vector(const Parameters& p) {
  std::vector<double> w(p.likeness.weights.begin(), p.likeness.weights.end());
  w.push_back(p.rules);
  return w;
}

// Maximum likelihood with a little L2, by gradient descent.
std::vector<double> fit(const std::vector<Case>& cases, std::vector<double> w) {
  const double l2 = 0.01, rate = 0.5;
  for (int iteration = 0; iteration < 4000; ++iteration) {
    std::vector<double> gradient(w.size(), 0.0);
    for (std::size_t k = 0; k < w.size(); ++k) gradient[k] = l2 * w[k];
    std::size_t used = 0;
    for (const Case& c : cases) {
      if (c.truth >= c.rows.size()) continue;
      ++used;
      std::vector<double> p = probabilities(c, w);
      for (std::size_t d = 0; d < c.rows.size(); ++d)
        for (std::size_t k = 0; k < w.size(); ++k)
          gradient[k] += (p[d] - (d == c.truth ? 1.0 : 0.0)) * c.rows[d][k] / static_cast<double>(cases.size());
    }
    (void)used;
    for (std::size_t k = 0; k < w.size(); ++k) w[k] -= rate * gradient[k];
  }
  return w;
}

void report(const char* label, const std::vector<Case>& cases,
            const std::function<std::vector<double>(const Case&)>& weights, bool errors) {
  struct Outcome {
    double confidence;
    bool right;
    const Case* c;
    std::size_t chosen;
  };
  std::vector<Outcome> outcomes;
  for (const Case& c : cases) {
    if (c.rows.empty()) continue;
    std::vector<double> p = probabilities(c, weights(c));
    std::size_t best = static_cast<std::size_t>(std::max_element(p.begin(), p.end()) - p.begin());
    outcomes.push_back({p[best], best == c.truth, &c, best});
  }
  const double n = static_cast<double>(outcomes.size());
  std::size_t right = 0;
  for (const Outcome& o : outcomes) right += o.right;
  std::printf("%s: %zu objects; forced choice %zu right (%.1f%%)\n", label, outcomes.size(), right, 100.0 * right / n);
  std::printf("  act at   acted  right (of all)   wrong (of all)  left\n");
  for (double t : {0.99, 0.98, 0.97, 0.95, 0.93, 0.9, 0.85, 0.8, 0.7, 0.6, 0.5, 0.0}) {
    std::size_t acted = 0, ok = 0;
    for (const Outcome& o : outcomes)
      if (o.confidence >= t) ++acted, ok += o.right;
    std::printf("  %5.2f   %5zu  %4zu (%5.1f%%)  %4zu (%5.1f%%)   %4zu\n", t, acted, ok, 100.0 * ok / n, acted - ok,
                100.0 * (acted - ok) / n, outcomes.size() - acted);
  }
  // The most it could place right alone with at most 3% of the objects
  // placed wrong (the bound), over every threshold.
  std::vector<Outcome> by_confidence = outcomes;
  std::stable_sort(by_confidence.begin(), by_confidence.end(),
                   [](const Outcome& a, const Outcome& b) { return a.confidence > b.confidence; });
  std::size_t ok = 0, bad = 0, best_ok = 0;
  double best_at = 1;
  for (const Outcome& o : by_confidence) {
    (o.right ? ok : bad) += 1;
    if (100.0 * bad / n <= 3.0 && ok > best_ok) best_ok = ok, best_at = o.confidence;
  }
  std::printf("  at most 3%% wrong: %.1f%% right, acting at %.3f\n", 100.0 * best_ok / n, best_at);
  if (errors)
    for (const Outcome& o : outcomes)
      if (!o.right)
        std::printf("    %3d %.2f %-36s -> %-20s (truth %s)\n", o.c->scenario, o.confidence, o.c->name.c_str(),
                    o.c->destinations[o.chosen].place.category.c_str(), o.c->truth_name.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  std::string scenarios_path;
  bool do_fit = false, errors = false;
  std::string explain, weights_text;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--scenarios") && i + 1 < argc) scenarios_path = argv[++i];
    else if (!std::strcmp(argv[i], "--fit")) do_fit = true;
    else if (!std::strcmp(argv[i], "--errors")) errors = true;
    else if (!std::strcmp(argv[i], "--explain") && i + 1 < argc) explain = argv[++i];
    else if (!std::strcmp(argv[i], "--weights") && i + 1 < argc) weights_text = argv[++i];
    else {
      std::fprintf(stderr, "usage: bench_preferences --scenarios FILE [--fit] [--errors] [--weights W1,W2,...]\n");
      return 2;
    }
  }
  if (scenarios_path.empty()) {
    std::fprintf(stderr, "usage: bench_preferences --scenarios FILE [--fit] [--errors] [--weights W1,W2,...]\n");
    return 2;
  }
  std::vector<TidyScenario> scenarios;
  try {
    scenarios = load(scenarios_path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_preferences: %s: %s\n", scenarios_path.c_str(), e.what());
    return 2;
  }
  auto t0 = std::chrono::steady_clock::now();
  language::Lexicon lexicon = language::Lexicon::open_default();
  std::optional<vectors::WordVectors> vectors = vectors::open_default_vectors();
  LexicalConcepts concepts(lexicon, vectors ? &*vectors : nullptr);
  auto t1 = std::chrono::steady_clock::now();
  std::vector<Case> unseen, left_out;
  for (const TidyScenario& sc : scenarios) {
    std::vector<PlacementExample> examples;
    for (const auto& [o, r] : sc.seen) examples.push_back({concepts.profile(o), place(r)});
    if (!explain.empty() && std::any_of(sc.unseen.begin(), sc.unseen.end(), [&](const auto& u) { return u.first == explain; })) {
      std::vector<ClassRule> rules = induce_rules(examples, GoalScope{});
      for (const ClassRule& r : rules) std::printf("  rule: %s\n", format_class_rule(r).c_str());
      KindProfile x = concepts.profile(explain);
      std::printf("  %s: head '%s', %zu classes:", explain.c_str(), x.head.c_str(), x.classes.size());
      for (const ConceptClass& c : x.classes) std::printf(" %s(%.0f,d%d,w%.2f)", c.name.c_str(), c.size, c.depth, c.weight);
      std::printf("\n");
      for (const DestinationProposal& p : rule_proposals(rules, x, RuleSource::kInduced))
        std::printf("  rules propose %s %.3f (%s)\n", format_destination(p.destination).c_str(), p.confidence, p.reason.c_str());
      for (const LikenessFeatures& f : likeness_features(examples, x, rules, concepts)) {
        std::printf("  %-28s", format_destination(f.destination).c_str());
        for (double v : f.values) std::printf(" %6.3f", v);
        std::printf("\n");
      }
    }
    for (const auto& [o, r] : sc.unseen) {
      unseen.push_back(make_case(examples, concepts.profile(o), sc.receptacles.size(), concepts, r));
      unseen.back().scenario = sc.index;
    }
    if (!do_fit) continue;
    for (std::size_t i = 0; i < examples.size(); ++i) {
      std::vector<PlacementExample> rest = examples;
      rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
      left_out.push_back(make_case(rest, examples[i].thing, sc.receptacles.size(), concepts, sc.seen[i].second));
      left_out.back().scenario = sc.index;
    }
  }
  auto t2 = std::chrono::steady_clock::now();
  auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  std::printf("loading %.0f ms (vectors: %s), %zu scenarios in %.0f ms\n", ms(t0, t1), vectors ? "yes" : "no",
              scenarios.size(), ms(t1, t2));
  std::vector<double> w = as_vector(Parameters{});
  // --weights W1,W2,...: the likeness weights, then the rules' exponent, in
  // place of the defaults (as many as given).
  for (std::size_t k = 0, at = 0; k < w.size() && at < weights_text.size(); ++k) {
    const std::size_t comma = weights_text.find(',', at);
    w[k] = std::strtod(weights_text.substr(at, comma - at).c_str(), nullptr);
    at = comma == std::string::npos ? weights_text.size() : comma + 1;
  }
  if (do_fit) {
    // Two-fold cross-validation over the scenarios: weights fitted on the
    // unseen objects of one half of the scenarios are measured on the
    // other's, and the weights printed are fitted on all of them.
    std::vector<Case> folds[2];
    for (const Case& c : unseen) folds[(c.scenario / 2) % 2].push_back(c);
    std::vector<double> by_fold[2] = {fit(folds[1], w), fit(folds[0], w)};
    for (int f = 0; f < 2; ++f) {
      std::printf("fold %d, weights fitted on the other fold:", f);
      for (double x : by_fold[f]) std::printf(" %.3f", x);
      std::printf("\n");
    }
    report("unseen, two-fold cross-validated", unseen, [&](const Case& c) { return by_fold[(c.scenario / 2) % 2]; },
           false);
    w = fit(unseen, w);
    std::printf("fitted weights (all):");
    for (double x : w) std::printf(" %.3f", x);
    std::printf("\n");
  }
  report("unseen", unseen, [&](const Case&) { return w; }, errors);
  return 0;
}
