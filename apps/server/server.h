// `apprentice serve`: teach the agent from a web page. The program serves
// the page (data/web) and a small JSON API over HTTP (cpp-httplib); each
// session is its own agent on its own thread (teaching_session.h), and the
// page hears it through Server-Sent Events. docs/serve.md describes the
// page, the API, the log and the limits.
//
// Security: it listens on 127.0.0.1 unless told otherwise, and then only
// with a token that every request must carry; requests from other sites
// (Origin, Sec-Fetch-Site, a missing CSRF header) are refused; bodies,
// replies, sessions and idle time are limited; nothing a client sends
// names a file (catalogue.h).
#pragma once

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "catalogue.h"
#include "face/apprentice.h"
#include "knowledge/store_access.h"
#include "util/result.h"

namespace apprentice::serve {

struct ServeLimits {
  std::size_t max_body_bytes = std::size_t{320} << 10;   // any request's body
  UploadLimits world;                                    // an uploaded world: bytes, places, things
  std::size_t max_reply_chars = 2000;                    // one reply, in bytes of UTF-8
  int max_sessions = 32;                                 // teaching at once
  std::chrono::seconds idle{30 * 60};                    // a session with no request for this long ends
};

// The agent `teach` builds by default: inst+search4, a person teaching.
AgentSpec serve_agent_spec();

struct ServeOptions {
  std::string host = "127.0.0.1";
  int port = 8080;  // 0: any free port (printed)
  // Required for a host other than a loopback address; then every request
  // must carry it (the printed address has it; the page keeps it in a
  // cookie).
  std::string token;
  std::vector<std::filesystem::path> scenarios;  // offered besides data/scenarios; the first is preselected
  // Stores offered: an SQLite file, named on the page by its stem, or
  // postgresql://USER@HOST:PORT/DB, named by its database (catalogue.h).
  std::vector<std::string> knowledge;
  std::string household = kDefaultHousehold;  // whose goals and tasks the sessions read and write
  std::optional<std::filesystem::path> log_dir;  // each session's log as DIR/<session>.jsonl
  std::filesystem::path data_dir;                // the shipped data: scenarios, domains, web
  ServeLimits limits;
  // How each session's agent is built (face/apprentice.h), as `teach`
  // builds it: the condition, the generalization, the LLM. Its `knowledge`
  // is set per session, to the store the page chose.
  AgentSpec agent = serve_agent_spec();
};

// The address a person opens: "http://127.0.0.1:8080/" (with "?token=..."
// when there is a token).
std::string page_address(const ServeOptions& options, int port);

// Checks the options, loads the page and the worlds, listens, prints the
// address to `out` (once listening, flushed), and serves until
// `stop_requested` returns true (polled several times a second); then ends
// every session (what each taught is kept) and returns. Before it listens
// it builds one agent from `options.agent` (in the first world offered),
// so that a bad condition or an LLM that does not answer stops it at once;
// with `agent.llm.optional`, an LLM that does not answer is left out of
// every session, and a line says so. Errors: kInvalidInput for options (a
// public --host without --token, a short token, a limit out of range, a
// condition that needs an LLM without one), a broken --scenario or the
// missing page; the store's and the LLM's (kUnavailable); kIo when it
// cannot listen (the port is taken).
Status serve(const ServeOptions& options, std::ostream& out, const std::function<bool()>& stop_requested);

}  // namespace apprentice::serve
