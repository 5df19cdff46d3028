#include "agent/class_rule_knowledge.h"

#include <algorithm>
#include <set>

#include "agent/goal_proposals.h"
#include "language/narration.h"
#include "util/text.h"

namespace apprentice {

namespace {

// Lower case, words split on spaces and hyphens, "the"/"a" dropped.
std::vector<std::string> plain_words(std::string_view text) {
  std::vector<std::string> out;
  std::string word;
  auto flush = [&] {
    if (!word.empty() && word != "the" && word != "a" && word != "an") out.push_back(word);
    word.clear();
  };
  for (char c : text) {
    if (c == ' ' || c == '-' || c == '\t' || c == ',' || c == '.' || c == '"' || c == '\'') flush();
    else word += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  }
  flush();
  return out;
}

bool same_word(const std::string& a, const std::string& b) { return a == b || singular_noun(a) == singular_noun(b); }

// Whether `said` are the last words of `words` (each the same word, up to
// the plural).
bool ends_with_words(const std::vector<std::string>& words, const std::vector<std::string>& said) {
  if (said.empty() || said.size() > words.size()) return false;
  return std::equal(said.begin(), said.end(), words.end() - static_cast<std::ptrdiff_t>(said.size()), same_word);
}

std::string place_phrase(const ClassRule& rule) {
  std::string place = rule.destination.place.category;
  for (auto p = rule.destination.place.properties.rbegin(); p != rule.destination.place.properties.rend(); ++p)
    place = *p + " " + place;
  return place;
}

// Whether the words `said` are what `rule` is about.
bool names_subject(const ClassRule& rule, const std::vector<std::string>& said) {
  if (said.empty()) return false;
  std::vector<std::string> subject = plain_words(rule_subject(rule));
  if (said.size() == subject.size() && std::equal(said.begin(), said.end(), subject.begin(), same_word)) return true;
  // The class by its last words, with the rule's modifiers or "other" said or not.
  std::vector<std::string> words = said;
  if (rule.rest && !words.empty() && (words.front() == "other" || words.front() == "rest")) words.erase(words.begin());
  std::vector<std::string> modifiers;
  for (const std::string& m : rule.modifiers)
    for (std::string& w : plain_words(m)) modifiers.push_back(std::move(w));
  if (!modifiers.empty() && words.size() > modifiers.size() &&
      std::equal(modifiers.begin(), modifiers.end(), words.begin(), same_word))
    words.erase(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(modifiers.size()));
  std::vector<std::string> class_words = plain_words(rule.class_name);
  if (class_words.empty()) {
    // A rule of modifiers alone: "plastic", "plastic things", "plastic
    // items", "plastic stuff".
    std::vector<std::string> bare = said;
    if (bare.size() > modifiers.size() && is_one_of(bare.back(), {"things", "thing", "items", "item", "stuff"}))
      bare.pop_back();
    return !modifiers.empty() && bare.size() == modifiers.size() &&
           std::equal(bare.begin(), bare.end(), modifiers.begin(), same_word);
  }
  return ends_with_words(class_words, words);
}

}  // namespace

std::string rule_destination(const ClassRule& rule) {
  return rule.destination.relation + " the " + language::spoken_category(place_phrase(rule));
}

std::vector<ClassRule> class_rules_in_use(const Knowledge& knowledge, const ConceptSource& concepts) {
  std::vector<ClassRule> out;
  std::set<std::string> keys;
  auto keep = [&](const ClassRule& rule) {
    if (knowledge.forgot(rule) || !keys.insert(class_rule_key(rule)).second) return;
    out.push_back(rule);
  };
  for (const ClassRule& rule : knowledge.class_rules.all())
    if (rule.source != RuleSource::kInduced) keep(rule);
  GoalProposer proposer(concepts, knowledge.goals.all());
  for (const ClassRule& rule : proposer.all_induced()) keep(rule);
  return out;
}

std::vector<ClassRule> rules_named(std::span<const ClassRule> rules, std::string_view phrase) {
  std::vector<std::string> words = plain_words(phrase);
  // "the rule that ...", "the rule about ...", "the rule for ...", "that ...".
  for (const char* lead : {"rule", "that", "about", "for", "what", "you", "know"})
    if (!words.empty() && words.front() == lead) words.erase(words.begin());
  if (!words.empty() && words.front() == "that") words.erase(words.begin());
  // "the paper rule", "that paper stuff rule".
  while (!words.empty() && (words.back() == "rule" || words.back() == "rules")) words.pop_back();
  // Where the subject ends: at "go"/"goes" or at the relation.
  std::vector<std::string> subject = words, place;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& w = words[i];
    if (w == "go" || w == "goes" || w == "belong" || w == "belongs" || w == "on" || w == "in" || w == "into" ||
        w == "onto") {
      subject.assign(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(i));
      std::size_t at = i;
      while (at < words.size() && (words[at] == "go" || words[at] == "goes" || words[at] == "belong" ||
                                   words[at] == "belongs" || words[at] == "on" || words[at] == "in" ||
                                   words[at] == "into" || words[at] == "onto"))
        ++at;
      place.assign(words.begin() + static_cast<std::ptrdiff_t>(at), words.end());
      break;
    }
  }
  std::vector<ClassRule> out;
  for (const ClassRule& rule : rules) {
    if (!names_subject(rule, subject)) continue;
    if (!place.empty()) {
      std::vector<std::string> where = plain_words(place_phrase(rule));
      std::vector<std::string> spoken = plain_words(language::spoken_category(place_phrase(rule)));
      if (!ends_with_words(where, place) && !ends_with_words(spoken, place)) continue;
    }
    out.push_back(rule);
  }
  return out;
}

