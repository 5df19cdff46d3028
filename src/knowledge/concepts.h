// What the preference model needs to know about words, asked of a source
// the agent supplies: knowledge/ knows neither WordNet (language's Lexicon)
// nor the word vectors (vectors/), and sees only plain data about a kind of
// thing: the classes it belongs to, how large each is, and its vectors.
// The agent's source (agent/concept_source.h) answers from WordNet and the
// GloVe vectors; tests answer from a small table of their own.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "util/cosine.h"

namespace apprentice {

// A class a kind of thing belongs to.
struct ConceptClass {
  // The source's identity of the class ("wordnet:07705931"): two kinds are
  // in one class when their classes share an id.
  std::string id;
  // Its name, as a person would say it: "edible fruit".
  std::string name;
  // How surely the kind is one, 0..1 (a word's senses share the belief:
  // "orange" the fruit more than "orange" the colour).
  double weight = 1;
  // How many kinds it holds, at least 1 (the kind itself): what the size
  // principle weighs (a class that covers the examples by being huge,
  // "entity", explains them poorly).
  double size = 1;
  // Steps up from the kind (0: the kind's own sense).
  int depth = 0;
};

// What is known of one kind of thing, by its name.
struct KindProfile {
  std::string kind;  // as asked: "stainless steel fork", "Kleenex tissue box"
  // The words that name what it is ("fork", "tissue box") and the words
  // before them ("stainless", "steel"); a name unknown to WordNet has its
  // last word as the head.
  std::string head;
  std::vector<std::string> modifiers;
  // Its classes, nearest first; empty when WordNet does not know it.
  std::vector<ConceptClass> classes;
  // Unit vectors of the whole name (the head weighted more), the head, and
  // the modifiers; empty when the vectors know none of its words (or are
  // not installed).
  std::vector<float> vector;
  std::vector<float> head_vector;
  std::vector<float> modifier_vector;
  // The unit vector of each word of the name, modifiers first and the
  // head's words last (a word the vectors lack is left out); empty without
  // the vectors.
  std::vector<std::vector<float>> word_vectors;
};

class ConceptSource {
 public:
  virtual ~ConceptSource() = default;
  // Everything known of a kind of thing; a name nothing knows gets a
  // profile with only its words.
  virtual KindProfile profile(std::string_view kind) const = 0;
  // The classes a class word names ("fruits": edible fruit, fruit), for a
  // rule said in words; each with its size and depth 0.
  virtual std::vector<ConceptClass> classes_named(std::string_view words) const = 0;
  // The unit vector of a word or phrase ("electronics", "art supplies");
  // empty when unknown.
  virtual std::vector<float> vector_of(std::string_view words) const = 0;
};

}  // namespace apprentice
