#include "agent/transfer.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include <spdlog/spdlog.h>

#include "language/narration.h"
#include "util/text.h"

namespace apprentice {
namespace {

// WordNet's lexicographer files of things a robot can hold or put away.
constexpr int kLexObject = 17;  // noun.object: natural objects
constexpr int kLexPlant = 20;   // noun.plant: fruit and vegetables

bool is_physical(const language::Synset& synset) {
  int file = synset.lexicographer_file;
  return file == language::kLexArtifact || file == language::kLexFood || file == language::kLexSubstance ||
         file == kLexObject || file == kLexPlant;
}

// "trash-can" -> "trash can", as WordNet and the lexicon spell phrases.
std::string spaced(std::string_view category) {
  std::string out = to_lower(category);
  for (char& c : out)
    if (c == '-' || c == '_') c = ' ';
  return join(split_words(out), " ");
}

std::vector<std::string> hyphen_words(std::string_view category) {
  return split_words(spaced(category));
}

// WordNet's answers about single words and phrases, each asked once.
class WordCache {
 public:
  explicit WordCache(const language::Lexicon& lexicon) : lexicon_(lexicon) {}

  // The spellings of a phrase WordNet vouches for: itself, its base forms
  // and its variants ("crackers" -> "cracker", "recycle bin" -> "recycling bin").
  const std::set<std::string>& forms(std::string_view category) {
    std::string text = spaced(category);
    auto found = forms_.find(text);
    if (found != forms_.end()) return found->second;
    std::set<std::string> out{text};
    for (std::string& form : lexicon_.lemmas(text)) out.insert(std::move(form));
    for (language::PhraseVariant& variant : lexicon_.variants(text)) out.insert(std::move(variant.phrase));
    return forms_.emplace(text, std::move(out)).first->second;
  }

  bool same_word(std::string_view a, std::string_view b) { return intersect(forms(a), forms(b)); }

  // Whether WordNet puts the two (or their forms) in one synset.
  bool share_synset(std::string_view a, std::string_view b) {
    const std::set<std::string>& b_forms = forms(b);
    for (const std::string& form : forms(a)) {
      auto found = synonyms_.find(form);
      if (found == synonyms_.end()) {
        std::vector<std::string> list = lexicon_.synonyms(form);
        found = synonyms_.emplace(form, std::set<std::string>(list.begin(), list.end())).first;
      }
      if (intersect(found->second, b_forms)) return true;
    }
    return false;
  }

 private:
  static bool intersect(const std::set<std::string>& a, const std::set<std::string>& b) {
    return std::any_of(a.begin(), a.end(), [&](const std::string& x) { return b.count(x) > 0; });
  }

  const language::Lexicon& lexicon_;
  std::map<std::string, std::set<std::string>> forms_;
  std::map<std::string, std::set<std::string>> synonyms_;
};

// Why a world category means a learned one, or "" if WordNet does not say
// so by its words: the same word, a shared synset (items), or compounds
// word by word. Places' other relations come from Lexicon::related.
std::string same_words(WordCache& words, const std::string& learned, const std::string& world, bool place) {
  if (words.same_word(learned, world)) return "'" + world + "' is another form of '" + learned + "'";
  if (!place && words.share_synset(world, learned))
    return "'" + world + "' and '" + learned + "' share a WordNet synset";
  std::vector<std::string> a = hyphen_words(learned), b = hyphen_words(world);
  if (a.size() < 2 || a.size() != b.size()) return "";
  std::vector<std::string> pairs;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] == b[i]) continue;
    if (!words.same_word(a[i], b[i]) && !words.share_synset(b[i], a[i])) return "";
    pairs.push_back("'" + b[i] + "' for '" + a[i] + "'");
  }
  return "word by word, WordNet gives " + join(pairs, " and ");
}

struct LearnedCategories {
  std::set<std::string> items, places;
};

LearnedCategories learned_categories(const Knowledge& knowledge) {
  LearnedCategories out;
  for (const TaskKnowledge& task : knowledge.tasks)
    for (const LearnedSubtask& subtask : task.subtasks) out.places.insert(subtask.place_category);
  for (const GoalKnowledge& goal : knowledge.goals.all()) {
    out.items.insert(goal.key.category);
    out.places.insert(goal.key.place);
    for (const GoalTemplateLiteral& literal : goal.literals)
      for (const GoalTemplateArgument& argument : literal.arguments)
        if (!argument.object_of_interest) out.places.insert(argument.category);
  }
  for (const Rule& rule : knowledge.rules.rules())
    for (const RuleVariable& variable : rule.variables)
      if (variable.category) out.places.insert(*variable.category);
  return out;
}

}  // namespace

