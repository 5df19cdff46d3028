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
#include <algorithm>
#include <functional>
#include <limits>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "cmd_agent.h"
#include "cmd_benchmark.h"
#include "cmd_core.h"
#include "cmd_interpret.h"
#include "cmd_serve.h"
#include "face/apprentice.h"
#include "llm/factory.h"
#include "util/log.h"
#include "util/spelling.h"
#include "util/text.h"

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

// Validators whose messages name the value the way git does: "--depth: 'abc'
// is not a number" (CLI11 puts the option's name in front).
CLI::Validator whole_number_in(long low, long high) {
  return CLI::Validator(
      [low, high](std::string& text) -> std::string {
        long value = 0;
        if (!CLI::detail::lexical_cast(text, value)) return "'" + text + "' is not a whole number";
        if (value < low || value > high)
          return "'" + text + "' is out of range (" + std::to_string(low) + " to " + std::to_string(high) + ")";
        return {};
      },
      "INT in [" + std::to_string(low) + " - " + std::to_string(high) + "]");
}
CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0;
        if (!CLI::detail::lexical_cast(text, value)) return "'" + text + "' is not a number";
        if (!(value > 0)) return "'" + text + "' is not a positive number";
        return {};
      },
      "POSITIVE");
}

// --llm names a backend before anything runs, so that a slip is blamed on
// the flag, not on the first condition that would have used it. The llm
// module reads the spec (llm::check_llm_spec), so the two cannot differ.
void check_llm_flag(const LlmFlags& flags) {
  if (trim(flags.spec).empty()) return;
  if (auto checked = llm::check_llm_spec(flags.spec); !checked)
    throw CLI::ValidationError("--llm", checked.error().message);
}

// The subcommands a user can name, for "did you mean".
std::vector<std::string> command_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
  return names;
}

// The first word that is not an option of the program itself, or nothing.
std::optional<std::string> first_word(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    std::string_view arg = argv[i];
    if (arg == "--") return i + 1 < argc ? std::optional<std::string>(argv[i + 1]) : std::nullopt;
    if (!arg.starts_with("-")) return std::string(arg);
  }
  return std::nullopt;
}

// "apprentice: 'frobnicate' is not a command. See 'apprentice --help'." and
// "did you mean" for a near miss, as git says it.
int not_a_command(const CLI::App& app, const std::string& word) {
  std::cerr << "apprentice: '" << word << "' is not a command. See 'apprentice --help'.\n";
  if (auto near = closest_match(word, command_names(app))) std::cerr << "\nThe most similar command is\n\t" << *near << "\n";
  return 2;
}

// `apprentice help [COMMAND]`, as `git help`.
int help(const CLI::App& app, int argc, char** argv) {
  int at = 1;
  while (at < argc && std::string_view(argv[at]) != "help") ++at;
  if (at + 1 >= argc) {
    std::cout << app.help();
    return 0;
  }
  const std::string word = argv[at + 1];
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->get_name() == word) {
      std::cout << sub->help();
      return 0;
    }
  return not_a_command(app, word);
}

// The options of `command` (and of the program) a user may type, long and
// short: "--scenario", "-q".
std::vector<std::string> option_names(const CLI::App& app, const CLI::App* command) {
  std::vector<std::string> names;
  for (const CLI::App* owner : {command, &app}) {
    if (owner == nullptr) continue;
    for (const CLI::Option* option : owner->get_options()) {
      for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
      for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    }
  }
  return names;
}

// The first word of the command line that looks like an option and is none
// of `command`'s: "--scenrio" (from "--scenrio=FILE" too), or nothing.
std::optional<std::string> unknown_option(const std::vector<std::string>& known, int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    std::string_view arg = argv[i];
    if (arg == "--") break;
    if (!arg.starts_with("-") || arg == "-") continue;
    std::string name(arg.substr(0, arg.find('=')));
    if (std::find(known.begin(), known.end(), name) == known.end()) return name;
  }
  return std::nullopt;
}

