#include "face/apprentice.h"
#include "face/llm_setup.h"

#include "util/log.h"

namespace apprentice {

llm::LlmOptions llm_client_options(const LlmSpec& spec) {
  llm::LlmOptions options;
  options.model = spec.model;
  options.api_key = spec.api_key;
  options.seed = spec.seed;
  if (spec.timeout) options.transport.request_timeout = *spec.timeout;
  if (spec.connect_timeout) options.transport.connect_timeout = *spec.connect_timeout;
  return options;
}

Result<bool> check_llm_before_run(const std::string& spec, const llm::LlmOptions& options, bool optional,
                                  LlmCheck when) {
  auto checked = llm::check_llm_server(spec, options);
  if (checked) {
    const llm::LogprobsArrived logprobs = checked->logprobs;
    if (checked->asked)
      spdlog::info("the LLM server answered a one-token request in {} ms, {} ({})", checked->took.count(),
                   logprobs == llm::LogprobsArrived::kYes  ? "with log-probabilities"
                   : logprobs == llm::LogprobsArrived::kNo ? "without log-probabilities"
                                                           : "with no text",
                   checked->server);
    if (checked->asked && logprobs == llm::LogprobsArrived::kNo)
      spdlog::warn("the LLM server at {} gives no log-probabilities: its candidates keep the order they came in",
                   checked->server);
    return true;
  }
  // A server that is down or too slow may be done without; a configuration
  // it refuses (a wrong URL, key or model) is the user's to fix, whatever
  // --llm-optional says.
  const ErrorCode code = checked.error().code;
  const bool unreachable = code == ErrorCode::kUnavailable || code == ErrorCode::kDeadlineExceeded;
  if (!unreachable) return tl::unexpected(checked.error());
  if (!optional) {
    Error error = checked.error();
    error.message += " (--llm-optional goes on without it)";
    return tl::unexpected(std::move(error));
  }
  spdlog::warn("{}; {}", checked.error().message,
               when == LlmCheck::kBeforeRun ? "going on without the LLM (--llm-optional)"
                                            : "the LLM conditions left run without it, marked degraded");
  return false;
}

}  // namespace apprentice
