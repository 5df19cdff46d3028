// A completion server over HTTP (libcurl): OpenAI-compatible legacy
// completions or llama-server's native /completion (see wire_format.h).
//
// Failure behaviour, so that a failing LLM never stalls or crashes a run:
//  - every attempt is bounded by connect_timeout and request_timeout, and is
//    abandoned when no byte is sent or received for stall_timeout (checked
//    about once a second, so it may fire up to a second late);
//  - HTTP 429 and 5xx, and connection failures (refused, reset, nothing
//    received, body cut short) are retried up to max_retries times, waiting
//    backoff_initial * 2^n (at most backoff_max) or, on 429/5xx, the server's
//    Retry-After seconds (at most retry_after_cap);
//  - a timeout is not retried (kDeadlineExceeded): the server is too slow and
//    asking again would only double the wait;
//  - any other answer becomes an Error with a clear message: 401/403 are
//    kFailedPrecondition, 404 kNotFound, other 4xx kInvalidInput, bodies that
//    are not UTF-8 or not the expected JSON are kUnavailable (not retried).
// The API key is sent only in the Authorization header; it is never logged and
// is scrubbed from every error message (a server may echo it back).
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "llm/llm_client.h"
#include "llm/wire_format.h"

namespace apprentice::llm {

struct HttpOptions {
  // The endpoint, complete: ".../v1/completions" or ".../completion".
  std::string endpoint;
  WireFormat format = WireFormat::kOpenAi;
  std::string model;    // sent as "model" when not empty
  std::string api_key;  // sent as "Authorization: Bearer ..." when not empty
  std::optional<int> seed;
  std::chrono::milliseconds connect_timeout{5'000};
  std::chrono::milliseconds request_timeout{30'000};
  std::chrono::milliseconds stall_timeout{30'000};
  int max_retries = 3;
  std::chrono::milliseconds backoff_initial{500};
  std::chrono::milliseconds backoff_max{8'000};
  std::chrono::milliseconds retry_after_cap{30'000};
  // How the client waits between attempts; empty: std::this_thread::sleep_for.
  // Tests inject their own to check the waits without a wall clock.
  std::function<void(std::chrono::milliseconds)> sleep;
};

class HttpLlmClient : public LlmClient {
 public:
  explicit HttpLlmClient(HttpOptions options);
  ~HttpLlmClient() override;

  // "openai http://host:8080/v1/completions model=x" (never the key).
  std::string describe() const override;

  // Whether the server accepts a connection, within connect_timeout (a TCP
  // connection, and TLS for https; no request is sent, so it costs the
  // server nothing). Errors: kUnavailable (refused, unreachable, a name
  // that does not resolve), kDeadlineExceeded (no answer to the connection
  // in time).
  Status check_connection();

 protected:
  Result<Completion> do_complete(const CompletionRequest& request) override;

 private:
  struct Attempt;  // one HTTP exchange (defined in the .cc)
  struct Handle;   // the curl easy handle, kept for connection reuse

  Attempt post_once(const std::string& body);
  Error scrub(Error error) const;

  HttpOptions options_;
  std::unique_ptr<Handle> handle_;
};

}  // namespace apprentice::llm
