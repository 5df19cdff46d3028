#include "experiment/progress.h"

namespace apprentice {
namespace {

class ObservedLlmClient final : public llm::LlmClient {
 public:
  ObservedLlmClient(std::unique_ptr<llm::LlmClient> inner, ExperimentObserver& observer)
      : inner_(std::move(inner)), observer_(observer) {}

  std::string describe() const override { return inner_->describe(); }
  bool pools_sources() const override { return inner_->pools_sources(); }

 protected:
  Result<llm::Completion> do_complete(const llm::CompletionRequest& request) override {
    ++calls_;
    observer_.llm_query_started(request.about, calls_);
    auto completion = inner_->complete(request);
    observer_.llm_query_finished(request.about, calls_);
    return completion;
  }

 private:
  std::unique_ptr<llm::LlmClient> inner_;
  ExperimentObserver& observer_;
  int calls_ = 0;
};

}  // namespace

std::unique_ptr<llm::LlmClient> observe_llm(std::unique_ptr<llm::LlmClient> client, ExperimentObserver& observer) {
  return std::make_unique<ObservedLlmClient>(std::move(client), observer);
}

}  // namespace apprentice
