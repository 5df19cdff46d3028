// The reader of a person's rule (rule_reader.h). A rule is read sentence by
// sentence; a sentence is a list of clauses "CLASSES [verb] PREPOSITION
// PLACE", each ending where its place's words end (at a comma, "and", or
// the sentence's end). A preposition starts a place only when the words
// after it name a place of this world, or look like a place's name (a
// determiner first, or nothing after them but the clause's end), so that
// "books on cooking on the shelf" keeps "on cooking" in its class.
#include "language/rule_reader.h"

#include <algorithm>
#include <cctype>

#include "language/generation.h"
#include "language/narration.h"
#include "language/reference.h"
#include "language/reply_acts_parts.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {

bool RuleReading::has_class_clause() const {
  return std::any_of(clauses.begin(), clauses.end(), [](const RuleClause& c) { return !c.thing; });
}

namespace {

using Words = std::vector<std::string>;

bool is_punctuation(const std::string& token) { return token == "," || token == ";" || token == ":"; }

// Lower case; ",", ";" and ":" as tokens of their own; a sentence ends at
// ".", "!" or "?" (not inside a word such as "e.g").
std::vector<Words> sentences_of(std::string_view text) {
  std::vector<Words> sentences(1);
  std::string word;
  auto flush = [&] {
    if (!word.empty()) sentences.back().push_back(word);
    word.clear();
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(text[i])));
    const bool ends_sentence = (c == '.' || c == '!' || c == '?') &&
                               (i + 1 == text.size() || std::isspace(static_cast<unsigned char>(text[i + 1])));
    if (ends_sentence || c == '\n') {
      flush();
      if (!sentences.back().empty()) sentences.emplace_back();
    } else if (c == ',' || c == ';' || c == ':') {
      flush();
      sentences.back().push_back(std::string(1, c));
    } else if (std::isspace(static_cast<unsigned char>(c)) || c == '"' || c == '(' || c == ')') {
      flush();
    } else {
      word += c;
    }
  }
  flush();
  if (sentences.back().empty()) sentences.pop_back();
  for (Words& sentence : sentences) expand_shorthand(sentence);  // "pls", "u", as the reply reader reads them
  return sentences;
}

bool starts_with(const Words& words, std::size_t at, std::initializer_list<std::string_view> sequence) {
  if (at + sequence.size() > words.size()) return false;
  std::size_t i = at;
  for (std::string_view w : sequence)
    if (words[i++] != w) return false;
  return true;
}

// Words that open a sentence without being part of a clause: "by the
// way", "also", "remember that", "I want you to", "if there's ever".
std::size_t skip_openers(const Words& words, std::size_t at) {
  static const std::vector<std::vector<std::string_view>> kOpeners = {
      {"by", "the", "way"}, {"btw"}, {"also"}, {"oh"}, {"and"}, {"please"}, {"ok"}, {"okay"}, {"so"}, {"well"},
      {"then"}, {"actually"}, {"remember", "that"}, {"remember"}, {"note", "that"}, {"in", "general"},
      {"generally"}, {"usually"}, {"always"}, {"just"}, {"i", "want", "you", "to"}, {"i'd", "like", "you", "to"},
      {"i", "would", "like", "you", "to"}, {"could", "you"}, {"can", "you"}, {"would", "you"}, {"you", "should"},
      {"you", "can"}, {"go", "ahead", "and"}, {"make", "sure"}, {"i", "like", "to"}, {"i", "prefer", "to"},
      {"we"}, {"i"}, {"first"}, {"finally"}, {"lastly"}, {"next"}, {"from", "now", "on"}, {"in", "the", "future"},
      {"in", "future"}, {"going", "forward"}, {"for", "future", "reference"}, {"as", "a", "general", "rule"},
      {"as", "a", "rule"}, {"rule", "of", "thumb"}, {"in", "general"}, {"on", "second", "thought"},
      {"fair", "enough"}, {"fyi"}, {"for", "your", "information"}, {"if", "there", "is"}, {"if", "there's"},
      {"if", "theres"}, {"if", "there", "are"}, {"whenever", "there", "is"}, {"whenever", "there's"},
      {"whenever", "theres"}, {"ever"}, {"for", "next", "time"}, {"next", "time"}, {"for", "the", "record"},
      {","}, {":"}, {"-"}};
  for (bool more = true; more && at < words.size();) {
    more = false;
    for (const auto& opener : kOpeners) {
      if (opener.size() <= words.size() - at &&
          std::equal(opener.begin(), opener.end(), words.begin() + static_cast<long>(at))) {
        at += opener.size();
        more = true;
        break;
      }
    }
  }
  return at;
}