std::vector<CategoryMatch> match_categories(const Knowledge& knowledge, const World& world,
                                            const language::Lexicon& lexicon) {
  std::vector<CategoryMatch> matches;
  if (!lexicon.has_wordnet()) return matches;
  LearnedCategories learned = learned_categories(knowledge);
  std::map<std::string, ObjectKind> world_kinds;
  for (const ObjectInfo& info : world.universe->objects()) world_kinds.emplace(info.category, info.kind);
  auto is_learned = [&](const std::string& c) { return learned.items.count(c) || learned.places.count(c); };
  // The learned categories the world lacks, and the world's categories
  // nothing learned names: only these can be matched.
  std::vector<std::string> absent_items, absent_places, new_items, new_places;
  for (const std::string& c : learned.items)
    if (!world_kinds.count(c)) absent_items.push_back(c);
  for (const std::string& c : learned.places)
    if (!world_kinds.count(c) && !learned.items.count(c)) absent_places.push_back(c);
  for (const auto& [name, kind] : world_kinds)
    if (!is_learned(name)) (kind == ObjectKind::kItem ? new_items : new_places).push_back(name);
  // Every candidate pair, then only those that are one to one.
  std::map<std::pair<std::string, std::string>, std::string> candidates;
  WordCache words(lexicon);
  auto compare = [&](const std::vector<std::string>& absent, const std::vector<std::string>& fresh, bool place) {
    for (const std::string& l : absent)
      for (const std::string& w : fresh)
        if (std::string reason = same_words(words, l, w, place); !reason.empty()) candidates.emplace(std::pair{l, w}, reason);
  };
  compare(absent_items, new_items, false);
  compare(absent_places, new_places, true);
  // Places also by the relations the grounder accepts when a person names a
  // place, the world's word taken as the person's ("refrigerator" for the
  // learned "fridge"), and the other way round ("fridge" for "refrigerator").
  if (!absent_places.empty()) {
    for (const std::string& w : new_places) {
      bool receptacle = world_kinds[w] == ObjectKind::kReceptacle;
      for (const language::CategoryRelation& r : lexicon.related(spaced(w), absent_places, receptacle))
        candidates.emplace(std::pair{r.category, w}, r.reason);
    }
    for (const std::string& l : absent_places)
      for (const language::CategoryRelation& r : lexicon.related(spaced(l), new_places, false))
        candidates.emplace(std::pair{l, r.category}, r.reason);
  }
  std::map<std::string, int> per_learned, per_world;
  for (const auto& [pair, reason] : candidates) {
    ++per_learned[pair.first];
    ++per_world[pair.second];
  }
  for (const auto& [pair, reason] : candidates) {
    if (per_learned[pair.first] == 1 && per_world[pair.second] == 1) {
      matches.push_back({pair.first, pair.second, reason});
    } else {
      spdlog::info("transfer: '{}' could be the '{}' here ({}), but not only it", pair.first, pair.second, reason);
    }
  }
  return matches;
}

Knowledge rename_categories(const Knowledge& knowledge, const Domain& domain, std::span<const CategoryMatch> matches) {
  std::map<std::string, std::string> to_world;
  for (const CategoryMatch& m : matches) to_world[m.learned] = m.world;
  auto rename = [&](std::string& category) {
    if (auto found = to_world.find(category); found != to_world.end()) category = found->second;
  };
  Knowledge out;
  out.tasks = knowledge.tasks;
  for (TaskKnowledge& task : out.tasks)
    for (LearnedSubtask& subtask : task.subtasks) rename(subtask.place_category);
  for (GoalKnowledge goal : knowledge.goals.all()) {
    rename(goal.key.category);
    rename(goal.key.place);
    for (GoalTemplateLiteral& literal : goal.literals)
      for (GoalTemplateArgument& argument : literal.arguments)
        if (!argument.object_of_interest) rename(argument.category);
    out.goals.add(std::move(goal));
  }
  for (Rule rule : knowledge.rules.rules()) {
    for (RuleVariable& variable : rule.variables)
      if (variable.category) rename(*variable.category);
    out.rules.add(domain, std::move(rule));
  }
  return out;
}

std::string say_renamings(std::span<const CategoryMatch> matches) {
  if (matches.empty()) return "";
  std::vector<std::string> pairs;
  for (const CategoryMatch& m : matches)
    pairs.push_back("the " + language::spoken_category(m.world) + " for the " + language::spoken_category(m.learned));
  return "Here I take " + language::list_phrase(pairs) + ".";
}

std::string ask_analogy(const World& world, ObjectId object, const Analogy& analogy) {
  return "Does " + language::spoken_name_and_location(world, object) + " go like the " +
         language::spoken_category(analogy.learned_as) + ": " + language::goal_outcome(world, object, analogy.goal, "it") +
         "?";
}

std::string doubtful_analogy(const Analogy& analogy) {
  char confidence[16];
  std::snprintf(confidence, sizeof confidence, "%.2f", analogy.confidence);
  return "it may go like the " + language::spoken_category(analogy.learned_as) + ", but I am not sure enough (confidence " +
         confidence + ", below " + std::to_string(kAdoptAnalogyAt).substr(0, 3) + ")";
}

