// The apprentice command line. This is the only place where errors become
// exit codes:
//   0  success
//   1  the goal or task was not reached
//   2  bad input: a malformed file, flag or sentence; a missing file
//   3  local storage failed or holds unreadable data
//   4  a needed service (the LLM server) is unavailable or timed out
//   130 interrupted
#include <unistd.h>

#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>

#include "cmd_agent.h"
#include "cmd_core.h"
#include "cmd_interpret.h"
#include "util/log.h"

namespace apprentice::cli {
namespace {

int exit_code_for(const Error& error) {
  switch (error.code) {
    case ErrorCode::kInvalidInput:
    case ErrorCode::kNotFound:
    case ErrorCode::kFailedPrecondition: return 2;
    case ErrorCode::kIo:
    case ErrorCode::kDataLoss: return 3;
    case ErrorCode::kUnavailable:
    case ErrorCode::kDeadlineExceeded: return 4;
    case ErrorCode::kCancelled: return 130;
  }
  return 2;
}

int finish(const CommandResult& result) {
  if (!result) {
    std::cerr << "apprentice: " << result.error().describe() << "\n";
    return exit_code_for(result.error());
  }
  if (*result == Outcome::kInterrupted) return 130;
  return *result == Outcome::kSuccess ? 0 : 1;
}

int run(int argc, char** argv) {
  CLI::App app{"apprentice: an agent that learns new tasks online, in one shot, from an instructor, "
               "its own search, an LLM and WordNet"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "apprentice 0.1.0");
  bool verbose = false;
  app.add_flag("-v,--verbose", verbose, "Log what the agent does to stderr")->each([](const std::string&) {
    spdlog::set_level(spdlog::level::info);
  });

  CommandResult result = Outcome::kSuccess;

  WorldOptions world;
  auto* world_cmd = app.add_subcommand("world", "Print the perceived world of a scenario (never its intent)");
  world_cmd->add_option("--scenario", world.scenario, "Scenario file (YAML)")->required();
  world_cmd->add_flag("--json", world.json, "Machine-readable output");
  world_cmd->callback([&] { result = run_world(world, std::cout); });

  PlanOptions plan;
  auto* plan_cmd = app.add_subcommand(
      "plan", "Plan from a scenario's state to a goal: greedy best-first search, or iterative deepening with --depth");
  plan_cmd->add_option("--scenario", plan.scenario, "Scenario file (YAML)")->required();
  plan_cmd->add_option("--goal", plan.goal,
                       "Goal, e.g. '(and (in ketchup1 fridge1) (closed fridge1))', or 'intent' for the whole task")
      ->required();
  plan_cmd->add_option("--depth", plan.depth, "Iterative deepening to this depth (a shortest plan)")
      ->check(CLI::Range(0, 64));
  plan_cmd->add_option("--node-limit,--max-nodes", plan.node_limit, "Stop after expanding this many nodes")
      ->check(CLI::PositiveNumber);
  plan_cmd->add_option("--time-limit", plan.time_limit_s, "Stop after this many seconds")
      ->check(CLI::PositiveNumber);
  plan_cmd->add_flag("--no-pruning", plan.no_pruning, "Ground every object, not only those relevant to the goal");
  plan_cmd->add_flag("--json", plan.json, "Machine-readable output");
  plan_cmd->callback([&] {
    plan.progress = isatty(fileno(stderr)) != 0;
    result = run_plan(plan, std::cout, std::cerr);
  });

  ExportPddlOptions export_pddl;
  auto* export_cmd = app.add_subcommand("export-pddl", "Write the PDDL domain and a problem for a scenario and goal");
  export_cmd->add_option("--scenario", export_pddl.scenario, "Scenario file (YAML)")->required();
  export_cmd->add_option("--goal", export_pddl.goal, "Goal, as for plan ('intent' for the whole task)")->required();
  export_cmd->add_option("--out", export_pddl.out_dir, "Directory to write domain.pddl and problem.pddl into")->required();
  export_cmd->callback([&] { result = run_export_pddl(export_pddl, std::cout); });

  auto add_llm_flags = [](CLI::App* cmd, LlmFlags& flags) {
    cmd->add_option("--llm", flags.spec,
                    "LLM backend: openai:URL, llama:URL, replay:FILE, record:FILE,SPEC, corpus:FILE "
                    "(default: $APPRENTICE_LLM)");
    cmd->add_option("--llm-model", flags.model, "Model name sent to the LLM server (default: $OPENAI_MODEL)");
    cmd->add_option("--llm-api-key", flags.api_key, "API key for the LLM server (default: $OPENAI_API_KEY)");
    cmd->add_option("--llm-timeout-ms", flags.timeout_ms, "Total time allowed for one LLM request")
        ->check(CLI::PositiveNumber);
  };
  const std::string program = argc > 0 ? argv[0] : "apprentice";

  InterpretOptions interpret;
  std::string interpret_sentence, interpret_object, interpret_subtask, interpret_corpus;
  auto* interpret_cmd = app.add_subcommand(
      "interpret", "Print a sentence's logical form and its grounding, or ground a corpus of LLM goal statements");
  interpret_cmd->add_option("--scenario", interpret.scenario, "Scenario file (YAML)")->required();
  interpret_cmd->add_option("--object", interpret_object, "The object of interest: an id (mug2) or a category");
  interpret_cmd->add_option("--subtask", interpret_subtask, "The subtask (a category --object is taken at its place)");
  interpret_cmd->add_option("--corpus", interpret_corpus, "A JSONL corpus of LLM goal statements to ground");
  interpret_cmd->add_flag("--json", interpret.json, "Machine-readable output");
  std::string interpret_asked, interpret_recent;
  interpret_cmd->add_option("--asked", interpret_asked,
                            "Read the sentence as a reply to a question: task, task-step, subtask-end, goal, action, "
                            "yes-no or which");
  interpret_cmd->add_option("--recent", interpret_recent, "With --asked: the place named last (an id)");
  interpret_cmd->add_option("--choices", interpret.choices, "With --asked which: the ids offered")->delimiter(',')->allow_extra_args(false);
  interpret_cmd->add_option("sentence", interpret_sentence, "The sentence to interpret");
  interpret_cmd->callback([&] {
    if (!interpret_asked.empty()) interpret.asked = interpret_asked;
    if (!interpret_recent.empty()) interpret.recent = interpret_recent;
    if (!interpret_sentence.empty()) interpret.sentence = interpret_sentence;
    if (!interpret_object.empty()) interpret.object = interpret_object;
    if (!interpret_subtask.empty()) interpret.subtask = interpret_subtask;
    if (!interpret_corpus.empty()) interpret.corpus = interpret_corpus;
    result = run_interpret(interpret, std::cout);
  });

  ExperimentOptions experiment;
  auto* experiment_cmd = app.add_subcommand(
      "experiment", "Run the paper's conditions from empty knowledge with the simulated instructor");
  experiment_cmd->add_option("--scenario", experiment.scenario, "Scenario file (YAML)")->required();
  experiment_cmd->add_option("--conditions", experiment.conditions,
                             "Comma-separated conditions, e.g. instruction,inst+search4 (default: all that can run)")
      ->delimiter(',');
  experiment_cmd->add_flag("--json", experiment.json, "Print a JSON array with one object per condition");
  experiment_cmd->add_option("--plot", experiment.plot, "Draw the results into FILE.svg or FILE.png (needs python3-matplotlib)");
  experiment_cmd->add_flag("-q,--quiet", experiment.quiet, "No progress line on a terminal");
  experiment_cmd->add_option("--transcript", experiment.transcript_dir, "Write each condition's dialogue to DIR/<condition>.txt");
  experiment_cmd->add_option("--knowledge-out", experiment.knowledge_out, "Keep each condition's knowledge in DIR/<condition>.sqlite");
  experiment_cmd->add_option("--knowledge-in", experiment.knowledge_in,
                             "Start every condition from a copy of this knowledge store (never modified)");
  experiment_cmd->add_option("--generalization", experiment.generalization, "Rule generalization: full or paper")
      ->capture_default_str();
  experiment_cmd->add_flag("--no-rules", experiment.no_rules, "Do not use learned policy rules");
  add_llm_flags(experiment_cmd, experiment.llm);
  experiment_cmd->callback([&] { result = run_experiment(experiment, program, std::cout); });

  TeachOptions teach;
  auto* teach_cmd = app.add_subcommand("teach", "Teach the agent at the terminal: it asks, you answer");
  teach_cmd->add_option("--scenario", teach.scenario, "Scenario file (YAML)")->required();
  teach_cmd->add_option("--knowledge", teach.knowledge, "Knowledge store to load and extend (SQLite)");
  teach_cmd->add_option("--condition", teach.condition, "Sources besides you: inst, inst+search4, inst+llm, ...")
      ->capture_default_str();
  teach_cmd->add_option("--generalization", teach.generalization, "Rule generalization: full or paper")
      ->capture_default_str();
  teach_cmd->add_flag("-q,--quiet", teach.quiet, "Print only the agent's questions and the summary");
  add_llm_flags(teach_cmd, teach.llm);
  teach_cmd->callback([&] { result = run_teach(teach, program, stdin, std::cout); });

  RunOptions run_options;
  auto* run_cmd = app.add_subcommand("run", "Perform a learned task with learned knowledge alone");
  run_cmd->add_option("--scenario", run_options.scenario, "Scenario file (YAML)")->required();
  run_cmd->add_option("--knowledge", run_options.knowledge, "Knowledge store (SQLite)")->required();
  run_cmd->add_option("--task", run_options.task, "Task name (default: the only one learned)");
  run_cmd->add_flag("--json", run_options.json, "Machine-readable output");
  run_cmd->callback([&] { result = run_run(run_options, std::cout); });

  KnowledgeOptions knowledge;
  auto* knowledge_cmd = app.add_subcommand("knowledge", "Print what was learned (tasks, goals, rules) in English, with where each came from");
  knowledge_cmd->add_option("--knowledge", knowledge.knowledge, "Knowledge store (SQLite)")->required();
  knowledge_cmd->add_option("--domain", knowledge.domain, "PDDL domain the rules use (default: the kitchen)");
  knowledge_cmd->add_flag("--json", knowledge.json, "Machine-readable output");
  knowledge_cmd->add_flag("--pddl", knowledge.pddl, "Goals and rules in PDDL terms instead of English");
  knowledge_cmd->callback([&] { result = run_knowledge(knowledge, program, std::cout); });

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  return finish(result);
}

}  // namespace
}  // namespace apprentice::cli

int main(int argc, char** argv) {
  apprentice::configure_logging(apprentice::LogLevel::kWarn);
  return apprentice::cli::run(argc, argv);
}
