#include "language/grounding_types.h"

namespace apprentice::language {

std::string_view to_string(FailureKind kind) {
  switch (kind) {
    case FailureKind::kUnknownWord: return "unknown-word";
    case FailureKind::kUninterpretable: return "uninterpretable";
    case FailureKind::kUngroundedObject: return "ungrounded-object";
    case FailureKind::kAffordanceMismatch: return "affordance-mismatch";
    case FailureKind::kUnknownPredicate: return "unknown-predicate";
  }
  return "uninterpretable";
}

std::string_view to_string(ReferenceMethod method) {
  switch (method) {
    case ReferenceMethod::kObjectOfInterest: return "object-of-interest";
    case ReferenceMethod::kCategory: return "category";
    case ReferenceMethod::kHead: return "head";
    case ReferenceMethod::kMorphology: return "morphology";
    case ReferenceMethod::kWordNet: return "wordnet";
    case ReferenceMethod::kPartialName: return "partial-name";
  }
  return "category";
}

}  // namespace apprentice::language
