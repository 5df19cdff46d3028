#include "cmd_benchmark.h"

#include <filesystem>
#include <fstream>
#include <iostream>

#include "benchmark/tidybot_benchmark.h"
#include "experiment/runner.h"
#include "llm/factory.h"
#include "llm/placement_corpus.h"
#include "util/text.h"

namespace apprentice::cli {

namespace {

Status write_transcripts(const benchmark::BenchmarkResults& results, const std::filesystem::path& dir) {
  for (const benchmark::SettingResult& r : results.results) {
    std::error_code ec;
    const std::filesystem::path setting_dir = dir / r.setting.name;
    std::filesystem::create_directories(setting_dir, ec);
    if (ec) return make_error(ErrorCode::kIo, setting_dir.string() + ": " + ec.message());
    for (const benchmark::ScenarioOutcome& s : r.scenarios) {
      const std::filesystem::path path = setting_dir / (std::to_string(s.index) + ".txt");
      std::ofstream file(path, std::ios::binary);
      file << s.transcript;
      file.close();
      if (!file) return make_error(ErrorCode::kIo, path.string() + ": write failed");
    }
  }
  return {};
}

}  // namespace

CommandResult run_benchmark(const BenchmarkCommandOptions& options, std::ostream& out) {
  if (options.benchmark != "tidybot")
    return make_error(ErrorCode::kInvalidInput,
                      apprentice::quoted(options.benchmark) + " is not a benchmark; the one there is: tidybot");
  auto scenarios = benchmark::load_tidybot_scenarios(options.scenarios);
  if (!scenarios) return tl::unexpected(scenarios.error());
  if (!options.only.empty()) {
    std::vector<benchmark::TidyBotScenario> chosen;
    for (int index : options.only) {
      auto it = std::find_if(scenarios->begin(), scenarios->end(),
                             [&](const benchmark::TidyBotScenario& s) { return s.index == index; });
      if (it == scenarios->end())
        return make_error(ErrorCode::kInvalidInput, "--only: " + options.scenarios + " has no scenario " +
                                                        std::to_string(index));
      chosen.push_back(*it);
    }
    *scenarios = std::move(chosen);
  }
  benchmark::BenchmarkOptions run;
  for (const std::string& name : options.settings) {
    auto setting = benchmark::parse_setting(name);
    if (!setting) return tl::unexpected(prefix_error(setting.error(), "--settings"));
    run.settings.push_back(*setting);
  }
  run.prompts_dir = data_dir() / "prompts";
  run.domain = data_dir() / "domains" / "kitchen.pddl";
  run.keep_transcripts = !options.transcript_dir.empty();
  if (auto spec = llm::resolve_llm_spec(options.llm.spec)) {
    auto reachable = check_llm_before_run(*spec, llm_options(options.llm), options.llm.optional);
    if (!reachable) return tl::unexpected(reachable.error());
    // TidyBot's own recorded answers, when they are the LLM: their scores beside ours.
    if (spec->starts_with("corpus:") && llm::PlacementCorpusClient::recognizes(spec->substr(7))) {
      auto answers = llm::read_recorded_answers(spec->substr(7));
      if (!answers) return tl::unexpected(answers.error());
      run.recorded_answers = std::move(*answers);
    }
    if (*reachable) {
      const llm::LlmOptions client_options = llm_options(options.llm);
      run.llm = [spec = *spec, client_options] { return llm::make_llm_client(spec, client_options); };
    }
  }
  auto results = benchmark::run_tidybot(*scenarios, run);
  if (!results) return tl::unexpected(results.error());
  if (run.keep_transcripts)
    if (auto s = write_transcripts(*results, options.transcript_dir); !s) return tl::unexpected(s.error());
  out << (options.json ? benchmark::tidybot_json(*results) + "\n" : benchmark::format_tidybot_table(*results));
  for (const benchmark::SettingResult& r : results->results)
    if (r.llm_failures > 0 && !options.llm.optional)
      return make_error(ErrorCode::kUnavailable, "the LLM failed " + std::to_string(r.llm_failures) + " times in " +
                                                     r.setting.name + ": its figures are degraded (--llm-optional "
                                                     "accepts a run without it)");
  return Outcome::kSuccess;
}

}  // namespace apprentice::cli
