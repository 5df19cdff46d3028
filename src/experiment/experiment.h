// The paper's experiment: each condition runs from empty knowledge (or from
// a copy of given knowledge) with the simulated instructor on a fresh copy
// of the scenario, and is measured as in Table 3.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "agent/agent.h"
#include "face/apprentice.h"
#include "instructor/dialogue.h"
#include "llm/llm_client.h"
#include "llm/prompts.h"
#include "world/scenario.h"

namespace apprentice {

// One condition's row: the face's report of its session (SessionReport:
// the counts, completion, objects, the LLM's totals, the agent's report and
// the transcript), with what only the experiment works out. The paper's
// completion counts assertions that already held at the start (the doors
// of the tidy kitchen start closed and must end closed), so a run that
// moves nothing scores above zero.
struct ConditionResult : SessionReport {
  std::string condition;
  // Yes answers over yes/no questions, in percent. Without an instructor:
  // the share of adopted LLM goals that are the intended ones. Unset when
  // the condition uses no LLM (the paper's "--"), or when it asked the LLM
  // but nothing came of it to measure (no yes/no question; no goal adopted).
  std::optional<double> relevance;
  bool uses_llm = false;  // the condition asks an LLM (Relevant% "n/a" rather than "--")
  double wall_ms = 0;

  // A row with failed LLM queries, or whose LLM was stopped: its figures
  // are not what the LLM would have given.
  bool degraded() const { return llm_failures > 0 || llm_stopped; }
};

// Why a degraded row is degraded, as the table's note and the JSON's
// "degraded_why" both say it: "the LLM failed 3 queries and was not asked
// again after query 3", "the LLM could not be reached and was not asked".
// Empty for a row that is not degraded.
std::string degraded_why(const ConditionResult& result);

// Makes a fresh LLM client for one condition.
using LlmFactory = std::function<Result<std::unique_ptr<llm::LlmClient>>()>;

struct ExperimentOptions {
  Generalization generalization = Generalization::kFull;
  bool use_rules = true;
  LlmFactory llm;  // required for LLM conditions
  std::filesystem::path prompts_dir;
  // When set, each condition's knowledge is kept in DIR/<condition>.sqlite:
  // what it started from and what it learned, as `household`'s.
  std::optional<std::filesystem::path> knowledge_out;
  std::string household = kDefaultHousehold;
  // What every condition starts from (a copy each); empty knowledge if unset.
  std::optional<Knowledge> knowledge_in;
  // LLM goals: analysis and repair steps, re-prompts, and the paper's way
  // of offering responses that do not ground (see AgentOptions).
  GoalRepairOptions goal_repair;
  int max_reprompts = 1;
  bool offer_ungrounded = false;
  // The LLM server could not be reached and the run goes on without it:
  // LLM conditions run with the LLM switched off (and are marked degraded).
  bool llm_disabled = false;
  int goal_responses = 5;  // unique LLM goal statements per query (LlmAdvisorOptions)
};

// The scenario can be run by the simulated instructor: it has a task and an
// intent. kInvalidInput saying what is missing otherwise.
Status check_runnable(const Scenario& scenario);

// The face's report of one condition's session as the experiment's row:
// the one place the two meet (the report moves in whole; Relevant% is
// worked out here). The wall time is the caller's.
ConditionResult condition_result(const Scenario& scenario, const Condition& condition, SessionReport report);

// Runs one condition on a copy of `scenario`'s world; nothing is kept
// beyond the result (and DIR/<condition>.sqlite with knowledge_out).
// Errors: kInvalidInput for an LLM condition without `options.llm`; the
// LLM factory's and the prompt templates' errors; kIo when knowledge_out
// cannot be written; the agent's (TaskLearningAgent::learn).
// experiment/runner.h runs several conditions in order.
Result<ConditionResult> run_condition(const Scenario& scenario, const Condition& condition,
                                      const ExperimentOptions& options);

// count_achieved_assertions, completion_percent and count_objects_done
// are the face's (face/apprentice.h).

// The least any condition with an instructor can hear on this scenario:
// the task structure, and one goal description per goal type (subtask and
// kind of object), in the simulated instructor's words. inst+search4 needs
// no more when search finds every plan.
DialogueCounts instruction_floor(const Scenario& scenario);

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

// The table as text; with `beside_paper` (only for the paper's kitchen,
// Scenario::reference "table3") each condition's row is followed by the
// paper's Table 3 row for it. A row whose LLM answers pooled several
// sources is labelled "ensemble" and is never set beside the paper's; a
// degraded row is marked '*' and explained below the table.
std::string format_results_table(const std::vector<ConditionResult>& results, bool beside_paper);

}  // namespace apprentice
