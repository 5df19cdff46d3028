#include "language/reference.h"

#include <algorithm>
#include <set>

#include <spdlog/spdlog.h>

#include "language/generation.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {
namespace {

using Candidates = CandidateSet;

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

// Nothing fits: blame the first word neither the world's names nor WordNet
// know, else the phrase as a whole.
GroundingFailure unresolved(const std::string& phrase, const ReferenceContext& context) {
  std::set<std::string> vocabulary{"object"};
  for (const ObjectInfo& info : context.world.universe->objects()) {
    for (std::string& part : name_parts(info.category)) vocabulary.insert(std::move(part));
    for (const std::string& property : info.properties) vocabulary.insert(property);
  }
  for (const std::string& part : name_parts(phrase))
    if (!vocabulary.count(part) && !context.lexicon.knows(part))
      return {FailureKind::kUnknownWord, part, "I do not know the word '" + part + "'."};
  return {FailureKind::kUngroundedObject, phrase, not_seen_message(phrase, context.world)};
}

bool has_property(const ObjectInfo& info, const std::string& word, const Lexicon& lexicon) {
  return std::any_of(info.properties.begin(), info.properties.end(),
                     [&](const std::string& p) { return says_property(word, p, lexicon); });
}

// Words before the rest of a phrase that name properties of objects here:
// "top drawer" -> {"top"} and "drawer", "lower drawer" -> {"lower"} and
// "drawer".
std::pair<std::vector<std::string>, std::string> split_properties(const std::string& phrase, const World& world,
                                                                  const Lexicon& lexicon) {
  std::vector<std::string> words = split_words(phrase);
  std::vector<std::string> properties;
  std::size_t i = 0;
  while (i + 1 < words.size() && names_property_here(words[i], world, lexicon)) properties.push_back(words[i++]);
  return {properties, join(std::vector<std::string>(words.begin() + static_cast<std::ptrdiff_t>(i), words.end()), " ")};
}

bool has_properties(const ObjectInfo& info, const std::vector<std::string>& said, const Lexicon& lexicon) {
  return std::all_of(said.begin(), said.end(), [&](const std::string& w) { return has_property(info, w, lexicon); });
}

// A word's noun forms: itself, WordNet's base forms, and a plain singular.
std::vector<std::string> noun_forms(const std::string& word, const Lexicon& lexicon) {
  std::vector<std::string> forms{word};
  for (std::string& base : lexicon.lemmas(word)) forms.push_back(std::move(base));
  if (word.size() > 3 && word.back() == 's' && !word.ends_with("ss")) {
    forms.push_back(word.substr(0, word.size() - 1));
    if (word.ends_with("es")) forms.push_back(word.substr(0, word.size() - 2));
  }
  return forms;
}

// Everyday replies: words that are part of names here. Every word of the
// phrase in a category's name ("glass" -> glass-tumbler, "pop tarts" ->
// pop-tart-box), else a phrase holding all of a category's name and more
// ("the ketchup bottle" -> ketchup; the longest name wins).
std::optional<Candidates> by_parts(const std::string& phrase, Role role, const ReferenceContext& context) {
  const Universe& universe = *context.world.universe;
  std::vector<std::vector<std::string>> forms;
  for (const std::string& word : name_parts(phrase)) forms.push_back(noun_forms(word, context.lexicon));
  if (forms.empty()) return std::nullopt;
  auto said = [&](const std::string& part) {
    return std::any_of(forms.begin(), forms.end(), [&](const std::vector<std::string>& f) {
      return std::find(f.begin(), f.end(), part) != f.end();
    });
  };
  std::set<std::string> within, containing;
  std::size_t longest = 0;
  for (const ObjectInfo& info : universe.objects()) {
    if (!fits(info, role)) continue;
    std::vector<std::string> parts = name_parts(info.category);
    // Parts run together count too: "poptarts" is pop + tart; and so do
    // their base forms: "granola bar" is part of "granola-bars".
    std::vector<std::string> pieces = parts;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      std::string joined = parts[i];
      for (std::size_t j = i + 1; j < parts.size(); ++j) pieces.push_back(joined += parts[j]);
    }
    for (const std::string& part : parts)
      for (std::string& form : noun_forms(part, context.lexicon)) pieces.push_back(std::move(form));
    bool all_in = std::all_of(forms.begin(), forms.end(), [&](const std::vector<std::string>& f) {
      return std::any_of(f.begin(), f.end(), [&](const std::string& form) {
        return std::find(pieces.begin(), pieces.end(), form) != pieces.end();
      });
    });
    if (all_in) within.insert(info.category);
    auto part_said = [&](const std::string& part) {
      std::vector<std::string> part_forms = noun_forms(part, context.lexicon);
      return std::any_of(part_forms.begin(), part_forms.end(), said);
    };
    if (!all_in && parts.size() < forms.size() && std::all_of(parts.begin(), parts.end(), part_said)) {
      if (parts.size() > longest) containing.clear();
      if (parts.size() >= longest) {
        longest = parts.size();
        containing.insert(info.category);
      }
    }
  }
  const std::set<std::string>& found = within.empty() ? containing : within;
  if (found.empty()) return std::nullopt;
  std::string names = join(std::vector<std::string>(found.begin(), found.end()), ", ");
  return Candidates{with_categories(universe, found, role), ReferenceMethod::kPartialName,
                    "'" + phrase + "' is part of the name " + names};
}

