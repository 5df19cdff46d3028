// A thread-safe, read-only view of the WordNet 3.0 database through
// Princeton's C library (Debian's wordnet-dev over wordnet-base).
//
// The C library keeps all of its state in process globals: open FILE*s,
// static result buffers, morphstr's iteration state. That is a fact of the
// library, not a choice of ours, so this wrapper is its single owner: every
// call into it, from any WordNet handle, holds one process-wide lock, and
// wninit() runs once. No other file of apprentice may include <wn.h>.
//
// Every answer is kept for the process (until another directory is
// opened): the database never changes, and each look-up costs the library
// hundreds of seeks and reads, under that one lock. Agents that run at
// once (`apprentice serve`'s sessions) would otherwise queue behind each
// other's look-ups of the same words.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"

namespace apprentice::language {

using SynsetOffset = long;

// WordNet's lexicographer files that matter here (the "fnum" of a synset).
inline constexpr int kLexArtifact = 6;    // noun.artifact: fridge, bin, cupboard
inline constexpr int kLexFood = 13;       // noun.food: garbage (food waste), ketchup
inline constexpr int kLexSubstance = 27;  // noun.substance: trash, waste

// One noun synset, copied out of the C library's structures.
struct Synset {
  SynsetOffset offset = 0;
  int lexicographer_file = 0;
  std::vector<std::string> lemmas;  // lower-case, with spaces: "garbage can"
  std::string gloss;                // the definition, without the examples
  std::vector<SynsetOffset> hypernyms;
  std::vector<SynsetOffset> hyponyms;
  // Verbs only: the synsets of the same verb group ("$" in data.verb).
  std::vector<SynsetOffset> groups = {};
};

class WordNet {
 public:
  // Every query of a handle answers "nothing" ({}, nullopt, false) while
  // the database is closed, as after a failed open() of another directory.
  //
  // Opens the database once per process. `dictionary` (a directory holding
  // index.noun, data.noun, ...) overrides the environment's WNSEARCHDIR;
  // without either the library uses its compiled default, which on Debian
  // is /usr/share/wordnet. Fails with kUnavailable if it cannot be read.
  static Result<WordNet> open(const std::optional<std::filesystem::path>& dictionary = std::nullopt);

  // Noun base forms WordNet's morphology gives for a word or collocation,
  // excluding the word itself: "crackers" -> {"cracker"}, "glasses" ->
  // {"glass"}; {} for a base form or an unknown word.
  std::vector<std::string> noun_base_forms(std::string_view word) const;
  // The same for verbs: "tidying" -> {"tidy"}, "threw" -> {"throw"}.
  std::vector<std::string> verb_base_forms(std::string_view word) const;
  // The same for adjectives: "smaller" -> {"small"}, "lower" -> {"low"}.
  std::vector<std::string> adjective_base_forms(std::string_view word) const;
  // The noun synsets of an exact lemma ("trash can" or "trash_can"), most
  // frequent sense first; {} if WordNet has no such noun.
  std::vector<SynsetOffset> noun_senses(std::string_view lemma) const;
  // The synset at an offset of data.noun. Pass only offsets WordNet gave
  // (noun_senses, a Synset's pointers): the C library trusts them.
  std::optional<Synset> synset(SynsetOffset offset) const;
  // The same for verbs: the verb synsets of an exact lemma ("clean up"),
  // most frequent sense first, and the synset at an offset of data.verb
  // (its hypernyms and verb groups; no hyponyms).
  std::vector<SynsetOffset> verb_senses(std::string_view lemma) const;
  std::optional<Synset> verb_synset(SynsetOffset offset) const;
  // How many noun synsets a class holds: itself and every synset below it
  // by hyponymy (one under two hypernyms counts in each); 1 for a leaf, 0
  // for an offset WordNet lacks. Read from data.noun once per process, on
  // the first call (about a tenth of a second), since walking a large class
  // synset by synset would read tens of thousands of them.
  int class_size(SynsetOffset offset) const;
  bool has_noun(std::string_view lemma) const;
  bool has_verb(std::string_view lemma) const;
  // In WordNet under any part of speech, directly or through morphology.
  bool knows(std::string_view word) const;

 private:
  WordNet() = default;
};

}  // namespace apprentice::language
