#include "language/reply_clauses.h"

#include <algorithm>
#include <array>
#include <utility>

#include "language/known_verbs.h"
#include "language/reference.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {
namespace {


struct HouseholdVerb {
  std::string_view base;
  VerbClass kind;
};

// The verbs people use for moving things around a house, by what they do.
constexpr std::array<HouseholdVerb, 73> kHouseholdVerbs{{
    {"put", VerbClass::kPlace},      {"place", VerbClass::kPlace},    {"set", VerbClass::kPlace},
    {"store", VerbClass::kPlace},    {"keep", VerbClass::kPlace},     {"leave", VerbClass::kPlace},
    {"move", VerbClass::kPlace},     {"bring", VerbClass::kPlace},    {"carry", VerbClass::kPlace},
    {"stick", VerbClass::kPlace},    {"shove", VerbClass::kPlace},    {"pop", VerbClass::kPlace},
    {"stash", VerbClass::kPlace},    {"return", VerbClass::kPlace},   {"load", VerbClass::kPlace},
    {"hang", VerbClass::kPlace},     {"slide", VerbClass::kPlace},    {"insert", VerbClass::kPlace},
    {"file", VerbClass::kPlace},     {"transfer", VerbClass::kPlace}, {"stow", VerbClass::kPlace},
    {"tuck", VerbClass::kPlace},     {"lay", VerbClass::kPlace},      {"drop", VerbClass::kPlace},
    {"deposit", VerbClass::kPlace},  {"refrigerate", VerbClass::kPlace}, {"shelve", VerbClass::kPlace},
    {"go", VerbClass::kBe},          {"belong", VerbClass::kBe},      {"live", VerbClass::kBe},
    {"stay", VerbClass::kBe},        {"sit", VerbClass::kBe},         {"end", VerbClass::kBe},
    {"fit", VerbClass::kBe},         {"lie", VerbClass::kBe},         {"rest", VerbClass::kBe},
    {"pick", VerbClass::kPick},      {"take", VerbClass::kPick},      {"grab", VerbClass::kPick},
    {"get", VerbClass::kPick},       {"lift", VerbClass::kPick},      {"fetch", VerbClass::kPick},
    {"remove", VerbClass::kPick},    {"collect", VerbClass::kPick},   {"hold", VerbClass::kPick},
    {"retrieve", VerbClass::kPick},  {"open", VerbClass::kOpen},      {"close", VerbClass::kClose},
    {"shut", VerbClass::kClose},     {"lock", VerbClass::kClose},     {"throw", VerbClass::kDiscard},  {"toss", VerbClass::kDiscard},
    {"chuck", VerbClass::kDiscard},  {"trash", VerbClass::kDiscard},  {"bin", VerbClass::kDiscard},
    {"discard", VerbClass::kDiscard}, {"dump", VerbClass::kDiscard},  {"junk", VerbClass::kDiscard},
    {"ditch", VerbClass::kDiscard},  {"rid", VerbClass::kDiscard},    {"recycle", VerbClass::kRecycle},
    {"compost", VerbClass::kDiscard}, {"empty", VerbClass::kNone},    {"clear", VerbClass::kNone},
    {"stack", VerbClass::kPlace},    {"pack", VerbClass::kPlace},     {"squeeze", VerbClass::kPlace},
    {"slot", VerbClass::kPlace},     {"stuff", VerbClass::kPlace},    {"cram", VerbClass::kPlace},
    {"wedge", VerbClass::kPlace},    {"arrange", VerbClass::kPlace},  {"sort", VerbClass::kPlace},
}};

const HouseholdVerb* find_household(std::string_view base) {
  for (const HouseholdVerb& v : kHouseholdVerbs)
    if (v.base == base) return &v;
  return nullptr;
}


std::optional<Preposition> preposition_of(std::string_view w) {
  if (is_one_of(w, {"in", "into", "inside", "within"})) return Preposition::kIn;
  if (is_one_of(w, {"on", "onto", "atop"})) return Preposition::kOn;
  if (is_one_of(w, {"to", "toward", "towards"})) return Preposition::kTo;
  if (is_one_of(w, {"from", "off", "out"})) return Preposition::kFrom;
  if (is_one_of(w, {"at", "by", "near", "under", "beside", "behind", "below", "above", "of", "for", "next", "through",
                    "across", "around", "about", "as"}))
    return Preposition::kOther;
  return std::nullopt;
}

// Multi-word prepositions, longest first: how many words and what they mean.
std::optional<std::pair<std::size_t, Preposition>> preposition_at(const std::vector<std::string>& w, std::size_t i) {
  auto at = [&](std::size_t k) -> std::string_view { return i + k < w.size() ? std::string_view(w[i + k]) : ""; };
  if (at(0) == "on" && at(1) == "top" && at(2) == "of") return std::pair{std::size_t{3}, Preposition::kOn};
  if ((at(0) == "out" || at(0) == "off") && at(1) == "of") return std::pair{std::size_t{2}, Preposition::kFrom};
  if (at(0) == "in" && at(1) == "to") return std::pair{std::size_t{2}, Preposition::kIn};
  if (at(0) == "inside" && at(1) == "of") return std::pair{std::size_t{2}, Preposition::kIn};
  if (at(0) == "over" && at(1) == "to") return std::pair{std::size_t{2}, Preposition::kTo};
  if (at(0) == "next" && at(1) == "to") return std::pair{std::size_t{2}, Preposition::kOther};
  if (at(0) == "in" && at(1) == "front" && at(2) == "of") return std::pair{std::size_t{3}, Preposition::kOther};
  if (auto p = preposition_of(at(0))) return std::pair{std::size_t{1}, *p};
  return std::nullopt;
}

// Frames people wrap a request in, removed wherever they occur.
const std::vector<std::vector<std::string_view>>& frames() {
  static const std::vector<std::vector<std::string_view>> kFrames{
    {"make", "sure", "that"}, {"make", "sure", "to"}, {"make", "sure"}, {"be", "sure", "to"},
    {"do", "not", "forget", "to"}, {"never", "forget", "to"}, {"remember", "to"}, {"go", "ahead", "and"},
    {"can", "you"}, {"could", "you"}, {"would", "you"}, {"will", "you"}, {"can", "we"},
    {"i", "would", "like", "you", "to"}, {"i", "want", "you", "to"}, {"i", "need", "you", "to"},
    {"you", "need", "to"}, {"you", "have", "to"}, {"you", "should"}, {"you", "must"}, {"you", "can"},
    {"you", "could"}, {"you", "will"}, {"we", "need", "to"}, {"we", "should"}, {"let", "us"},
    {"i", "would"}, {"i", "think"}, {"i", "guess"}, {"i", "believe"}, {"thank", "you"}, {"for", "now"},
    {"for", "me"}, {"if", "you", "can"}, {"if", "you", "would"}, {"after", "that"}, {"and", "then"},
    {"when", "you", "are", "done"}, {"once", "you", "are", "done"}, {"when", "done"},
    {"start", "by"}, {"begin", "by"}, {"first", "of", "all"}, {"as", "well"}, {"like", "i", "said"},
    {"as", "i", "said"}, {"i", "said"}, {"i", "told", "you"}, {"i", "mean"}, {"i", "meant"},
    {"the", "goal", "is", "that"}, {"the", "goal", "is", "for"}, {"the", "goal", "is", "to"},
    {"the", "goal", "is"}, {"your", "goal", "is", "to"},
  };
  return kFrames;
}

// "the stuff that is on the counter": "that is" / "which are" after a noun.
bool relative_marker(const std::vector<std::string>& w, std::size_t i) {
  return i + 1 < w.size() && is_one_of(w[i], {"that", "which", "who"}) && is_copula(w[i + 1]);
}

class ClauseReader {
 public:
  ClauseReader(const std::vector<std::string>& words, const ReplyVocabulary& vocabulary)
      : w_(words), v_(vocabulary) {}