// A CLI11 error as the rest of our errors read: "apprentice: " first, the
// subcommand named, and where to look for help. An option that is none of
// the command's is named alone, with the nearest one when it is a slip:
// "--scenrio: did you mean --scenario?".
int parse_failure(const CLI::App& app, const CLI::ParseError& e, int argc, char** argv) {
  std::string command;
  const CLI::App* parsed = nullptr;
  for (const CLI::App* sub : app.get_subcommands()) {
    command = sub->get_name();
    parsed = sub;
  }
  std::string message = e.what();
  if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr) {
    const std::vector<std::string> known = option_names(app, parsed);
    if (auto unknown = unknown_option(known, argc, argv)) {
      message = "unknown option " + apprentice::quoted(*unknown);
      if (auto near = closest_match(*unknown, known)) {
        message = *unknown + ": did you mean " + *near + "?";
      } else if (is_one_of(*unknown, {"--store", "--db", "--database", "--save", "--memory", "--kb"}) &&
                 std::find(known.begin(), known.end(), "--knowledge") != known.end()) {
        // Other words for the knowledge store.
        message = *unknown + ": did you mean --knowledge (the knowledge store)?";
      }
    } else {
      // "The following argument was not expected: FILE"
      const auto colon = message.find(": ");
      const std::string what = colon == std::string::npos ? message : message.substr(colon + 2);
      message = (what.starts_with("-") ? "unknown option " : "unexpected argument ") + apprentice::quoted(what);
    }
  }
  const char* stop = message.ends_with("?") ? " " : ". ";
  std::cerr << "apprentice: " << (command.empty() ? "" : command + ": ") << message << stop << "See 'apprentice help"
            << (command.empty() ? "" : " " + command) << "'.\n";
  return 2;
}

