#include "experiment/runner.h"

#include <algorithm>
#include <fstream>

#include <nlohmann/json.hpp>

#include "util/json.h"

#include "util/log.h"

namespace apprentice {

std::string per_condition_llm_spec(const std::string& spec, const std::string& condition) {
  return llm::spec_for_condition(spec, condition);
}

namespace {

LlmFactory make_factory(std::string spec, llm::LlmOptions options, ExperimentObserver* observer) {
  return [spec = std::move(spec), options = std::move(options), observer]() -> Result<std::unique_ptr<llm::LlmClient>> {
    auto client = llm::make_llm_client(spec, options);
    if (!client) return tl::unexpected(client.error());
    if (observer) return observe_llm(std::move(*client), *observer);
    return std::move(*client);
  };
}

}  // namespace

Result<ExperimentResults> run_experiment(const Scenario& scenario, const ExperimentRequest& request) {
  ExperimentResults out;
  std::vector<Condition> conditions;
  if (request.conditions.empty()) {
    for (const std::string& name : paper_condition_names()) {
      auto condition = parse_condition(name);
      if (!condition) return tl::unexpected(condition.error());
      if (condition->llm && !request.llm_spec) out.skipped.push_back(name);
      else conditions.push_back(*condition);
    }
  } else {
    for (const std::string& name : request.conditions) {
      auto condition = parse_condition(name);
      if (!condition) return tl::unexpected(condition.error());
      conditions.push_back(*condition);
    }
  }
  ExperimentOptions options = request.options;
  if (request.llm_spec && std::any_of(conditions.begin(), conditions.end(), [](const Condition& c) { return c.llm; })) {
    auto reachable = check_llm_before_run(*request.llm_spec, request.llm_options, request.llm_optional);
    if (!reachable) return tl::unexpected(reachable.error());
    options.llm_disabled = !*reachable;
  }
  const int count = static_cast<int>(conditions.size());
  bool llm_suspect = false;  // the breaker tripped in the last LLM condition
  for (int i = 0; i < count; ++i) {
    const Condition& condition = conditions[i];
    if (request.llm_spec) {
      std::string spec = count > 1 ? per_condition_llm_spec(*request.llm_spec, condition.name) : *request.llm_spec;
      options.llm = make_factory(spec, request.llm_options, request.observer);
    }
    if (condition.llm && llm_suspect && !options.llm_disabled) {
      // The breaker tripped in an earlier condition: ask the server once
      // more before this one depends on it, so that a server that died or
      // hung costs this condition one timeout rather than the breaker's three.
      auto answers = check_llm_before_run(*request.llm_spec, request.llm_options, true, LlmCheck::kBetweenConditions);
      if (!answers) return tl::unexpected(answers.error());
      options.llm_disabled = !*answers;
      llm_suspect = false;
    }
    if (request.observer) request.observer->condition_started(condition.name, i, count);
    spdlog::info("running condition {}", condition.name);
    auto result = run_condition(scenario, condition, options);
    if (!result) return tl::unexpected(prefix_error(result.error(), "condition " + condition.name));
    if (request.observer) request.observer->condition_finished(*result);
    if (request.on_result) {
      if (auto status = request.on_result(*result); !status) return tl::unexpected(status.error());
    }
    if (result->llm_stopped_after_calls) llm_suspect = true;
    out.results.push_back(std::move(*result));
  }
  return out;
}

Status write_transcript(const std::filesystem::path& dir, const ConditionResult& result) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return make_error(ErrorCode::kIo, dir.string() + ": " + ec.message());
  const std::filesystem::path path = dir / (result.condition + ".txt");
  std::ofstream file(path, std::ios::binary);
  file << result.transcript;
  file.close();
  if (!file) return make_error(ErrorCode::kIo, path.string() + ": write failed");
  return {};
}

std::string results_json(const std::vector<ConditionResult>& results) {
  nlohmann::json all = nlohmann::json::array();
  for (const ConditionResult& r : results)
    all.push_back(nlohmann::json{{"condition", r.condition},
                                 {"llm_failures", r.llm_failures},
                                 {"degraded", r.degraded()},
                                 {"degraded_why", r.degraded() ? nlohmann::json(degraded_why(r)) : nlohmann::json(nullptr)},
                                 {"llm_stopped", r.llm_stopped},
                                 {"llm_stopped_after_calls", r.llm_stopped_after_calls ? nlohmann::json(*r.llm_stopped_after_calls)
                                                                                      : nlohmann::json(nullptr)},
                                 {"llm_stop_error", r.llm_stop_error.empty() ? nlohmann::json(nullptr)
                                                                             : nlohmann::json(r.llm_stop_error)},
                                 {"llm_ensemble", r.llm_ensemble},
                                 {"completion_rate", r.completion_rate},
                                 {"assertions_achieved", r.assertions_achieved},
                                 {"assertions_total", r.assertions_total},
                                 {"objects_done", r.objects_done},
                                 {"objects_total", r.objects_total},
                                 {"instructions", r.counts.instructions},
                                 {"words", r.counts.words},
                                 {"yes_no", r.counts.yes_no},
                                 {"relevance", r.relevance ? nlohmann::json(*r.relevance) : nlohmann::json(nullptr)},
                                 {"llm_calls", r.llm_calls},
                                 {"llm_tokens", r.llm_tokens},
                                 {"search_nodes", r.agent.search_nodes},
                                 {"transfer", nlohmann::json{{"renamed", r.agent.renamed}, {"analogies", r.agent.analogies}}},
                                 {"wall_ms", r.wall_ms}});
  return dump_json(all, 2);
}

}  // namespace apprentice