// The openers, and the verb of an imperative after them ("put", "throw
// away").
std::size_t skip_opening(const Words& words, std::size_t at) {
  at = skip_openers(words, at);
  static const std::vector<std::vector<std::string_view>> kVerbs = {
      {"throw", "away"}, {"throw", "out"}, {"hang", "up"}, {"put", "away"}, {"put"}, {"place"}, {"store"},
      {"keep"}, {"move"}, {"throw"}, {"toss"}, {"leave"}, {"hang"}, {"set"}, {"stack"}, {"file"}, {"arrange"},
      {"organize"}, {"sort"}, {"drop"}, {"stash"}, {"stow"}, {"return"}, {"bring"}, {"take"}, {"lay"}, {"pack"}};
  for (const auto& verb : kVerbs)
    if (verb.size() <= words.size() - at && std::equal(verb.begin(), verb.end(), words.begin() + static_cast<long>(at)))
      return at + verb.size();
  return at;
}

// A preposition that starts a place, and how many words it takes: "in",
// "on", "into", "onto", "inside", "on top of", "at".
std::size_t preposition_at(const Words& words, std::size_t at, Relation& relation) {
  const std::string& w = words[at];
  if (starts_with(words, at, {"on", "top", "of"})) {
    relation = Relation::kOn;
    return 3;
  }
  if (starts_with(words, at, {"inside", "of"})) {
    relation = Relation::kIn;
    return 2;
  }
  if (w == "in" || w == "into" || w == "inside" || w == "within") {
    relation = Relation::kIn;
    return 1;
  }
  if (w == "on" || w == "onto" || w == "at") {
    relation = Relation::kOn;
    return 1;
  }
  // "go to the closet": "to" after a verb of going.
  if (w == "to" && at > 0 && is_one_of(words[at - 1], {"go", "goes", "belong", "belongs", "return", "returned"})) {
    relation = Relation::kIn;
    return 1;
  }
  return 0;
}

bool is_separator(const std::string& token) {
  return is_punctuation(token) || is_one_of(token, {"and", "or", "then", "while", "but", "plus"});
}

// Verbs and adverbs between a class and its place: "shoes always go on",
// "books should be kept in", "toys belong in".
bool is_linking_word(const std::string& word) {
  return is_one_of(word, {"go", "goes", "going", "always", "usually", "typically", "normally", "generally",
                          "should", "must", "can", "could", "will", "would", "be", "are", "is", "get", "gets",
                          "kept", "stored", "placed", "put", "stay", "stays", "live", "lives", "belong", "belongs",
                          "need", "needs", "to", "sit", "sits", "do", "does", "also", "too", "all", "both",
                          "away", "up", "down", "back", "neatly", "only", "please", "hang", "hangs", "sit", "lie",
                          "lies"});
}

std::string base_form(const Lexicon& lexicon, const std::string& word) {
  if (word == "clothes" || word == "ones") return word;  // WordNet's "clothes" is a noun of its own
  std::vector<std::string> forms = lexicon.lemmas(word);
  return forms.empty() ? word : forms.front();
}

struct ClassWords {
  Words words;          // the class phrase's words, determiners and "other" removed
  bool rest = false;
  std::string article;  // "the", "this", ... when one was said
};

// Determiners, "other", "the rest of", "everything else".
ClassWords strip_class(Words words) {
  ClassWords out;
  std::size_t at = 0;
  while (at < words.size()) {
    if (words[at] == "rest" || words[at] == "remaining" || words[at] == "other" || words[at] == "others") {
      out.rest = true;
      ++at;
      if (at < words.size() && words[at] == "of") ++at;
    } else if (is_determiner(words[at])) {
      if (out.article.empty()) out.article = words[at];
      ++at;
    } else {
      break;
    }
  }
  words.erase(words.begin(), words.begin() + static_cast<long>(at));
  // "everything else", "anything else", "all else", "things left".
  while (!words.empty() && (words.back() == "else" || words.back() == "left")) {
    out.rest = true;
    words.pop_back();
  }
  if (words.size() == 1 && is_one_of(words[0], {"everything", "anything", "something"})) words.clear();
  out.words = std::move(words);
  return out;
}

