// A completion server over HTTP (libcurl): OpenAI-compatible legacy
// completions or llama-server's native /completion (see wire_format.h).
//
// Failure behaviour, so that a failing LLM never stalls or crashes a run:
//  - every attempt is bounded by request_timeout in all (connecting, which
//    connect_timeout bounds too, sending, the server's thinking, reading the
//    answer): there is no other deadline, so a slow server on a CPU gets all
//    of it;
//  - HTTP 429 and 5xx, and connection failures (refused, reset, nothing
//    received, body cut short) are retried up to max_retries times, waiting
//    backoff_initial * 2^n (at most backoff_max) or, on 429/5xx, the server's
//    Retry-After seconds (at most retry_after_cap);
//  - a timeout is not retried (kDeadlineExceeded): the server is too slow and
//    asking again would only double the wait;
//  - any other answer becomes an Error with a clear message that names the
//    flag to fix: 401/403 are kFailedPrecondition (--llm-api-key), 404
//    kNotFound (the URL in --llm, or --llm-model when the answer is about
//    the model, as vLLM, Ollama and OpenAI word it), other 4xx
//    kInvalidInput; bodies that are not UTF-8 or not the expected JSON are
//    kUnavailable (not retried).
// The API key is sent only in the Authorization header; it is never logged and
// is scrubbed from every error message (a server may echo it back).
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "llm/llm_client.h"
#include "llm/wire_format.h"

namespace apprentice::llm {

// How a client waits on its server: the one timeout model of the flags
// --llm-connect-timeout-ms and --llm-timeout-ms, and the retries.
// LlmOptions (factory.h) carries one and hands it over whole.
struct HttpTransport {
  // Connecting (TCP, and TLS for https), within request_timeout.
  std::chrono::milliseconds connect_timeout{5'000};
  // The whole of one attempt, from connecting to the last byte of the
  // answer. An attempt still unanswered then is given up and not retried.
  std::chrono::milliseconds request_timeout{30'000};
  int max_retries = 3;
  std::chrono::milliseconds backoff_initial{500};
  std::chrono::milliseconds backoff_max{8'000};
  std::chrono::milliseconds retry_after_cap{30'000};
  // How the client waits between attempts; empty: std::this_thread::sleep_for.
  // Tests inject their own to check the waits without a wall clock.
  std::function<void(std::chrono::milliseconds)> sleep;
};

struct HttpOptions {
  // The endpoint, complete: ".../v1/completions" or ".../completion".
  std::string endpoint;
  WireFormat format = WireFormat::kOpenAi;
  WireOptions wire;     // the model and seed sent, when set
  std::string api_key;  // sent as "Authorization: Bearer ..." when not empty
  HttpTransport transport;
};

class HttpLlmClient : public LlmClient {
 public:
  explicit HttpLlmClient(HttpOptions options);
  ~HttpLlmClient() override;

  // "openai http://host:8080/v1/completions model=x" (never the key).
  std::string describe() const override;

 protected:
  Result<Completion> do_complete(const CompletionRequest& request) override;

 private:
  struct Attempt;  // one HTTP exchange (defined in the .cc)
  struct Handle;   // the curl easy handle, kept for connection reuse

  Attempt post_once(const std::string& body);
  Error refusal(long status, std::string_view body) const;
  Error scrub(Error error) const;

  HttpOptions options_;
  std::unique_ptr<Handle> handle_;
};

}  // namespace apprentice::llm