// Everyday replies: a phrase whose first words only describe the thing
// ("the silverware drawer", "the clean mug"): its last words name it.
std::optional<Candidates> by_last_words(const std::string& phrase, Role role, const ReferenceContext& context) {
  std::vector<std::string> words = split_words(phrase);
  for (std::size_t k = 1; k < words.size(); ++k) {
    std::string rest = join(std::vector<std::string>(words.begin() + static_cast<std::ptrdiff_t>(k), words.end()), " ");
    std::optional<Candidates> named = by_name(rest, role, context.world, ReferenceMethod::kPartialName, "");
    if (!named) named = by_parts(rest, role, context);
    if (named) {
      named->method = ReferenceMethod::kPartialName;
      named->reason = "'" + join(std::vector<std::string>(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(k)), " ") +
                      "' only describes the " + rest + "; " + named->reason;
      return named;
    }
  }
  return std::nullopt;
}

// "the mic": a word WordNet does not know and no name here has, of at
// least three letters, that begins exactly one longer word of the names
// here ("microphone") is that word, clipped as people type.
std::optional<Candidates> by_clipped_word(const std::string& phrase, Role role, const ReferenceContext& context) {
  std::vector<std::string> words = split_words(phrase);
  bool clipped = false;
  std::vector<std::string> taken;
  // Words of the closed classes WordNet leaves out are never clipped
  // names ("she'll want it": not the shelf).
  auto closed_class = [](std::string_view w) {
    return is_object_pronoun(w) ||
           is_one_of(w, {"she", "her", "hers", "him", "his", "you", "your", "yours", "our", "ours", "its", "their",
                         "theirs", "who", "whom", "whose", "what", "which", "the", "and", "but", "with", "from",
                         "into", "onto", "for", "are", "was", "were", "has", "had", "did", "does", "can", "could",
                         "would", "should", "will", "shall", "may", "might", "must", "been", "being", "than"});
  };
  for (std::string& word : words) {
    if (word.size() < 3 || context.lexicon.knows(word) || closed_class(word)) continue;
    std::string found;
    bool several = false, named = false;
    for (const ObjectInfo& info : context.world.universe->objects())
      for (const std::string& part : name_parts(info.category)) {
        named = named || part == word;
        if (part.size() >= word.size() + 2 && part.starts_with(word)) {
          several = several || (!found.empty() && found != part);
          found = part;
        }
      }
    if (named || found.empty() || several) continue;
    taken.push_back("'" + word + "' taken as '" + found + "'");
    word = found;
    clipped = true;
  }
  if (!clipped) return std::nullopt;
  const std::string whole = join(words, " ");
  std::optional<Candidates> out = by_name(whole, role, context.world, ReferenceMethod::kPartialName, "");
  if (!out) out = by_parts(whole, role, context);
  if (out) out->reason = join(taken, ", ") + "; " + out->reason;
  return out;
}

// All candidates for a phrase, by the first tier that finds any.
std::variant<Candidates, GroundingFailure> candidates(const NounPhrase& np, Role role, const ReferenceContext& context);