  Clause read() {
    c_.words = w_;
    while (i_ < w_.size()) step();
    return std::move(c_);
  }

 private:
  std::string_view at(std::size_t k) const { return i_ + k < w_.size() ? std::string_view(w_[i_ + k]) : ""; }

  bool starts_noun(std::size_t k) const {
    std::string_view x = at(k);
    if (x.empty()) return false;
    return is_determiner(x) || is_object_pronoun(x) || v_.is_name_word(x) || x == "there" || x == "here" ||
           is_generic_noun(x);
  }

  bool is_verb_here(std::string_view word, std::string& base) const {
    // A name here is a noun, unless it starts the clause as a verb's base
    // form before its object ("bin it", "store the things ..."), not
    // "recycling bin".
    if (v_.is_name_word(word) && !(i_ == 0 && v_.household_verb(word) == word && starts_noun(1))) return false;
    // "trash can", "recycle bin": the first word of a compound noun.
    if (i_ + 1 < w_.size() && v_.compound_noun(word, at(1))) return false;
    // "lower drawer", "upper cabinet": a word for a property of a look-alike
    // before a name is the name's, unless it is a household verb.
    if (i_ + 1 < w_.size() && v_.is_property(word) && v_.is_name_word(at(1)) && v_.household_verb(word).empty())
      return false;
    base = v_.household_verb(word);
    if (!base.empty()) return true;
    base = v_.any_verb(word);
    if (base.empty()) return false;
    // An imperative ("tidy the kitchen") or a verb after its subject
    // ("ketchup lives in the fridge") that WordNet does not also have as a noun.
    if (i_ == 0) return w_.size() == 1 || starts_noun(1) || is_particle(at(1)) || preposition_of(at(1));
    return c_.subject && !v_.lexicon().has_noun(word);
  }

