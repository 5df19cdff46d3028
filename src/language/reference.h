// Reference resolution: which perceived object a noun phrase names. Used by
// language/grounding.cc; public so that tests can probe the policy alone.
//
// Tiers, first that answers wins (docs/language.md):
//   1. "the object": the object of interest;
//   2. the phrase is a category, hyphenated or spaced ("plastic bottle"),
//      or a type of the domain ("receptacle": every receptacle);
//   3. a bare head noun that ends the names of the role's categories ("bin"
//      -> recycling-bin: the world calls nothing else here a bin);
//   4. a WordNet base form that is a category ("ketchups");
//   5. WordNet spellings and relations (language/lexicon.h), over the
//      categories of the role's objects, accepted only if exactly one
//      object fits.
// Where several objects fit, the object of interest wins if it is one of
// them, else the only one at the place the sentence names; otherwise the
// phrase is ambiguous, which is a failure.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "language/grounding_types.h"
#include "language/lexicon.h"
#include "language/logical_form.h"
#include "world/world.h"

namespace apprentice::language {

// What kind of thing the sentence needs there: an item to move, a place to
// put it or open, or either. Only tiers 3 and 5 filter by role; a category
// named exactly is taken whatever it is, so that "Open the ketchup" is an
// affordance mismatch rather than a mystery.
enum class Role { kItem, kPlace, kAny };

struct ReferenceContext {
  const World& world;
  const Lexicon& lexicon;
  std::optional<ObjectId> object_of_interest;
  // A place the sentence locates the thing at ("Pick up the plate from the
  // table"): among several fitting objects, the one there is meant.
  std::optional<ObjectId> located_at = std::nullopt;
  // Everyday replies (language/reply.h): a phrase may name a thing by part
  // of its name ("glass" for a glass-tumbler, "pop tarts" for a
  // pop-tart-box) or with words that only describe it ("the silverware
  // drawer"). Off for the grammar's sentences and the LLM's, whose
  // outcomes docs/language.md reports.
  bool partial_names = false;
};

using Resolution = std::variant<Reference, GroundingFailure>;

// Every object a phrase may name, by the first tier that finds any.
struct CandidateSet {
  std::vector<ObjectId> objects;  // id order, no duplicates, never empty
  ReferenceMethod method = ReferenceMethod::kCategory;
  std::string reason;
};

// The candidates before the reference policy chooses among them (for
// callers that ask back instead of failing: language/reply.h). Besides the
// tiers above, a one-word phrase that is an object's id ("drawer2") names
// that object, "it" is the object of interest, and leading words that are
// properties of objects here ("the top drawer") keep only the objects
// that have them.
std::variant<CandidateSet, GroundingFailure> candidates_for(const NounPhrase& phrase, Role role,
                                                            const ReferenceContext& context);

// "I don't see a bookshelf here.", or, when words of the phrase are part of
// names here, "I don't see a glass here; do you mean the glass tumbler?".
std::string not_seen_message(std::string_view phrase, const World& world);

// Whether a word a person says names the property `property` of a thing
// (ObjectInfo::properties): the word itself; its adjective base form
// ("smaller" for small, "lower" for low); or a word for the same end of
// one scale of position or size ("upper" and "higher" for top, "lower"
// for bottom, "large" for big, "little" for small).
bool says_property(std::string_view word, std::string_view property, const Lexicon& lexicon);
// Whether `word` says a property of some object here ("top", "lower").
bool names_property_here(const std::string& word, const World& world, const Lexicon& lexicon);

Resolution resolve(const NounPhrase& phrase, Role role, const ReferenceContext& context);

// The category a phrase names ("a ketchup" in "If the object is a
// ketchup"), by the same tiers; every fitting object must share it.
std::variant<std::string, GroundingFailure> resolve_category(const NounPhrase& phrase,
                                                             const ReferenceContext& context);

// "recycling bin" / "recycling-bin" -> "recycling-bin".
std::string category_key(std::string_view phrase);

}  // namespace apprentice::language
