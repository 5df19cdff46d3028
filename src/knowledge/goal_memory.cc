#include "knowledge/goal_memory.h"

#include <algorithm>

namespace apprentice {

namespace {

// The objects a template argument (not the object of interest) can stand
// for: those of its category that have all of its properties.
std::vector<ObjectId> matching_objects(const Universe& universe, const GoalTemplateArgument& argument) {
  std::vector<ObjectId> out;
  for (ObjectId id : universe.with_category(argument.category)) {
    const std::vector<std::string>& has = universe.info(id).properties;
    if (std::all_of(argument.properties.begin(), argument.properties.end(), [&](const std::string& p) {
          return std::find(has.begin(), has.end(), p) != has.end();
        }))
      out.push_back(id);
  }
  return out;
}

// "drawer" or, with properties, "top drawer".
std::string argument_text(const GoalTemplateArgument& argument) {
  if (argument.object_of_interest) return "?o";
  std::string text = argument.category;
  for (auto p = argument.properties.rbegin(); p != argument.properties.rend(); ++p) text = *p + " " + text;
  return argument.properties.empty() ? text : "[" + text + "]";
}

}  // namespace

Result<GoalKnowledge> generalize_goal(const World& world, const GoalKey& key, ObjectId object,
                                      const Goal& goal, Provenance provenance) {
  const Universe& universe = *world.universe;
  GoalKnowledge knowledge{key, {}, std::move(provenance)};
  for (const Literal& l : goal.literals) {
    GoalTemplateLiteral t{world.domain->predicates.at(l.fact.predicate).name, l.positive, {}};
    for (ObjectId o : l.fact.arguments()) {
      if (o == object) {
        t.arguments.push_back(GoalTemplateArgument{true, "", {}});
        continue;
      }
      const ObjectInfo& info = universe.info(o);
      GoalTemplateArgument argument{false, info.category, {}};
      if (universe.with_category(info.category).size() != 1) {
        argument.properties = info.properties;
        if (info.properties.empty() || matching_objects(universe, argument).size() != 1)
          return make_error(ErrorCode::kInvalidInput,
                            "the goal names " + universe.name(o) + ", but there is more than one " + info.category +
                                " and nothing tells them apart, so the goal cannot be learned for every " +
                                key.category);
      }
      t.arguments.push_back(std::move(argument));
    }
    knowledge.literals.push_back(std::move(t));
  }
  return knowledge;
}

std::optional<Goal> instantiate_goal(const World& world, const GoalKnowledge& knowledge, ObjectId object) {
  std::vector<Literal> literals;
  for (const GoalTemplateLiteral& t : knowledge.literals) {
    auto predicate = world.domain->find_predicate(t.predicate);
    if (!predicate) return std::nullopt;
    std::vector<ObjectId> args;
    for (const GoalTemplateArgument& a : t.arguments) {
      if (a.object_of_interest) {
        args.push_back(object);
        continue;
      }
      auto matches = matching_objects(*world.universe, a);
      if (matches.size() != 1) return std::nullopt;
      args.push_back(matches.front());
    }
    if (args.size() != world.domain->predicates[*predicate].parameter_types.size()) return std::nullopt;
    literals.push_back(Literal{Fact(*predicate, args), t.positive});
  }
  return Goal(std::move(literals));
}

std::string format_goal_knowledge(const GoalKnowledge& k) {
  std::string out = "If the task is " + k.key.task + ", the subtask is " + k.key.subtask +
                    " and the object is a " + k.key.category + " at the " + k.key.place +
                    "\nThen the goal is";
  for (std::size_t i = 0; i < k.literals.size(); ++i) {
    const GoalTemplateLiteral& t = k.literals[i];
    std::string atom = "(" + t.predicate;
    for (const GoalTemplateArgument& a : t.arguments) atom += " " + argument_text(a);
    atom += ")";
    out += (i ? " and " : " ") + (t.positive ? atom : "(not " + atom + ")");
  }
  return out + "\n";
}

void GoalMemory::add(GoalKnowledge knowledge) {
  auto [at, inserted] = index_.try_emplace(knowledge.key, goals_.size());
  if (!inserted) {
    goals_[at->second] = std::move(knowledge);
    return;
  }
  goals_.push_back(std::move(knowledge));
}

bool GoalMemory::remove(const GoalKey& key) {
  auto at = index_.find(key);
  if (at == index_.end()) return false;
  const std::size_t removed = at->second;
  goals_.erase(goals_.begin() + static_cast<std::ptrdiff_t>(removed));
  index_.erase(at);
  for (auto& [k, i] : index_)
    if (i > removed) --i;
  return true;
}

const GoalKnowledge* GoalMemory::find(const GoalKey& key) const {
  auto at = index_.find(key);
  return at == index_.end() ? nullptr : &goals_[at->second];
}

}  // namespace apprentice
