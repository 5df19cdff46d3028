#include "world_view.h"

#include <nlohmann/json.hpp>

#include "language/narration.h"
#include "world/state_lookup.h"

namespace apprentice::serve {

std::string bare_name(const World& world, ObjectId object) {
  std::string name = language::spoken_name(world, object);
  for (std::string_view article : {"the ", "a ", "an "})
    if (name.rfind(article, 0) == 0) return name.substr(article.size());
  return name;
}

namespace {

nlohmann::json thing(const World& world, ObjectId object) {
  return nlohmann::json{{"id", world.universe->name(object)}, {"name", bare_name(world, object)},
                        {"category", world.universe->info(object).category}};
}

}  // namespace

nlohmann::json world_view(const World& world) {
  const Universe& u = *world.universe;
  const Vocabulary& v = world.vocabulary;
  nlohmann::json places = nlohmann::json::array();
  std::vector<ObjectId> place_ids = u.of_kind(ObjectKind::kSurface);
  const std::vector<ObjectId>& receptacles = u.of_kind(ObjectKind::kReceptacle);
  place_ids.insert(place_ids.end(), receptacles.begin(), receptacles.end());
  std::unordered_map<ObjectId, std::size_t> index_of;
  for (ObjectId p : place_ids) {
    nlohmann::json place = thing(world, p);
    const bool surface = u.info(p).kind == ObjectKind::kSurface;
    place["kind"] = surface ? "surface" : "receptacle";
    place["door"] = nullptr;
    if (world.state.holds(Fact(v.openable, {p}))) place["door"] = world.state.holds(Fact(v.closed, {p})) ? "closed" : "open";
    place["items"] = nlohmann::json::array();
    index_of[p] = places.size();
    places.push_back(std::move(place));
  }
  // Each item's support; in a stacking world an item may rest on another
  // item, and is drawn in the place at the bottom of its stack.
  std::unordered_map<ObjectId, ObjectId> support;
  nlohmann::json hand = nullptr;
  const std::vector<ObjectId>& items = u.of_kind(ObjectKind::kItem);
  for (ObjectId item : items) {
    if (auto on = facts_about(world.state, v.on, item); !on.empty()) support[item] = on.front().args[1];
    else if (auto in = facts_about(world.state, v.in, item); !in.empty()) support[item] = in.front().args[1];
    else if (world.state.holds(Fact(v.holding, {item}))) hand = thing(world, item);
  }
  for (ObjectId item : items) {
    auto at = support.find(item);
    if (at == support.end()) continue;
    ObjectId base = at->second;
    for (std::size_t steps = 0; !index_of.contains(base) && support.contains(base) && steps < items.size(); ++steps)
      base = support[base];
    if (!index_of.contains(base)) continue;
    nlohmann::json entry = thing(world, item);
    if (base != at->second) entry["on"] = bare_name(world, at->second);
    places[index_of[base]]["items"].push_back(std::move(entry));
  }
  return nlohmann::json{{"location", world.location}, {"places", std::move(places)}, {"hand", std::move(hand)}};
}

}  // namespace apprentice::serve
