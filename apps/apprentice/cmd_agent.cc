#include "cmd_agent.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "experiment/experiment.h"
#include "instructor/terminal_instructor.h"
#include "llm/factory.h"
#include "util/json.h"
#include "util/log.h"
#include "util/text.h"
#include "world/pddl.h"

#ifndef APPRENTICE_DATA_DIR
#define APPRENTICE_DATA_DIR "data"
#endif

namespace apprentice::cli {

namespace {

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

Result<Generalization> parse_generalization(const std::string& text) {
  if (text == "full") return Generalization::kFull;
  if (text == "paper") return Generalization::kPaper;
  return make_error(ErrorCode::kInvalidInput, "--generalization must be full or paper, not " + text);
}

llm::LlmOptions llm_options(const LlmFlags& flags) {
  llm::LlmOptions options;
  options.model = flags.model;
  options.api_key = flags.api_key;
  if (flags.timeout_ms) options.request_timeout = std::chrono::milliseconds(*flags.timeout_ms);
  if (flags.connect_timeout_ms) options.connect_timeout = std::chrono::milliseconds(*flags.connect_timeout_ms);
  return options;
}

std::optional<LlmFactory> llm_factory(const LlmFlags& flags, const std::string& condition = "") {
  auto spec = llm::resolve_llm_spec(flags.spec);
  if (!spec) return std::nullopt;
  // With several conditions each keeps its own cassette (llm/factory.h).
  if (!condition.empty()) spec = llm::spec_for_condition(*spec, condition);
  llm::LlmOptions options = llm_options(flags);
  std::string s = *spec;
  return LlmFactory([s, options]() { return llm::make_llm_client(s, options); });
}

// Before a run that needs the LLM: whether its server can be reached at
// all, so that a dead server costs seconds, not a run's worth of timeouts.
// Returns whether to go on with the LLM; an error (exit 4) when it cannot
// be reached and the LLM is not optional.
Result<bool> check_llm(const LlmFlags& flags) {
  auto spec = llm::resolve_llm_spec(flags.spec);
  if (!spec) return true;
  auto reachable = llm::check_llm_connection(*spec, llm_options(flags));
  if (reachable) return true;
  if (!flags.optional) {
    Error error = reachable.error();
    error.message += " (--llm-optional goes on without it)";
    return tl::unexpected(std::move(error));
  }
  spdlog::warn("{}; going on without the LLM (--llm-optional)", reachable.error().message);
  return false;
}

nlohmann::json result_json(const ConditionResult& r) {
  return nlohmann::json{{"condition", r.condition},
                        {"llm_failures", r.llm_failures},
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
                        {"search_nodes", r.search_nodes},
                        {"wall_ms", r.wall_ms}};
}

Status write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  file << text;
  file.close();
  if (!file) return make_error(ErrorCode::kIo, path.string() + ": write failed");
  return {};
}

// The knowledge in a store, read once; the store is left as it was.
Result<Knowledge> load_knowledge_copy(const std::filesystem::path& path, const Domain& domain) {
  auto store = KnowledgeStore::open(path, StoreAccess::kReadOnly);
  if (!store) return tl::unexpected(store.error());
  return store->load(domain);
}

}  // namespace