// A word that cannot be (part of) a class's name: a negation, a
// preposition or particle, a pronoun, a filler or a correction's marker
// ("not", "on", "it", "um", "wait"; "hang" and "hold" of "hang on").
bool names_no_class(const std::string& w) {
  return is_negation(w) || is_particle(w) || is_object_pronoun(w) || is_filler(w) || is_determiner(w) ||
         acts::is_marker(w) || acts::is_interjection(w) ||
         is_one_of(w, {"on", "in", "at", "to", "of", "with", "by", "for", "from", "into", "onto", "hang", "hold", "yes"});
}

// The head and modifiers of a class phrase: "heavy items" (item; heavy),
// "things made of metal" (thing; metal), "items that are fragile" (item;
// fragile), "bags of rice" (bag; rice).
RuleClass class_of(const Lexicon& lexicon, const ClassWords& said, const RuleClass* previous) {
  RuleClass rule_class;
  rule_class.rest = said.rest;
  Words words = said.words;
  Words after;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const bool made = words[i] == "made" && i + 1 < words.size() && is_one_of(words[i + 1], {"of", "from", "out"});
    const bool relative = is_one_of(words[i], {"that", "which", "who"}) && i + 1 < words.size() &&
                          is_one_of(words[i + 1], {"are", "is", "look", "looks", "feel", "feels"});
    if (made || relative || words[i] == "of" || words[i] == "with") {
      std::size_t skip = made || relative ? 2 : 1;
      if (made && i + 2 < words.size() && words[i + 2] == "of") ++skip;  // "made out of"
      after.assign(words.begin() + static_cast<long>(std::min(i + skip, words.size())), words.end());
      words.resize(i);
      break;
    }
  }
  if (words.empty() && !after.empty()) std::swap(words, after);
  if (!words.empty() && (words.back() == "ones" || words.back() == "one") && previous != nullptr) {
    words.pop_back();
    rule_class.head = previous->head;
  } else if (!words.empty()) {
    rule_class.head = base_form(lexicon, words.back());
    words.pop_back();
  }
  rule_class.modifiers = words;
  for (const std::string& w : after)
    if (!is_determiner(w)) rule_class.modifiers.push_back(w);
  Words phrase = said.words;
  if (phrase.empty() || phrase.back() == "ones" || phrase.back() == "one") {
    phrase = rule_class.modifiers;
    if (!rule_class.head.empty()) phrase.push_back(rule_class.head);
  }
  rule_class.phrase = join(phrase, " ");
  return rule_class;
}

// The classes of a clause's first part: "books and magazines", "oil,
// vinegar and spices", "pillows and other small items". Examples said
// with a class are classes too: "gadgets like chargers and headphones" is
// gadgets, chargers and headphones.
std::vector<Words> split_classes(const Words& words) {
  std::vector<Words> parts(1);
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& w = words[i];
    const bool such_as = w == "such" && i + 1 < words.size() && words[i + 1] == "as";
    if (such_as) ++i;
    if (w == "and" || w == "or" || w == "," || w == "&" || w == "plus" || such_as ||
        ((w == "like" || w == "including") && !parts.back().empty())) {
      if (!parts.back().empty()) parts.emplace_back();
    } else {
      parts.back().push_back(words[i]);
    }
  }
  if (parts.back().empty()) parts.pop_back();
  return parts;
}

class SentenceReader {
 public:
  SentenceReader(const World& world, const Lexicon& lexicon, std::optional<ObjectId> object_of_interest,
                 std::optional<ObjectId> there,
                 RuleReading& reading)
      : world_(world), lexicon_(lexicon), object_(object_of_interest), reading_(reading), there_(there) {}

  void read(const Words& words) {
    std::size_t at = skip_opening(words, 0);
    while (at < words.size()) {
      while (at < words.size() && is_separator(words[at])) ++at;
      if (at >= words.size()) break;
      at = read_clause(words, skip_opening(words, at));
    }
  }

