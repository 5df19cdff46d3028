// The agent's ConceptSource (knowledge/concepts.h): what WordNet and the
// word vectors know of a kind of thing, by its name, for the preference
// model.
//
// A name is read as a person writes it ("The Los Angeles Times newspaper",
// "stainless steel fork", "case of canned tuna", "decorative pillow 2") or as
// a world's category ("ceramic-plate"): lower case, a trailing number and
// "'s" dropped, hyphens kept where WordNet or the vectors know the
// hyphenated word ("t-shirt", "Play-Doh") and otherwise words apart. Its head
// is the longest ending WordNet knows as a noun, by its base form ("potato
// chips" -> "potato chip"); what a container holds is the head ("case of
// canned tuna": "tuna", with "case" and "canned" as modifiers). A name
// WordNet does not know ("Kleenex tissue box" is known by "tissue box";
// "Skittles" by nothing) has its last word as its head and no classes.
//
// Classes: the head's physical noun senses (artifacts, foods, natural
// objects and substances, then plants and animals; all senses when it has
// none of these), the first weighing most, and every hypernym above them,
// each with its size: how many synsets it holds (WordNet::class_size).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "knowledge/concepts.h"
#include "language/lexicon.h"
#include "vectors/word_vectors.h"

namespace apprentice {

// The words of a name, as described above: "The Los Angeles Times
// newspaper" -> {"the", "los", "angeles", "times", "newspaper"}.
// `known` says whether a hyphenated word is kept whole.
std::vector<std::string> name_words(std::string_view name, const std::function<bool(std::string_view)>& known);

// Not thread-safe (it caches what it looks up): one per agent.
class LexicalConcepts final : public ConceptSource {
 public:
  // Both must outlive this object; `vectors` may be null (not installed).
  LexicalConcepts(const language::Lexicon& lexicon, const vectors::WordVectors* vectors);

  KindProfile profile(std::string_view kind) const override;
  std::vector<ConceptClass> classes_named(std::string_view words) const override;
  std::vector<float> vector_of(std::string_view words) const override;

  bool has_vectors() const { return vectors_ != nullptr; }

 private:
  // The senses of a lemma to use, with their weights.
  std::vector<std::pair<language::SynsetOffset, double>> senses(const std::string& lemma) const;
  // The classes above weighted senses, nearest first.
  std::vector<ConceptClass> classes_above(const std::vector<std::pair<language::SynsetOffset, double>>& senses) const;
  double class_size(language::SynsetOffset offset) const;
  std::string class_name(language::SynsetOffset offset) const;
  bool known_word(std::string_view word) const;
  std::vector<float> words_vector(const std::vector<std::string>& words, const std::vector<double>& weights) const;

  const language::Lexicon* lexicon_;
  const vectors::WordVectors* vectors_;
  mutable std::map<std::string, KindProfile, std::less<>> profiles_;
};

}  // namespace apprentice