// Options marked required are checked after the rest of the command line,
// so that an unknown option or a bad value is what is reported first (CLI11
// checks requirements before leftovers). Call once every option exists.
std::map<const CLI::App*, std::vector<CLI::Option*>> defer_requirements(CLI::App& app) {
  std::map<const CLI::App*, std::vector<CLI::Option*>> required;
  for (CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    for (CLI::Option* option : sub->get_options([](const CLI::Option* o) { return o->get_required(); })) {
      option->required(false);
      required[sub].push_back(option);
    }
  return required;
}

// The world a command works in, given either way: `apprentice teach FILE`
// or `apprentice teach --scenario FILE` (not both). `serve` takes several.
class WorldArguments {
 public:
  void add(CLI::App* command, std::string& scenario) {
    Argument& world = worlds_[command];
    world.scenario = &scenario;
    command->add_option("--scenario", scenario, "Scenario file (YAML); it may also be given first, without --scenario");
    command->add_option("world", world.given, "Scenario file (YAML): the same as --scenario FILE");
  }
  void add_many(CLI::App* command, std::vector<std::string>& scenarios) {
    Argument& world = worlds_[command];
    world.many = &scenarios;
    command->add_option("world", world.many_given, "Worlds to offer, as --scenario FILE (after those given with --scenario)");
  }
  // Once `command`'s line is parsed: its world where the command reads it,
  // or a CLI error naming what is wrong.
  void take(const CLI::App* command) {
    auto found = worlds_.find(command);
    if (found == worlds_.end()) return;
    Argument& world = found->second;
    if (world.many != nullptr) {
      world.many->insert(world.many->end(), world.many_given.begin(), world.many_given.end());
      return;
    }
    if (!world.given.empty()) {
      if (!world.scenario->empty())
        throw CLI::ValidationError("unexpected argument " + apprentice::quoted(world.given) +
                                   ": the world is already given by --scenario");
      *world.scenario = world.given;
    }
    if (world.scenario->empty())
      throw CLI::ValidationError("no world given: name a scenario file, as in 'apprentice " + command->get_name() +
                                 " FILE' or '--scenario FILE'");
  }

 private:
  struct Argument {
    std::string* scenario = nullptr;           // where --scenario stores it
    std::vector<std::string>* many = nullptr;  // serve's worlds
    std::string given;                         // the world given without --scenario
    std::vector<std::string> many_given;       // serve's, given without --scenario
  };
  // std::map: its elements stay where they are, as CLI11 keeps pointers to them.
  std::map<const CLI::App*, Argument> worlds_;
};

// What the command line is read into: each command's options, where CLI11
// stores them, and what the command that ran returned. CLI11 keeps pointers
// into it, so it lives as long as the parse.
struct CommandLine {
  std::string program;  // argv[0], for the commands that start themselves again
  CommandResult result = Outcome::kSuccess;
  bool verbose = false, quiet = false;  // -v and -q (they set the log level as they are read)
  // The options each command requires, checked once its line is parsed
  // (see defer_requirements).
  std::map<const CLI::App*, std::vector<CLI::Option*>> required;
  WorldArguments worlds;

  WorldOptions world;
  PlanOptions plan;
  ExportPddlOptions export_pddl;
  InterpretOptions interpret;
  struct {
    std::string sentence, object, subtask, corpus, asked, recent;
  } interpret_given;  // optional in InterpretOptions when given
  ExperimentOptions experiment;
  TeachOptions teach;
  RunOptions run;
  KnowledgeOptions knowledge;
  serve::ServeOptions serve;
  struct {
    std::vector<std::string> scenarios, knowledge;
    std::string log_dir;
    int idle_seconds = 0;
  } serve_given;
  ServeAgentFlags serve_agent;
  BenchmarkCommandOptions bench;

  // `action` runs when `command` is the one given, after its world is taken
  // and its required options are checked.
  void on_run(CLI::App* command, std::function<void()> action) {
    command->callback([this, command, action = std::move(action)] {
      worlds.take(command);
      for (const CLI::Option* option : required[command])
        if (option->count() == 0) throw CLI::RequiredError(option->get_name());
      action();
    });
  }
};

// -v and -q are the program's, accepted before or after the subcommand
// (fallthrough), as in `apprentice run -v ...`.
void add_program_flags(CLI::App& app, CommandLine& c) {
  app.name("apprentice");
  app.require_subcommand(1);
  app.set_version_flag("--version", "apprentice 0.1.0");
  app.fallthrough();
  app.add_flag("-v,--verbose", c.verbose, "Log what the agent does to stderr")->each([](const std::string&) {
    spdlog::set_level(spdlog::level::info);
  });
  app.add_flag("-q,--quiet", c.quiet, "Log only errors")->each([](const std::string&) { spdlog::set_level(spdlog::level::err); });
}

// world, plan and export-pddl: the world and the planner, no agent.
void add_world_commands(CLI::App& app, CommandLine& c) {
  auto* world_cmd = app.add_subcommand("world", "Print the perceived world of a scenario (never its intent)");
  c.worlds.add(world_cmd, c.world.scenario);
  world_cmd->add_flag("--json", c.world.json, "Machine-readable output");
  c.on_run(world_cmd, [&c] { c.result = run_world(c.world, std::cout); });

  auto* plan_cmd = app.add_subcommand(
      "plan", "Plan from a scenario's state to a goal: greedy best-first search, or iterative deepening with --depth");
  c.worlds.add(plan_cmd, c.plan.scenario);
  plan_cmd->add_option("--goal", c.plan.goal,
                       "Goal, e.g. '(and (in ketchup1 fridge1) (closed fridge1))', or 'intent' for the whole task")
      ->required();
  plan_cmd->add_option("--depth", c.plan.depth, "Iterative deepening to this depth (a shortest plan)")
      ->check(whole_number_in(0, 64));
  plan_cmd->add_option("--node-limit,--max-nodes", c.plan.node_limit, "Stop after expanding this many nodes")
      ->check(whole_number_in(1, std::numeric_limits<long>::max()));
  plan_cmd->add_option("--time-limit", c.plan.time_limit_s, "Stop after this many seconds")->check(positive_number());
  plan_cmd->add_flag("--no-pruning", c.plan.no_pruning, "Ground every object, not only those relevant to the goal");
  plan_cmd->add_flag("--pddl", c.plan.pddl, "The plan in PDDL, one action a line, and the search's figures on a ';;' line");
  plan_cmd->add_flag("--json", c.plan.json, "Machine-readable output");
  c.on_run(plan_cmd, [&c] {
    c.plan.progress = isatty(fileno(stderr)) != 0;
    c.result = run_plan(c.plan, std::cout, std::cerr);
  });

  auto* export_cmd = app.add_subcommand("export-pddl", "Write the PDDL domain and a problem for a scenario and goal");
  c.worlds.add(export_cmd, c.export_pddl.scenario);
  export_cmd->add_option("--goal", c.export_pddl.goal, "Goal, as for plan ('intent' for the whole task)")->required();
  export_cmd->add_option("--out", c.export_pddl.out_dir, "Directory to write domain.pddl and problem.pddl into")->required();
  c.on_run(export_cmd, [&c] { c.result = run_export_pddl(c.export_pddl, std::cout); });
}

// The LLM's flags, the same on every command that may ask one.
void add_llm_flags(CLI::App* cmd, LlmFlags& flags) {
  cmd->add_option("--llm", flags.spec, "LLM backend: " + llm::llm_spec_forms() + " (default: $APPRENTICE_LLM)");
  cmd->add_option("--llm-model", flags.model, "Model name sent to the LLM server (default: $OPENAI_MODEL)");
  cmd->add_option("--llm-api-key", flags.api_key, "API key for the LLM server (default: $OPENAI_API_KEY)");
  cmd->add_option("--llm-timeout-ms", flags.timeout_ms,
                  "Time allowed for one LLM request in all, connecting, the server's work and its answer; "
                  "not retried when it runs out (default 30000)")
      ->check(whole_number_in(1, std::numeric_limits<int>::max()));
  cmd->add_option("--llm-connect-timeout-ms", flags.connect_timeout_ms,
                  "Time allowed to connect to the LLM server, within --llm-timeout-ms (default 5000)")
      ->check(whole_number_in(1, std::numeric_limits<int>::max()));
  cmd->add_option("--llm-seed", flags.seed, "Seed sent to the LLM server with every request (servers that take one)")
      ->check(whole_number_in(0, std::numeric_limits<int>::max()));
  cmd->add_flag("--llm-optional", flags.optional,
                "Go on without the LLM when its server cannot be reached or fails (else exit 4)");
  cmd->add_option("--goal-repair", flags.goal_repair,
                  "LLM goal analysis and repair: all, none, steps (drop,close,check,choose,reprompt) or "
                  "steps to leave out (-choose)")
      ->capture_default_str();
  cmd->add_option("--llm-goal-responses", flags.goal_responses,
                  "Unique goal statements retrieved per LLM query (the paper's is 3)")
      ->capture_default_str()
      ->check(CLI::Range(1, 10));
  cmd->add_flag("--offer-ungrounded", flags.offer_ungrounded,
                "Offer LLM goals and actions the agent cannot ground, as the paper did");
}

void add_interpret_command(CLI::App& app, CommandLine& c) {
  auto& given = c.interpret_given;
  auto* cmd = app.add_subcommand(
      "interpret", "Print a sentence's logical form and its grounding, or ground a corpus of LLM goal statements");
  cmd->add_option("--scenario", c.interpret.scenario, "Scenario file (YAML)")->required();
  cmd->add_option("--object", given.object, "The object of interest: an id (mug2) or a category");
  cmd->add_option("--subtask", given.subtask, "The subtask (a category --object is taken at its place)");
  cmd->add_option("--corpus", given.corpus, "A JSONL corpus of LLM goal statements to ground");
  cmd->add_flag("--json", c.interpret.json, "Machine-readable output");
  cmd->add_option("--asked", given.asked, "Read the sentence as a reply to this kind of question: " + join(question_kinds(), ", "));
  cmd->add_option("--recent", given.recent, "With --asked: the place named last (an id)");
  cmd->add_option("--choices", c.interpret.choices, "With --asked which: the ids offered")->delimiter(',')->allow_extra_args(false);
  cmd->add_option("sentence", given.sentence, "The sentence to interpret");
  c.on_run(cmd, [&c, &given] {
    InterpretOptions& options = c.interpret;
    using Given = std::pair<const std::string*, std::optional<std::string>*>;
    for (const Given& g : {Given{&given.asked, &options.asked}, Given{&given.recent, &options.recent},
                           Given{&given.sentence, &options.sentence}, Given{&given.object, &options.object},
                           Given{&given.subtask, &options.subtask}, Given{&given.corpus, &options.corpus}})
      if (!g.first->empty()) *g.second = *g.first;
    c.result = run_interpret(options, std::cout);
  });
}

// "instruction, inst+search4": spaces around the commas are not part of the names.
std::vector<std::string> trimmed_names(const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const std::string& name : names)
    if (!trim(name).empty()) out.emplace_back(trim(name));
  return out;
}