// Everyday replies: "sharps bin", "the meds box": a head WordNet has as a
// container, after words that name receptacles here (by a part of their
// names, or as WordNet relates them), is one of those receptacles.
std::optional<Candidates> by_modifier_of_a_container(const std::string& phrase, Role role,
                                                     const ReferenceContext& context) {
  if (role == Role::kItem || !context.lexicon.has_wordnet()) return std::nullopt;
  const std::vector<std::string> words = split_words(phrase);
  if (words.size() < 2) return std::nullopt;
  const std::vector<std::string> head{words.back()};
  if (context.lexicon.kinds_under("container", head).empty()) return std::nullopt;
  const NounPhrase modifiers{"", std::vector<std::string>(words.begin(), words.end() - 1)};
  auto found = candidates(modifiers, role, context);
  auto* named = std::get_if<Candidates>(&found);
  if (named == nullptr || named->objects.empty()) return std::nullopt;
  // Several receptacles ("rubbish" is scrap too) are asked about by name.
  for (ObjectId object : named->objects)
    if (context.world.universe->info(object).kind != ObjectKind::kReceptacle) return std::nullopt;
  named->method = ReferenceMethod::kPartialName;
  named->reason = "'" + words.back() + "' said of what '" + modifiers.text() + "' names; " + named->reason;
  return *named;
}

