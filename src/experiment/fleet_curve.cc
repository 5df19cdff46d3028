#include "experiment/fleet_curve.h"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "experiment/experiment.h"
#include "face/apprentice.h"
#include "instructor/simulated_instructor.h"

namespace apprentice {

Scenario vary_intent(const Scenario& scenario, double vary, std::mt19937& random, int& varied) {
  // Every (place, closed) the intent wants somewhere, in the order first wanted.
  std::vector<std::pair<ObjectId, bool>> places;
  for (const IntentEntry& e : scenario.intent)
    if (std::find(places.begin(), places.end(), std::pair{e.place, e.closed}) == places.end())
      places.emplace_back(e.place, e.closed);
  Scenario out = scenario;
  varied = 0;
  std::uniform_real_distribution<double> chance(0.0, 1.0);
  for (IntentEntry& e : out.intent) {
    if (places.size() < 2 || chance(random) >= vary) continue;
    std::vector<std::pair<ObjectId, bool>> others;
    for (const auto& p : places)
      if (p.first != e.place) others.push_back(p);
    if (others.empty()) continue;
    std::uniform_int_distribution<std::size_t> pick(0, others.size() - 1);
    const auto& chosen = others[pick(random)];
    e.place = chosen.first;
    e.closed = chosen.second;
    ++varied;
  }
  return out;
}

Result<std::vector<HouseholdEffort>> run_fleet_curve(const Scenario& scenario, const FleetCurveOptions& options) {
  if (auto s = check_runnable(scenario); !s) return tl::unexpected(s.error());
  if (options.households < 1) return make_error(ErrorCode::kInvalidInput, "the fleet curve needs at least 1 household");
  std::mt19937 random(options.seed);
  std::vector<HouseholdEffort> curve;
  for (int n = 1; n <= options.households; ++n) {
    HouseholdEffort effort;
    effort.n = n;
    effort.household = "household-" + std::to_string(n);
    Scenario wanted = vary_intent(scenario, options.vary, random, effort.varied_kinds);
    AgentSpec spec = default_agent_spec();
    spec.condition = options.condition;
    spec.knowledge = options.knowledge;
    spec.household = effort.household;
    spec.fleet_prior = options.fleet_prior;
    // The first household starts the store over; the others add to it.
    spec.store_access = n == 1 ? StoreAccess::kFresh : StoreAccess::kReadWrite;
    auto session = make_agent_session(spec, wanted);
    if (!session) return tl::unexpected(session.error());
    SimulatedInstructor instructor(wanted);
    auto report = (*session)->learn(instructor);
    if (!report) return tl::unexpected(report.error());
    if (report->stopped) return make_error(ErrorCode::kCancelled, effort.household + ": " + report->stop_reason);
    effort.counts = report->counts;
    for (const ObjectReport& o : report->agent.objects)
      if (o.goal_source == GoalSource::kFleet) ++effort.goals_from_fleet;
    effort.assertions_achieved = report->assertions_achieved;
    effort.assertions_total = report->assertions_total;
    effort.transcript = std::move(report->transcript);
    curve.push_back(std::move(effort));
  }
  return curve;
}

std::string format_fleet_curve(const std::vector<HouseholdEffort>& curve) {
  std::string out =
      "| household | kinds varied | instructions | words | yes/no (yes) | goals from the fleet | goal assertions held |\n"
      "|---:|---:|---:|---:|---:|---:|---:|\n";
  char line[256];
  for (const HouseholdEffort& e : curve) {
    std::snprintf(line, sizeof line, "| %d | %d | %d | %d | %d (%d) | %d | %d/%d |\n", e.n, e.varied_kinds,
                  e.counts.instructions, e.counts.words, e.counts.yes_no, e.counts.yes, e.goals_from_fleet,
                  e.assertions_achieved, e.assertions_total);
    out += line;
  }
  return out;
}

}  // namespace apprentice