void add_experiment_command(CLI::App& app, CommandLine& c) {
  ExperimentOptions& e = c.experiment;
  auto* cmd = app.add_subcommand("experiment",
                                 "Run the paper's conditions from empty knowledge with the simulated instructor");
  c.worlds.add(cmd, e.scenario);
  cmd->add_option("--conditions", e.conditions,
                  "Comma-separated conditions, e.g. instruction,inst+search4 (default: all that can run)")
      ->delimiter(',');
  cmd->add_flag("--json", e.json, "Print a JSON array with one object per condition");
  cmd->add_option("--plot", e.plot, "Draw the results into FILE.svg or FILE.png (needs python3-matplotlib)");
  cmd->add_flag("-q,--quiet", e.quiet, "No progress line on a terminal");
  cmd->add_option("--transcript", e.transcript_dir, "Write each condition's dialogue to DIR/<condition>.txt");
  cmd->add_option("--knowledge-out", e.knowledge_out, "Keep each condition's knowledge in DIR/<condition>.sqlite");
  cmd->add_option("--knowledge-in", e.knowledge_in,
                  "Start every condition from a copy of this knowledge store, an SQLite file or postgresql://... (never modified)");
  cmd->add_option("--household", e.household, "The household whose goals and tasks --knowledge-in starts from and --knowledge-out keeps")
      ->capture_default_str();
  cmd->add_option("--generalization", e.generalization, "Rule generalization: full or paper")->capture_default_str();
  cmd->add_flag("--no-rules", e.no_rules, "Do not use learned policy rules");
  add_llm_flags(cmd, e.llm);
  c.on_run(cmd, [&c, &e] {
    e.conditions = trimmed_names(e.conditions);
    check_llm_flag(e.llm);
    c.result = run_experiment(e, c.program, std::cout);
  });
}