  void step() {
    std::string_view t = at(0);
    if (is_negation(t)) {
      c_.negated = true;
      ++i_;
      return;
    }
    if (is_one_of(t, {"do", "does", "did"}) && at(1) == "not") {
      c_.negated = true;
      i_ += 2;
      return;
    }
    if (t == "where" && (c_.copula || c_.subject)) {
      c_.where = true;
      ++i_;
      return;
    }
    if (is_copula(t)) {
      c_.copula = true;
      ++i_;
      return;
    }
    // "do the counter" is a verb; "do not", "does it" are auxiliaries.
    if (is_one_of(t, {"do", "does", "did"}) && c_.verb.empty() && (is_determiner(at(1)) || v_.is_name_word(at(1)))) {
      c_.verb = "do";
      c_.verb_word = std::string(t);
      ++i_;
      return;
    }
    // "to the fridge", "to recycling": a place; "needs to go": an infinitive.
    if (t == "to" && (is_determiner(at(1)) || v_.is_name_word(at(1)) || is_object_pronoun(at(1)))) {
      ++i_;
      PrepPhrase phrase{Preposition::kTo, chunk(), "to"};
      c_.phrases.push_back(std::move(phrase));
      return;
    }
    // "get the milk" is a verb; "gets closed", "get put away" are auxiliaries.
    if (is_one_of(t, {"get", "gets", "got"}) && c_.verb.empty() && starts_noun(1)) {
      c_.verb = "get";
      c_.verb_word = std::string(t);
      ++i_;
      return;
    }
    if (is_auxiliary(t)) {
      ++i_;
      return;
    }
    // "the door of the fridge", "the top shelf of the fridge": one phrase.
    if (t == "of" && (c_.object || c_.subject || !c_.phrases.empty())) {
      ++i_;
      Chunk noun = chunk();
      Chunk& previous = !c_.phrases.empty() ? c_.phrases.back().noun : c_.object ? *c_.object : *c_.subject;
      for (std::string& word : noun.words) previous.words.push_back(std::move(word));
      return;
    }
    // "throw it out", "put the book away": a particle, unless a place follows.
    // Right after the verb, "out" before its object is one ("tip out the
    // bucket", "clean out the van"), not "out of".
    const bool out_before_object = t == "out" && !c_.object && at(1) != "of";
    if (is_particle(t) && !c_.verb.empty() && c_.particle.empty() &&
        (out_before_object || !(preposition_of(t) && (starts_noun(1) || at(1) == "of")))) {
      c_.particle = std::string(t);
      ++i_;
      return;
    }
    if (auto p = preposition_at(w_, i_)) {
      PrepPhrase phrase{p->second, {}, std::string(t)};
      i_ += p->first;
      // "for the mug on the counter": a place after a noun inside such a
      // phrase says where that noun is.
      inside_other_ = p->second == Preposition::kOther;
      if (i_ < w_.size() && (starts_noun(0) || continues_noun(0, true))) phrase.noun = chunk();
      inside_other_ = false;
      c_.phrases.push_back(std::move(phrase));
      return;
    }
    if (is_state_word(t)) {
      std::string base;
      if ((t == "open" || t == "shut") && c_.verb.empty() && !c_.copula && starts_noun(1)) {
        c_.verb = t == "open" ? "open" : "shut";
      } else {
        c_.closed = !(t == "open" || t == "opened");
      }
      ++i_;
      return;
    }
    if (relative_marker(w_, i_)) {
      i_ += 2;
      return;
    }
    std::string base;
    // "keep clearing the table", "start unloading": the gerund is the verb.
    if (is_one_of(c_.verb, {"keep", "start", "begin", "continue", "stop", "finish", "try"}) && !c_.object &&
        t.ends_with("ing") && !v_.any_verb(t).empty() && !v_.is_name_word(t)) {
      c_.verb = v_.any_verb(t);
      c_.verb_word = std::string(t);
      ++i_;
      return;
    }
    if (c_.verb.empty() && is_verb_here(t, base)) {
      c_.verb = base;
      c_.verb_word = std::string(t);
      ++i_;
      // "get rid of": the verb is "rid".
      if (c_.verb == "get" && at(0) == "rid") {
        c_.verb = "rid";
        i_ += at(1) == "of" ? 2 : 1;
      }
      return;
    }
    std::size_t before = i_;
    Chunk noun = chunk();
    if (i_ == before) {
      ++i_;  // a word that starts nothing: skip it
      return;
    }
    if (noun.empty()) return;
    if (c_.verb.empty() && !c_.copula && !c_.subject) c_.subject = std::move(noun);
    else if (!c_.object) c_.object = std::move(noun);
    else c_.others.push_back(std::move(noun));
  }

