// `apprentice benchmark tidybot`: the TidyBot benchmark through the agent
// (src/benchmark/tidybot_benchmark.h).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "cmd_agent.h"
#include "outcome.h"

namespace apprentice::cli {

struct BenchmarkCommandOptions {
  std::string benchmark;              // "tidybot", the only one
  std::string scenarios;              // --scenarios FILE (the benchmark's own format)
  std::vector<std::string> settings;  // empty: every setting that can run
  std::vector<int> only;              // --only: these benchmark indexes
  std::string transcript_dir;         // --transcript DIR: DIR/<setting>/<index>.txt
  bool json = false;
  LlmFlags llm;
};
CommandResult run_benchmark(const BenchmarkCommandOptions& options, std::ostream& out);

}  // namespace apprentice::cli
