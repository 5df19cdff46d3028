#include "agent/llm_advisor.h"

#include "util/log.h"

namespace apprentice {

LlmAdvisor::LlmAdvisor(std::unique_ptr<llm::LlmClient> client, llm::PromptTemplates templates)
    : client_(std::move(client)), templates_(std::move(templates)) {}

void LlmAdvisor::account(const llm::Retrieval& retrieval) {
  last_failure_ = retrieval.failure;
  if (retrieval.failure) {
    ++failures_;
    spdlog::warn("the LLM failed ({}); asking the instructor instead", retrieval.failure->describe());
  }
}

std::vector<llm::Candidate> LlmAdvisor::goals(const llm::TaskContext& context) {
  llm::Retrieval retrieval = llm::retrieve_goals(*client_, templates_, context);
  account(retrieval);
  llm::sort_by_mean_logprob(retrieval.candidates);
  return retrieval.candidates;
}

std::vector<llm::Candidate> LlmAdvisor::actions(const llm::TaskContext& context, const std::string& goal_text,
                                                const std::vector<std::string>& steps_so_far,
                                                const llm::IsKnownActionWord& is_known_action_word) {
  llm::Retrieval retrieval =
      llm::retrieve_actions(*client_, templates_, context, goal_text, steps_so_far, is_known_action_word);
  account(retrieval);
  llm::sort_by_mean_logprob(retrieval.candidates);
  return retrieval.candidates;
}

LlmTotals LlmAdvisor::totals() const {
  const llm::LlmUsage& usage = client_->usage();
  return LlmTotals{static_cast<int>(usage.queries), static_cast<long>(usage.prompt_tokens + usage.completion_tokens),
                   failures_};
}

}  // namespace apprentice