Status forget_rule(Knowledge& knowledge, KnowledgeStore* store, const ClassRule& rule) {
  if (store != nullptr)
    if (auto s = store->forget_class_rule(rule); !s) return s;
  knowledge.class_rules.remove(rule);
  knowledge.forgotten_rules.add(rule);
  return {};
}

Result<std::vector<ClassRule>> forget_rules_named(const std::string& location, const std::string& household,
                                                  const Domain& domain, std::string_view what,
                                                  const ConceptSource& concepts) {
  const std::string said(trim(what));
  if (said.empty())
    return make_error(ErrorCode::kInvalidInput,
                      "knowledge forget takes what the rule is about, for example \"fruit\" or \"fruit on the coffee table\"");
  auto store = KnowledgeStore::open(location, StoreAccess::kReadWrite, household);
  if (!store) return tl::unexpected(store.error());
  auto knowledge = store->load(domain);
  if (!knowledge) return tl::unexpected(knowledge.error());
  const std::vector<ClassRule> in_use = class_rules_in_use(*knowledge, concepts);
  std::vector<ClassRule> named = rules_named(in_use, said);
  if (named.empty()) {
    std::vector<std::string> subjects;
    for (const ClassRule& rule : in_use)
      if (std::find(subjects.begin(), subjects.end(), rule_subject(rule)) == subjects.end())
        subjects.push_back(rule_subject(rule));
    return make_error(ErrorCode::kInvalidInput,
                      "I hold no rule about \"" + said + "\"." +
                          (subjects.empty() ? std::string(" I hold no rules about classes of things.")
                                            : " The rules I hold are about " + language::list_phrase(subjects) + "."));
  }
  // Rules that say different things need the person to say which; the
  // same rule learned in several places is forgotten everywhere.
  std::set<std::string> differing;
  for (const ClassRule& rule : named) differing.insert(rule_subject(rule) + "|" + format_destination(rule.destination));
  if (differing.size() > 1) {
    std::vector<std::string> lines;
    for (const ClassRule& rule : named) lines.push_back(say_class_rule(rule));
    const ClassRule& first = named.front();
    return make_error(ErrorCode::kInvalidInput,
                      "\"" + said + "\" names " + std::to_string(named.size()) + " rules: " + join(lines, "; ") +
                          ". Say which, for example: forget \"" + rule_subject(first) + " " + rule_destination(first) + "\"");
  }
  for (const ClassRule& rule : named)
    if (auto s = forget_rule(*knowledge, &*store, rule); !s) return tl::unexpected(s.error());
  return named;
}

Status keep_induced_rules(Knowledge& knowledge, KnowledgeStore* store, const ConceptSource& concepts) {
  GoalProposer proposer(concepts, knowledge.goals.all());
  std::vector<ClassRule> induced = proposer.all_induced();
  std::erase_if(induced, [&](const ClassRule& rule) { return knowledge.forgot(rule); });
  std::set<std::string> keys;
  for (const ClassRule& rule : induced) keys.insert(class_rule_key(rule));
  std::vector<ClassRule> stale;
  for (const ClassRule& rule : knowledge.class_rules.all())
    if (rule.source == RuleSource::kInduced && !keys.contains(class_rule_key(rule))) stale.push_back(rule);
  for (const ClassRule& rule : stale) {
    if (store != nullptr)
      if (auto s = store->remove_class_rule(rule); !s) return s;
    knowledge.class_rules.remove(rule);
  }
  for (const ClassRule& rule : induced) {
    const ClassRule* known = knowledge.class_rules.find(rule);
    if (known != nullptr && *known == rule) continue;
    if (store != nullptr)
      if (auto s = store->save_class_rule(rule); !s) return s;
    knowledge.class_rules.add(rule);
  }
  return {};
}

}  // namespace apprentice
