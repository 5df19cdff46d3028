// The one place an agent is wired: the store, the LLM and its advisor, the
// options, the agent (face/apprentice.h).
#include "face/apprentice.h"

#include <dlfcn.h>

#include <cstdlib>

#include <nlohmann/json.hpp>

#include "agent/agent.h"
#include "face/llm_setup.h"
#include "language/generation.h"
#include "language/narration.h"
#include "language/narration_summary.h"
#include "llm/prompts.h"
#include "util/json.h"
#include "util/text.h"

#ifndef APPRENTICE_DATA_DIR
#define APPRENTICE_DATA_DIR "data"
#endif

namespace apprentice {

AgentSpec default_agent_spec() { return AgentSpec{}; }

int count_achieved_assertions(const Scenario& scenario, const State& state) {
  int achieved = 0;
  for (const Literal& l : scenario.goal_assertions())
    if (state.satisfies(l)) ++achieved;
  return achieved;
}

int count_objects_done(const Scenario& scenario, const State& state) {
  int done = 0;
  for (ObjectId o : scenario.objects_to_tidy()) {
    auto goal = scenario.intended_goal(scenario.subtask_of(o)->verb, o);
    if (goal && goal->satisfied_by(state)) ++done;
  }
  return done;
}

double completion_percent(int achieved, int total) { return total == 0 ? 100.0 : 100.0 * achieved / total; }

std::filesystem::path data_dir() {
  if (const char* chosen = std::getenv("APPRENTICE_DATA"); chosen && *chosen) return chosen;
  std::error_code ec;
  // The file this code is in: the program, or the Python module's shared
  // object. The main program may be named as it was started: then
  // /proc/self/exe says where it is.
  std::filesystem::path here;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&default_agent_spec), &info) != 0 && info.dli_fname != nullptr &&
      std::filesystem::path(info.dli_fname).is_absolute())
    here = info.dli_fname;
  else
    here = std::filesystem::read_symlink("/proc/self/exe", ec);
  for (std::filesystem::path dir = here.parent_path(); !dir.empty() && dir != dir.root_path(); dir = dir.parent_path()) {
    if (std::filesystem::exists(dir / "share" / "apprentice" / "prompts" / "goal.txt", ec))
      return dir / "share" / "apprentice";
    if (std::filesystem::exists(dir / "data" / "prompts" / "goal.txt", ec)) return dir / "data";
  }
  return APPRENTICE_DATA_DIR;
}

Result<Scenario> load_world(const std::filesystem::path& path) {
  return load_scenario(path, {data_dir() / "domains"});
}

struct AgentSession::Parts {
  Scenario scenario;
  std::string store_label;  // the store as the spec named it
  std::optional<KnowledgeStore> store;
  std::unique_ptr<LlmAdvisor> own_advisor;
  LlmAdvisor* advisor = nullptr;  // own_advisor's, or lent
  std::unique_ptr<TaskLearningAgent> agent;
};