 private:
  // One clause from `start`; returns where the next may begin.
  std::size_t read_clause(const Words& words, std::size_t start) {
    for (std::size_t p = start; p < words.size(); ++p) {
      Relation relation = Relation::kIn;
      std::size_t length = preposition_at(words, p, relation);
      // "hats and caps go there too": "there" after the verb is the place
      // named last, with no preposition.
      const bool there = length == 0 && there_ && words[p] == "there" && p > start && is_linking_word(words[p - 1]);
      if (there) relation = world_.universe->info(*there_).kind == ObjectKind::kSurface ? Relation::kOn : Relation::kIn;
      if (length == 0 && !there) continue;
      std::size_t end = p + length;
      while (end < words.size() && !is_separator(words[end]) && words[end] != "not") ++end;
      // "in the wastebasket not the filing cabinet": where it does not go
      // is no place of the clause, nor a clause of its own.
      std::size_t next = end;
      if (next < words.size() && words[next] == "not")
        while (next < words.size() && !is_separator(words[next])) ++next;
      const Words place_words(words.begin() + static_cast<long>(p + length), words.begin() + static_cast<long>(end));
      if (place_words.empty()) continue;
      std::vector<ObjectId> places = ground_place(place_words);
      // Words that name no place here are still a place when a determiner
      // says so ("in the attic") or no other preposition follows.
      if (places.empty() && !is_determiner(place_words.front()) && preposition_follows(words, end)) continue;
      Words class_part = class_words(words, start, p);
      const std::string text = join(Words(words.begin() + static_cast<long>(start), words.begin() + static_cast<long>(end)), " ");
      // "newspapers dont go in the magazine rack": where things do not go
      // is no clause; "they", in the clause after, are those things.
      if (without_negation(class_part)) {
        negated_class_ = class_part;
        return next;
      }
      if (class_part.size() == 1 && is_one_of(class_part[0], {"they", "those", "these", "them"}) && !negated_class_.empty())
        class_part = negated_class_;
      if (class_part.empty()) {
        reading_.not_understood.push_back(text);
      } else if (places.empty()) {
        reading_.not_understood.push_back(text);
      } else {
        add_clause(class_part, relation, std::move(places), text);
      }
      return next;
    }
    // No place: what is left is not a clause.
    const Words rest(words.begin() + static_cast<long>(start), words.end());
    Words meaningful;
    // ("lol no. books go on the shelf": a yes or no, or a filler, said
    // with a rule is no part of it left unread.)
    for (const std::string& w : rest)
      if (!is_separator(w) && !is_linking_word(w) && !is_filler(w) &&
          !is_one_of(w, {"yes", "no", "yeah", "yep", "yup", "nope", "nah", "lol", "sure", "right", "oh"}))
        meaningful.push_back(w);
    if (!meaningful.empty()) reading_.not_understood.push_back(join(rest, " "));
    return words.size();
  }

  // Whether the class part ends with a negation among its linking words
  // ("newspapers do not", "bananas never"); if so, `part` without them.
  static bool without_negation(Words& part) {
    std::size_t end = part.size();
    bool negated = false;
    while (end > 0 && (is_linking_word(part[end - 1]) || is_negation(part[end - 1]))) {
      negated = negated || is_negation(part[end - 1]);
      --end;
    }
    if (negated) part.resize(end);
    return negated;
  }

  static bool preposition_follows(const Words& words, std::size_t from) {
    for (std::size_t i = from; i < words.size(); ++i) {
      Relation relation = Relation::kIn;
      if (preposition_at(words, i, relation) > 0) return true;
    }
    return false;
  }

  // The class part of a clause: its words before the preposition, without
  // the verbs and adverbs that link it to its place.
  static Words class_words(const Words& words, std::size_t start, std::size_t preposition) {
    Words part(words.begin() + static_cast<long>(start), words.begin() + static_cast<long>(preposition));
    while (!part.empty() && (is_linking_word(part.back()) || is_punctuation(part.back()))) part.pop_back();
    while (!part.empty() && (is_one_of(part.front(), {"and", "then", "also", "or"}) || is_punctuation(part.front())))
      part.erase(part.begin());
    return part;
  }

