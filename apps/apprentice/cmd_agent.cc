#include "cmd_agent.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "agent/concept_source.h"
#include "agent/explanation.h"
#include "agent/goal_proposals.h"
#include "agent/understanding.h"
#include "experiment/experiment.h"
#include "experiment/runner.h"
#include "instructor/terminal_instructor.h"
#include "language/narration.h"
#include "llm/factory.h"
#include "plot.h"
#include "progress.h"
#include "util/json.h"
#include "util/log.h"
#include "util/text.h"
#include "world/pddl.h"

#ifndef APPRENTICE_DATA_DIR
#define APPRENTICE_DATA_DIR "data"
#endif

namespace apprentice::cli {

// The shipped data: next to the binary's build directory when run from a
// checkout (build/apprentice -> data/), else where the build was configured.
std::filesystem::path data_dir() {
  std::error_code ec;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    for (std::filesystem::path dir = exe.parent_path(); !dir.empty() && dir != dir.root_path(); dir = dir.parent_path()) {
      if (std::filesystem::exists(dir / "data" / "prompts" / "goal.txt", ec)) return dir / "data";
    }
  }
  return APPRENTICE_DATA_DIR;
}

llm::LlmOptions llm_options(const LlmFlags& flags) {
  llm::LlmOptions options;
  options.model = flags.model;
  options.api_key = flags.api_key;
  options.seed = flags.seed;
  if (flags.timeout_ms) options.transport.request_timeout = std::chrono::milliseconds(*flags.timeout_ms);
  if (flags.connect_timeout_ms) options.transport.connect_timeout = std::chrono::milliseconds(*flags.connect_timeout_ms);
  return options;
}

namespace {

Status write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  file << text;
  file.close();
  if (!file) return make_error(ErrorCode::kIo, path.string() + ": write failed");
  return {};
}

}  // namespace

// Printed under the table: what its columns mean where that is not plain.
const char* const kTableLegend =
    "Relevant%: yes answers over yes/no questions; without an instructor (search4+llm), the share of the LLM's\n"
    "goals adopted that were the intended ones. --: the condition asks the LLM nothing, as in the paper.\n"
    "n/a: it asked the LLM, but no yes/no question came of it (without an instructor: no goal was adopted).\n";

std::string skipped_hint(const std::vector<std::string>& skipped) {
  std::string names;
  for (const std::string& name : skipped) names += (names.empty() ? "" : ", ") + name;
  return "Skipped for want of an LLM: " + names +
         ".\nTo run them, pass --llm SPEC or set APPRENTICE_LLM: openai:http://127.0.0.1:8080/v1 for any "
         "OpenAI-compatible\nserver, or corpus:FILE for recorded responses (see docs/llm.md).\n";
}

// Where the LLM answers came from, for the table's header: one source for
// all, or each condition's own (a cassette each on replay).
std::string llm_sources(const std::vector<ConditionResult>& results) {
  std::vector<const ConditionResult*> asked;
  for (const ConditionResult& r : results)
    if (!r.llm_description.empty()) asked.push_back(&r);
  if (asked.empty()) return "";
  const bool one = std::all_of(asked.begin(), asked.end(),
                               [&](const ConditionResult* r) { return r->llm_description == asked.front()->llm_description; });
  if (one) return "; LLM answers from " + asked.front()->llm_description;
  std::string out = "; LLM answers from";
  for (size_t i = 0; i < asked.size(); ++i)
    out += std::string(i == 0 ? " " : ", ") + asked[i]->llm_description + " (" + asked[i]->condition + ")";
  return out;
}

// What the conditions carried over from the knowledge they started from:
// the words taken for learned ones (the same in every condition), and each
// condition's goals by analogy.
void print_transfer(const std::vector<ConditionResult>& results, std::ostream& out) {
  const std::vector<std::string>& renamed = results.front().report.renamed;
  if (renamed.empty()) out << "No learned word needed another here.\n";
  else out << "The knowledge brought in, in this world's words (every condition):\n";
  for (const std::string& note : renamed) out << "  " << note << "\n";
  for (const ConditionResult& r : results) {
    if (r.report.analogies.empty()) continue;
    out << r.condition << ", by analogy:\n";
    for (const std::string& note : r.report.analogies) out << "  " << note << "\n";
  }
}

