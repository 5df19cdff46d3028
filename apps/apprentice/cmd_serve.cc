#include "cmd_serve.h"

#include <csignal>
#include <ostream>

#include "cmd_agent.h"

namespace apprentice::cli {

namespace {

// Set by the SIGINT and SIGTERM handler, the one state a signal handler can
// reach; the server polls it.
volatile std::sig_atomic_t g_stop = 0;

extern "C" void on_stop_signal(int) { g_stop = 1; }

}  // namespace

CommandResult run_serve(serve::ServeOptions options, const ServeAgentFlags& agent, std::ostream& out) {
  options.data_dir = data_dir();
  // As `teach` builds its agent (run_teach), for every session.
  options.agent = serve::serve_agent_spec();
  options.agent.condition = agent.condition;
  options.agent.generalization = agent.generalization;
  options.agent.goal_repair = agent.llm.goal_repair;
  options.agent.offer_ungrounded = agent.llm.offer_ungrounded;
  options.agent.llm = llm_spec(agent.llm);
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  struct sigaction previous_int {}, previous_term {};
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
  g_stop = 0;
  Status served = serve::serve(options, out, [] { return g_stop != 0; });
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
  if (!served) return tl::unexpected(served.error());
  out << "Stopped; every session has ended, and what each taught is kept.\n";
  return Outcome::kSuccess;
}

}  // namespace apprentice::cli