// teach and run: a person teaches a task, and the agent performs it alone.
void add_teach_and_run_commands(CLI::App& app, CommandLine& c) {
  TeachOptions& teach = c.teach;
  auto* teach_cmd = app.add_subcommand("teach", "Teach the agent at the terminal: it asks, you answer");
  c.worlds.add(teach_cmd, teach.scenario);
  teach_cmd->add_option("--knowledge", teach.knowledge, "Knowledge store to load and extend: an SQLite file, or postgresql://USER@HOST:PORT/DB");
  teach_cmd->add_option("--household", teach.household, "The household whose goal preferences and task structures are read and written (default: default); rules are shared")->capture_default_str();
  teach_cmd->add_option("--robot", teach.robot, "This robot's name, kept with what it learns and told to the other robots sharing the store (default: the host name)");
  teach_cmd->add_option("--condition", teach.condition, "Sources besides you: inst, inst+search4, inst+llm, ...")
      ->capture_default_str();
  teach_cmd->add_option("--generalization", teach.generalization, "Rule generalization: full or paper")
      ->capture_default_str();
  teach_cmd->add_flag("-q,--quiet", teach.quiet, "Print only the agent's questions and the summary");
  add_llm_flags(teach_cmd, teach.llm);
  c.on_run(teach_cmd, [&c, &teach] {
    check_llm_flag(teach.llm);
    c.result = run_teach(teach, c.program, stdin, std::cout);
  });

  RunOptions& run = c.run;
  auto* run_cmd = app.add_subcommand("run", "Perform a learned task with learned knowledge alone");
  c.worlds.add(run_cmd, run.scenario);
  run_cmd->add_option("--knowledge", run.knowledge, "Knowledge store: an SQLite file, or postgresql://USER@HOST:PORT/DB")->required();
  run_cmd->add_option("--household", run.household, "The household whose goal preferences and task structures are read and written (default: default); rules are shared")->capture_default_str();
  run_cmd->add_option("--task", run.task, "Task name (default: the only one learned)");
  run_cmd->add_flag("--json", run.json, "Machine-readable output");
  c.on_run(run_cmd, [&c, &run] { c.result = run_run(run, std::cout); });
}

