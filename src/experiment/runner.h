// Running several conditions one after another, as `apprentice experiment`
// and the Python module's apprentice.experiment() both do, and their
// results as the JSON both print.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "experiment/experiment.h"
#include "experiment/progress.h"
#include "llm/factory.h"

namespace apprentice {

struct ExperimentRequest {
  // Condition names as parse_condition reads them. Empty: every condition
  // of the paper's Table 3 that can run (those with an LLM only when
  // `llm_spec` is set).
  std::vector<std::string> conditions;
  // The LLM backend (llm/factory.h), already resolved from --llm or
  // APPRENTICE_LLM; unset: no LLM. With several conditions, each records to
  // and replays from its own cassette (per_condition_llm_spec).
  std::optional<std::string> llm_spec;
  llm::LlmOptions llm_options;
  // When the LLM server cannot be reached before the first LLM condition:
  // false, the experiment stops (kUnavailable, exit 4); true, it goes on
  // with the LLM switched off and those rows marked degraded.
  bool llm_optional = false;
  // Everything else about a condition; `options.llm` is set from llm_spec.
  ExperimentOptions options;
  // Told of each condition and LLM query as they happen; may be null.
  ExperimentObserver* observer = nullptr;
  // Called with each condition's result as soon as it is measured (to keep
  // its transcript, say); an error stops the experiment.
  std::function<Status(const ConditionResult&)> on_result;
};

struct ExperimentResults {
  std::vector<ConditionResult> results;  // in the order run
  // The paper's LLM conditions left out for want of an LLM (only when no
  // conditions were named).
  std::vector<std::string> skipped;
};

// Errors: kInvalidInput for an unknown condition name, for an LLM condition
// without an LLM, or for an LLM spec that does not parse; kUnavailable when
// the LLM server cannot be reached before the first LLM condition (unless
// `llm_optional`); then whatever a condition returns (run_condition),
// prefixed with the condition's name.
Result<ExperimentResults> run_experiment(const Scenario& scenario, const ExperimentRequest& request);

// record:FILE,SPEC and replay:FILE with ".<condition>" put before FILE's
// extension, also inside a record's SPEC (record:NEW,replay:OLD); any other
// spec unchanged (llm::spec_for_condition).
std::string per_condition_llm_spec(const std::string& spec, const std::string& condition);

// Whether to go on with the LLM, checked once before a run that needs it, so
// that a dead server costs seconds rather than a run's worth of timeouts:
// true when `spec`'s server answers; false when it does not and `optional`
// (with one warning); kUnavailable naming the server when it does not.
// kBetweenConditions is the check again after the breaker tripped, which
// never stops the run: its warning says the conditions left go without it.
enum class LlmCheck { kBeforeRun, kBetweenConditions };
Result<bool> check_llm_before_run(const std::string& spec, const llm::LlmOptions& options, bool optional,
                                  LlmCheck when = LlmCheck::kBeforeRun);

// The results as `experiment --json` prints them: a JSON array with one
// object per condition (keys in docs/experiment.md), pretty-printed.
std::string results_json(const std::vector<ConditionResult>& results);

}  // namespace apprentice
