// The shallow syntax of everyday replies, for read_reply (language/reply.h):
// a reply's words split into clauses, and each clause into its verb, the
// noun phrases before and after it, its prepositional phrases and the state
// it names ("closed", "open"). Nothing here resolves a noun phrase; the
// world is consulted only to know which words are names here (so that
// "can" in "the soda can" is a noun) and WordNet only to know verbs.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "language/lexicon.h"
#include "world/universe.h"

namespace apprentice::language {

// What a verb does, whatever words say it.
enum class VerbClass {
  kNone,     // no verb, or a verb that says nothing about where things go
  kPlace,    // put, place, store, keep, load, stick, ...: X goes where the phrase says
  kBe,       // go, belong, live, stay, end up: the subject goes where the phrase says
  kPick,     // pick up, take, grab, get, lift: hold X
  kOpen,     // open
  kClose,    // close, shut
  kDiscard,  // throw away, toss, trash, get rid of: into the trash
  kRecycle,  // recycle: into the recycling
};

// The words the reader needs to know about one world.
class ReplyVocabulary {
 public:
  ReplyVocabulary(const Universe& universe, const Lexicon& lexicon);

  const Lexicon& lexicon() const { return lexicon_; }
  // A word of a name here: a category's part, a property, an id (plurals too).
  bool is_name_word(std::string_view word) const;
  // A property of something here, or a word for it ("lower" for bottom:
  // language::says_property).
  bool is_property(std::string_view word) const;
  // The base form if `word` is a household verb ("threw" -> "throw"), else "".
  std::string household_verb(std::string_view word) const;
  // The base form if WordNet has `word` as a verb ("tidying" -> "tidy"), else "".
  std::string any_verb(std::string_view word) const;
  // Whether two words make one noun ("trash can", "recycle bin").
  bool compound_noun(std::string_view first, std::string_view second) const;

 private:
  const Lexicon& lexicon_;
  std::set<std::string> names_;
  std::set<std::string> properties_;
};

VerbClass verb_class(std::string_view base, std::string_view particle);

enum class Preposition { kIn, kOn, kTo, kFrom, kOther };

// A noun phrase as said: "the top drawer" is determiner "the" and words
// {"top", "drawer"}.
struct Chunk {
  std::string determiner = {};
  std::vector<std::string> words = {};  // empty for a pronoun, and for "the one"
  bool pronoun = false;                 // it, this, that, them, this one, that one
  bool place_pronoun = false;           // there, here
  // "the mug on the counter", "the glasses from the dish rack", "the stuff
  // that is on the counter": where the thing is said to be.
  std::optional<Preposition> located_by = std::nullopt;
  std::vector<std::string> location = {};

  std::string text() const;
  bool empty() const { return words.empty() && !pronoun && !place_pronoun; }

  static Chunk of_words(std::vector<std::string> words);
  static Chunk it();     // what "it" means
  static Chunk there();  // the place named last
};

struct PrepPhrase {
  Preposition preposition = Preposition::kOther;
  Chunk noun;        // empty for "put it inside"
  std::string word;  // as said: "in", "into", "to"
};

struct Clause {
  std::vector<std::string> words;  // as read, for messages
  std::string verb;                // base form of the main verb; "" if none
  std::string verb_word;           // the verb as said: "unloaded", "clear"
  std::string particle;            // away, up, back, down, out, off
  bool negated = false;
  bool copula = false;             // is/are/be before the predicate
  bool where = false;              // "the fridge is where it goes"
  std::optional<Chunk> subject;    // before the verb (or the copula)
  std::optional<Chunk> object;     // after the verb, or after the copula
  std::vector<PrepPhrase> phrases; // in order
  std::vector<Chunk> others;       // further noun phrases, in order
  std::optional<bool> closed;      // "closed", "shut": true; "open": false

  VerbClass verb_class() const { return language::verb_class(verb, particle); }
  // "the table is clear": a verb's base form after "is" is an adjective.
  bool adjective() const { return copula && !verb.empty() && verb_word == verb; }
};

// Splits at clause breaks (",", "and", "then", "with", ...) and reads each
// clause. Fillers ("please", "just", "now") are dropped unless they are
// properties of something here.
std::vector<Clause> read_clauses(const std::vector<std::string>& words, const ReplyVocabulary& vocabulary);

// The words with fillers and the frames people wrap a request in ("can
// you", "make sure", "don't forget to", "I'd") removed; clause breaks stay.
std::vector<std::string> without_fillers(std::vector<std::string> words, const ReplyVocabulary& vocabulary);

}  // namespace apprentice::language