void add_knowledge_command(CLI::App& app, CommandLine& c) {
  KnowledgeOptions& k = c.knowledge;
  auto* cmd = app.add_subcommand("knowledge", "Print what was learned (tasks, goals, rules) in English, with where each came from");
  cmd->add_option("action", k.action,
                  "export: copy the store into --to STORE; import: copy --from STORE into it (SQLite or "
                  "PostgreSQL, either way); forget WHAT: forget the rule about WHAT (\"fruit\", \"fruit on "
                  "the coffee table\"), for good")
      ->check(CLI::IsMember({"export", "import", "forget"}));
  cmd->add_option("what", k.what, "With forget: what the rule is about, and where it sends things if "
                                  "several rules are about it");
  cmd->add_option("--knowledge", k.knowledge, "Knowledge store: an SQLite file, or postgresql://USER@HOST:PORT/DB")->required();
  cmd->add_option("--household", k.household,
                  "The household whose goals and tasks to print (default: default); the rules are shared");
  cmd->add_option("--to", k.to, "With export: the store to copy into (created if missing)");
  cmd->add_option("--from", k.from, "With import: the store to copy from (only read)");
  cmd->add_option("--domain", k.domain, "PDDL domain the rules use (default: the kitchen)");
  cmd->add_flag("--json", k.json, "Machine-readable output");
  cmd->add_flag("--pddl", k.pddl, "Goals and rules in PDDL terms instead of English");
  cmd->add_flag("--all", k.all,
                "Every rule induced from the goals, also those I am less than even odds sure of (--json has all)");
  c.on_run(cmd, [&c, &k] { c.result = run_knowledge(k, c.program, std::cout); });
}

void add_serve_command(CLI::App& app, CommandLine& c) {
  serve::ServeOptions& options = c.serve;
  auto& given = c.serve_given;
  given.idle_seconds = static_cast<int>(options.limits.idle.count());
  auto* cmd = app.add_subcommand("serve", "Teach the agent from a web page: serve it, and each session it starts");
  cmd->add_option("--scenario", given.scenarios,
                  "A world to offer besides data/scenarios (YAML; repeatable; the first is preselected)");
  c.worlds.add_many(cmd, given.scenarios);
  cmd->add_option("--knowledge", given.knowledge,
                  "A knowledge store to offer, named on the page by its file or database name: an SQLite file "
                  "(created if missing), or postgresql://USER@HOST:PORT/DB (repeatable)");
  cmd->add_option("--household", options.household,
                  "The household whose goals and tasks every session reads and writes; rules are shared")
      ->capture_default_str();
  cmd->add_option("--robot", options.agent.robot,
                  "This robot's name, kept with what its sessions learn and told to the other robots sharing the "
                  "store (default: the host name)");
  cmd->add_option("--host", options.host, "Address to listen on (other than loopback: needs --token)")
      ->capture_default_str();
  cmd->add_option("--port", options.port, "Port to listen on (0: any free port)")
      ->capture_default_str()
      ->check(whole_number_in(0, 65535));
  cmd->add_option("--token", options.token, "Secret every request must carry (16+ letters, digits, - or _)");
  cmd->add_option("--log-dir", given.log_dir, "Keep each session's log as DIR/<session>.jsonl");
  cmd->add_option("--max-sessions", options.limits.max_sessions, "Sessions teaching at once")
      ->capture_default_str()
      ->check(whole_number_in(1, 256));
  cmd->add_option("--idle-seconds", given.idle_seconds, "End a session whose question has waited this long with no request from its page")
      ->capture_default_str()
      ->check(whole_number_in(1, 7 * 24 * 3600));
  cmd->add_option("--condition", c.serve_agent.condition, "Sources besides the person: inst, inst+search4, inst+llm, ...")
      ->capture_default_str();
  cmd->add_option("--generalization", c.serve_agent.generalization, "Rule generalization: full or paper")
      ->capture_default_str();
  add_llm_flags(cmd, c.serve_agent.llm);
  c.on_run(cmd, [&c, &options, &given] {
    check_llm_flag(c.serve_agent.llm);
    options.scenarios.assign(given.scenarios.begin(), given.scenarios.end());
    options.knowledge = given.knowledge;
    if (!given.log_dir.empty()) options.log_dir = given.log_dir;
    options.limits.idle = std::chrono::seconds(given.idle_seconds);
    c.result = run_serve(options, c.serve_agent, std::cout);
  });
}