std::variant<Candidates, GroundingFailure> candidates(const NounPhrase& np, Role role,
                                                      const ReferenceContext& context) {
  std::string phrase = np.text();
  if (np.is_object_of_interest()) {
    if (!context.object_of_interest)
      return GroundingFailure{FailureKind::kUngroundedObject, "object", "I am not attending to any object."};
    return Candidates{{*context.object_of_interest}, ReferenceMethod::kObjectOfInterest, "the object of interest"};
  }
  if (np.article.empty() && phrase == "it") {
    if (!context.object_of_interest)
      return GroundingFailure{FailureKind::kUngroundedObject, "it", "I do not know what \"it\" refers to here."};
    return Candidates{{*context.object_of_interest}, ReferenceMethod::kObjectOfInterest, "'it' is the object of interest"};
  }
  // An object's own id ("drawer2") names it.
  if (np.words.size() == 1)
    if (auto id = context.world.universe->find(phrase))
      return Candidates{{*id}, ReferenceMethod::kCategory, "'" + phrase + "' is the id of " + phrase};
  // A look-alike's property said after its name, last: "the bin on the
  // left" is the left bin.
  if (const auto& w = np.words; w.size() >= 4 && is_one_of(w[w.size() - 3], {"on", "at", "to"}) &&
                                w[w.size() - 2] == "the" && names_property_here(w.back(), context.world, context.lexicon)) {
    NounPhrase property_first{np.article, {w.back()}};
    property_first.words.insert(property_first.words.end(), w.begin(), w.end() - 3);
    return candidates(property_first, role, context);
  }
  // A whole name wins, unless it names only things of the other role and
  // the phrase also reads as properties of things of this one: "the paper
  // bag" a thing is taken out of is the bag with the property paper, not
  // the paper-bag lying on the counter.
  std::optional<Candidates> whole = by_name(phrase, role, context.world, ReferenceMethod::kCategory, "");
  auto fits_role = [&](const std::vector<ObjectId>& objects) {
    return std::any_of(objects.begin(), objects.end(),
                       [&](ObjectId id) { return fits(context.world.universe->info(id), role); });
  };
  if (whole && (role == Role::kAny || fits_role(whole->objects))) return *whole;
  // Properties tell look-alikes apart: "the top drawer" is the drawer with
  // the property "top".
  if (auto [properties, rest] = split_properties(phrase, context.world, context.lexicon); !properties.empty()) {
    NounPhrase head{"", split_words(rest)};
    auto found = candidates(head, role, context);
    if (auto* c = std::get_if<Candidates>(&found)) {
      std::vector<ObjectId> kept;
      for (ObjectId id : c->objects)
        if (has_properties(context.world.universe->info(id), properties, context.lexicon)) kept.push_back(id);
      if (whole && !fits_role(kept)) return *whole;
      if (kept.empty())
        return GroundingFailure{FailureKind::kUngroundedObject, phrase, not_seen_message(phrase, context.world)};
      c->objects = std::move(kept);
      c->reason += "; with the properties " + join(properties, ", ");
      return *c;
    }
  }
  if (whole) return *whole;
  for (const std::string& form : context.lexicon.lemmas(phrase)) {
    std::string reason = "WordNet's morphology gives the base form '" + form + "'";
    if (auto named = by_name(form, role, context.world, ReferenceMethod::kMorphology, reason)) return *named;
  }
  if (context.partial_names)
    if (auto named = by_parts(phrase, role, context)) return *named;
  if (auto related = by_wordnet(phrase, role, context)) return *related;
  if (context.partial_names)
    if (auto named = by_last_words(phrase, role, context)) return *named;
  if (context.partial_names)
    if (auto named = by_clipped_word(phrase, role, context)) return *named;
  if (context.partial_names)
    if (auto named = by_modifier_of_a_container(phrase, role, context)) return *named;
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

bool names_property_here(const std::string& word, const World& world, const Lexicon& lexicon) {
  const auto& objects = world.universe->objects();
  return std::any_of(objects.begin(), objects.end(),
                     [&](const ObjectInfo& info) { return has_property(info, word, lexicon); });
}


std::variant<CandidateSet, GroundingFailure> candidates_for(const NounPhrase& phrase, Role role,
                                                            const ReferenceContext& context) {
  return candidates(phrase, role, context);
}

bool says_property(std::string_view word, std::string_view property, const Lexicon& lexicon) {
  if (word.empty() || property.empty()) return false;
  if (word == property) return true;
  // The ends of the scales people tell look-alikes apart by, in base forms.
  static const std::vector<std::vector<std::string_view>> kSameEnd{
      {"top", "upper", "high", "uppermost", "topmost"},
      {"bottom", "low", "lowermost", "bottommost", "nether"},
      {"big", "large", "huge", "bigger"},
      {"small", "little", "tiny", "smaller"},
      {"middle", "center", "centre", "central", "mid"},
      {"back", "rear", "hind", "behind"},
      {"left", "leftmost", "lefthand"},
      {"right", "rightmost", "righthand"}};
  // Both in base forms too: "bottom" says the property "lower" ("low").
  std::vector<std::string> forms{std::string(word)};
  for (std::string& base : lexicon.adjective_lemmas(word)) forms.push_back(std::move(base));
  std::vector<std::string> property_forms{std::string(property)};
  for (std::string& base : lexicon.adjective_lemmas(property)) property_forms.push_back(std::move(base));
  for (const std::string& form : forms)
    for (const std::string& said : property_forms) {
      if (form == said) return true;
      for (const auto& end : kSameEnd) {
        bool has_form = std::find(end.begin(), end.end(), form) != end.end();
        if (has_form && std::find(end.begin(), end.end(), said) != end.end()) return true;
      }
    }
  return false;
}

std::string not_seen_message(std::string_view phrase, const World& world) {
  std::string text(phrase);
  std::vector<std::string> words = name_parts(text);
  std::vector<std::string> suggestions;
  for (const ObjectInfo& info : world.universe->objects()) {
    std::vector<std::string> parts = name_parts(info.category);
    if (parts.size() < 2 || category_key(text) == info.category) continue;
    bool shares = std::any_of(words.begin(), words.end(), [&](const std::string& w) {
      auto has = [&](const std::string& x) { return std::find(parts.begin(), parts.end(), x) != parts.end(); };
      bool plural = w.size() > 3 && w.back() == 's' && !w.ends_with("ss");
      return has(w) || (plural && has(w.substr(0, w.size() - 1))) ||
             (plural && w.ends_with("es") && has(w.substr(0, w.size() - 2)));
    });
    std::string spoken = "the " + join(parts, " ");
    if (shares && std::find(suggestions.begin(), suggestions.end(), spoken) == suggestions.end())
      suggestions.push_back(spoken);
  }
  bool plural = text.size() > 3 && text.back() == 's' && !text.ends_with("ss");
  std::string seen = "I don't see " + (plural ? "any " + text : std::string(article_for(text)) + " " + text);
  if (suggestions.empty() || suggestions.size() > 3) return seen + " here.";
  return seen + "; do you mean " + say_alternatives(suggestions) + "?";
}

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
    return GroundingFailure{FailureKind::kUngroundedObject, phrase, say_which_question(context.world, c.objects)};
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