namespace {

// Copies knowledge into a store, so that it holds what the agent started
// from as well as what it learns.
Status save_knowledge(KnowledgeStore& store, const Domain& domain, const Knowledge& knowledge) {
  for (const TaskKnowledge& task : knowledge.tasks)
    if (auto s = store.save_task(task); !s) return s;
  for (const GoalKnowledge& goal : knowledge.goals.all())
    if (auto s = store.save_goal(goal); !s) return s;
  for (const Rule& rule : knowledge.rules.rules())
    if (auto s = store.save_rule(domain, rule); !s) return s;
  return {};
}

// "knowledge-only": learned knowledge alone, for perform (apprentice run).
Result<Condition> condition_of(const AgentSpec& spec) {
  if (spec.condition == "knowledge-only") return Condition{"knowledge-only", false, 0, false, false};
  Result<Condition> condition = spec.condition_parts ? Result<Condition>(*spec.condition_parts) : parse_condition(spec.condition);
  if (!condition) return condition;
  if (spec.instructed_always) condition->instruction = true;
  return condition;
}

Result<std::unique_ptr<llm::LlmClient>> make_client(const AgentSpec& spec, const Condition& condition,
                                                    bool& reachable) {
  reachable = !spec.llm.off;
  if (spec.llm.make_client) return spec.llm.make_client();
  auto backend = llm::resolve_llm_spec(spec.llm.backend);
  if (!backend)
    return make_error(ErrorCode::kInvalidInput, "condition " + condition.name +
                                                    " needs an LLM: pass --llm SPEC (in Python, llm=SPEC), e.g. "
                                                    "openai:http://127.0.0.1:8080/v1, or set APPRENTICE_LLM");
  const llm::LlmOptions options = llm_client_options(spec.llm);
  auto client = llm::make_llm_client(*backend, options);
  if (!client) return client;
  if (spec.llm.check_first && reachable) {
    auto answers = check_llm_before_run(*backend, options, spec.llm.optional);
    if (!answers) return tl::unexpected(answers.error());
    reachable = *answers;
  }
  return client;
}

Status attach_llm(const AgentSpec& spec, const Condition& condition, AgentSession::Parts& parts) {
  if (!condition.llm) return {};
  if (spec.lent_advisor != nullptr) {
    parts.advisor = spec.lent_advisor;
    return {};
  }
  bool reachable = true;
  auto client = make_client(spec, condition, reachable);
  if (!client) return tl::unexpected(client.error());
  auto templates = llm::PromptTemplates::load((spec.data.empty() ? data_dir() : spec.data) / "prompts");
  if (!templates) return tl::unexpected(templates.error());
  std::unique_ptr<llm::LlmClient> used = std::move(*client);
  if (spec.llm.wrap) used = spec.llm.wrap(std::move(used));
  LlmAdvisorOptions advice;
  advice.instructed = condition.instruction;
  advice.disabled = !reachable;
  advice.goal_responses = spec.llm.goal_responses;
  parts.own_advisor = std::make_unique<LlmAdvisor>(std::move(used), std::move(*templates), advice);
  parts.advisor = parts.own_advisor.get();
  return {};
}

}  // namespace

Result<std::unique_ptr<AgentSession>> make_agent_session(const AgentSpec& spec, const Scenario& scenario) {
  auto condition = condition_of(spec);
  if (!condition) return tl::unexpected(condition.error());
  auto generalization = parse_generalization(spec.generalization);
  if (!generalization) return tl::unexpected(generalization.error());
  auto repair = parse_goal_repair(spec.goal_repair);
  if (!repair) return tl::unexpected(repair.error());

  auto parts = std::make_unique<AgentSession::Parts>();
  parts->scenario = scenario;
  parts->store_label = spec.knowledge;
  const Domain& domain = *scenario.world.domain;
  Knowledge knowledge = spec.start_from ? *spec.start_from : Knowledge{};
  if (!spec.knowledge.empty()) {
    auto opened = KnowledgeStore::open(spec.knowledge, spec.store_access, spec.household, spec.robot);
    if (!opened) return tl::unexpected(opened.error());
    parts->store.emplace(std::move(*opened));
    if (spec.start_from) {
      if (auto s = save_knowledge(*parts->store, domain, knowledge); !s) return tl::unexpected(s.error());
    } else {
      auto loaded = parts->store->load(domain);
      if (!loaded) return tl::unexpected(loaded.error());
      knowledge = std::move(*loaded);
    }
  }
  if (auto s = attach_llm(spec, *condition, *parts); !s) return tl::unexpected(s.error());

  AgentOptions options;
  options.condition = *condition;
  options.generalization = *generalization;
  options.use_rules = spec.use_rules;
  options.max_actions_per_object = spec.max_actions_per_object;
  options.max_retries = spec.max_retries;
  options.goal_repair = *repair;
  options.max_reprompts = spec.max_reprompts;
  options.offer_ungrounded = spec.offer_ungrounded;
  options.fleet_prior = spec.fleet_prior;
  // A store opened read-only is read, never written: the agent is not lent it.
  KnowledgeStore* store = parts->store && spec.store_access != StoreAccess::kReadOnly ? &*parts->store : nullptr;
  parts->agent = std::make_unique<TaskLearningAgent>(options, std::move(knowledge), Understanding(), store,
                                                     parts->advisor);
  // What other robots learn meanwhile (the store's news), read or write.
  if (parts->store) parts->agent->watch(&*parts->store);
  return std::unique_ptr<AgentSession>(new AgentSession(std::move(parts)));
}

