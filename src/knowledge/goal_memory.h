// Declarative goal knowledge: for (task, subtask, object category, place),
// the goal to achieve, learned once from the instructor or a confirmed LLM
// response and retrieved for every later object of that kind.
//
// Goals are stored as templates: the object of interest is a variable and
// every other object is named by its category ("the dishwasher"), so the
// knowledge applies to another object of the category and in another world
// with the same kinds of places.
#pragma once

#include <optional>
#include <map>
#include <string>
#include <vector>

#include "knowledge/rule.h"
#include "util/result.h"
#include "world/goal.h"
#include "world/world.h"

namespace apprentice {

struct GoalTemplateArgument {
  bool object_of_interest = false;
  std::string category;  // when not the object of interest
  // Where the world had several objects of the category: the properties
  // that told this one apart ("top" for the top drawer); empty otherwise.
  std::vector<std::string> properties = {};
  friend bool operator==(const GoalTemplateArgument&, const GoalTemplateArgument&) = default;
};

struct GoalTemplateLiteral {
  std::string predicate;
  bool positive = true;
  std::vector<GoalTemplateArgument> arguments;
  friend bool operator==(const GoalTemplateLiteral&, const GoalTemplateLiteral&) = default;
};

struct GoalKey {
  std::string task;      // "tidy kitchen"
  std::string subtask;   // "clear"
  std::string category;  // "ceramic-plate"
  std::string place;     // the category of the subtask's place: "table"
  friend bool operator==(const GoalKey&, const GoalKey&) = default;
  friend auto operator<=>(const GoalKey&, const GoalKey&) = default;
};

struct GoalKnowledge {
  GoalKey key;
  std::vector<GoalTemplateLiteral> literals;
  Provenance provenance;
  friend bool operator==(const GoalKnowledge&, const GoalKnowledge&) = default;
};

// Generalizes a goal about `object`. Another object the goal names is kept
// by its category, and, where the world has several of that category, by
// the properties that tell it apart (ObjectInfo::properties: "the top
// drawer"). Fails (kInvalidInput) if neither says which one was meant.
Result<GoalKnowledge> generalize_goal(const World& world, const GoalKey& key, ObjectId object,
                                      const Goal& goal, Provenance provenance);

// The goal for `object` in `world`, or nullopt if some object the template
// names (by category, and properties where it has them) is absent or not
// unique there.
std::optional<Goal> instantiate_goal(const World& world, const GoalKnowledge& knowledge, ObjectId object);

// "If the object is a ceramic-plate on the table in clear then the goal is
// (in ?o dishwasher) (closed dishwasher)"
std::string format_goal_knowledge(const GoalKnowledge& knowledge);

class GoalMemory {
 public:
  // Replaces any goal already known for the same key.
  void add(GoalKnowledge knowledge);
  const GoalKnowledge* find(const GoalKey& key) const;
  // Forgets the goal known for `key`; returns whether there was one.
  bool remove(const GoalKey& key);
  const std::vector<GoalKnowledge>& all() const { return goals_; }
  std::size_t size() const { return goals_.size(); }

 private:
  std::vector<GoalKnowledge> goals_;
  // Where each key's goal is in goals_: add and find in O(log n), so that
  // loading a store of 100,000 goals is not quadratic.
  std::map<GoalKey, std::size_t> index_;
};

}  // namespace apprentice
