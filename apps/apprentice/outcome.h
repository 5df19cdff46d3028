// What a subcommand reports to main(), which alone turns it into an exit
// code (docs/cli.md lists them).
#pragma once

#include "util/result.h"

namespace apprentice::cli {

enum class Outcome {
  kSuccess,         // exit 0
  kGoalNotReached,  // exit 1: a plan or task did not reach its goal
  kInterrupted,     // exit 130: the person pressed Ctrl-C (the command has said so)
};

using CommandResult = Result<Outcome>;

}  // namespace apprentice::cli
