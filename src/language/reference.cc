#include "language/reference.h"

#include <algorithm>
#include <set>

#include <spdlog/spdlog.h>

#include "util/text.h"

namespace apprentice::language {
namespace {

// Candidate objects for a phrase, and how they were found.
struct Candidates {
  std::vector<ObjectId> objects;  // id order, no duplicates
  ReferenceMethod method = ReferenceMethod::kCategory;
  std::string reason;
};

bool fits(const ObjectInfo& info, Role role) {
  switch (role) {
    case Role::kItem: return info.kind == ObjectKind::kItem;
    case Role::kPlace: return info.kind != ObjectKind::kItem;
    case Role::kAny: return true;
  }
  return true;
}

std::string head_of(std::string_view category) {
  auto dash = category.rfind('-');
  return std::string(dash == std::string_view::npos ? category : category.substr(dash + 1));
}

std::vector<ObjectId> with_categories(const Universe& universe, const std::set<std::string>& categories,
                                      std::optional<Role> role) {
  std::vector<ObjectId> out;
  for (ObjectId id = 0; id < universe.size(); ++id) {
    const ObjectInfo& info = universe.info(id);
    if (categories.count(info.category) && (!role || fits(info, *role))) out.push_back(id);
  }
  return out;
}

// Tiers 2 and 3 for one spelling of the phrase.
std::optional<Candidates> by_name(const std::string& phrase, Role role, const World& world,
                                  ReferenceMethod method, const std::string& reason) {
  const Universe& universe = *world.universe;
  const Domain& domain = *world.domain;
  std::string key = category_key(phrase);
  if (auto objects = with_categories(universe, {key}, std::nullopt); !objects.empty())
    return Candidates{objects, method, reason.empty() ? "'" + phrase + "' is the category " + key : reason};
  // The domain's own types ("item", "place") and the kinds of place
  // ("receptacle", "surface", whose types are receptacle-place and
  // surface-place) name every object of that type.
  std::string type_key = key;
  if (auto kind = parse_object_kind(key); kind && *kind != ObjectKind::kItem) type_key = type_name(*kind);
  if (auto type = domain.find_type(type_key); type && *type != kRootType) {
    std::vector<ObjectId> objects;
    for (ObjectId id = 0; id < universe.size(); ++id)
      if (domain.is_subtype(universe.info(id).type, *type)) objects.push_back(id);
    if (!objects.empty()) return Candidates{objects, method, "'" + phrase + "' is the type " + type_key};
  }
  if (key.find('-') != std::string::npos || key.empty()) return std::nullopt;
  std::set<std::string> heads;
  for (const ObjectInfo& info : universe.objects())
    if (fits(info, role) && info.category.find('-') != std::string::npos && head_of(info.category) == key)
      heads.insert(info.category);
  if (heads.empty()) return std::nullopt;
  std::string names = join(std::vector<std::string>(heads.begin(), heads.end()), ", ");
  return Candidates{with_categories(universe, heads, role),
                    method == ReferenceMethod::kCategory ? ReferenceMethod::kHead : method,
                    (reason.empty() ? "" : reason + "; ") + "'" + key + "' ends the name of " + names};
}

// Tier 5: every spelling WordNet vouches for, and every category it relates
// any of them to. All fitting objects are returned, so that the caller sees
// ambiguity instead of a first guess.
std::optional<Candidates> by_wordnet(const std::string& phrase, Role role, const ReferenceContext& context) {
  const Lexicon& lexicon = context.lexicon;
  const Universe& universe = *context.world.universe;
  if (!lexicon.has_wordnet()) return std::nullopt;
  std::vector<PhraseVariant> spellings{{phrase, ""}};
  for (PhraseVariant& v : lexicon.variants(phrase)) spellings.push_back(std::move(v));
  std::set<std::string> role_categories;
  for (const ObjectInfo& info : universe.objects())
    if (fits(info, role)) role_categories.insert(info.category);
  std::vector<std::string> categories(role_categories.begin(), role_categories.end());
  std::set<std::string> matched;
  std::vector<std::string> reasons;
  for (const PhraseVariant& spelling : spellings) {
    if (!spelling.reason.empty()) {
      if (auto named = by_name(spelling.phrase, role, context.world, ReferenceMethod::kWordNet, spelling.reason)) {
        for (ObjectId id : named->objects) matched.insert(universe.info(id).category);
        reasons.push_back(named->reason);
        continue;
      }
    }
    for (CategoryRelation& r : lexicon.related(spelling.phrase, categories, role == Role::kPlace)) {
      if (matched.insert(r.category).second) reasons.push_back(r.category + ": " + r.reason);
    }
  }
  if (matched.empty()) {
    spdlog::debug("wordnet: nothing here is related to '{}'", phrase);
    return std::nullopt;
  }
  return Candidates{with_categories(universe, matched, std::nullopt), ReferenceMethod::kWordNet, join(reasons, "; ")};
}

std::string list_ids(const Universe& universe, const std::vector<ObjectId>& ids) {
  std::vector<std::string> names;
  for (ObjectId id : ids) names.push_back(universe.name(id));
  return join(names, ", ");
}

std::vector<std::string> split_parts(std::string_view text) {
  std::vector<std::string> parts;
  std::string part;
  for (char c : std::string(text) + " ") {
    if (c == '-' || c == ' ') {
      if (!part.empty()) parts.push_back(part);
      part.clear();
    } else {
      part.push_back(c);
    }
  }
  return parts;
}

// Nothing fits: blame the first word neither the world's names nor WordNet
// know, else the phrase as a whole.
GroundingFailure unresolved(const std::string& phrase, const ReferenceContext& context) {
  std::set<std::string> vocabulary{"object"};
  for (const ObjectInfo& info : context.world.universe->objects())
    for (std::string& part : split_parts(info.category)) vocabulary.insert(std::move(part));
  for (const std::string& part : split_parts(phrase))
    if (!vocabulary.count(part) && !context.lexicon.knows(part))
      return {FailureKind::kUnknownWord, part, "I do not know the word '" + part + "'."};
  return {FailureKind::kUngroundedObject, phrase, "I do not see the " + phrase + " here."};
}

// All candidates for a phrase, by the first tier that finds any.
std::variant<Candidates, GroundingFailure> candidates(const NounPhrase& np, Role role,
                                                      const ReferenceContext& context) {
  std::string phrase = np.text();
  if (np.is_object_of_interest()) {
    if (!context.object_of_interest)
      return GroundingFailure{FailureKind::kUngroundedObject, "object", "I am not attending to any object."};
    return Candidates{{*context.object_of_interest}, ReferenceMethod::kObjectOfInterest, "the object of interest"};
  }
  if (auto named = by_name(phrase, role, context.world, ReferenceMethod::kCategory, "")) return *named;
  for (const std::string& form : context.lexicon.lemmas(phrase)) {
    std::string reason = "WordNet's morphology gives the base form '" + form + "'";
    if (auto named = by_name(form, role, context.world, ReferenceMethod::kMorphology, reason)) return *named;
  }
  if (auto related = by_wordnet(phrase, role, context)) return *related;
  // A phrase naming only things of the other role ("Pick up the bin", "the
  // trash is in the kitchen") should fail on that thing's affordances, not
  // on its name.
  if (role != Role::kAny) {
    Role other = role == Role::kItem ? Role::kPlace : Role::kItem;
    if (auto named = by_name(phrase, other, context.world, ReferenceMethod::kCategory, "")) return *named;
    if (auto related = by_wordnet(phrase, other, context)) return *related;
  }
  return unresolved(phrase, context);
}

// The single candidate located on or in `context.located_at`, if any.
std::optional<ObjectId> only_one_at(const ReferenceContext& context, const std::vector<ObjectId>& objects) {
  if (!context.located_at) return std::nullopt;
  const World& world = context.world;
  std::optional<ObjectId> found;
  for (ObjectId id : objects) {
    if (world.state.holds(Fact(world.vocabulary.on, {id, *context.located_at})) ||
        world.state.holds(Fact(world.vocabulary.in, {id, *context.located_at}))) {
      if (found) return std::nullopt;
      found = id;
    }
  }
  return found;
}

}  // namespace

std::string category_key(std::string_view phrase) {
  std::string key;
  for (const std::string& word : split_words(to_lower(phrase))) {
    if (!key.empty()) key.push_back('-');
    key += word;
  }
  return key;
}

Resolution resolve(const NounPhrase& np, Role role, const ReferenceContext& context) {
  auto found = candidates(np, role, context);
  if (auto* failure = std::get_if<GroundingFailure>(&found)) return *failure;
  auto& c = std::get<Candidates>(found);
  const Universe& universe = *context.world.universe;
  std::string phrase = np.text();
  ObjectId chosen = 0;
  auto ooi = context.object_of_interest;
  if (ooi && std::find(c.objects.begin(), c.objects.end(), *ooi) != c.objects.end()) {
    chosen = *ooi;
  } else if (c.objects.size() == 1) {
    chosen = c.objects.front();
  } else if (auto there = only_one_at(context, c.objects)) {
    chosen = *there;
  } else {
    if (c.method == ReferenceMethod::kWordNet)
      spdlog::info("wordnet: not grounding '{}': it could be {} ({})", phrase, list_ids(universe, c.objects), c.reason);
    return GroundingFailure{FailureKind::kUngroundedObject, phrase,
                            "I do not know which you mean by the " + phrase + ": " + list_ids(universe, c.objects) + "."};
  }
  if (c.method == ReferenceMethod::kWordNet)
    spdlog::info("wordnet: '{}' -> {} ({})", phrase, universe.name(chosen), c.reason);
  return Reference{phrase, chosen, c.method, c.reason};
}

std::variant<std::string, GroundingFailure> resolve_category(const NounPhrase& np, const ReferenceContext& context) {
  auto found = candidates(np, Role::kItem, context);
  if (auto* failure = std::get_if<GroundingFailure>(&found)) return *failure;
  const auto& c = std::get<Candidates>(found);
  const Universe& universe = *context.world.universe;
  std::set<std::string> categories;
  for (ObjectId id : c.objects) categories.insert(universe.info(id).category);
  if (categories.size() != 1)
    return GroundingFailure{FailureKind::kUngroundedObject, np.text(),
                            "I do not know which kind of thing you mean by " + np.text() + "."};
  return *categories.begin();
}

}  // namespace apprentice::language