  // Whether a verb, a copula or an auxiliary comes later in the clause. A
  // verb's form after a determiner is a noun ("in the trash").
  bool verb_ahead() const {
    for (std::size_t k = i_; k < w_.size(); ++k)
      if (is_copula(w_[k]) || (is_auxiliary(w_[k]) && w_[k] != "to") ||
          (!v_.household_verb(w_[k]).empty() && !v_.is_name_word(w_[k]) && !(k > 0 && is_determiner(w_[k - 1]))))
        return true;
    return false;
  }

  // A noun phrase from i_: determiners, then words up to a word that
  // structures the clause. Names here never end a phrase ("the soda can").
  Chunk chunk() {
    Chunk out;
    while (i_ < w_.size()) {
      std::string_view t = at(0);
      if (t == "of" && (out.determiner == "all" || out.determiner == "each" || out.determiner == "both")) {
        ++i_;
        continue;
      }
      if (!is_determiner(t)) break;
      // "this" / "that" alone are pronouns; before a noun, determiners.
      if ((t == "this" || t == "that" || t == "these" || t == "those") && !noun_follows(1)) {
        out.pronoun = true;
        ++i_;
        if (at(0) == "one" || at(0) == "ones") ++i_;
        return located(std::move(out));
      }
      out.determiner = std::string(t);
      ++i_;
    }
    std::string_view first = at(0);
    if (out.determiner.empty() && (first == "it" || first == "them" || first == "they" || first == "itself")) {
      out.pronoun = true;
      ++i_;
      return located(std::move(out));
    }
    if (out.determiner.empty() && (first == "there" || first == "here")) {
      out.place_pronoun = true;
      ++i_;
      return out;
    }
    for (bool first = true; i_ < w_.size() && continues_noun(0, first); first = false) {
      if (at(0) != "one" && at(0) != "ones") out.words.emplace_back(at(0));
      ++i_;
    }
    // "the shelf on the right", "the cabinet up top", "the drawer at the
    // bottom": a look-alike's property said after its name, last in the
    // phrase ("on the top shelf" names another place).
    if (!out.words.empty()) {
      if (property_said_after_name(0)) {
        out.words.insert(out.words.begin(), std::string(at(2)));
        i_ += 3;
      } else if (at(0) == "up" && v_.is_property(at(1)) && ends_phrase(2)) {
        out.words.insert(out.words.begin(), std::string(at(1)));
        i_ += 2;
      }
    }
    // "this one", "that one": the thing asked about.
    if (out.words.empty() && is_one_of(out.determiner, {"this", "that", "these", "those"})) out.pronoun = true;
    return located(std::move(out));
  }