  std::vector<ObjectId> ground_place(const Words& words) {
    // "hats go there too": the place named last.
    if (there_ && (words == Words{"there"} || words == Words{"there", "too"} || words == Words{"over", "there"}))
      return {*there_};
    std::vector<ObjectId> places = candidates(words);
    // "light ones on the right": the place of the clause before, by its
    // properties alone (not "put the lid back on after").
    const bool properties_alone = std::all_of(words.begin(), words.end(), [&](const std::string& w) {
      return is_determiner(w) || is_one_of(w, {"one", "ones", "side", "please"}) ||
             names_property_here(w, world_, lexicon_);
    });
    if (places.empty() && last_place_ && !words.empty() && properties_alone) {
      Words with_category = words;
      for (const std::string& w : split_words(spoken_category(world_, *last_place_))) with_category.push_back(w);
      places = candidates(with_category);
    }
    if (!places.empty()) last_place_ = places.front();
    return places;
  }

  std::vector<ObjectId> candidates(const Words& words) const {
    NounPhrase phrase;
    std::size_t at = 0;
    if (at < words.size() && is_determiner(words[at])) phrase.article = words[at++] == "the" ? "the" : "";
    phrase.words.assign(words.begin() + static_cast<long>(at), words.end());
    while (!phrase.words.empty() && phrase.words.back() == "please") phrase.words.pop_back();  // "... on the left pls"
    if (phrase.words.empty()) return {};
    ReferenceContext context{world_, lexicon_, std::nullopt, std::nullopt, true};
    auto found = candidates_for(phrase, Role::kPlace, context);
    const auto* set = std::get_if<CandidateSet>(&found);
    if (set == nullptr) return {};
    std::vector<ObjectId> places;
    for (ObjectId o : set->objects)
      if (world_.universe->info(o).kind != ObjectKind::kItem) places.push_back(o);
    return places;
  }

  void add_clause(const Words& said_part, Relation relation, std::vector<ObjectId> places, const std::string& text) {
    RuleClause clause;
    clause.text = text;
    clause.relation = relation;
    clause.places = std::move(places);
    std::optional<Words> class_part = class_phrase(said_part);
    if (!class_part) {
      reading_.not_understood.push_back(text);
      return;
    }
    // "slippers by the door": where the things are now is no part of their
    // class; it is said back as not followed.
    for (std::size_t i = 1; i + 1 < class_part->size(); ++i) {
      const Words& w = *class_part;
      if (!is_one_of(w[i], {"by", "near", "beside", "behind", "under", "underneath", "outside", "around", "from"}) ||
          w[i - 1] == "made" || !is_determiner(w[i + 1]))
        continue;
      reading_.not_understood.push_back(join(Words(w.begin() + static_cast<long>(i), w.end()), " "));
      class_part->resize(i);
      break;
    }
    const std::vector<Words> parts = split_classes(*class_part);
    if (parts.size() == 1) clause.thing = particular_thing(parts.front());
    for (const Words& part : parts) {
      ClassWords said = strip_class(part);
      if (said.words.empty() && !said.rest) continue;  // "the" alone
      // "hang on, ...", "not on the shelf": words that name no class.
      if (!said.rest && std::all_of(said.words.begin(), said.words.end(), names_no_class)) continue;
      const RuleClass* previous = clauses_classes_.empty() ? nullptr : &clauses_classes_.back();
      clause.classes.push_back(class_of(lexicon_, said, previous));
      clauses_classes_.push_back(clause.classes.back());
    }
    if (clause.classes.empty() && !clause.thing) {
      reading_.not_understood.push_back(text);
      return;
    }
    if (clause.classes.empty()) clause.classes.push_back(RuleClass{join(*class_part, " "), "", {}, false});
    reading_.clauses.push_back(std::move(clause));
  }

