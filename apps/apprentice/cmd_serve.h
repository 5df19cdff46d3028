// The serve subcommand: the page of apps/server, until Ctrl-C or SIGTERM.
#pragma once

#include <iosfwd>
#include <string>

#include "cmd_agent.h"
#include "outcome.h"
#include "server.h"

namespace apprentice::cli {

// How each session's agent is built, in the forms `teach` takes them.
struct ServeAgentFlags {
  std::string condition = "inst+search4";
  std::string generalization = "full";
  LlmFlags llm;
};

// Serves until SIGINT or SIGTERM, then ends every session (keeping what
// was taught) and succeeds.
CommandResult run_serve(serve::ServeOptions options, const ServeAgentFlags& agent, std::ostream& out);

}  // namespace apprentice::cli
