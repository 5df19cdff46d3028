// The serve subcommand: the page of apps/server, until Ctrl-C or SIGTERM.
#pragma once

#include <iosfwd>

#include "outcome.h"
#include "server.h"

namespace apprentice::cli {

// Serves until SIGINT or SIGTERM, then ends every session (keeping what
// was taught) and succeeds.
CommandResult run_serve(serve::ServeOptions options, std::ostream& out);

}  // namespace apprentice::cli