AgentSession::AgentSession(std::unique_ptr<Parts> parts) : parts_(std::move(parts)) {}
AgentSession::~AgentSession() = default;

const Knowledge& AgentSession::knowledge() const { return parts_->agent->knowledge(); }
const Scenario& AgentSession::scenario() const { return parts_->scenario; }
std::optional<std::filesystem::path> AgentSession::store_path() const {
  if (!parts_->store) return std::nullopt;
  return parts_->store->path();
}

namespace {

SessionReport measured(const Scenario& scenario, const State& end, AgentReport agent) {
  SessionReport out;
  out.agent = std::move(agent);
  out.end = end;
  out.measured = scenario.has_intent;
  out.assertions_total = static_cast<int>(scenario.goal_assertions().size());
  out.assertions_achieved = count_achieved_assertions(scenario, end);
  out.completion_rate = completion_percent(out.assertions_achieved, out.assertions_total);
  out.objects_total = static_cast<int>(scenario.objects_to_tidy().size());
  out.objects_done = count_objects_done(scenario, end);
  return out;
}

void add_llm_totals(const LlmAdvisor* advisor, SessionReport& out) {
  if (advisor == nullptr) return;
  LlmTotals totals = advisor->totals();
  out.llm_calls = totals.calls;
  out.llm_tokens = totals.tokens;
  out.llm_failures = totals.failures;
  out.llm_stopped = totals.stopped;
  out.llm_stopped_after_calls = totals.stopped_after_calls;
  if (totals.stop_error) out.llm_stop_error = totals.stop_error->describe();
  out.llm_ensemble = advisor->pools_sources();
  out.llm_description = advisor->describe();
}

// Why there is nothing to perform, naming the store (or the agent) and what
// it holds; nothing when there is a task to perform.
std::optional<Error> unknown_task(const TaskLearningAgent& agent, const std::string& name, const std::string& holder) {
  const Knowledge& knowledge = agent.knowledge();
  if (knowledge.tasks.empty())
    return Error{ErrorCode::kNotFound, holder + " holds no learned task yet; teach one with 'apprentice teach'"};
  if (agent.find_task(name) != nullptr) return std::nullopt;
  std::vector<std::string> names;
  for (const TaskKnowledge& task : knowledge.tasks) names.push_back(apprentice::quoted(task.name));
  const std::string holds =
      " holds " + language::count_phrase(static_cast<long long>(names.size()), "task") + ": " + join(names, ", ");
  if (name.empty()) return Error{ErrorCode::kInvalidInput, "name the task with --task: " + holder + holds};
  return Error{ErrorCode::kNotFound, "no task " + apprentice::quoted(name) + " has been learned; " + holder + holds};
}

}  // namespace