  // Whether the word at k ends a noun phrase (or there is none).
  bool ends_phrase(std::size_t k) const { return at(k).empty() || is_one_of(at(k), {",", "and", "then", "please"}); }

  // Whether the words at k say a look-alike's property after its name, last
  // in the phrase: "on the left" in "the bin on the left" (not a place of
  // its own).
  bool property_said_after_name(std::size_t k) const {
    return is_one_of(at(k), {"on", "at", "to"}) && at(k + 1) == "the" && v_.is_property(at(k + 2)) && ends_phrase(k + 3);
  }

  // Whether the word at k is a noun ("that one", "this mug"), not a verb
  // ("that goes in the fridge").
  bool noun_follows(std::size_t k) const {
    std::string_view t = at(k);
    if (t.empty()) return false;
    if (v_.is_name_word(t) || is_generic_noun(t)) return true;
    return continues_noun(k, false) && v_.any_verb(t).empty();
  }

  // Whether the word at k ends the phrase and names a kind of container.
  bool ends_with_a_container_word(std::size_t k) const {
    const bool ends = at(k + 1).empty() || is_one_of(at(k + 1), {",", "and", "please", "then", "too"});
    const std::size_t here = i_ + k;
    if (!ends || here == 0 || here > w_.size() || w_[here - 1] == "'s") return false;
    const std::vector<std::string> word{std::string(at(k))};
    return !v_.lexicon().kinds_under("container", word).empty();
  }

  // Whether the word at k belongs to a noun phrase being read; the first
  // word of a phrase may be a verb's form ("the trash", "the recycling").
  bool continues_noun(std::size_t k, bool first) const {
    std::string_view t = at(k);
    if (t.empty() || t == ",") return false;
    // "the bottle can be recycled": a name that is also an auxiliary, before a verb.
    if (!first && is_auxiliary(t) && (is_copula(at(k + 1)) || at(k + 1) == "not" || !v_.household_verb(at(k + 1)).empty()))
      return false;
    if (v_.is_name_word(t)) return true;
    if (is_copula(t) || is_auxiliary(t) || is_negation(t) || preposition_of(t) || is_state_word(t) ||
        is_clause_break(t) || is_determiner(t) || is_object_pronoun(t) || t == "where" || t == "there" ||
        t == "here" || t == "that" || t == "which")
      return false;
    if (is_particle(t)) return false;
    if (first) return true;
    // "the rubbish bin", "sharps bin": a household verb that ends the
    // phrase and names a container is the phrase's head ("bin it" has an
    // object; "... and you close" is a verb).
    if (!v_.household_verb(t).empty() && !ends_with_a_container_word(k)) return false;
    // A word WordNet has as a verb and not as a noun ends the phrase
    // ("the ketchup lives ...").
    std::string verb = v_.any_verb(t);
    if (!verb.empty() && !v_.lexicon().has_noun(t) && v_.lexicon().lemmas(t).empty()) return false;
    return true;
  }

