// The LLM as a knowledge source for the agent: retrieves candidate goals
// and next actions with the paper's algorithms (llm/retrieval.h) and keeps
// the counts the experiment reports. Grounding, repairing and confirming
// candidates is the agent's business (agent/goal_repair.h).
//
// A failing LLM never stops a run. The first failure is a warning; after
// `breaker_threshold` consecutive failed queries the advisor stops asking
// for the rest of the run (a circuit breaker, one more warning), so that a
// dead or hung server costs at most that many timeouts.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "llm/llm_client.h"
#include "llm/preference_prompts.h"
#include "llm/prompts.h"
#include "llm/retrieval.h"

namespace apprentice {

struct LlmAdvisorOptions {
  // Whether an instructor takes over when the LLM fails (what the warning says).
  bool instructed = true;
  // Consecutive failed queries after which the LLM is not asked again; 0: never stop.
  int breaker_threshold = 3;
  // Never ask: the server was found unreachable before the run and the run
  // goes on without it (--llm-optional).
  bool disabled = false;
  // Unique goal statements to retrieve per query: Algorithm 2's
  // num_responses, 3 in the paper; 5 here, so that the choice after repair
  // (agent/goal_repair.h) has more statements to weigh.
  int goal_responses = 5;
};

struct LlmTotals {
  int calls = 0;           // queries made
  long tokens = 0;
  int failures = 0;        // queries that failed
  bool stopped = false;    // the breaker tripped, or the LLM was disabled
  // When the breaker tripped: the queries made until then (the last of them
  // failed) and the last failure. Unset when it did not trip.
  std::optional<int> stopped_after_calls;
  std::optional<Error> stop_error;
};

class LlmAdvisor {
 public:
  LlmAdvisor(std::unique_ptr<llm::LlmClient> client, llm::PromptTemplates templates,
             LlmAdvisorOptions options = {});

  // Candidate goal statements, in retrieval order. An LLM failure gives
  // what was retrieved before it (possibly nothing) and `last_failure`.
  // `context.rejected` makes it a re-prompt with the failure context.
  std::vector<llm::Candidate> goals(const llm::TaskContext& context);
  // Candidate next steps towards `goal_text`, in retrieval order.
  std::vector<llm::Candidate> actions(const llm::TaskContext& context, const std::string& goal_text,
                                      const std::vector<std::string>& steps_so_far,
                                      const llm::IsKnownActionWord& is_known_action_word);

  // A person's preferences (llm/preference_prompts.h), once the prompts are
  // given (without them these ask nothing). The rule the `examples` follow,
  // in one sentence ("" when the LLM has none, or fails); and where each of
  // `objects` goes, among `receptacles`, by `rule` when it is not empty,
  // else by the examples, else by common sense (those it places, in the
  // world's words).
  void set_preference_prompts(llm::PreferencePrompts prompts) { preference_prompts_ = std::move(prompts); }
  bool knows_preference_prompts() const { return preference_prompts_.has_value(); }
  std::string summarize(const std::vector<std::string>& receptacles, const std::vector<llm::ThingPlace>& examples);
  std::vector<llm::ThingPlace> place(const std::vector<std::string>& receptacles, const std::string& rule,
                                     const std::vector<llm::ThingPlace>& examples,
                                     const std::vector<std::string>& objects);

  LlmTotals totals() const;
  // The error that cut the last retrieval short, if any (none when the
  // advisor did not ask at all).
  const std::optional<Error>& last_failure() const { return last_failure_; }
  // False once the breaker has tripped (or the LLM was disabled).
  bool asking() const { return !stopped_; }
  std::string describe() const { return client_->describe(); }
  bool pools_sources() const { return client_->pools_sources(); }

 private:
  // Keeps the counts after a retrieval that made queries from `before`.
  void account(const llm::Retrieval& retrieval, const llm::LlmUsage& before);
  // One query of its own, counted as a retrieval is; the answer's text ("" when
  // there is none or it failed).
  std::string ask(const llm::CompletionRequest& request);

  std::unique_ptr<llm::LlmClient> client_;
  llm::PromptTemplates templates_;
  std::optional<llm::PreferencePrompts> preference_prompts_;
  LlmAdvisorOptions options_;
  int consecutive_failures_ = 0;
  bool warned_ = false;
  bool stopped_ = false;
  std::optional<int> stopped_after_calls_;
  std::optional<Error> stop_error_;
  std::optional<Error> last_failure_;
};

}  // namespace apprentice
