// The paper's experiment: each condition runs from empty knowledge with the
// simulated instructor on a fresh copy of the scenario, and is measured as
// in Table 3.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "agent/agent.h"
#include "instructor/dialogue.h"
#include "llm/llm_client.h"
#include "llm/prompts.h"
#include "world/scenario.h"

namespace apprentice {

struct ConditionResult {
  std::string condition;
  int assertions_achieved = 0;
  int assertions_total = 0;
  double completion_rate = 0;  // percent
  DialogueCounts counts;
  // Yes answers over yes/no questions, in percent. Without an instructor:
  // the share of adopted LLM goals that are the intended ones. Unset when
  // the condition uses no LLM (the paper's "--").
  std::optional<double> relevance;
  int llm_calls = 0;
  long llm_tokens = 0;
  std::uint64_t search_nodes = 0;
  double wall_ms = 0;
  AgentReport report;
  std::string transcript;
  std::string llm_description;  // where LLM answers came from, if any
};

// Makes a fresh LLM client for one condition.
using LlmFactory = std::function<Result<std::unique_ptr<llm::LlmClient>>()>;

struct ExperimentOptions {
  Generalization generalization = Generalization::kFull;
  bool use_rules = true;
  LlmFactory llm;  // required for LLM conditions
  std::filesystem::path prompts_dir;
  // When set, each condition's knowledge is kept in DIR/<condition>.sqlite.
  std::optional<std::filesystem::path> knowledge_out;
};

// Runs one condition on a copy of `scenario`'s world; nothing is kept
// beyond the result (and DIR/<condition>.sqlite with knowledge_out).
// Errors: kInvalidInput for an LLM condition without `options.llm`; the
// LLM factory's and the prompt templates' errors; kIo when knowledge_out
// cannot be written; the agent's (TaskLearningAgent::learn).
// experiment/runner.h runs several conditions in order.
Result<ConditionResult> run_condition(const Scenario& scenario, const Condition& condition,
                                      const ExperimentOptions& options);

// The goal assertions of the scenario's intent that hold in `state`.
int count_achieved_assertions(const Scenario& scenario, const State& state);

// The paper's Table 3 row for a condition, if it has one.
struct PaperRow {
  const char* condition;
  double completion;
  std::optional<double> relevance;
  int instructions;
  int words;
  int yes_no;
};
std::optional<PaperRow> paper_row(std::string_view condition);

// The table as text, each condition beside the paper's figures.
std::string format_results_table(const std::vector<ConditionResult>& results);

}  // namespace apprentice
