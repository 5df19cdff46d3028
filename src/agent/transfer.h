// Knowledge across worlds, by WordNet.
//
// What the agent learns is keyed by category words: goals by the kind of
// object and the kinds of places they name ("ketchup", "fridge"), the task
// structure by the kinds of places its subtasks empty ("table"), rules
// learned the paper's way by the categories they test. Another world may
// call the same things by other words: a kitchen whose fridge is a
// "refrigerator" and whose garbage is a "trash can".
//
// Synonyms: on meeting a world, the agent renames each learned category the
// world lacks to the one world category WordNet says means the same, so
// that everything it knows applies there as it stands.
//
// Analogy: for a kind of object it knows no goal for, the agent finds the
// nearest kind in WordNet's hierarchy that it learned a goal for before the
// session began ("saltines" are a kind of "crackers"; "cream" and
// "half-and-half" are both dairy products) and proposes that goal: to the
// teacher as a yes/no question, or, alone, only at kAdoptAnalogyAt or more.
// Goals learned in the session itself serve no analogies: the teacher is
// teaching this world, and the paper's one-shot figures stay as they are.
//
// docs/knowledge.md ("Knowledge across worlds") has the rules and figures.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "knowledge/store.h"
#include "language/lexicon.h"
#include "world/goal.h"
#include "world/world.h"

namespace apprentice {

// A learned category and the world's word for the same kind of thing.
struct CategoryMatch {
  std::string learned;  // "fridge"
  std::string world;    // "refrigerator"
  std::string reason;   // why WordNet says they mean the same
};

// Which learned categories the world calls by other words. A learned
// category the world has keeps its name. One the world lacks is matched to
// the world category (of the same kind: item or place) that means the same:
//   - the same word by WordNet's morphology or spelling ("crackers" and
//     "cracker", "recycle bin" and "recycling bin");
//   - for items, a shared WordNet synset ("catsup" and "ketchup");
//   - for places, any relation the grounder accepts when a person names a
//     place (Lexicon::related: a shared synset, one directly above the
//     other, each defined by the other, containers for the same material:
//     "refrigerator" and "fridge", "trash can" and "garbage");
//   - compounds word by word, each word the same or a synonym ("pop-can"
//     and "soda-can").
// Matches are one to one: a learned category several world categories could
// mean, or a world category that could stand for several learned ones, is
// left unmatched. Without WordNet only the same words match, so nothing is
// renamed.
std::vector<CategoryMatch> match_categories(const Knowledge& knowledge, const World& world,
                                            const language::Lexicon& lexicon);

// The knowledge with every matched category renamed to the world's word:
// goal keys and templates, the task structure, and rules' category tests.
Knowledge rename_categories(const Knowledge& knowledge, const Domain& domain, std::span<const CategoryMatch> matches);

// A goal learned for one kind of object, proposed for another.
struct Analogy {
  GoalKnowledge like;  // the goal learned before, for `like.key.category`
  // That category as it was learned, before any renaming: "ketchup" for a
  // goal now keyed "catsup" in a world that says catsup. For the teacher.
  std::string learned_as;
  Goal goal;           // the same goal for the object, in this world
  // How far apart the two kinds are in WordNet's noun hierarchy: 0 the same
  // kind (the same word in another task or subtask), 1 one directly a kind
  // of the other ("saltines" and "crackers"), 2 sisters under one kind
  // ("cream" and "half-and-half") or two kinds of one thing named by their
  // last word ("juice-box" and "cereal-box").
  int distance = 0;
  // Learned for the same task, subtask and kind of place.
  bool same_context = false;
  // 1 / (1 + distance), halved when learned in another context.
  double confidence = 0;
};

// Farther kinds are never proposed.
inline constexpr int kMaxAnalogyDistance = 2;
// Without a teacher the agent adopts an analogy only at this confidence or
// more: the same kind of object in another task or subtask (0.5), or a kind
// directly above or below it in the same one (0.5). Sisters (0.33) and
// anything from another context at distance 1 or more (0.25 or less) are
// left, and reported as needing help.
inline constexpr double kAdoptAnalogyAt = 0.5;

// What the agent says on meeting a world whose words differ: "Here I take
// the refrigerator for the fridge and the trash can for the garbage." ""
// when nothing was renamed.
std::string say_renamings(std::span<const CategoryMatch> matches);

// The yes/no question that proposes an analogy to the teacher: "Does the
// cream go like the half-and-half: in the fridge, and the fridge ends
// closed?"
std::string ask_analogy(const World& world, ObjectId object, const Analogy& analogy);

// Why the agent, alone, did not adopt an analogy (Analogy::confidence below
// kAdoptAnalogyAt), for the report's help list: "it may go like the
// half-and-half, but I am not sure enough (confidence 0.33)".
std::string doubtful_analogy(const Analogy& analogy);

// The agent's view of its knowledge in one world, for one session.
class KnowledgeTransfer {
 public:
  // Renames `knowledge` in place for `world` (match_categories,
  // rename_categories) and keeps its goals, as renamed, as the ones
  // analogies draw on. `lexicon` must outlive this object.
  KnowledgeTransfer(Knowledge& knowledge, const World& world, const language::Lexicon& lexicon);

  const std::vector<CategoryMatch>& matches() const { return matches_; }
  // The goals known when the session began, in this world's words.
  const std::vector<GoalKnowledge>& prior_goals() const { return prior_goals_; }

  // The nearest goal learned before the session for another kind of object
  // (or for the same kind in another context), that means something for
  // `object` in `world`; nullopt if none is within kMaxAnalogyDistance.
  // `key` is the object's: its task, subtask, category and kind of place.
  std::optional<Analogy> analogy(const World& world, const GoalKey& key, ObjectId object) const;

  // How far apart two kinds of object are (Analogy::distance): through the
  // nearest common hypernym of their physical WordNet senses, word by word
  // for compounds of as many words, or by the last word of a compound
  // WordNet lacks (one more step per such side). -1 if more than
  // kMaxAnalogyDistance or unknown to WordNet.
  int kind_distance(const std::string& a, const std::string& b) const;

 private:
  // WordNet's physical noun senses of a phrase and their hypernyms within
  // kMaxAnalogyDistance, by depth; computed once per phrase.
  const std::map<language::SynsetOffset, int>& ancestors(const std::string& phrase) const;
  // Edges between two phrases through their nearest common hypernym; -1 if
  // none within reach.
  int phrase_distance(const std::string& a, const std::string& b) const;

  const language::Lexicon* lexicon_;
  std::vector<CategoryMatch> matches_;
  std::vector<GoalKnowledge> prior_goals_;
  mutable std::map<std::string, std::map<language::SynsetOffset, int>> ancestors_;
};

}  // namespace apprentice