  // "the mug on the counter", "the stuff that is on the counter": a place
  // right after a noun, before the verb or before another place, says where
  // the thing is.
  Chunk located(Chunk noun) {
    std::size_t save = i_;
    bool relative = false;
    bool generic = !noun.words.empty() && std::all_of(noun.words.begin(), noun.words.end(),
                                                      [](const std::string& w) { return is_generic_noun(w); });
    if (relative_marker(w_, i_)) {
      i_ += 2;
      relative = true;
    } else if (generic && is_copula(at(0))) {  // "whatever is on the counter"
      i_ += 1;
      relative = true;
    }
    auto p = preposition_at(w_, i_);
    // Before the verb, and only if a verb comes: "crackers in the pantry"
    // says where the crackers go, "the glasses from the rack go ..." which.
    bool before_verb = c_.verb.empty() && !c_.copula && verb_ahead();
    if (p && !noun.pronoun && (p->second == Preposition::kIn || p->second == Preposition::kOn || p->second == Preposition::kFrom)) {
      std::size_t after = i_ + p->first;
      // After the verb, a place is the thing's location only if another
      // place follows ("put the mug from the rack in the cupboard").
      bool another_follows = false;
      for (std::size_t k = after; k < w_.size(); ++k)
        if (auto q = preposition_at(w_, k); q && q->second != Preposition::kFrom && q->second != Preposition::kOther &&
                                            !property_said_after_name(k - i_))
          another_follows = true;
      if ((before_verb && !noun.empty()) || relative || another_follows || inside_other_ ||
          p->second == Preposition::kFrom) {
        if (p->second == Preposition::kFrom && !before_verb && !relative && !another_follows && !inside_other_) {
          i_ = save;  // "take the mug from the dish rack": the clause's phrase
          return noun;
        }
        i_ = after;
        Chunk place = chunk();
        bool generic_place = std::all_of(place.words.begin(), place.words.end(),
                                         [](const std::string& w) { return is_generic_noun(w); });
        if (!place.empty() && !place.pronoun && !place.place_pronoun && !generic_place) {
          noun.located_by = p->second;
          noun.location = place.words;
          return noun;
        }
      }
    }
    i_ = save;
    return noun;
  }

  const std::vector<std::string>& w_;
  const ReplyVocabulary& v_;
  Clause c_;
  std::size_t i_ = 0;
  bool inside_other_ = false;
};

}  // namespace

ReplyVocabulary::ReplyVocabulary(const Universe& universe, const Lexicon& lexicon) : lexicon_(lexicon) {
  for (const ObjectInfo& info : universe.objects()) {
    names_.insert(info.category);
    names_.insert(info.id);
    for (std::string& part : name_parts(info.category)) names_.insert(std::move(part));
    for (const std::string& p : info.properties) {
      names_.insert(p);
      properties_.insert(p);
    }
  }
  // Function words inside names ("walk-in-pantry") are not nouns.
  for (std::string_view function : {"in", "on", "and", "of", "the", "a", "an", "to", "with", "at", "from", "is", "for",
                                    "by", "off", "out", "up", "into"})
    names_.erase(std::string(function));
}

bool ReplyVocabulary::is_property(std::string_view word) const {
  if (properties_.count(std::string(word))) return true;
  return std::any_of(properties_.begin(), properties_.end(),
                     [&](const std::string& p) { return says_property(word, p, lexicon_); });
}

bool ReplyVocabulary::is_name_word(std::string_view word) const {
  std::string w(word);
  if (names_.count(w)) return true;
  if (w.size() > 3 && w.back() == 's' && !w.ends_with("ss")) {
    if (names_.count(w.substr(0, w.size() - 1))) return true;
    if (w.ends_with("es") && names_.count(w.substr(0, w.size() - 2))) return true;
    if (w.ends_with("ies") && names_.count(w.substr(0, w.size() - 3) + "y")) return true;
  }
  return false;
}

std::string ReplyVocabulary::household_verb(std::string_view word) const {
  std::string base = verb_base(word, [](std::string_view b) { return find_household(b) != nullptr; });
  return find_household(base) ? base : "";
}

std::string ReplyVocabulary::any_verb(std::string_view word) const {
  if (std::string base = household_verb(word); !base.empty()) return base;
  if (lexicon_.has_verb(word)) return std::string(word);
  for (const std::string& base : lexicon_.verb_lemmas(word))
    if (lexicon_.has_verb(base)) return base;
  // "declutter": a verb WordNet has with another reversative prefix.
  if (!reversative_lemma(lexicon_, word).empty()) return std::string(word);
  return "";
}