std::string to_json(const SessionReport& report) {
  const AgentReport& agent = report.agent;
  nlohmann::json objects = nlohmann::json::array();
  for (const ObjectReport& o : agent.objects)
    objects.push_back({{"object", o.object},
                       {"subtask", o.subtask},
                       {"part_place", o.part_place},
                       {"goal_source", std::string(to_string(o.goal_source))},
                       {"goal", o.goal},
                       {"achieved", o.achieved},
                       {"note", o.note},
                       {"proposed", o.proposed},
                       {"belief", o.belief},
                       {"because", o.because}});
  nlohmann::json j{{"instructions", report.counts.instructions},
                   {"words", report.counts.words},
                   {"yes_no", report.counts.yes_no},
                   {"yes", report.counts.yes},
                   {"llm_calls", report.llm_calls},
                   {"search_nodes", agent.search_nodes},
                   {"actions", agent.actions_executed},
                   {"rule_actions", agent.rule_actions},
                   {"goals_learned", agent.goals_learned},
                   {"rules_learned", agent.rules_learned},
                   {"task_finished", agent.task_finished},
                   {"objects", objects},
                   {"help_needed", agent.help_needed},
                   {"renamed", agent.renamed},
                   {"analogies", agent.analogies},
                   {"news", agent.news}};
  if (report.stopped) j["stopped"] = report.stop_reason;
  if (report.measured) {
    j["completion_rate"] = report.completion_rate;
    j["assertions_achieved"] = report.assertions_achieved;
    j["assertions_total"] = report.assertions_total;
    j["objects_done"] = report.objects_done;
    j["objects_total"] = report.objects_total;
  }
  return dump_json(j, 2);
}

Result<SessionReport> AgentSession::learn(Instructor& instructor) {
  const Scenario& scenario = parts_->scenario;
  Simulator simulator(scenario.world);
  Dialogue dialogue(instructor);
  auto report = parts_->agent->learn(simulator, dialogue);
  const bool stopped = !report && report.error().code == ErrorCode::kCancelled;
  if (!report && !stopped) return tl::unexpected(report.error());
  SessionReport out = measured(scenario, simulator.state(), report ? std::move(*report) : AgentReport{});
  out.stopped = stopped;
  if (stopped) out.stop_reason = report.error().message;
  out.counts = dialogue.counts();
  out.transcript = dialogue.transcript_text();
  add_llm_totals(parts_->advisor, out);
  language::TeachingEnd end;
  end.finished = !stopped;
  end.instructions = out.counts.instructions;
  if (parts_->store) end.store = parts_->store->path().string();
  out.summary = language::teaching_summary(scenario, out.end, end);
  return out;
}

Result<SessionReport> AgentSession::perform(const std::string& task, const Scenario* elsewhere) {
  const std::string holder = parts_->store ? parts_->store->location() : std::string("the agent");
  if (auto missing = unknown_task(*parts_->agent, task, holder)) return tl::unexpected(*missing);
  const Scenario& scenario = elsewhere != nullptr ? *elsewhere : parts_->scenario;
  Simulator simulator(scenario.world);
  auto report = parts_->agent->perform(simulator, task);
  if (!report) return tl::unexpected(report.error());
  SessionReport out = measured(scenario, simulator.state(), std::move(*report));
  language::PerformanceEnd end;
  end.measured = out.measured;
  end.achieved = out.assertions_achieved;
  end.total = out.assertions_total;
  end.completion = out.completion_rate;
  end.actions = out.agent.actions_executed;
  end.search_nodes = out.agent.search_nodes;
  end.renamed = out.agent.renamed;
  end.analogies = out.agent.analogies;
  end.help_needed = out.agent.help_needed;
  World now = scenario.world;
  now.state = simulator.state();
  end.unmet = language::unmet_assertions(scenario, now);
  out.summary = language::performance_summary(end);
  return out;
}

namespace words {

std::string task_name(std::string_view name) { return language::say_task_name(name); }
std::string repeat_while(const World& world, std::span<const ObjectId> places) {
  return language::say_repeat_while(world, places);
}
std::string subtask(std::string_view verb, const World& world, std::span<const ObjectId> places) {
  return language::say_subtask(verb, world, places);
}
std::string goal(const World& world, ObjectId object, const Goal& goal) {
  return language::describe_goal_instruction(world, object, goal);
}
std::string repeat() { return language::say_repeat(); }
std::string done() { return language::say_done(); }
std::string answer(bool yes) { return language::say_answer(yes); }

}  // namespace words

}  // namespace apprentice
