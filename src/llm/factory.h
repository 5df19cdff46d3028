// Builds an LLM client from a backend spec (the CLI's --llm SPEC, or the
// environment variable APPRENTICE_LLM):
//
//   openai:URL        OpenAI-compatible legacy completions. URL is the API
//                     base (".../v1", as in OPENAI_BASE_URL); "/completions"
//                     is added. A URL without a path gets "/v1/completions";
//                     one that already ends in "/completions" is used as is.
//   openai            the same, with URL from OPENAI_BASE_URL.
//   openai-chat:URL   the OpenAI-compatible chat endpoint (URL + "/chat/completions")
//                     with "logprobs": true, the same prompts as one user
//                     message; openai-chat alone takes OPENAI_BASE_URL.
//   llama:URL         llama-server's native endpoint: URL + "/completion"
//                     (used as is when it already ends in "/completion").
//   replay:FILE       answers from a cassette (cassette.h).
//   record:FILE,SPEC  runs SPEC and records every exchange to FILE.
//   corpus:FILE       answers goal queries from a corpus of recorded goal
//                     statements (corpus_client.h): the TBP condition's (the
//                     paper's method) in its own order.
//   corpus:FILE,condition=NAME   that condition's responses (e.g. STARS).
//   corpus:FILE,pool=all         every condition pooled: an ensemble.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "llm/http_client.h"
#include "llm/llm_client.h"
#include "util/result.h"

namespace apprentice::llm {

struct LlmOptions {
  // The model name sent to the server. Empty: OPENAI_MODEL if set, else none
  // (llama-server ignores it; OpenAI, vLLM and Ollama need it).
  std::string model;
  // The API key. Not set: OPENAI_API_KEY if set, else none. It is sent only
  // in the Authorization header, and never logged or written to a cassette.
  std::optional<std::string> api_key;
  std::optional<int> seed;  // sent to the server when set (--llm-seed)
  // Timeouts and retries, handed to an HTTP backend whole (http_client.h).
  HttpTransport transport;
  // corpus: this condition's responses; empty: TBP (see corpus_client.h).
  // A ",condition=NAME" or ",pool=all" in the spec takes precedence.
  std::string corpus_condition;
};

// The forms a spec takes, as one phrase for help and messages: "openai:URL,
// openai, openai-chat:URL, ...", with each backend's options (corpus's
// ",condition=NAME") when `with_options`. The backends are listed once, in
// factory.cc.
std::string llm_spec_forms(bool with_options = true);

// Whether `spec` names a backend in a form it takes (a known scheme; a URL,
// or OPENAI_BASE_URL for openai and openai-chat; FILE,SPEC for record:,
// whose SPEC is checked the same way; corpus options), without opening a
// file or reaching a server: what the CLI checks --llm with before anything
// runs. kInvalidInput saying what is wrong and listing the forms.
Status check_llm_spec(std::string_view spec);

// Errors: kInvalidInput for a spec that does not parse (check_llm_spec),
// kNotFound / kDataLoss / kIo from opening files. Creating an HTTP client
// does not contact the server.
Result<std::unique_ptr<LlmClient>> make_llm_client(std::string_view spec, const LlmOptions& options);

// What the check before a run found.
struct ServerCheck {
  bool asked = false;          // a server was asked (false: replay, corpus)
  std::string server;          // its description (LlmClient::describe)
  std::chrono::milliseconds took{0};
  // Whether its answer came with log-probabilities (kNoText: it had none
  // to give, the answer being empty).
  LogprobsArrived logprobs = LogprobsArrived::kNoText;
};

// Whether the LLM server of `spec` answers, before a run depends on it: one
// real, tiny request (a one-token completion of "Hello", with the client's
// timeouts and retries), so that a server that accepts connections but
// never answers, a wrong URL, a refused key or an unknown model are found
// at once; also through record: (nothing is recorded). Backends without a
// server (replay:, corpus:) are fine here: their files are read when the
// client is made. Errors: as make_llm_client for a bad spec; those of the
// request (HttpLlmClient): kUnavailable or kDeadlineExceeded for a server
// that does not answer, kFailedPrecondition, kNotFound or kInvalidInput for
// a configuration it refuses (each naming the flag to fix).
Result<ServerCheck> check_llm_server(std::string_view spec, const LlmOptions& options);

// The spec to use: `flag` when not empty, else APPRENTICE_LLM, else nothing.
std::optional<std::string> resolve_llm_spec(std::string_view flag);

// The spec one condition of several uses, so that each keeps its own
// cassette: every FILE of a record: or replay: in the spec, however nested,
// gets ".<condition>" before its extension ("record:new.jsonl,replay:old.jsonl"
// -> "record:new.inst+llm.jsonl,replay:old.inst+llm.jsonl"). Other specs are
// returned as they are.
std::string spec_for_condition(std::string_view spec, std::string_view condition);

// The full endpoint for openai:URL and llama:URL (see above). Exposed for tests.
std::string openai_endpoint(std::string_view base_url);
std::string openai_chat_endpoint(std::string_view base_url);
std::string llama_endpoint(std::string_view base_url);

}  // namespace apprentice::llm