CommandResult run_experiment(const ExperimentOptions& options, const std::string& program, std::ostream& out) {
  (void)program;
  auto scenario = load_scenario(options.scenario);
  if (!scenario) return tl::unexpected(scenario.error());
  if (auto s = check_runnable(*scenario); !s) return tl::unexpected(s.error());
  auto generalization = parse_generalization(options.generalization);
  if (!generalization) return tl::unexpected(generalization.error());
  apprentice::ExperimentOptions experiment;
  if (!options.knowledge_in.empty()) {
    auto knowledge = load_knowledge_copy(options.knowledge_in, *scenario->world.domain);
    if (!knowledge) return tl::unexpected(knowledge.error());
    experiment.knowledge_in = std::move(*knowledge);
  }
  experiment.generalization = *generalization;
  experiment.use_rules = !options.no_rules;
  experiment.prompts_dir = data_dir() / "prompts";
  if (auto factory = llm_factory(options.llm)) experiment.llm = *factory;
  if (!options.knowledge_out.empty()) experiment.knowledge_out = options.knowledge_out;
  auto repair = parse_goal_repair(options.llm.goal_repair);
  if (!repair) return tl::unexpected(repair.error());
  experiment.goal_repair = *repair;
  experiment.offer_ungrounded = options.llm.offer_ungrounded;
  experiment.goal_responses = options.llm.goal_responses;
  std::vector<std::string> names = options.conditions;
  if (names.empty()) {
    for (const std::string& name : paper_condition_names()) {
      auto condition = parse_condition(name);
      if (condition && (!condition->llm || experiment.llm)) names.push_back(name);
    }
  }
  std::vector<Condition> conditions;
  for (const std::string& name : names) {
    auto condition = parse_condition(name);
    if (!condition) return tl::unexpected(condition.error());
    conditions.push_back(*condition);
  }
  if (experiment.llm && std::any_of(conditions.begin(), conditions.end(), [](const Condition& c) { return c.llm; })) {
    auto reachable = check_llm(options.llm);
    if (!reachable) return tl::unexpected(reachable.error());
    experiment.llm_disabled = !*reachable;
  }
  std::vector<ConditionResult> results;
  for (const std::string& name : names) {
    auto condition = parse_condition(name);
    if (!condition) return tl::unexpected(condition.error());
    if (names.size() > 1) {
      if (auto factory = llm_factory(options.llm, name)) experiment.llm = *factory;
    }
    spdlog::info("running condition {}", name);
    auto result = run_condition(*scenario, *condition, experiment);
    if (!result) return tl::unexpected(prefix_error(result.error(), "condition " + name));
    if (!options.transcript_dir.empty()) {
      std::error_code ec;
      std::filesystem::create_directories(options.transcript_dir, ec);
      if (ec) return make_error(ErrorCode::kIo, options.transcript_dir + ": " + ec.message());
      auto status = write_file(std::filesystem::path(options.transcript_dir) / (name + ".txt"), result->transcript);
      if (!status) return tl::unexpected(status.error());
    }
    results.push_back(std::move(*result));
  }
  if (options.json) {
    nlohmann::json all = nlohmann::json::array();
    for (const ConditionResult& r : results) all.push_back(result_json(r));
    out << dump_json(all, 2) << "\n";
  } else {
    DialogueCounts floor = instruction_floor(*scenario);
    out << "Scenario " << scenario->name << ": " << scenario->objects_to_tidy().size() << " objects to tidy, "
        << scenario->goal_assertions().size() << " goal assertions; the floor (task structure and one goal per goal "
        << "type) is " << floor.instructions << " instructions, " << floor.words << " words";
    if (experiment.knowledge_in)
      out << "; every condition starts from the knowledge in " << options.knowledge_in << " ("
          << experiment.knowledge_in->goals.size() << " goals, " << experiment.knowledge_in->rules.size() << " rules)";
    for (const ConditionResult& r : results)
      if (!r.llm_description.empty()) {
        out << "; LLM answers from " << r.llm_description;
        break;
      }
    out << "\n" << format_results_table(results, scenario->reference == "table3");
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
  std::unique_ptr<LlmAdvisor> advisor;
  if (condition->llm) {
    auto factory = llm_factory(options.llm);
    if (!factory) return make_error(ErrorCode::kInvalidInput, "condition " + condition->name + " needs --llm SPEC");
    auto client = (*factory)();
    if (!client) return tl::unexpected(client.error());
    auto templates = llm::PromptTemplates::load(data_dir() / "prompts");
    if (!templates) return tl::unexpected(templates.error());
    auto reachable = check_llm(options.llm);
    if (!reachable) return tl::unexpected(reachable.error());
    LlmAdvisorOptions advice;
    advice.disabled = !*reachable;
    advice.goal_responses = options.llm.goal_responses;
    advisor = std::make_unique<LlmAdvisor>(std::move(*client), std::move(*templates), advice);
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
  TerminalInstructor instructor(in, out);
  Dialogue dialogue(instructor);
  out << "Teaching in " << scenario->name << " (" << condition->name
      << "). Type 'status' to see the world, Ctrl-D to stop.\n";
  auto report = agent.learn(simulator, dialogue);
  if (!report && report.error().code != ErrorCode::kCancelled) return tl::unexpected(report.error());
  out << (report ? "The task is learned." : "Stopped.");
  // Without an intent the teacher is the only authority: no completion.
  int achieved = count_achieved_assertions(*scenario, simulator.state());
  int total = static_cast<int>(scenario->goal_assertions().size());
  if (scenario->has_intent) out << " " << achieved << " of " << total << " goal assertions hold;";
  out << " " << dialogue.counts().instructions << " instructions.";
  if (store) out << " Knowledge is in " << store->path().string() << ".";
  out << "\n";
  if (!scenario->has_intent) return report ? Outcome::kSuccess : Outcome::kGoalNotReached;
  return achieved == total ? Outcome::kSuccess : Outcome::kGoalNotReached;
}

CommandResult run_run(const RunOptions& options, std::ostream& out) {
  auto scenario = load_scenario(options.scenario);
  if (!scenario) return tl::unexpected(scenario.error());
  auto store = KnowledgeStore::open(options.knowledge, StoreAccess::kReadOnly);
  if (!store) return tl::unexpected(store.error());
  auto knowledge = store->load(*scenario->world.domain);
  if (!knowledge) return tl::unexpected(knowledge.error());
  AgentOptions agent_options;
  agent_options.condition = Condition{"knowledge-only", false, 0, false};
  TaskLearningAgent agent(agent_options, std::move(*knowledge), Understanding(), nullptr, nullptr);
  Simulator simulator(scenario->world);
  auto report = agent.perform(simulator, options.task);
  if (!report) return tl::unexpected(report.error());
  int achieved = count_achieved_assertions(*scenario, simulator.state());
  int total = static_cast<int>(scenario->goal_assertions().size());
  double completion = total == 0 ? 100.0 : 100.0 * achieved / total;
  // Without an intent nothing says what the task should achieve: no completion.
  const bool measured = scenario->has_intent;
  if (options.json) {
    nlohmann::json j{{"instructions", 0}, {"search_nodes", report->search_nodes}, {"llm_calls", 0},
                     {"actions", report->actions_executed}, {"help_needed", report->help_needed}};
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
    if (measured) out << achieved << " of " << total << " goal assertions (" << completion << "%), ";
    out << report->actions_executed << " actions, 0 instructions, " << report->search_nodes
        << " search nodes, 0 LLM calls.\n";
    if (report->help_needed.empty()) out << "No help was needed.\n";
    for (const std::string& help : report->help_needed) out << "Would need help: " << help << "\n";
  }
  return (!measured || achieved == total) && report->help_needed.empty() ? Outcome::kSuccess : Outcome::kGoalNotReached;
}

CommandResult run_knowledge(const KnowledgeOptions& options, const std::string& program, std::ostream& out) {
  (void)program;
  std::filesystem::path domain_path =
      options.domain.empty() ? data_dir() / "domains" / "kitchen.pddl" : std::filesystem::path(options.domain);
  auto domain = read_domain_file(domain_path);
  if (!domain) return tl::unexpected(domain.error());
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

}  // namespace apprentice::cli
