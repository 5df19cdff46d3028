// The fleet-prior curve (issue 23): N households, taught one after another
// into one store, each by a simulated instructor who wants its own places.
// How much the n-th household's teacher has to say, against the first's,
// shows what the households before it save it: the policy rules are the
// fleet's, and for a kind a household never taught, what the others chose
// is offered as a yes/no (knowledge/fleet_prior.h).
//
// Households differ: each household's intent is the scenario's, with each
// kind's place changed, with probability `vary`, to another place the
// scenario's intent uses (vary_intent), so what most households chose is
// not always what the next one wants.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "instructor/dialogue.h"
#include "util/result.h"
#include "world/scenario.h"

namespace apprentice {

struct FleetCurveOptions {
  // The store every household is taught into: an SQLite path or a
  // postgresql:// URL. It is started over first (refused while another
  // process has it open).
  std::string knowledge;
  int households = 10;
  double vary = 0.2;
  unsigned seed = 1;
  std::string condition = "instruction";
  // false: the agent does not use the other households' goals (the policy
  // rules are still shared), for the curve without the prior.
  bool fleet_prior = true;
};

// What the n-th household's teacher did, and how the task ended.
struct HouseholdEffort {
  int n = 0;                // 1-based
  std::string household;    // "household-1"
  int varied_kinds = 0;     // kinds whose place differs from the scenario's
  DialogueCounts counts;    // instructions, words, yes/no (Table 3's counts)
  int goals_from_fleet = 0; // objects whose goal the fleet's prior gave (asked or not)
  int assertions_achieved = 0, assertions_total = 0;
  std::string transcript;   // "Agent: ...\nInstructor: ...\n"
};

// The scenario with its intent varied: each entry's place (and whether it
// ends closed) replaced, with probability `vary`, by another (place,
// closed) that some entry of the intent has. Sets `varied` to how many
// entries changed.
Scenario vary_intent(const Scenario& scenario, double vary, std::mt19937& random, int& varied);

// Teaches `options.households` households in turn (SimulatedInstructor,
// `options.condition`), each into its own household of the store.
// Errors: the store's, the condition's and the agent's.
Result<std::vector<HouseholdEffort>> run_fleet_curve(const Scenario& scenario, const FleetCurveOptions& options);

// A Markdown table, one row per household.
std::string format_fleet_curve(const std::vector<HouseholdEffort>& curve);

}  // namespace apprentice