CommandResult run_experiment(const ExperimentOptions& options, const std::string& program, std::ostream& out) {
  (void)program;
  auto scenario = load_scenario(options.scenario);
  if (!scenario) return tl::unexpected(scenario.error());
  if (auto s = check_runnable(*scenario); !s) return tl::unexpected(s.error());
  auto generalization = parse_generalization(options.generalization);
  if (!generalization) return tl::unexpected(generalization.error());
  ExperimentRequest request;
  if (!options.knowledge_in.empty()) {
    auto knowledge = load_knowledge_read_only(options.knowledge_in, *scenario->world.domain);
    if (!knowledge) return tl::unexpected(knowledge.error());
    request.options.knowledge_in = std::move(*knowledge);
  }
  request.conditions = options.conditions;
  request.llm_spec = llm::resolve_llm_spec(options.llm.spec);
  request.llm_options = llm_options(options.llm);
  request.llm_optional = options.llm.optional;
  auto repair = parse_goal_repair(options.llm.goal_repair);
  if (!repair) return tl::unexpected(repair.error());
  request.options.goal_repair = *repair;
  request.options.offer_ungrounded = options.llm.offer_ungrounded;
  request.options.goal_responses = options.llm.goal_responses;
  request.options.generalization = *generalization;
  request.options.use_rules = !options.no_rules;
  request.options.prompts_dir = data_dir() / "prompts";
  if (!options.knowledge_out.empty()) request.options.knowledge_out = options.knowledge_out;
  if (!options.transcript_dir.empty()) {
    request.on_result = [&](const ConditionResult& result) -> Status {
      std::error_code ec;
      std::filesystem::create_directories(options.transcript_dir, ec);
      if (ec) return make_error(ErrorCode::kIo, options.transcript_dir + ": " + ec.message());
      return write_file(std::filesystem::path(options.transcript_dir) / (result.condition + ".txt"), result.transcript);
    };
  }
  Result<ExperimentResults> run;
  {
    TerminalProgress progress(stderr, !options.json && !options.quiet, TerminalProgress::Mode::kWholeRun);
    if (progress.active()) request.observer = &progress;
    run = run_experiment(*scenario, request);
  }
  if (!run) return tl::unexpected(run.error());
  const std::vector<ConditionResult>& results = run->results;
  std::string json = results_json(results);
  if (options.json) {
    out << json << "\n";
  } else {
    DialogueCounts floor = instruction_floor(*scenario);
    out << "Scenario " << scenario->name << ": " << scenario->objects_to_tidy().size() << " objects to tidy, "
        << scenario->goal_assertions().size() << " goal assertions; the floor (task structure and one goal per goal "
        << "type) is " << floor.instructions << " instructions, " << floor.words << " words";
    if (request.options.knowledge_in)
      out << "; every condition starts from the knowledge in " << scrub_store_location(options.knowledge_in) << " ("
          << request.options.knowledge_in->goals.size() << " goals, " << request.options.knowledge_in->rules.size() << " rules)";
    out << llm_sources(results);
    out << "\n" << format_results_table(results, scenario->reference == "table3") << "\n" << kTableLegend;
    if (request.options.knowledge_in && !results.empty()) print_transfer(results, out);
    if (!run->skipped.empty()) out << skipped_hint(run->skipped);
  }
  if (!options.plot.empty()) {
    if (auto status = plot_results(json, options.plot, scenario->reference == "table3"); !status) return tl::unexpected(status.error());
    if (!options.json && !options.quiet) out << "The figure is in " << options.plot << ".\n";
  }
  std::vector<std::string> degraded;
  for (const ConditionResult& r : results)
    if (r.degraded()) degraded.push_back(r.condition);
  if (!degraded.empty() && !options.llm.optional)
    return make_error(ErrorCode::kUnavailable, "the LLM failed in " + join(degraded, ", ") +
                                                   ": those figures are degraded (marked '*'; --llm-optional "
                                                   "accepts a run without it)");
  return Outcome::kSuccess;
}

