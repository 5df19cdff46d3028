// The face's own (defined in apprentice_llm.cc): making and checking the
// LLM a session uses. Not installed; front ends set AgentSpec::llm instead.
#pragma once

#include <memory>
#include <string>

#include "llm/factory.h"
#include "llm/llm_client.h"

namespace apprentice {

struct LlmSpec;  // face/apprentice.h

// The client's options from the spec: model, key, seed and timeouts.
llm::LlmOptions llm_client_options(const LlmSpec& spec);

// Whether to go on with the LLM, checked once before a run that needs it, so
// that a dead server costs seconds rather than a run's worth of timeouts:
// true when `spec`'s server answers; false when it does not and `optional`
// (with one warning); kUnavailable naming the server when it does not.
// kBetweenConditions is the check again after the breaker tripped, which
// never stops the run: its warning says the conditions left go without it.
enum class LlmCheck { kBeforeRun, kBetweenConditions };
Result<bool> check_llm_before_run(const std::string& spec, const llm::LlmOptions& options, bool optional,
                                  LlmCheck when = LlmCheck::kBeforeRun);

}  // namespace apprentice
