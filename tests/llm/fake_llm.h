// A scripted LlmClient for the algorithm tests: answers with a function of
// the request and keeps every request it saw.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "llm/llm_client.h"
#include "util/text.h"

namespace apprentice::llm::testing {

class FakeClient : public LlmClient {
 public:
  using Responder = std::function<Result<Completion>(const CompletionRequest&, size_t call)>;
  explicit FakeClient(Responder responder) : responder_(std::move(responder)) {}
  std::string describe() const override { return "fake"; }

  std::vector<CompletionRequest> requests;

  std::vector<double> temperatures() const {
    std::vector<double> out;
    for (const auto& request : requests) out.push_back(request.temperature);
    return out;
  }

 protected:
  Result<Completion> do_complete(const CompletionRequest& request) override {
    requests.push_back(request);
    return responder_(request, requests.size() - 1);
  }

 private:
  Responder responder_;
};

// A model answer whose words are tokens, each with `logprob`.
inline Completion answer(const std::string& text, double logprob = -0.1) {
  Completion completion;
  for (const std::string& word : split_words(text)) {
    completion.tokens.push_back(TokenLogprob{" " + word, logprob});
    completion.top_logprobs.push_back({TokenLogprob{" " + word, logprob}});
  }
  completion.text = " " + text;
  completion.completion_tokens = static_cast<int64_t>(completion.tokens.size());
  completion.finish_reason = "stop";
  return completion;
}

}  // namespace apprentice::llm::testing
