// Helpers for the experiment tests: LLM backends built from specs with
// small timeouts, and one condition run. Paths, scenarios, running the
// binary (run_cli) and ScratchTest come from tests/common.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "common/paths.h"
#include "common/process.h"
#include "common/scenarios.h"
#include "common/scratch.h"
#include "experiment/experiment.h"
#include "llm/factory.h"

namespace apprentice::testing {

namespace fs = std::filesystem;

// Small enough that a failing server costs a test little time.
inline llm::LlmOptions fast_failing_options() {
  llm::LlmOptions options;
  options.transport.connect_timeout = std::chrono::milliseconds(300);
  options.transport.request_timeout = std::chrono::milliseconds(300);
  options.transport.max_retries = 1;
  options.transport.backoff_initial = std::chrono::milliseconds(5);
  options.transport.backoff_max = std::chrono::milliseconds(10);
  options.transport.retry_after_cap = std::chrono::milliseconds(30);
  return options;
}

inline LlmFactory factory(std::string spec, llm::LlmOptions options = fast_failing_options()) {
  return [spec, options]() { return llm::make_llm_client(spec, options); };
}

inline ExperimentOptions experiment_options(LlmFactory llm = nullptr) {
  ExperimentOptions options;
  options.prompts_dir = source_path("data/prompts");
  options.llm = std::move(llm);
  return options;
}

// Runs one condition; fails the test if it does not run.
inline ConditionResult run(const Scenario& scenario, std::string_view condition_name,
                           const ExperimentOptions& options) {
  auto condition = parse_condition(condition_name);
  EXPECT_TRUE(condition.has_value());
  if (!condition) return {};
  auto result = run_condition(scenario, *condition, options);
  EXPECT_TRUE(result.has_value()) << condition_name << ": " << (result ? "" : result.error().describe());
  return result ? std::move(*result) : ConditionResult{};
}

}  // namespace apprentice::testing