namespace {

// Each goal assertion that does not hold in `now`, in English, once, with
// how many times it occurs: look-alikes are named by where they were at the
// start ("the glass tumbler from the dish rack should be in the cupboard").
std::vector<std::pair<std::string, int>> unmet_assertions(const Scenario& scenario, const World& now) {
  const Universe& u = *now.universe;
  std::vector<std::pair<std::string, int>> unmet;
  for (const Literal& l : scenario.goal_assertions()) {
    if (now.state.satisfies(l)) continue;
    std::string sentence = language::expected_fact(now, l);
    if (l.fact.arity > 0 && u.info(l.fact.args[0]).kind == ObjectKind::kItem) {
      ObjectId item = l.fact.args[0];
      std::string name = language::spoken_name(now, item);
      std::string from = language::spoken_location(scenario.world, item);
      std::size_t space = from.find(' ');
      std::vector<ObjectId> alike = u.with_category(u.info(item).category);
      bool elsewhere = std::any_of(alike.begin(), alike.end(), [&](ObjectId other) {
        return language::spoken_location(scenario.world, other) != from;
      });
      if (elsewhere && space != std::string::npos && sentence.rfind(name, 0) == 0)
        sentence.insert(name.size(), " from" + from.substr(space));
    }
    auto same = std::find_if(unmet.begin(), unmet.end(), [&](const auto& entry) { return entry.first == sentence; });
    if (same == unmet.end()) unmet.emplace_back(sentence, 1);
    else ++same->second;
  }
  return unmet;
}

// The end of a teaching session, in English: how much of the scenario's
// intent holds (where it has one), which assertions do not, and where the
// knowledge is, or that nothing was kept.
void print_teach_summary(const Scenario& scenario, const State& state, bool finished, int instructions,
                         const KnowledgeStore* store, std::ostream& out) {
  std::vector<Literal> assertions = scenario.goal_assertions();
  int achieved = count_achieved_assertions(scenario, state);
  std::string instructions_phrase = language::count_phrase(instructions, "instruction");
  out << (finished ? "The task is learned" : "Stopped");
  if (assertions.empty()) out << ", after " << instructions_phrase << ".\n";
  else
    out << ": " << achieved << " of " << language::count_phrase(static_cast<long long>(assertions.size()), "goal assertion")
        << (achieved == 1 ? " holds" : " hold") << ", after " << instructions_phrase << ".\n";
  World now = scenario.world;
  now.state = state;
  for (const auto& [sentence, times] : unmet_assertions(scenario, now))
    out << "Not done: " << sentence << (times > 1 ? " (" + std::to_string(times) + " of them)" : std::string()) << ".\n";
  if (store) out << "What you taught me is kept in " << store->path().string() << ".\n";
  else
    out << "Nothing was saved. To keep what you teach, give a knowledge store: apprentice teach --scenario " << scenario.source.string()
        << " --knowledge FILE (for example kitchen.sqlite).\n";
}

}  // namespace