void add_benchmark_command(CLI::App& app, CommandLine& c) {
  BenchmarkCommandOptions& bench = c.bench;
  auto* cmd = app.add_subcommand(
      "benchmark", "Run an outside benchmark through the agent and print its published figures beside ours");
  cmd->add_option("name", bench.benchmark, "The benchmark: tidybot (Wu et al. 2023)")->required();
  cmd->add_option("--scenarios", bench.scenarios, "The benchmark's scenarios, in its own format (scenarios.yml)")
      ->required();
  cmd->add_option("--settings", bench.settings,
                  "Comma-separated settings: a-alone, a-alone+llm, a-teacher, a-teacher+llm, b-alone, "
                  "b-alone+llm, b-teacher (default: all that can run)")
      ->delimiter(',');
  cmd->add_option("--only", bench.only, "Run only the scenarios with these benchmark indexes (comma-separated)")
      ->delimiter(',')
      ->check(whole_number_in(1, std::numeric_limits<int>::max()));
  cmd->add_option("--transcript", bench.transcript_dir, "Write each dialogue to DIR/<setting>/<index>.txt");
  cmd->add_flag("--json", bench.json, "Right, wrong and left counts and questions per setting, tag and scenario");
  add_llm_flags(cmd, bench.llm);
  c.on_run(cmd, [&c, &bench] {
    bench.settings = trimmed_names(bench.settings);
    check_llm_flag(bench.llm);
    c.result = run_benchmark(bench, std::cout);
  });
}

// Reads the command line and runs the command it names: `help`, a word that
// is no command, and a line CLI11 refuses are answered before anything runs.
int parse_and_run(CLI::App& app, CommandLine& c, int argc, char** argv) {
  c.required = defer_requirements(app);
  if (auto word = first_word(argc, argv)) {
    if (*word == "help") return help(app, argc, argv);
    const std::vector<std::string> names = command_names(app);
    if (std::find(names.begin(), names.end(), *word) == names.end()) return not_a_command(app, *word);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    return parse_failure(app, e, argc, argv);
  }
  return finish(c.result);
}

int run(int argc, char** argv) {
  CLI::App app{"apprentice: an agent that learns new tasks online, in one shot, from an instructor, "
               "its own search, an LLM and WordNet"};
  CommandLine c;
  c.program = argc > 0 ? argv[0] : "apprentice";
  add_program_flags(app, c);
  add_world_commands(app, c);
  add_interpret_command(app, c);
  add_experiment_command(app, c);
  add_teach_and_run_commands(app, c);
  add_knowledge_command(app, c);
  add_serve_command(app, c);
  add_benchmark_command(app, c);
  return parse_and_run(app, c, argc, argv);
}

}  // namespace
}  // namespace apprentice::cli

int main(int argc, char** argv) {
  apprentice::configure_logging(apprentice::LogLevel::kWarn);
  return apprentice::cli::run(argc, argv);
}
