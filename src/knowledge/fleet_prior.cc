#include "knowledge/fleet_prior.h"

#include <algorithm>
#include <map>
#include <set>

#include "knowledge/preferences.h"

namespace apprentice {

void FleetPrior::add(std::string household, GoalKnowledge goal) {
  goals_.push_back(FleetGoal{std::move(household), std::move(goal)});
}

std::vector<DestinationProposal> FleetPrior::propose(const GoalKey& key) const {
  // Each household's choice, in the same context if any household taught
  // the kind there, else in the same task.
  auto choices = [&](auto&& fits) {
    std::map<std::string, Destination> by_household;
    for (const FleetGoal& g : goals_) {
      if (g.goal.key.category != key.category || !fits(g.goal.key)) continue;
      auto destination = destination_of(g.goal.literals);
      if (destination) by_household.emplace(g.household, std::move(*destination));
    }
    return by_household;
  };
  auto chosen = choices([&](const GoalKey& k) {
    return k.task == key.task && k.subtask == key.subtask && k.place == key.place;
  });
  if (chosen.empty()) chosen = choices([&](const GoalKey& k) { return k.task == key.task; });
  if (chosen.empty()) return {};

  struct Votes {
    Destination destination;
    std::vector<std::string> households;
  };
  std::vector<Votes> votes;
  for (const auto& [household, destination] : chosen) {
    auto it = std::find_if(votes.begin(), votes.end(), [&](const Votes& v) { return v.destination == destination; });
    if (it == votes.end()) votes.push_back(Votes{destination, {household}});
    else it->households.push_back(household);
  }
  std::stable_sort(votes.begin(), votes.end(),
                   [](const Votes& a, const Votes& b) { return a.households.size() > b.households.size(); });
  const std::size_t households = chosen.size();
  const double outcomes = static_cast<double>(votes.size() + 1);  // the destinations named, and elsewhere
  std::vector<DestinationProposal> out;
  for (const Votes& v : votes) {
    DestinationProposal p;
    p.destination = v.destination;
    p.source = ProposalSource::kFleet;
    p.households = v.households.size();
    p.of_households = households;
    p.confidence = (static_cast<double>(p.households) + 1) / (static_cast<double>(households) + outcomes);
    p.reason = "fleet: " + std::to_string(p.households) + " of " + std::to_string(households) +
               " other households put it " + format_destination(v.destination);
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace apprentice
