// The agent's subcommands: experiment, teach, run and knowledge.
#pragma once

#include <cstdio>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "face/apprentice.h"
#include "llm/factory.h"
#include "outcome.h"

namespace apprentice::cli {

// Options shared by the subcommands that may use an LLM.
struct LlmFlags {
  std::string spec;  // --llm; APPRENTICE_LLM when empty
  std::string model;
  std::optional<std::string> api_key;
  std::optional<int> timeout_ms;
  std::optional<int> connect_timeout_ms;
  std::optional<int> seed;  // --llm-seed
  // Go on without the LLM when its server cannot be reached (else exit 4).
  bool optional = false;
  std::string goal_repair = "all";  // --goal-repair
  bool offer_ungrounded = false;    // --offer-ungrounded
  int goal_responses = 5;           // --llm-goal-responses
};

// The face's LLM spec from the flags (face/apprentice.h).
LlmSpec llm_spec(const LlmFlags& flags);
// The LLM client's options from the flags.
llm::LlmOptions llm_options(const LlmFlags& flags);

struct ExperimentOptions {
  std::string scenario;
  std::vector<std::string> conditions;  // empty: every condition that can run
  bool json = false;
  std::string transcript_dir;
  std::string knowledge_out;
  std::string knowledge_in;  // empty: every condition starts from nothing
  std::string household = kDefaultHousehold;  // the household --knowledge-in reads and --knowledge-out keeps
  std::string generalization = "full";
  bool no_rules = false;
  std::string plot;    // --plot FILE.svg|FILE.png: draw the results
  bool quiet = false;  // no progress line
  LlmFlags llm;
};
CommandResult run_experiment(const ExperimentOptions& options, const std::string& program, std::ostream& out);

struct TeachOptions {
  std::string scenario;
  std::string knowledge;  // empty: nothing kept
  std::string household = kDefaultHousehold;
  std::string robot;  // empty: the host name
  std::string condition = "inst+search4";
  std::string generalization = "full";
  bool quiet = false;  // only the questions and the summary; no progress line
  LlmFlags llm;
};
CommandResult run_teach(const TeachOptions& options, const std::string& program, std::FILE* in, std::ostream& out);

struct RunOptions {
  std::string scenario;
  std::string knowledge;
  std::string household = kDefaultHousehold;
  std::string task;  // empty: the only task learned
  bool json = false;
};
CommandResult run_run(const RunOptions& options, std::ostream& out);

struct KnowledgeOptions {
  // "" (print what was learned), "export" (copy into `to`) or "import"
  // (copy from `from`).
  // "forget": forget the class rule `what` names, for good.
  std::string action;
  std::vector<std::string> what;
  std::string to, from;
  std::string knowledge;
  // The household printed; empty: the default one (export and import copy
  // every household and refuse this).
  std::string household;
  std::string domain;  // empty: the shipped kitchen domain
  bool json = false;
  bool pddl = false;  // goals and rules in PDDL terms, not English
  bool all = false;   // every rule induced from the goals, not only those at least even odds
};
CommandResult run_knowledge(const KnowledgeOptions& options, const std::string& program, std::ostream& out);

}  // namespace apprentice::cli
