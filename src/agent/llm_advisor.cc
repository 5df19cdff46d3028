#include "agent/llm_advisor.h"

#include "util/log.h"

namespace apprentice {

LlmAdvisor::LlmAdvisor(std::unique_ptr<llm::LlmClient> client, llm::PromptTemplates templates,
                       LlmAdvisorOptions options)
    : client_(std::move(client)), templates_(std::move(templates)), options_(options),
      stopped_(options.disabled) {}

void LlmAdvisor::account(const llm::Retrieval& retrieval, const llm::LlmUsage& before) {
  last_failure_ = retrieval.failure;
  const llm::LlmUsage& after = client_->usage();
  const int64_t queries = after.queries - before.queries;
  const int64_t failed = after.failures - before.failures;
  if (failed == 0) {
    if (queries > 0) consecutive_failures_ = 0;
    return;
  }
  // A retrieval stops at its first failed query, so the failure is its
  // last query: the run of failures goes on only if nothing succeeded.
  consecutive_failures_ = queries == failed ? consecutive_failures_ + static_cast<int>(failed) : 1;
  const char* fallback = options_.instructed ? "asking the instructor instead" : "going on without it";
  if (!warned_) {
    warned_ = true;
    spdlog::warn("the LLM failed ({}); {}", retrieval.failure->describe(), fallback);
  } else {
    spdlog::info("the LLM failed ({}); {}", retrieval.failure->describe(), fallback);
  }
  if (options_.breaker_threshold > 0 && consecutive_failures_ >= options_.breaker_threshold) {
    stopped_ = true;
    stopped_after_calls_ = static_cast<int>(after.queries);
    stop_error_ = retrieval.failure;
    spdlog::warn("the LLM failed {} times in a row: it is not asked again in this run ({})", consecutive_failures_,
                 client_->describe());
  }
}

std::vector<llm::Candidate> LlmAdvisor::goals(const llm::TaskContext& context) {
  last_failure_.reset();
  if (stopped_) return {};
  const llm::LlmUsage before = client_->usage();
  llm::GoalParams params;
  params.unique.desired = options_.goal_responses;
  llm::Retrieval retrieval = llm::retrieve_goals(*client_, templates_, context, params);
  account(retrieval, before);
  return retrieval.candidates;
}

std::vector<llm::Candidate> LlmAdvisor::actions(const llm::TaskContext& context, const std::string& goal_text,
                                                const std::vector<std::string>& steps_so_far,
                                                const llm::IsKnownActionWord& is_known_action_word) {
  last_failure_.reset();
  if (stopped_) return {};
  const llm::LlmUsage before = client_->usage();
  llm::Retrieval retrieval =
      llm::retrieve_actions(*client_, templates_, context, goal_text, steps_so_far, is_known_action_word);
  account(retrieval, before);
  return retrieval.candidates;
}

std::string LlmAdvisor::ask(const llm::CompletionRequest& request) {
  last_failure_.reset();
  if (stopped_) return {};
  const llm::LlmUsage before = client_->usage();
  llm::Retrieval retrieval;
  auto answer = client_->complete(request);
  retrieval.queries = 1;
  if (!answer) retrieval.failure = answer.error();
  account(retrieval, before);
  if (!answer || !answer->answered) return {};
  return answer->text;
}

std::string LlmAdvisor::summarize(const std::vector<std::string>& receptacles,
                                  const std::vector<llm::ThingPlace>& examples) {
  if (!preference_prompts_ || examples.empty()) return {};
  return llm::read_summary(ask(preference_prompts_->summary_request(receptacles, examples)));
}

std::vector<llm::ThingPlace> LlmAdvisor::place(const std::vector<std::string>& receptacles, const std::string& rule,
                                               const std::vector<llm::ThingPlace>& examples,
                                               const std::vector<std::string>& objects) {
  if (!preference_prompts_ || objects.empty()) return {};
  return llm::read_placements(ask(preference_prompts_->placement_request(receptacles, rule, examples, objects)),
                              objects, receptacles);
}

LlmTotals LlmAdvisor::totals() const {
  const llm::LlmUsage& usage = client_->usage();
  return LlmTotals{static_cast<int>(usage.queries),
                   static_cast<long>(usage.prompt_tokens + usage.completion_tokens),
                   static_cast<int>(usage.failures),
                   stopped_,
                   stopped_after_calls_,
                   stop_error_};
}

}  // namespace apprentice
