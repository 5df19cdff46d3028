// The world, plan and export-pddl subcommands. Options are plain structs
// filled by main(); output goes to the given streams.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include "outcome.h"

namespace apprentice::cli {

struct WorldOptions {
  std::string scenario;
  bool json = false;
};
CommandResult run_world(const WorldOptions& options, std::ostream& out);

struct PlanOptions {
  std::string scenario;
  std::string goal;  // PDDL, or "intent" (kIntentGoal, face/apprentice.h)
  // Iterative deepening to this depth; without it, greedy best-first search.
  std::optional<int> depth;
  std::optional<long> node_limit;
  std::optional<double> time_limit_s;
  bool no_pruning = false;
  bool json = false;
  bool pddl = false;      // the plan in PDDL and the search's figures on a ";;" line, instead of sentences
  bool progress = false;  // report progress on `progress_out` about once a second after the first
};
// Progress lines go to `progress_out` (stderr, when it is a terminal).
CommandResult run_plan(const PlanOptions& options, std::ostream& out, std::ostream& progress_out);

struct ExportPddlOptions {
  std::string scenario;
  std::string goal;  // PDDL, or "intent" (kIntentGoal, face/apprentice.h)
  std::string out_dir;
};
CommandResult run_export_pddl(const ExportPddlOptions& options, std::ostream& out);

}  // namespace apprentice::cli
