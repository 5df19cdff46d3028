// The LLM as a knowledge source for the agent: retrieves candidate goals
// and next actions with the paper's algorithms (llm/retrieval.h) and keeps
// the counts the experiment reports. Grounding and confirming candidates is
// the agent's business.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "llm/llm_client.h"
#include "llm/prompts.h"
#include "llm/retrieval.h"

namespace apprentice {

struct LlmTotals {
  int calls = 0;
  long tokens = 0;
  int failures = 0;  // retrievals cut short by an unavailable LLM
};

class LlmAdvisor {
 public:
  LlmAdvisor(std::unique_ptr<llm::LlmClient> client, llm::PromptTemplates templates);

  // Candidate goal statements, most probable first. An LLM failure gives
  // what was retrieved before it (possibly nothing) and `last_failure`.
  std::vector<llm::Candidate> goals(const llm::TaskContext& context);
  // Candidate next steps towards `goal_text`, most probable first.
  std::vector<llm::Candidate> actions(const llm::TaskContext& context, const std::string& goal_text,
                                      const std::vector<std::string>& steps_so_far,
                                      const llm::IsKnownActionWord& is_known_action_word);

  LlmTotals totals() const;
  // The error that cut the last retrieval short, if any.
  const std::optional<Error>& last_failure() const { return last_failure_; }
  std::string describe() const { return client_->describe(); }

 private:
  void account(const llm::Retrieval& retrieval);

  std::unique_ptr<llm::LlmClient> client_;
  llm::PromptTemplates templates_;
  int failures_ = 0;
  std::optional<Error> last_failure_;
};

}  // namespace apprentice
