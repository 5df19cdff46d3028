// What grounding gives besides its results: the typed failures and how each
// noun phrase was resolved. Their own unit, so that reference resolution
// (reference.h) can name them without the grounder, which uses it.
#pragma once

#include <string>
#include <string_view>

#include "world/fact.h"

namespace apprentice::language {

enum class FailureKind {
  kUnknownWord,         // a word neither the world nor WordNet knows: "trashcan" without WordNet
  kUninterpretable,     // the grammar fails
  kUngroundedObject,    // no such thing is here, or more than one thing fits
  kAffordanceMismatch,  // closing a lidless bin, putting a fridge into a drawer
  kUnknownPredicate,    // "turned on", "full of water": no predicate for it
};

std::string_view to_string(FailureKind kind);  // "unknown-word", ...

struct GroundingFailure {
  FailureKind kind = FailureKind::kUninterpretable;
  // A stable key for logs and golden files: the word ("trashcan"), the
  // phrase ("cabinet"), the predicate words ("turned on") or the missing
  // affordance and object ("closed recycling-bin1").
  std::string detail;
  // A sentence the agent can say: "The recycling bin has no door to close."
  std::string message;
};

// How one noun phrase was resolved.
enum class ReferenceMethod {
  kObjectOfInterest,  // "the object"
  kCategory,          // the phrase is a category: "recycling bin"
  kHead,              // a bare head noun naming one category here: "bin"
  kMorphology,        // a WordNet base form is a category: "ketchups"
  kWordNet,           // a WordNet relation or spelling: "trash can" -> garbage
  kPartialName,       // everyday replies: part of a name, "glass" -> glass-tumbler
};

std::string_view to_string(ReferenceMethod method);

struct Reference {
  std::string phrase;  // as written, with spaces: "trash can"
  ObjectId object = 0;
  ReferenceMethod method = ReferenceMethod::kCategory;
  std::string reason;  // why, for logs and `apprentice interpret`
};

}  // namespace apprentice::language