bool ReplyVocabulary::compound_noun(std::string_view first, std::string_view second) const {
  if (first.empty() || second.empty() || first == "," || second == ",") return false;
  std::string pair = std::string(first) + " " + std::string(second);
  if (names_.count(std::string(first) + "-" + std::string(second))) return true;
  // "goes on the shelf": WordNet's "go-on" is no noun here; a preposition
  // after a word starts a phrase, unless a name here says otherwise.
  if (preposition_of(second)) return false;
  return lexicon_.has_noun(pair) || !lexicon_.variants(pair).empty();
}

VerbClass verb_class(std::string_view base, std::string_view particle) {
  const HouseholdVerb* v = find_household(base);
  if (!v) return VerbClass::kNone;
  if (base == "put" && (particle == "away" || particle == "back")) return VerbClass::kPlace;
  if (base == "take" && (particle == "out" || particle == "away")) return VerbClass::kDiscard;
  return v->kind;
}

Chunk Chunk::of_words(std::vector<std::string> words) {
  Chunk chunk;
  chunk.words = std::move(words);
  return chunk;
}

Chunk Chunk::it() {
  Chunk chunk;
  chunk.pronoun = true;
  return chunk;
}

Chunk Chunk::there() {
  Chunk chunk;
  chunk.place_pronoun = true;
  return chunk;
}

std::string Chunk::text() const {
  std::vector<std::string> all = words;
  if (pronoun && all.empty()) return "it";
  if (located_by) {
    all.emplace_back(*located_by == Preposition::kOn ? "on" : *located_by == Preposition::kFrom ? "from" : "in");
    all.emplace_back("the");
    for (const std::string& w : location) all.push_back(w);
  }
  return join(all, " ");
}

std::vector<std::string> without_fillers(std::vector<std::string> words, const ReplyVocabulary& vocabulary) {
  for (const auto& frame : frames()) erase_phrase(words, frame);
  std::vector<std::string> out;
  for (std::string& w : words)
    if (!is_filler(w) || vocabulary.is_property(w)) out.push_back(std::move(w));
  return out;
}

// A lid said on or off, as its state: "with the lid on", "lid down" are
// "lid closed"; "put the lid back on" is "close the lid"; "lid off", "lid
// up" are "lid open".
std::vector<std::string> lid_states(std::vector<std::string> w) {
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (!is_one_of(w[i], {"lid", "lids", "cover"})) continue;
    std::size_t j = i + 1;
    if (j < w.size() && w[j] == "back") ++j;
    if (j >= w.size() || !is_one_of(w[j], {"on", "down", "off", "up"})) continue;
    if (j + 1 < w.size() && !is_clause_break(w[j + 1]) && !is_filler(w[j + 1])) continue;
    const bool closed = is_one_of(w[j], {"on", "down"});
    // "put the lid (back) on": the verb said before the lid.
    std::size_t verb = i >= 2 && is_determiner(w[i - 1]) ? i - 2 : i - 1;
    if (i >= 1 && verb < i && is_one_of(w[verb], {"put", "pop", "stick", "snap"})) {
      w[verb] = closed ? "close" : "open";
      w.erase(w.begin() + static_cast<std::ptrdiff_t>(i + 1), w.begin() + static_cast<std::ptrdiff_t>(j + 1));
    } else {
      w.erase(w.begin() + static_cast<std::ptrdiff_t>(i + 1), w.begin() + static_cast<std::ptrdiff_t>(j + 1));
      w.insert(w.begin() + static_cast<std::ptrdiff_t>(i + 1), closed ? "closed" : "open");
    }
  }
  return w;
}

std::vector<Clause> read_clauses(const std::vector<std::string>& words, const ReplyVocabulary& vocabulary) {
  std::vector<std::string> kept = lid_states(without_fillers(words, vocabulary));
  std::vector<Clause> clauses;
  std::vector<std::string> current;
  auto flush = [&] {
    if (!current.empty()) clauses.push_back(ClauseReader(current, vocabulary).read());
    current.clear();
  };
  for (std::string& w : kept) {
    if (is_clause_break(w)) flush();
    else current.push_back(std::move(w));
  }
  flush();
  return clauses;
}

}  // namespace apprentice::language