  // The words that name the clause's things, without what people say
  // before them ("hmm the mug", "noo the folder", "i already said the hoe",
  // "now fix the candy wrapper": the mug, the folder, the hoe, the candy
  // wrapper); nullopt when they hold a pronoun after a verb ("coil it"),
  // which names no class.
  static std::optional<Words> class_phrase(Words words) {
    // "close the lid after, the cat gets in there": a door closed or opened
    // before a comma names nothing that goes anywhere.
    while (!words.empty() && is_one_of(words.front(), {"close", "shut", "open", "lock", "latch"})) {
      const auto comma = std::find(words.begin(), words.end(), ",");
      if (comma == words.end()) return std::nullopt;
      words.erase(words.begin(), comma + 1);
    }
    // "fix the candy wrapper, it goes ...": "it" after a comma is what was
    // named before it.
    for (std::size_t i = 0; i + 1 < words.size(); ++i)
      if (words[i] == "," && is_one_of(words[i + 1], {"it", "they", "them", "that", "those"})) {
        words.resize(i);
        break;
      }
    auto drop_front = [&](std::size_t n) { words.erase(words.begin(), words.begin() + static_cast<long>(n)); };
    // "just so you know for next time, all the books ...": a part before a
    // comma in which the speaker or the listener is named frames the
    // sentence; it names no things.
    for (auto comma = std::find(words.begin(), words.end(), ","); comma != words.end();
         comma = std::find(words.begin(), words.end(), ",")) {
      if (std::none_of(words.begin(), comma, [](const std::string& w) {
            return is_one_of(w, {"you", "i", "we", "me", "us", "ya", "im", "i'm", "youre", "you're"});
          }))
        break;
      words.erase(words.begin(), comma + 1);
    }
    for (bool more = true; more && !words.empty();) {
      more = false;
      // "i already said", "i meant", "i think": what the teacher says of
      // their words, within the first few.
      for (std::size_t i = 0; i < std::min<std::size_t>(words.size(), 3); ++i)
        if (is_one_of(words[i], {"said", "mean", "meant", "think", "guess"}) && i + 1 < words.size()) {
          drop_front(i + 1);
          more = true;
          break;
        }
      // "nah not trash, cables and chargers go in the top drawer": what is
      // said not to be meant, up to a comma, is no class.
      if (!words.empty() && is_negation(words.front())) {
        const auto comma = std::find(words.begin(), words.end(), ",");
        if (comma != words.end() && comma + 1 != words.end()) {
          words.erase(words.begin(), comma + 1);
          more = true;
          continue;
        }
      }
      if (!words.empty() && words.size() > 1 && !is_determiner(words.front()) && names_no_class(words.front())) {
        drop_front(1);
        more = true;
      }
      // "(no i mean) if theres ever ribbon": an opener after them.
      if (const std::size_t at = skip_openers(words, 0); at > 0 && at < words.size()) {
        drop_front(at);
        more = true;
      }
    }
    // "fix the candy wrapper": a verb before a determiner.
    if (words.size() > 2 && !is_determiner(words[0]) && !is_one_of(words[0], {"all", "both", "half", "rest"}) &&
        is_one_of(words[1], {"the", "my", "this", "that", "these", "those", "your", "our"}))
      drop_front(1);
    const bool pronoun_after = std::any_of(words.begin() + (words.empty() ? 0 : 1), words.end(),
                                           [](const std::string& w) { return is_one_of(w, {"it", "them"}); });
    if (words.empty() || pronoun_after) return std::nullopt;
    return words;
  }

  // "it", "this", "the sweater" (one thing here of that name): a particular
  // thing rather than a class.
  std::optional<ObjectId> particular_thing(const Words& words) const {
    if (words.size() == 1 && is_one_of(words[0], {"it", "this", "that"})) return object_;
    if (words.size() == 2 && words[0] == "the" && words[1] == "object") return object_;  // the script's words for it
    if (words.empty() || !is_one_of(words[0], {"the", "this", "that"}) || words.size() < 2) return std::nullopt;
    NounPhrase phrase{"the", Words(words.begin() + 1, words.end())};
    ReferenceContext context{world_, lexicon_, object_, std::nullopt, false};
    auto found = candidates_for(phrase, Role::kItem, context);
    const auto* set = std::get_if<CandidateSet>(&found);
    if (set == nullptr || set->objects.size() != 1 || set->method != ReferenceMethod::kCategory) return std::nullopt;
    return set->objects.front();
  }

  const World& world_;
  const Lexicon& lexicon_;
  std::optional<ObjectId> object_;
  RuleReading& reading_;
  std::optional<ObjectId> last_place_;
  std::optional<ObjectId> there_;  // what "there" names
  std::vector<RuleClass> clauses_classes_;  // every class read so far: what "ones" refers to
  Words negated_class_;  // the class of the last clause said not to go somewhere: what "they" is after it
};

}  // namespace

