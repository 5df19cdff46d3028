// Resolving the noun phrases of everyday replies (language/reply_reading.h).
#include <algorithm>

#include "language/generation.h"
#include "language/reply_reading.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {
namespace {

// Look-alikes no one can tell apart: same category, place and properties.
bool interchangeable(const World& world, const std::vector<ObjectId>& objects) {
  const ObjectInfo& first = world.universe->info(objects.front());
  auto where = place_of(world, objects.front());
  return std::all_of(objects.begin(), objects.end(), [&](ObjectId id) {
    const ObjectInfo& info = world.universe->info(id);
    return info.category == first.category && info.properties == first.properties && place_of(world, id) == where;
  });
}

// "the object", "this thing": the object asked about.
bool is_one_of_object_words(std::string_view w) { return w == "object" || w == "thing" || w == "item"; }

bool generic_only(const std::vector<std::string>& words) {
  return !words.empty() && std::all_of(words.begin(), words.end(), [](const std::string& w) { return is_generic_noun(w); });
}

}  // namespace

ReplyInput::ReplyInput(const Grounder& g, const World& w, const ReplyContext& c, std::vector<std::string> ws)
    : grounder(g), world(w), context(c), words(std::move(ws)), vocabulary(*w.universe, g.lexicon()) {}

Unusable unusable(const ReplyInput& in, const Problem& problem) {
  return Unusable{problem.reason, example_replies(in.world, in.context), problem.failure};
}

namespace {

// The objects that have every one of `words` as a property ("blue",
// "top"), of the kind `role` asks for; none if a word is no property.
std::vector<ObjectId> with_properties(const World& world, const std::vector<std::string>& words, Role role) {
  std::vector<ObjectId> out;
  if (words.empty()) return out;
  const Universe& universe = *world.universe;
  for (ObjectId id = 0; id < universe.size(); ++id) {
    const ObjectInfo& info = universe.info(id);
    if (role != Role::kAny && (info.kind == ObjectKind::kItem) != (role == Role::kItem)) continue;
    if (std::all_of(words.begin(), words.end(), [&](const std::string& w) {
          return std::find(info.properties.begin(), info.properties.end(), w) != info.properties.end();
        }))
      out.push_back(id);
  }
  return out;
}

}  // namespace

Resolver::Resolver(const ReplyInput& in) : in_(in) {}

ReferenceContext Resolver::reference_context() const {
  ReferenceContext context{in_.world, in_.grounder.lexicon(), in_.context.object};
  context.partial_names = true;
  return context;
}

std::variant<std::vector<ObjectId>, Problem> Resolver::candidates(const Chunk& chunk, Role role) const {
  const World& world = in_.world;
  auto place_named = [&]() -> std::variant<std::vector<ObjectId>, Problem> {
    if (auto place = last_place()) return std::vector<ObjectId>{*place};
    return Problem{"I don't know which place you mean; please name it.", std::nullopt};
  };
  if (chunk.place_pronoun) return place_named();
  for (const ReplyContext::Settled& settled : in_.context.settled)
    if (!chunk.empty() && settled.phrase == chunk.text()) return std::vector<ObjectId>{settled.object};
  bool the_object = chunk.words.size() == 1 && is_one_of_object_words(chunk.words[0]) &&
                    (chunk.determiner == "the" || chunk.determiner == "this" || chunk.determiner == "that");
  if (chunk.pronoun || the_object) {
    if (role == Role::kPlace) return place_named();
    if (in_.context.object) return located(std::vector<ObjectId>{*in_.context.object}, chunk);
    return Problem{"I don't know what \"" + (chunk.pronoun ? std::string("it") : chunk.text()) +
                       "\" means here; please name the thing.",
                   std::nullopt};
  }
  // "the door", "the fridge door", "the door of the fridge", "the lid".
  std::vector<std::string> words;
  bool door = false;
  for (const std::string& w : chunk.words) {
    if (is_door_word(w)) door = true;
    else if (w != "of") words.push_back(w);
  }
  if (door && words.empty()) return place_named();
  if (!door) words = chunk.words;
  if (words.empty() || generic_only(words))
    return Problem{"I don't know which thing you mean by \"" + chunk.text() + "\".", std::nullopt};
  NounPhrase np{"", words};
  auto found = candidates_for(np, door ? Role::kPlace : role, reference_context());
  if (const auto* failure = std::get_if<GroundingFailure>(&found)) {
    // "the blue one": properties alone, when they name no kind of thing.
    std::vector<ObjectId> having = with_properties(world, words, role);
    if (!door && !having.empty()) return located(std::move(having), chunk);
    return Problem{failure->message, *failure};
  }
  std::vector<ObjectId> objects = std::get<CandidateSet>(found).objects;
  // Prefer what the sentence needs there, when the phrase names both.
  if (role != Role::kAny) {
    std::vector<ObjectId> fitting;
    for (ObjectId id : objects)
      if ((world.universe->info(id).kind == ObjectKind::kItem) == (role == Role::kItem)) fitting.push_back(id);
    if (!fitting.empty()) objects = std::move(fitting);
  }
  return located(std::move(objects), chunk);
}

