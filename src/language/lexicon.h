// Lexical knowledge from WordNet, used only for words the world does not
// use. The Lexicon answers two questions about a noun phrase:
//   - which other forms of it WordNet vouches for (plural -> singular,
//     "trashcan" -> "trash can", "recycle bin" -> "recycling bin"), and
//   - which of a given set of world categories WordNet relates it to, and
//     why ("refrigerator" -> fridge: a fridge is a kind of refrigerator).
// It never decides what a phrase refers to: the grounder accepts a mapping
// only if exactly one object of the current world fits (docs/language.md).
//
// A Lexicon without WordNet (the database missing) answers nothing, so the
// agent still works on the world's own words.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "language/wordnet.h"

namespace apprentice::language {

// A form of a phrase that WordNet vouches for, and how.
struct PhraseVariant {
  std::string phrase;  // with spaces: "trash can"
  std::string reason;  // "WordNet splits 'trashcan' into the noun 'trash can'"
};

// A world category WordNet relates a phrase to, and how.
struct CategoryRelation {
  std::string category;  // as in the world: "garbage"
  std::string reason;    // "the lemma 'garbage can' of {ashcan, trash can, ...} is a can for garbage"
};

class Lexicon {
 public:
  explicit Lexicon(std::optional<WordNet> wordnet) : wordnet_(std::move(wordnet)) {}
  // WordNet from its default place, or no WordNet (with a warning logged).
  static Lexicon open_default();

  bool has_wordnet() const { return wordnet_.has_value(); }
  // The database itself, for callers that walk WordNet's hierarchy (the
  // agent's analogies across worlds); null without WordNet.
  const WordNet* wordnet() const { return wordnet_ ? &*wordnet_ : nullptr; }

  // Morphology: the phrase's noun base forms, by its last word
  // ("plastic bottles" -> {"plastic bottle"}); {} if none differ.
  std::vector<std::string> lemmas(std::string_view phrase) const;

  // Other spellings WordNet vouches for: base forms, a closed compound it
  // lists split ("trashcan" -> "trash can"), and a verb modifier turned into
  // its gerund when only that is a noun ("recycle bin" -> "recycling bin").
  std::vector<PhraseVariant> variants(std::string_view phrase) const;

  // Same-synset lemmas of the phrase's noun senses ("refrigerator" ->
  // {"icebox"}); for logs and for callers that want plain synonyms.
  std::vector<std::string> synonyms(std::string_view phrase) const;

  // Which of `categories` (world categories, hyphenated) WordNet relates
  // the phrase to, by any of the relations of docs/language.md: a shared
  // synset; the phrase names an ancestor of the category ("refrigerator" is
  // above "fridge"), when `as_container` the category's own hypernym
  // ("shelf" is one step above "bookshelf"), or the phrase's direct
  // hypernym; each one's definition names the
  // other ("cupboard" and "cabinet"); and, when `as_container` (the phrase
  // names a place things go in), a container named for what it holds
  // ("trash", "garbage can", "wastebasket" all hold waste, as the category
  // "garbage" does in WordNet). Several categories may come back: the
  // caller must treat that as ambiguity.
  std::vector<CategoryRelation> related(std::string_view phrase, std::span<const std::string> categories,
                                        bool as_container) const;

  // Which of `categories` are kinds of what the phrase names, as a class of
  // things ("tools": hammer, screwdriver and wrench, each at most three
  // steps below "tool" in WordNet); for "tools go in the top drawer". Unlike
  // related(), a general word is allowed: the phrase names every kind
  // under it, not one thing. {} without WordNet.
  std::vector<std::string> kinds_under(std::string_view phrase, std::span<const std::string> categories) const;

  // Whether WordNet knows the word under any part of speech; false
  // without WordNet.
  bool knows(std::string_view word) const;

  // Verb base forms of an inflected word ("tidying" -> {"tidy"}, "threw"
  // -> {"throw"}); {} for a base form, an unknown word, or without WordNet.
  std::vector<std::string> verb_lemmas(std::string_view word) const;
  // Adjective base forms of a comparative or superlative ("smaller" ->
  // {"small"}); {} for a base form, an unknown word, or without WordNet.
  std::vector<std::string> adjective_lemmas(std::string_view word) const;
  // Whether WordNet has the word (a base form) as a verb / as a noun.
  bool has_verb(std::string_view word) const;
  bool has_noun(std::string_view word) const;

 private:
  std::vector<Synset> synsets(std::string_view phrase) const;
  bool is_container(const Synset& synset) const;
  std::vector<Synset> contents(std::string_view phrase, const std::vector<Synset>& senses,
                               bool require_container) const;
  // Within `max_depth` steps up (a negative: the default, kMaxAncestorDepth).
  bool ancestor_of(SynsetOffset ancestor, const Synset& synset, std::string* path, int max_depth = -1) const;
  std::string sense_relation(const std::string& text, const std::string& name, const std::vector<Synset>& mine,
                             const std::vector<Synset>& theirs, bool as_container) const;

  std::optional<WordNet> wordnet_;
};

}  // namespace apprentice::language
