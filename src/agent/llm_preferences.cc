#include "agent/llm_preferences.h"

#include <algorithm>

#include "language/generation.h"
#include "llm/preference_prompts.h"
#include "util/text.h"

namespace apprentice {

namespace {

std::string spaced(std::string text) {
  std::replace(text.begin(), text.end(), '-', ' ');
  return text;
}

// The example a goal learned gives: its kind and the place here its
// template puts it (in or on one place, told apart by properties where
// several share its category); none for other goals or places not here.
std::optional<llm::ThingPlace> example_of(const World& world, const GoalKnowledge& goal) {
  for (const GoalTemplateLiteral& literal : goal.literals) {
    if (!literal.positive || (literal.predicate != "in" && literal.predicate != "on") || literal.arguments.size() != 2)
      continue;
    const GoalTemplateArgument& place = literal.arguments[1];
    if (!literal.arguments[0].object_of_interest || place.object_of_interest) continue;
    std::vector<ObjectId> here;
    for (ObjectId id : world.universe->with_category(place.category)) {
      const std::vector<std::string>& has = world.universe->info(id).properties;
      if (std::all_of(place.properties.begin(), place.properties.end(),
                      [&](const std::string& p) { return std::find(has.begin(), has.end(), p) != has.end(); }))
        here.push_back(id);
    }
    if (here.size() != 1) return std::nullopt;
    return llm::ThingPlace{spaced(goal.key.category), place_words(world, here.front())};
  }
  return std::nullopt;
}

}  // namespace

std::string place_words(const World& world, ObjectId place) {
  const ObjectInfo& info = world.universe->info(place);
  std::vector<std::string> words = info.properties;
  words.push_back(spaced(info.category));
  return join(words, " ");
}

void LlmPreferences::consult(LlmAdvisor& llm, const World& world, const std::vector<GoalKnowledge>& taught,
                             const std::map<std::string, std::string>& learned_as, const std::vector<ObjectId>& things,
                             const std::vector<ObjectId>& away_from, const std::string& person_rule,
                             const language::Lexicon& lexicon) {
  if (consulted_) return;
  consulted_ = true;
  const Universe& universe = *world.universe;
  std::vector<std::string> receptacles;
  std::map<std::string, ObjectId> place_named;
  for (const ObjectInfo& info : universe.objects()) {
    if (info.kind == ObjectKind::kItem) continue;
    const ObjectId id = *universe.find(info.id);
    if (std::find(away_from.begin(), away_from.end(), id) != away_from.end()) continue;
    const std::string name = place_words(world, id);
    if (place_named.emplace(name, id).second) receptacles.push_back(name);
  }
  std::vector<llm::ThingPlace> examples;
  for (GoalKnowledge goal : taught) {
    if (auto as = learned_as.find(goal.key.category); as != learned_as.end()) goal.key.category = as->second;
    auto example = example_of(world, goal);
    if (example && place_named.contains(example->second) &&
        std::find(examples.begin(), examples.end(), *example) == examples.end())
      examples.push_back(*example);
  }
  std::vector<std::string> names;
  std::map<std::string, std::vector<ObjectId>> named;
  for (ObjectId thing : things) {
    const std::string name = language::spoken_category(world, thing);
    if (named[name].empty()) names.push_back(name);
    named[name].push_back(thing);
  }
  if (person_rule.empty() && !examples.empty()) {
    summary_ = llm.summarize(receptacles, examples);
    if (!summary_.empty()) summary_rule_ = language::read_rule(world, lexicon, summary_);
  }
  placed_by_ = person_rule.empty() ? summary_ : person_rule;
  for (const auto& [thing, place] : llm.place(receptacles, placed_by_, examples, names))
    for (ObjectId id : named[thing]) placements_[id] = place_named.at(place);
  if (!person_rule.empty() || summary_.empty()) return;
  // The summary's own check, and a second opinion from the examples alone.
  std::vector<std::string> taught_things;
  for (const llm::ThingPlace& example : examples) taught_things.push_back(example.first);
  std::vector<llm::ThingPlace> back = llm.place(receptacles, summary_, {}, taught_things);
  if (!back.empty())
    summary_keeps_examples_ = std::all_of(examples.begin(), examples.end(), [&](const llm::ThingPlace& example) {
      return std::find(back.begin(), back.end(), example) != back.end();
    });
  for (const auto& [thing, place] : llm.place(receptacles, "", examples, names))
    for (ObjectId id : named[thing]) by_examples_[id] = place_named.at(place);
}

std::optional<ObjectId> LlmPreferences::place_by_examples(ObjectId thing) const {
  auto it = by_examples_.find(thing);
  if (it == by_examples_.end()) return std::nullopt;
  return it->second;
}

std::optional<ObjectId> LlmPreferences::place_for(ObjectId thing) const {
  auto it = placements_.find(thing);
  if (it == placements_.end()) return std::nullopt;
  return it->second;
}

}  // namespace apprentice
