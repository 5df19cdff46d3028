// The answer's words in read_acts (reply_acts.cc): slips of the world's
// names ("hampr"), words that carry nothing here ("nah", "obviously"),
// and remarks that name nothing here ("it's soaking").
#include <algorithm>

#include "language/generation.h"
#include "language/narration.h"
#include "language/parser.h"
#include "language/reply_acts_parts.h"
#include "language/reply_reading.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language::acts {
bool usable(const Reply& r) { return !std::holds_alternative<Unusable>(r) && !std::holds_alternative<Ambiguous>(r); }

// The place a goal puts the thing asked about.
std::optional<ObjectId> destination(const World& world, const Reply& reply) {
  const auto* given = std::get_if<GoalGiven>(&reply);
  if (given == nullptr) return std::nullopt;
  for (const Literal& l : given->goal.literals)
    if (l.positive && l.fact.arity == 2 && (l.fact.predicate == world.vocabulary.in || l.fact.predicate == world.vocabulary.on))
      return l.fact.args[1];
  return std::nullopt;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t up = row[j];
      std::size_t swap = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({up + 1, row[j - 1] + 1, swap});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// A word of the world's names a typed word is a slip of: "hampr" for
// "hamper", "cupbaord" for "cupboard"; "" when none or several.
std::string slip_of(const World& world, const std::string& word) {
  if (word.size() < 4) return "";
  std::string found;
  for (const ObjectInfo& info : world.universe->objects())
    for (const std::string& part : name_parts(info.category)) {
      if (part == word || part.size() < 4) continue;
      std::size_t most = word.size() >= 7 ? 2 : 1;
      // A letter swapped counts once ("cupbaord").
      std::string swapped = word;
      bool transposed = false;
      for (std::size_t i = 0; i + 1 < swapped.size() && !transposed; ++i) {
        std::swap(swapped[i], swapped[i + 1]);
        transposed = swapped == part;
        std::swap(swapped[i], swapped[i + 1]);
      }
      if (!transposed && edit_distance(word, part) > most) continue;
      if (!found.empty() && found != part) return "";
      found = part;
    }
  return found;
}

std::string quote(const std::string& s) { return "\"" + s + "\""; }

// The first word of a phrase nothing here fits that only describes ("wet",
// "dirty", "empty", "obviously"): an adjective or an "-ly" adverb to
// WordNet, no property of anything here and no part of a name here; "" when
// none.
std::string unmodelled_modifier(const Grounder& grounder, const World& world, const Words& phrase) {
  const Lexicon& lexicon = grounder.lexicon();
  if (!lexicon.has_wordnet()) return "";
  for (const std::string& w : phrase) {
    if (is_determiner(w) || w.size() < 3) continue;
    bool describes = !lexicon.adjective_lemmas(w).empty() || (w.ends_with("ly") && lexicon.knows(w));
    if (!describes) continue;
    bool here = false;
    for (const ObjectInfo& info : world.universe->objects()) {
      std::vector<std::string> parts = name_parts(info.category);
      if (std::find(info.properties.begin(), info.properties.end(), w) != info.properties.end() ||
          std::find(parts.begin(), parts.end(), w) != parts.end())
        here = true;
    }
    if (!here) return w;
  }
  return "";
}

// The answer's words read at the question; a word neither the world nor
// WordNet knows ("nah", "lol", "btw") is skipped when the rest then reads
// whole, and the notes say so. A word the meaning hangs on is not guessed
// at: "on the tabel" is asked back ("I do not know the word 'tabel'").
Reply read_answer(const Grounder& grounder, const World& world, const ReplyContext& context, std::string text,
                  std::vector<std::string>& notes) {
  const Reply first = read_reply(grounder, world, context, text);
  Reply reply = first;
  std::vector<std::string> skipped, modifiers;
  for (int tries = 0; tries < 3 && !usable(reply); ++tries) {
    const auto* u = std::get_if<Unusable>(&reply);
    if (u != nullptr && u->failure && u->failure->kind == FailureKind::kUngroundedObject) {
      // "the wet one", "the empty can", "in the trash obviously": a word
      // that describes, which the world does not model, narrows nothing.
      std::string modifier = unmodelled_modifier(grounder, world, split_words(u->failure->detail));
      Words words = reply_words(text);
      auto at = std::find(words.begin(), words.end(), modifier);
      if (modifier.empty() || at == words.end()) break;
      words.erase(at);
      modifiers.push_back(modifier);
      text = quoted_words(words);
      reply = read_reply(grounder, world, context, text);
      continue;
    }
    if (u == nullptr || !u->failure || u->failure->kind != FailureKind::kUnknownWord) break;
    const std::string word = u->failure->detail;
    Words words = reply_words(text);
    auto at = std::find(words.begin(), words.end(), word);
    if (at == words.end() || (grounder.lexicon().knows(word) && !is_interjection(word) && !is_marker(word))) break;
    if (!slip_of(world, word).empty()) break;  // a slip of a name here: the meaning hangs on it
    // A noun after a determiner ("by the thingamajig", "in the cubby") is
    // what the reply is about: the meaning hangs on it.
    if (at - words.begin() >= 2 && is_determiner(*(at - 1)) &&
        is_one_of(*(at - 2), {"in", "on", "into", "onto", "by", "near", "beside", "behind", "under", "next", "to", "at",
                              "with", "inside", "above", "below", "from"}))
      break;
    words.erase(at);
    skipped.push_back(word);
    text = quoted_words(words);
    reply = read_reply(grounder, world, context, text);
  }
  if (!usable(reply)) {
    // "in the cupbord": asked back with the name it may be a slip of.
    // ("filing cabnet with the papers", "top drawr": the reader may fail
    // elsewhere first; any word no one knows that is a slip of a name here
    // is asked about.)
    const auto* u = std::get_if<Unusable>(&first);
    if (u != nullptr) {
      std::vector<std::string> said = {};
      if (u->failure && u->failure->kind == FailureKind::kUnknownWord) said.push_back(u->failure->detail);
      for (const std::string& w : reply_words(text))
        if (grounder.lexicon().has_wordnet() && !grounder.lexicon().knows(w)) said.push_back(w);
      for (const std::string& word : said)
        if (std::string name = slip_of(world, word); !name.empty()) {
          Unusable asked = *u;
          asked.reason = "I do not know the word " + quote(word) + ". Did you mean " + quote(name) + "?";
          return asked;
        }
    }
    return first;
  }
  for (const std::string& word : skipped) notes.push_back("I took " + quote(word) + " as a filler.");
  for (const std::string& word : modifiers)
    notes.push_back("I took " + quote(word) + " as telling nothing apart: nothing here is told apart by it.");
  return reply;
}

// Segments that name nothing here and hold no instruction ("it's
// soaking", "kids", "I need it tomorrow"): remarks.
bool is_remark(const Grounder& grounder, const World& world, const Words& words) {
  ReferenceContext context{world, grounder.lexicon(), std::nullopt};
  context.partial_names = true;
  for (const std::string& w : words) {
    if (is_determiner(w) || is_object_pronoun(w) || is_copula(w) || is_filler(w)) continue;
    if (is_one_of(w, {"in", "on", "into", "onto", "inside", "put", "go", "goes", "leave", "clear", "empty", "done", "close",
                      "shut", "open", "throw", "recycle", "take", "hang", "store", "pick", "bin", "trash",
                      "finished", "all", "next", "first", "then", "same", "too", "rest", "keep", "more"}))
      return false;
    auto found = candidates_for(NounPhrase{"", {w}}, Role::kItem, context);
    if (std::holds_alternative<CandidateSet>(found)) return false;
    auto place = candidates_for(NounPhrase{"", {w}}, Role::kPlace, context);
    if (std::holds_alternative<CandidateSet>(place)) return false;
  }
  return true;
}

namespace {

// Words that begin a clause told about someone or something: its subject
// ("I", "we", "there", "more stuff", "a student").
bool begins_with_a_subject(const Words& words) {
  if (words.size() < 2) return false;
  return is_one_of(words.front(), {"i", "we", "you", "he", "she", "they", "it", "there", "someone", "somebody",
                                   "everyone", "nobody", "more", "a", "an", "some", "my", "our", "his", "her",
                                   "their", "kids"});
}

// Whether some word of `words` names a thing or a place here (by the
// reference's tiers, partial names included), or says where a thing goes.
bool names_or_places(const Grounder& grounder, const World& world, const Words& words) {
  ReferenceContext context{world, grounder.lexicon(), std::nullopt};
  context.partial_names = true;
  for (const std::string& w : words) {
    if (is_determiner(w) || is_object_pronoun(w) || is_copula(w) || is_filler(w)) continue;
    // ("I can grab it": a modal is no beer can.)
    if (is_one_of(w, {"can", "will", "would", "could", "might", "must", "may", "shall", "need", "needs", "have",
                      "has", "had", "do", "does", "did", "not", "still", "just", "already"}))
      continue;
    if (is_verb_of_going(w) || is_one_of(w, {"stay", "stays", "should"})) return true;
    if (std::holds_alternative<CandidateSet>(candidates_for(NounPhrase{"", {w}}, Role::kItem, context))) return true;
    if (std::holds_alternative<CandidateSet>(candidates_for(NounPhrase{"", {w}}, Role::kPlace, context))) return true;
  }
  return false;
}

bool is_reason_word(std::string_view w) { return is_one_of(w, {"so", "because", "cause", "coz", "since"}); }

}  // namespace

bool says_why(const Grounder& grounder, const World& world, const Words& said) {
  const Words words = without_leading_connectives(without_interjections(said));
  // "the cat gets in there": something not here, and what it does (not
  // "the bottom one", which picks a place by what the world says of it).
  const bool of_something_else =
      words.size() >= 3 && is_one_of(words.front(), {"the", "your"}) && !is_one_of(words.back(), {"one", "ones"}) &&
      std::none_of(words.begin(), words.end(), [&](const std::string& w) { return names_property_here(w, world, grounder.lexicon()); });
  const bool told = begins_with_a_subject(words) || of_something_else || (!words.empty() && is_reason_word(words.front()));
  return told && !names_or_places(grounder, world, words);
}

std::optional<Words> without_reason(const Grounder& grounder, const World& world, const Words& words) {
  for (std::size_t i = 1; i + 1 < words.size(); ++i) {
    if (!is_reason_word(words[i])) continue;
    // ("ok so I want you to ...": "so" after fillers begins the reply.)
    if (without_interjections(Words(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(i))).empty()) continue;
    const Words reason(words.begin() + static_cast<std::ptrdiff_t>(i), words.end());
    if (begins_with_a_subject(Words(reason.begin() + 1, reason.end())) && !names_or_places(grounder, world, reason))
      return Words(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(i));
  }
  return std::nullopt;
}

std::string joined(const std::vector<const Segment*>& parts) {
  std::vector<std::string> texts;
  for (const Segment* s : parts) texts.push_back(s->text);
  return join(texts, ", ");
}

}  // namespace apprentice::language::acts
