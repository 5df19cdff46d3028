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
  std::string goal;
  int depth = 4;
  std::optional<long> max_nodes;
  bool no_pruning = false;
  bool json = false;
};
CommandResult run_plan(const PlanOptions& options, std::ostream& out);

struct ExportPddlOptions {
  std::string scenario;
  std::string goal;
  std::string out_dir;
};
CommandResult run_export_pddl(const ExportPddlOptions& options, std::ostream& out);

}  // namespace apprentice::cli