std::variant<std::vector<ObjectId>, Problem> Resolver::located(std::vector<ObjectId> objects, const Chunk& chunk) const {
  if (!chunk.located_by || chunk.location.empty()) return objects;
  Chunk place_chunk;
  place_chunk.words = chunk.location;
  auto places = candidates(place_chunk, Role::kPlace);
  if (auto* problem = std::get_if<Problem>(&places)) return *problem;
  const auto& at = std::get<std::vector<ObjectId>>(places);
  std::vector<ObjectId> kept;
  for (ObjectId id : objects) {
    auto where = place_of(in_.world, id);
    if (where && std::find(at.begin(), at.end(), *where) != at.end()) kept.push_back(id);
  }
  if (kept.empty()) {
    std::string where = join(chunk.location, " ");
    return Problem{"I don't see " + (chunk.words.empty() ? std::string("it") : "a " + join(chunk.words, " ")) + " " +
                       (*chunk.located_by == Preposition::kOn ? "on" : "in") + " the " + where + ".",
                   std::nullopt};
  }
  return kept;
}

Choice Resolver::choose(const Chunk& chunk, Role role, bool recent) const {
  auto found = candidates(chunk, role);
  if (auto* problem = std::get_if<Problem>(&found)) return *problem;
  return choose(std::get<std::vector<ObjectId>>(found), chunk.text(), role, recent);
}

Choice Resolver::choose(const std::vector<ObjectId>& objects, const std::string& phrase, Role role, bool recent) const {
  if (objects.empty()) return Problem{"I don't see anything like \"" + phrase + "\" here.", std::nullopt};
  if (objects.size() == 1) return objects.front();
  auto asked = in_.context.object;
  if (role != Role::kPlace && asked && std::find(objects.begin(), objects.end(), *asked) != objects.end())
    return *asked;
  // "the drawer" after a placement in the top drawer is that drawer.
  if (auto place = recent ? last_place() : last_place_; place && role != Role::kItem && std::find(objects.begin(), objects.end(), *place) != objects.end())
    return *place;
  if (interchangeable(in_.world, objects)) return objects.front();
  return Ambiguous{phrase, objects, say_which_question(in_.world, objects)};
}

bool Resolver::fits_asked(const Chunk& chunk) const {
  if (!in_.context.object || chunk.words.empty() || chunk.pronoun || chunk.located_by) return false;
  const std::string& category = in_.world.universe->info(*in_.context.object).category;
  // A phrase that names the object's own kind is about one of that kind.
  auto found = candidates(Chunk::of_words(chunk.words), Role::kItem);
  if (const auto* ids = std::get_if<std::vector<ObjectId>>(&found))
    if (std::any_of(ids->begin(), ids->end(),
                    [&](ObjectId id) { return in_.world.universe->info(id).category == category; }))
      return false;
  std::string noun = chunk.words.back();
  if (noun.size() > 3 && noun.back() == 's' && !noun.ends_with("ss")) noun.pop_back();
  std::string closed = category;
  std::erase(closed, '-');
  if (closed.size() > noun.size() + 2 && closed.ends_with(noun) && category.find('-') == std::string::npos) return true;
  std::vector<std::string> categories{category};
  return !in_.grounder.lexicon().related(join(chunk.words, " "), categories, false).empty();
}

std::string verb_name(const std::string& verb, const std::string& particle) {
  if (particle == "away" || particle == "back" || particle == "out") return verb + " " + particle;
  // "tidy up" is "tidy", but "pick" alone is not "pick up".
  if (particle == "up" && (verb == "pick" || verb == "hang")) return verb + " up";
  return verb;
}

}  // namespace apprentice::language
