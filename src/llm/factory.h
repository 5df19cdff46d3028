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
  std::optional<int> seed;  // sent to the server when set
  std::chrono::milliseconds connect_timeout{5'000};
  // A request gets at most request_timeout in all: a hung server costs that,
  // and is not asked again (not retried).
  std::chrono::milliseconds request_timeout{30'000};
  std::chrono::milliseconds stall_timeout{30'000};
  int max_retries = 3;
  std::chrono::milliseconds backoff_initial{500};
  std::chrono::milliseconds backoff_max{8'000};
  std::chrono::milliseconds retry_after_cap{30'000};
  // How an HTTP client waits between attempts (HttpOptions::sleep).
  std::function<void(std::chrono::milliseconds)> sleep;
  // corpus: this condition's responses; empty: TBP (see corpus_client.h).
  // A ",condition=NAME" or ",pool=all" in the spec takes precedence.
  std::string corpus_condition;
};

// Errors: kInvalidInput for a spec that does not parse (the message lists
// the forms above), kNotFound / kDataLoss / kIo from opening files. Creating
// an HTTP client does not contact the server.
Result<std::unique_ptr<LlmClient>> make_llm_client(std::string_view spec, const LlmOptions& options);

// Whether the LLM server of `spec` accepts a connection (HttpLlmClient::
// check_connection), before a run depends on it; also through record:. No
// request is sent and no file is created. Backends without a server
// (replay:, corpus:) are fine here: their files are read when the client
// is made. Errors: as make_llm_client for a bad spec, kUnavailable or
// kDeadlineExceeded for a server that cannot be reached.
Status check_llm_connection(std::string_view spec, const LlmOptions& options);

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
