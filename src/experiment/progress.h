// Watching an experiment or a teaching session as it runs: which condition,
// which LLM query. The CLI draws a progress line on a terminal from these
// events (apps/apprentice/progress.h); a program may log them.
#pragma once

#include <memory>
#include <string>

#include "llm/llm_client.h"

namespace apprentice {

struct ConditionResult;

// Every method has an empty default, so an observer overrides what it
// needs. Called on the thread that runs the experiment; an observer must
// not throw.
class ExperimentObserver {
 public:
  virtual ~ExperimentObserver() = default;
  // `index` counts from 0 up to `count` - 1.
  virtual void condition_started(const std::string& condition, int index, int count) {
    (void)condition, (void)index, (void)count;
  }
  virtual void condition_finished(const ConditionResult& result) { (void)result; }
  // Before and after each LLM query; `calls` counts the queries of this
  // client so far, this one included.
  virtual void llm_query_started(const llm::QueryAbout& about, int calls) { (void)about, (void)calls; }
  virtual void llm_query_finished(const llm::QueryAbout& about, int calls) { (void)about, (void)calls; }
};

// Wraps `client` so that `observer` hears of every query it answers. The
// observer must outlive the returned client. Answers, errors and the
// description are the wrapped client's, unchanged.
std::unique_ptr<llm::LlmClient> observe_llm(std::unique_ptr<llm::LlmClient> client, ExperimentObserver& observer);

}  // namespace apprentice