CommandResult run_teach(const TeachOptions& options, const std::string& program, std::FILE* in, std::ostream& out) {
  (void)program;
  auto scenario = load_scenario(options.scenario);
  if (!scenario) return tl::unexpected(scenario.error());
  auto condition = parse_condition(options.condition);
  if (!condition) return tl::unexpected(condition.error());
  condition->instruction = true;
  auto generalization = parse_generalization(options.generalization);
  if (!generalization) return tl::unexpected(generalization.error());
  std::optional<KnowledgeStore> store;
  Knowledge knowledge;
  if (!options.knowledge.empty()) {
    auto opened = KnowledgeStore::open(options.knowledge);
    if (!opened) return tl::unexpected(opened.error());
    auto loaded = opened->load(*scenario->world.domain);
    if (!loaded) return tl::unexpected(loaded.error());
    knowledge = std::move(*loaded);
    store.emplace(std::move(*opened));
  }
  // While the LLM is asked, a progress line on a terminal's stderr.
  TerminalProgress progress(stderr, !options.quiet, TerminalProgress::Mode::kLlmQueries);
  std::unique_ptr<LlmAdvisor> advisor;
  if (condition->llm) {
    auto spec = llm::resolve_llm_spec(options.llm.spec);
    if (!spec) return make_error(ErrorCode::kInvalidInput, "condition " + condition->name + " needs --llm SPEC");
    auto client = llm::make_llm_client(*spec, llm_options(options.llm));
    if (!client) return tl::unexpected(client.error());
    auto templates = llm::PromptTemplates::load(data_dir() / "prompts");
    if (!templates) return tl::unexpected(templates.error());
    auto reachable = check_llm_before_run(*spec, llm_options(options.llm), options.llm.optional);
    if (!reachable) return tl::unexpected(reachable.error());
    LlmAdvisorOptions advice;
    advice.disabled = !*reachable;
    advice.goal_responses = options.llm.goal_responses;
    std::unique_ptr<llm::LlmClient> observed = std::move(*client);
    if (progress.active()) observed = observe_llm(std::move(observed), progress);
    advisor = std::make_unique<LlmAdvisor>(std::move(observed), std::move(*templates), advice);
  }
  auto repair = parse_goal_repair(options.llm.goal_repair);
  if (!repair) return tl::unexpected(repair.error());
  AgentOptions agent_options;
  agent_options.condition = *condition;
  agent_options.generalization = *generalization;
  agent_options.goal_repair = *repair;
  agent_options.offer_ungrounded = options.llm.offer_ungrounded;
  TaskLearningAgent agent(agent_options, std::move(knowledge), Understanding(), store ? &*store : nullptr,
                          advisor.get());
  Simulator simulator(scenario->world);
  TerminalInstructor instructor(in, out, TerminalOptions{options.quiet, true});
  Dialogue dialogue(instructor);
  if (!options.quiet)
    out << "Teaching in " << scenario->name << " (" << condition->name
        << "). Answer in your own words; type help at any question. Ctrl-D or quit stops and keeps what you "
           "taught.\n";
  auto report = agent.learn(simulator, dialogue);
  if (!report && report.error().code != ErrorCode::kCancelled) return tl::unexpected(report.error());
  if (instructor.interrupted()) {
    out << "Interrupted. "
        << (store ? "What you taught me is kept in " + store->path().string() + "."
                  : std::string("Nothing was saved (no --knowledge)."))
        << "\n";
    out.flush();
    return Outcome::kInterrupted;
  }
  print_teach_summary(*scenario, simulator.state(), report.has_value(), dialogue.counts().instructions,
                      store ? &*store : nullptr, out);
  int achieved = count_achieved_assertions(*scenario, simulator.state());
  int total = static_cast<int>(scenario->goal_assertions().size());
  if (!scenario->has_intent || total == 0) return report ? Outcome::kSuccess : Outcome::kGoalNotReached;
  return achieved == total ? Outcome::kSuccess : Outcome::kGoalNotReached;
}

namespace {

// Why `run --task NAME` has nothing to perform, naming the store and what it
// holds; nothing when there is a task to perform.
std::optional<Error> unknown_task(const Knowledge& knowledge, const std::string& name, const std::string& store) {
  if (knowledge.tasks.empty())
    return Error{ErrorCode::kNotFound, store + " holds no learned task yet; teach one with 'apprentice teach'"};
  if (knowledge.find_task(name) != nullptr || (name.empty() && knowledge.tasks.size() == 1)) return std::nullopt;
  std::vector<std::string> names;
  for (const TaskKnowledge& task : knowledge.tasks) names.push_back(apprentice::quoted(task.name));
  const std::string holds = " holds " + language::count_phrase(static_cast<long long>(names.size()), "task") + ": " +
                            join(names, ", ");
  if (name.empty()) return Error{ErrorCode::kInvalidInput, "name the task with --task: " + store + holds};
  return Error{ErrorCode::kNotFound, "no task " + apprentice::quoted(name) + " has been learned; " + store + holds};
}

}  // namespace

