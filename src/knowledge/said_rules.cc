#include "knowledge/said_rules.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "util/cosine.h"
#include "util/text.h"

namespace apprentice {

namespace {

std::vector<std::string> name_words_of(const KindProfile& thing) {
  std::vector<std::string> words;
  for (const std::string& m : thing.modifiers)
    for (const std::string& w : split_words(m)) words.push_back(singular_noun(w));
  for (const std::string& w : split_words(thing.head)) words.push_back(singular_noun(w));
  return words;
}

bool in_name(const KindProfile& thing, const std::string& word) {
  const std::vector<std::string> words = name_words_of(thing);
  auto has = [&](const std::string& w) { return std::find(words.begin(), words.end(), singular_noun(w)) != words.end(); };
  if (has(word)) return true;
  // A compound modifier is in the name when its words are ("stainless-steel
  // spoon": "stainless steel"), or its first word is and the rest says how
  // ("light-colored": the light yellow tank top; "short-sleeved").
  std::vector<std::string> parts;
  for (std::size_t at = 0, dash; at <= word.size(); at = dash + 1) {
    dash = std::min(word.find('-', at), word.size());
    if (dash > at) parts.push_back(word.substr(at, dash - at));
  }
  if (parts.size() < 2) return false;
  if (std::all_of(parts.begin(), parts.end(), has)) return true;
  return has(parts.front()) && parts.back().size() > 3 && parts.back().ends_with("ed");
}

}  // namespace

ClassRule as_head_and_modifiers(const ClassRule& rule, const ConceptSource& concepts) {
  if (rule.class_name.empty() || !rule.class_id.empty() || !concepts.classes_named(rule.class_name).empty()) return rule;
  const std::vector<std::string> words = split_words(rule.class_name);
  if (words.size() < 2 || concepts.classes_named(words.back()).empty()) return rule;
  ClassRule out = rule;
  out.class_name = words.back();
  out.modifiers.insert(out.modifiers.begin(), words.begin(), words.end() - 1);
  return out;
}

ClauseEvidence clause_evidence(const ClassRule& as_said, const KindProfile& thing, const ConceptSource& concepts) {
  ClauseEvidence e;
  e.said_a_class = !as_said.class_id.empty() || !as_said.class_name.empty() || !as_said.modifiers.empty();
  e.modifiers_only = as_said.class_id.empty() && as_said.class_name.empty() && !as_said.modifiers.empty();
  const ClassRule rule = as_head_and_modifiers(as_said, concepts);
  if (!rule.class_id.empty()) {
    e.wordnet = std::any_of(thing.classes.begin(), thing.classes.end(), [&](const ConceptClass& c) { return c.id == rule.class_id; });
  } else if (!rule.class_name.empty()) {
    // A class word's less usual senses ("books" as published works) count
    // only for a thing's first sense (a textbook), not for a sense of its
    // name rarely meant (a plastic cup's "cup" as a punch, which is food).
    for (const ConceptClass& said : concepts.classes_named(rule.class_name))
      for (const ConceptClass& c : thing.classes)
        if (c.id == said.id && (said.weight >= kUsualSenseWeight || c.weight >= 1.0))
          (said.depth == 0 ? e.wordnet : e.wordnet_parent) = true;
    if (e.wordnet) e.wordnet_parent = false;
    e.wordnet_knows_both = !thing.classes.empty() && !concepts.classes_named(rule.class_name).empty();
    // The class's own word in the thing's name: "toy hammer", "tissue box".
    const std::vector<std::string> class_words = split_words(rule.class_name);
    e.word_in_name = !class_words.empty() && in_name(thing, class_words.back());
  }
  if (!rule.modifiers.empty()) {
    const bool all = std::all_of(rule.modifiers.begin(), rule.modifiers.end(),
                                 [&](const std::string& m) { return in_name(thing, m); });
    e.modifiers_in_name = all;
    e.modifiers_missing = !all;
  }
  std::vector<std::string> words = rule.modifiers;
  if (!rule.class_name.empty()) words.push_back(rule.class_name);
  if (words.empty()) return e;
  const std::vector<float> phrase = concepts.vector_of(join(words, " "));
  if (phrase.empty()) return e;
  e.has_vectors = true;
  if (!thing.vector.empty()) e.name_cosine = cosine(thing.vector, phrase);
  if (!thing.head_vector.empty()) e.head_cosine = cosine(thing.head_vector, phrase);
  e.word_cosine = e.name_cosine;
  for (const std::vector<float>& v : thing.word_vectors) e.word_cosine = std::max(e.word_cosine, cosine(v, phrase));
  // The names of the classes WordNet puts the thing in, near it: a hoodie
  // is a garment, which is near "clothes"; a barbell, sports equipment.
  for (const ConceptClass& c : thing.classes) {
    if (c.depth > kAncestorDepth) continue;
    const std::vector<float> name = concepts.vector_of(c.name);
    if (name.empty()) continue;
    e.class_cosine = std::max(e.class_cosine, cosine(name, phrase) * c.weight);
    if (c.depth >= 1 && c.size <= kNearClassMostKinds) e.ancestor_cosine = std::max(e.ancestor_cosine, cosine(name, phrase) * c.weight);
  }
  return e;
}

bool ClauseEvidence::sure() const { return wordnet || word_in_name; }

bool ClauseEvidence::only_related() const {
  // A class of modifiers alone ("paper things", "heavy items") that the
  // thing's name does not carry: only the vectors speak for it, and they
  // put "paper" near half of a garage. Asked, never acted on alone.
  if (modifiers_only && !modifiers_in_name) return true;
  return said_a_class && wordnet_knows_both && !sure() && !wordnet_parent && !modifiers_in_name &&
         (ancestor_cosine < kNearClassCosine || word_cosine < kFitCosine);
}

bool ClauseEvidence::fits() const {
  if (!said_a_class || sure() || wordnet_parent || modifiers_in_name) return true;
  // (The names of its WordNet classes say what a thing is, not what it is
  // made of: "material" is near "paper".)
  if (modifiers_only) return has_vectors && word_cosine >= kFitCosine;
  return has_vectors && std::max(word_cosine, class_cosine) >= kFitCosine;
}

double SaidRuleWeights::score(const ClassRule& rule, const ClauseEvidence& e) const {
  double s = 0;
  if (e.wordnet) s += wordnet;
  if (e.wordnet_parent) s += wordnet_parent;
  if (e.word_in_name) s += word_in_name;
  if (e.modifiers_in_name) s += modifier;
  if (e.modifiers_missing && !rule.class_name.empty()) s -= modifier_missing;
  s += name_vector * e.name_cosine + word_vector * e.word_cosine + head_vector * e.head_cosine +
       class_vector * e.class_cosine;
  return s;
}


std::vector<DestinationProposal> said_rule_proposals(std::span<const ClassRule> rules, const KindProfile& thing,
                                                     RuleSource source, const ConceptSource& concepts,
                                                     const SaidRuleWeights& weights) {
  std::vector<const ClassRule*> mine;
  for (const ClassRule& rule : rules)
    if (rule.source == source &&
        std::find(rule.exceptions.begin(), rule.exceptions.end(), thing.kind) == rule.exceptions.end())
      mine.push_back(&rule);
  if (mine.empty()) return {};
  // A rule for the rest takes the thing only when no other clause is sure
  // of it ("outerwear in the closet and other clothes on the bed": the
  // parka is outerwear).
  std::vector<ClauseEvidence> evidence;
  for (const ClassRule* rule : mine) evidence.push_back(clause_evidence(*rule, thing, concepts));
  std::vector<double> scores(mine.size(), 0.0);
  bool another_is_sure = false;
  for (std::size_t i = 0; i < mine.size(); ++i) {
    if (mine[i]->rest) continue;
    scores[i] = weights.score(*mine[i], evidence[i]);
    another_is_sure = another_is_sure || evidence[i].sure();
  }
  for (std::size_t i = 0; i < mine.size(); ++i) {
    const ClassRule& rule = *mine[i];
    if (!rule.rest) continue;
    const double own = rule.class_name.empty() && rule.modifiers.empty() ? weights.rest : weights.score(rule, evidence[i]);
    scores[i] = own - (another_is_sure ? weights.rest_penalty : 0.0);
  }
  if (source == RuleSource::kLlm)
    for (double& s : scores) s *= weights.llm_sharpness;
  const double top = std::max(*std::max_element(scores.begin(), scores.end()), weights.none);
  double total = std::exp(weights.none - top);
  for (double& s : scores) total += s = std::exp(s - top);
  std::vector<double> shares(mine.size());
  for (std::size_t i = 0; i < mine.size(); ++i) shares[i] = scores[i] / total;
  // A person's rule for the rest is in doubt when a class said beside it
  // also fits the thing, if not surely ("outerwear in the closet and other
  // clothes on the bed": is a ski jacket outerwear?): what the rest has
  // above rest_in_doubt goes to the best of those clauses, so that the
  // thing is asked about, not placed alone, however few places there are.
  std::optional<std::size_t> fitting;
  for (std::size_t i = 0; i < mine.size(); ++i)
    if (!mine[i]->rest && evidence[i].said_a_class && evidence[i].fits() && (!fitting || scores[i] > scores[*fitting]))
      fitting = i;
  if (source == RuleSource::kPerson && fitting)
    for (std::size_t i = 0; i < mine.size(); ++i)
      if (mine[i]->rest && shares[i] > weights.rest_in_doubt) {
        shares[*fitting] += shares[i] - weights.rest_in_doubt;
        shares[i] = weights.rest_in_doubt;
      }
  std::vector<DestinationProposal> out;
  for (std::size_t i = 0; i < mine.size(); ++i) {
    const ClassRule& rule = *mine[i];
    if (source == RuleSource::kPerson && !evidence[i].fits()) continue;
    const double share = source == RuleSource::kPerson && evidence[i].only_related()
                             ? std::min(shares[i], weights.only_related_at_most)
                             : shares[i];
    auto same = std::find_if(out.begin(), out.end(), [&](const DestinationProposal& p) { return p.destination == rule.destination; });
    if (same != out.end()) {
      same->confidence += share * rule.confidence;
      continue;
    }
    DestinationProposal p;
    p.destination = rule.destination;
    p.confidence = share * rule.confidence;
    p.source = proposal_source_of(source);
    p.rule = rule;
    p.evidence = rule.evidence;
    p.reason = format_class_rule(rule);
    out.push_back(std::move(p));
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const DestinationProposal& a, const DestinationProposal& b) { return a.confidence > b.confidence; });
  return out;
}

}  // namespace apprentice