std::optional<RuleReading> read_rule(const World& world, const Lexicon& lexicon, std::string_view text,
                                     std::optional<ObjectId> object_of_interest, std::optional<ObjectId> there) {
  RuleReading reading;
  for (const Words& sentence : sentences_of(text)) {
    // "If the object is a dress then the goal is that the object is in the
    // basket": the script's goal for one thing, which the grammar reads.
    bool goal_statement = false;
    for (std::size_t i = 0; i + 2 < sentence.size(); ++i)
      goal_statement = goal_statement || starts_with(sentence, i, {"the", "goal", "is"});
    if (goal_statement) continue;
    // "just for tonight stick the shaker in the locker": what holds this
    // time only is no rule (the reply reader reads it as a goal for now).
    bool this_time = false;
    for (std::size_t i = 0; i < sentence.size(); ++i)
      this_time = this_time || is_one_of(sentence[i], {"tonight", "today"}) ||
                  starts_with(sentence, i, {"for", "now"}) || starts_with(sentence, i, {"this", "time"}) ||
                  starts_with(sentence, i, {"this", "once"}) || starts_with(sentence, i, {"till", "tomorrow"}) ||
                  starts_with(sentence, i, {"until", "tomorrow"});
    if (this_time) continue;
    SentenceReader reader(world, lexicon, object_of_interest, there, reading);
    reader.read(sentence);
  }
  if (reading.clauses.empty()) return std::nullopt;
  return reading;
}

std::string say_rule_class(const RuleClass& rule_class) {
  if (rule_class.phrase.empty()) return rule_class.rest ? "everything else" : "everything";
  return (rule_class.rest ? "other " : "") + rule_class.phrase;
}

namespace {

// The things a clause is about, as said ("toys", "books and magazines", "the
// sweater"), and whether they take a verb in the singular ("food goes").
std::pair<std::string, bool> clause_subject(const World& world, const RuleClause& clause) {
  std::vector<std::string> classes;
  if (clause.thing) classes.push_back(spoken_name(world, *clause.thing));
  else
    for (const RuleClass& c : clause.classes) classes.push_back(say_rule_class(c));
  const RuleClass& first = clause.classes.front();
  const std::string last = first.phrase.empty() ? "" : split_words(first.phrase).back();
  const bool singular = first.phrase.empty() || (last == first.head && !last.ends_with("s"));
  const bool one = clause.thing || (classes.size() == 1 && singular);
  return {say_alternatives(classes, "and"), one};
}

bool on_a_surface(const World& world, ObjectId place) {
  return world.universe->info(place).kind == ObjectKind::kSurface;
}

}  // namespace

std::string read_back_rule(const World& world, const RuleReading& reading) {
  std::vector<std::string> parts;
  for (const RuleClause& clause : reading.clauses) {
    std::vector<std::string> places;
    for (ObjectId place : clause.places) places.push_back(noun_for(world, place));
    const auto [subject, one] = clause_subject(world, clause);
    parts.push_back(subject + (one ? " goes " : " go ") + (on_a_surface(world, clause.places.front()) ? "on " : "in ") +
                    say_alternatives(places, "or"));
  }
  if (parts.empty()) return "";
  std::string out = "So " + (parts.size() == 1 ? parts.front() : say_alternatives(parts, "and"));
  return out + ".";
}

std::optional<std::string> ask_which_place_of(const World& world, const RuleClause& clause) {
  if (clause.places.size() < 2) return std::nullopt;
  const std::string& category = world.universe->info(clause.places.front()).category;
  for (ObjectId place : clause.places)
    if (world.universe->info(place).category != category) return std::nullopt;
  std::vector<std::string> places;
  for (ObjectId place : clause.places) places.push_back(distinct_noun_for(world, place, clause.places));
  const auto [subject, one] = clause_subject(world, clause);
  return "Which " + spoken_category(world, clause.places.front()) + (one ? " does " : " do ") + subject + " go " +
         (on_a_surface(world, clause.places.front()) ? "on" : "in") + ": " + say_alternatives(places, "or") + "?";
}

}  // namespace apprentice::language