CommandResult run_run(const RunOptions& options, std::ostream& out) {
  auto scenario = load_scenario(options.scenario);
  if (!scenario) return tl::unexpected(scenario.error());
  auto store = KnowledgeStore::open(options.knowledge, StoreAccess::kReadOnly);
  if (!store) return tl::unexpected(store.error());
  auto knowledge = store->load(*scenario->world.domain);
  if (!knowledge) return tl::unexpected(knowledge.error());
  if (auto missing = unknown_task(*knowledge, options.task, store->location())) return tl::unexpected(*missing);
  AgentOptions agent_options;
  agent_options.condition = Condition{"knowledge-only", false, 0, false};
  TaskLearningAgent agent(agent_options, std::move(*knowledge), Understanding(), nullptr, nullptr);
  Simulator simulator(scenario->world);
  auto report = agent.perform(simulator, options.task);
  if (!report) return tl::unexpected(report.error());
  int achieved = count_achieved_assertions(*scenario, simulator.state());
  int total = static_cast<int>(scenario->goal_assertions().size());
  double completion = completion_percent(achieved, total);
  // Without an intent nothing says what the task should achieve: no completion.
  const bool measured = scenario->has_intent;
  if (options.json) {
    nlohmann::json j{{"instructions", 0}, {"search_nodes", report->search_nodes}, {"llm_calls", 0},
                     {"actions", report->actions_executed}, {"help_needed", report->help_needed},
                     {"renamed", report->renamed}, {"analogies", report->analogies}};
    if (measured) {
      j["completion_rate"] = completion;
      j["assertions_achieved"] = achieved;
      j["assertions_total"] = total;
      j["objects_done"] = count_objects_done(*scenario, simulator.state());
      j["objects_total"] = scenario->objects_to_tidy().size();
    }
    out << dump_json(j, 2) << "\n";
  } else {
    out << "Performed with learned knowledge alone: ";
    if (measured)
      out << achieved << " of " << language::count_phrase(total, "goal assertion") << " ("
          << fmt::format("{:.1f}", completion) << "%), ";
    out << language::count_phrase(report->actions_executed, "action") << ", 0 instructions, "
        << language::count_phrase(static_cast<long long>(report->search_nodes), "search node") << ", 0 LLM calls.\n";
    for (const std::string& note : report->renamed) out << "From another world: I " << note << ".\n";
    for (const std::string& note : report->analogies) out << "By analogy: I " << note << ".\n";
    if (report->help_needed.empty()) out << "No help was needed.\n";
    for (const std::string& help : report->help_needed) out << "Would need help: " << help << "\n";
  }
  return (!measured || achieved == total) && report->help_needed.empty() ? Outcome::kSuccess : Outcome::kGoalNotReached;
}

namespace {

// `knowledge export --to OTHER` and `knowledge import --from OTHER`.
CommandResult copy_between_stores(const KnowledgeOptions& options, const Domain& domain, std::ostream& out) {
  const bool exporting = options.action == "export";
  const std::string& other = exporting ? options.to : options.from;
  if (other.empty() || !(exporting ? options.from : options.to).empty())
    return make_error(ErrorCode::kInvalidInput, "knowledge " + options.action + " takes " +
                                                    (exporting ? "--to STORE, the store to copy into"
                                                               : "--from STORE, the store to copy from"));
  const std::string& from = exporting ? options.knowledge : other;
  const std::string& to = exporting ? other : options.knowledge;
  auto copied = copy_knowledge(from, to, domain);
  if (!copied) return tl::unexpected(copied.error());
  if (options.json) {
    out << dump_json(nlohmann::json{{"from", scrub_store_location(from)}, {"to", scrub_store_location(to)},
                                    {"tasks", copied->tasks}, {"goals", copied->goals}, {"rules", copied->rules}},
                     2)
        << "\n";
    return Outcome::kSuccess;
  }
  out << "Copied " << language::count_phrase(static_cast<long long>(copied->tasks), "task") << ", "
      << language::count_phrase(static_cast<long long>(copied->goals), "goal") << " and "
      << language::count_phrase(static_cast<long long>(copied->rules), "rule") << " from " << scrub_store_location(from)
      << " to " << scrub_store_location(to) << ".\n";
  return Outcome::kSuccess;
}

}  // namespace