KnowledgeTransfer::KnowledgeTransfer(Knowledge& knowledge, const World& world, const language::Lexicon& lexicon)
    : lexicon_(&lexicon), matches_(match_categories(knowledge, world, lexicon)) {
  for (const CategoryMatch& m : matches_)
    spdlog::info("transfer: what I learned about '{}' applies to the '{}' here: {}", m.learned, m.world, m.reason);
  if (!matches_.empty()) knowledge = rename_categories(knowledge, *world.domain, matches_);
  prior_goals_ = knowledge.goals.all();
}

const std::map<language::SynsetOffset, int>& KnowledgeTransfer::ancestors(const std::string& phrase) const {
  auto cached = ancestors_.find(phrase);
  if (cached != ancestors_.end()) return cached->second;
  std::map<language::SynsetOffset, int> found;
  if (const language::WordNet* wordnet = lexicon_->wordnet()) {
    std::set<std::string> forms{std::string(phrase), spaced(phrase)};
    for (std::string& form : lexicon_->lemmas(spaced(phrase))) forms.insert(std::move(form));  // "half-and-half" is hyphenated in WordNet
    std::vector<language::SynsetOffset> frontier;
    for (const std::string& form : forms)
      for (language::SynsetOffset offset : wordnet->noun_senses(form))
        if (auto synset = wordnet->synset(offset); synset && is_physical(*synset)) frontier.push_back(offset);
    for (int depth = 0; depth <= kMaxAnalogyDistance && !frontier.empty(); ++depth) {
      std::vector<language::SynsetOffset> next;
      for (language::SynsetOffset offset : frontier) {
        if (!found.emplace(offset, depth).second) continue;
        if (auto synset = wordnet->synset(offset))
          next.insert(next.end(), synset->hypernyms.begin(), synset->hypernyms.end());
      }
      frontier = std::move(next);
    }
  }
  return ancestors_.emplace(phrase, std::move(found)).first->second;
}

int KnowledgeTransfer::phrase_distance(const std::string& a, const std::string& b) const {
  if (a == b) return 0;
  const auto& above_a = ancestors(a);
  const auto& above_b = ancestors(b);
  int best = -1;
  for (const auto& [offset, depth] : above_a) {
    auto other = above_b.find(offset);
    if (other == above_b.end()) continue;
    int distance = depth + other->second;
    if (best < 0 || distance < best) best = distance;
  }
  return best;
}

int KnowledgeTransfer::kind_distance(const std::string& a, const std::string& b) const {
  int best = phrase_distance(a, b);
  auto better = [&](int d) {
    if (d >= 0 && (best < 0 || d < best)) best = d;
  };
  std::vector<std::string> a_words = hyphen_words(a), b_words = hyphen_words(b);
  // Compounds of as many words, word by word: "plastic-beaker" is one step
  // from "plastic-cup", as a beaker is a kind of cup.
  if (a_words.size() >= 2 && a_words.size() == b_words.size()) {
    int sum = 0;
    for (std::size_t i = 0; i < a_words.size() && sum >= 0; ++i) {
      int d = phrase_distance(a_words[i], b_words[i]);
      sum = d < 0 ? -1 : sum + d;
    }
    better(sum);
  }
  // A compound WordNet lacks stands for its last word, one step away:
  // "juice-box" and "cereal-box" are two kinds of box.
  bool a_known = !ancestors(a).empty(), b_known = !ancestors(b).empty();
  if ((!a_known && a_words.size() >= 2) || (!b_known && b_words.size() >= 2)) {
    std::string a_head = a_known ? a : a_words.back(), b_head = b_known ? b : b_words.back();
    int d = phrase_distance(a_head, b_head);
    if (d >= 0) better(d + (a_known ? 0 : 1) + (b_known ? 0 : 1));
  }
  return best;
}

std::optional<Analogy> KnowledgeTransfer::analogy(const World& world, const GoalKey& key, ObjectId object) const {
  std::optional<Analogy> best;
  for (const GoalKnowledge& known : prior_goals_) {
    if (known.key == key) continue;  // not an analogy: the goal itself
    bool same_context = known.key.task == key.task && known.key.subtask == key.subtask && known.key.place == key.place;
    int distance = known.key.category == key.category ? 0 : kind_distance(key.category, known.key.category);
    if (distance < 0 || distance > kMaxAnalogyDistance) continue;
    double confidence = (same_context ? 1.0 : 0.5) / (1 + distance);
    if (best && confidence <= best->confidence) continue;
    auto goal = instantiate_goal(world, known, object);
    if (!goal) continue;  // it names a place this world lacks, or has several of
    std::string learned_as = known.key.category;
    for (const CategoryMatch& m : matches_)
      if (m.world == learned_as) learned_as = m.learned;
    best = Analogy{known, std::move(learned_as), std::move(*goal), distance, same_context, confidence};
  }
  if (best)
    spdlog::info("transfer: a {} may be like a {} (distance {}, {} context, confidence {:.2f})", key.category,
                 best->like.key.category, best->distance, best->same_context ? "same" : "another", best->confidence);
  return best;
}

}  // namespace apprentice
