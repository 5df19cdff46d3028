#include "experiment/runner.h"

#include <filesystem>

#include <nlohmann/json.hpp>

#include "util/json.h"

#include "util/log.h"

namespace apprentice {

std::string per_condition_llm_spec(const std::string& spec, const std::string& condition) {
  for (const char* scheme : {"record:", "replay:"}) {
    std::string prefix = scheme;
    if (spec.rfind(prefix, 0) != 0) continue;
    std::string rest = spec.substr(prefix.size());
    std::size_t comma = prefix == "record:" ? rest.find(',') : std::string::npos;
    std::filesystem::path file = rest.substr(0, comma);
    std::string tail = comma == std::string::npos ? "" : rest.substr(comma);
    std::filesystem::path renamed =
        file.parent_path() / (file.stem().string() + "." + condition + file.extension().string());
    return prefix + renamed.string() + tail;
  }
  return spec;
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
  const int count = static_cast<int>(conditions.size());
  for (int i = 0; i < count; ++i) {
    const Condition& condition = conditions[i];
    if (request.llm_spec) {
      std::string spec = count > 1 ? per_condition_llm_spec(*request.llm_spec, condition.name) : *request.llm_spec;
      options.llm = make_factory(spec, request.llm_options, request.observer);
    }
    if (request.observer) request.observer->condition_started(condition.name, i, count);
    spdlog::info("running condition {}", condition.name);
    auto result = run_condition(scenario, condition, options);
    if (!result) return tl::unexpected(prefix_error(result.error(), "condition " + condition.name));
    if (request.observer) request.observer->condition_finished(*result);
    if (request.on_result) {
      if (auto status = request.on_result(*result); !status) return tl::unexpected(status.error());
    }
    out.results.push_back(std::move(*result));
  }
  return out;
}

std::string results_json(const std::vector<ConditionResult>& results) {
  nlohmann::json all = nlohmann::json::array();
  for (const ConditionResult& r : results)
    all.push_back(nlohmann::json{{"condition", r.condition},
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
                                 {"search_nodes", r.search_nodes},
                                 {"transfer", nlohmann::json{{"renamed", r.report.renamed}, {"analogies", r.report.analogies}}},
                                 {"wall_ms", r.wall_ms}});
  return dump_json(all, 2);
}

}  // namespace apprentice