CommandResult run_knowledge(const KnowledgeOptions& options, const std::string& program, std::ostream& out) {
  (void)program;
  std::filesystem::path domain_path =
      options.domain.empty() ? data_dir() / "domains" / "kitchen.pddl" : std::filesystem::path(options.domain);
  auto domain = read_domain_file(domain_path);
  if (!domain) return tl::unexpected(domain.error());
  if (!options.action.empty()) return copy_between_stores(options, *domain, out);
  if (!options.to.empty() || !options.from.empty())
    return make_error(ErrorCode::kInvalidInput, "--to is for 'knowledge export' and --from for 'knowledge import'");
  auto store = KnowledgeStore::open(options.knowledge, StoreAccess::kReadOnly);
  if (!store) return tl::unexpected(store.error());
  auto knowledge = store->load(*domain);
  if (!knowledge) return tl::unexpected(knowledge.error());
  if (options.json) {
    nlohmann::json tasks = nlohmann::json::array(), goals = nlohmann::json::array(), rules = nlohmann::json::array();
    for (const TaskKnowledge& t : knowledge->tasks) {
      nlohmann::json subtasks = nlohmann::json::array();
      for (const LearnedSubtask& s : t.subtasks)
        subtasks.push_back({{"verb", s.verb}, {"relation", s.relation}, {"place", s.place_category}});
      tasks.push_back({{"name", t.name}, {"subtasks", subtasks}});
    }
    for (const GoalKnowledge& g : knowledge->goals.all())
      goals.push_back({{"text", format_goal_knowledge(g)}, {"object", g.provenance.object}, {"source", g.provenance.source}});
    for (const Rule& r : knowledge->rules.rules())
      rules.push_back({{"signature", rule_signature(*domain, r)}, {"object", r.provenance.object}, {"source", r.provenance.source}});
    out << dump_json(nlohmann::json{{"tasks", tasks}, {"goals", goals}, {"rules", rules}}, 2) << "\n";
    return Outcome::kSuccess;
  }
  if (options.pddl) {
    for (const TaskKnowledge& t : knowledge->tasks) {
      out << "Task " << t.name << ":\n";
      for (const LearnedSubtask& s : t.subtasks)
        out << "  while an object is " << s.relation << " the " << s.place_category << ", " << s.verb << " it\n";
    }
    out << "\n" << knowledge->goals.size() << " goals:\n";
    for (const GoalKnowledge& g : knowledge->goals.all())
      out << format_goal_knowledge(g) << "  (learned on " << g.provenance.object << " from " << g.provenance.source << ")\n\n";
    out << knowledge->rules.size() << " rules:\n";
    for (const Rule& r : knowledge->rules.rules())
      out << format_rule(*domain, r) << "  (learned on " << r.provenance.object << " from " << r.provenance.source << ")\n\n";
    return Outcome::kSuccess;
  }
  if (knowledge->tasks.empty() && knowledge->goals.size() == 0 && knowledge->rules.size() == 0) {
    out << "Nothing has been learned yet.\n";
    return Outcome::kSuccess;
  }
  out << language::capitalize(language::count_phrase(static_cast<long long>(knowledge->tasks.size()), "task")) << ":\n";
  for (const TaskKnowledge& t : knowledge->tasks) out << "  " << explain_task(t) << "\n";
  out << "\n" << language::capitalize(language::count_phrase(static_cast<long long>(knowledge->goals.size()), "goal")) << ":\n";
  for (const GoalKnowledge& g : knowledge->goals.all())
    out << "  " << explain_goal(g) << "\n    (" << explain_provenance(g.provenance) << ")\n";
  out << "\n" << language::capitalize(language::count_phrase(static_cast<long long>(knowledge->rules.size()), "rule")) << ":\n";
  int number = 0;
  for (const Rule& r : knowledge->rules.rules())
    out << "  " << ++number << ". " << explain_rule(*domain, r) << "\n     (" << explain_provenance(r.provenance) << ")\n";
  // The classes the goals support (induced anew from them: forgetting a
  // goal changes them), for things never taught.
  Understanding understanding;
  LexicalConcepts concepts(understanding.lexicon(), understanding.vectors());
  std::vector<std::string> preferences = explain_preferences(*knowledge, concepts);
  if (!preferences.empty()) {
    out << "\nFor things I was never taught, I generalize:\n";
    for (const std::string& line : preferences) out << "  " << line << "\n";
  }
  return Outcome::kSuccess;
}

}  // namespace apprentice::cli
