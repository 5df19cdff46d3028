#include "experiment/experiment.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <set>

#include "instructor/simulated_instructor.h"

namespace apprentice {

double completion_percent(int achieved, int total) { return total == 0 ? 100.0 : 100.0 * achieved / total; }

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

Status check_runnable(const Scenario& scenario) {
  if (!scenario.has_intent || scenario.task.subtasks.empty())
    return make_error(ErrorCode::kInvalidInput,
                      scenario.source.string() + ": the experiment needs a scenario with a task and an intent (where "
                      "each kind of object should end up), for the simulated instructor to teach and for measuring "
                      "completion; this one has no " + std::string(scenario.task.subtasks.empty() ? "task" : "intent") +
                      " (see docs/scenarios.md)");
  return {};
}

DialogueCounts instruction_floor(const Scenario& scenario) {
  // Asks a fresh simulated instructor what the agent asks when search
  // leaves it nothing else to ask, in the same order.
  SimulatedInstructor instructor(scenario);
  Dialogue dialogue(instructor);
  const World& world = scenario.world;
  auto ask = [&](QuestionKind kind, const std::string& subtask, std::optional<ObjectId> object) {
    Question question;
    question.kind = kind;
    question.task = scenario.task.name;
    question.subtask = subtask;
    question.object = object;
    (void)dialogue.ask(question, world);
  };
  ask(QuestionKind::kTaskName, "", std::nullopt);
  const std::vector<ObjectId> objects = scenario.objects_to_tidy();
  for (const Subtask& subtask : scenario.task.subtasks) {
    ask(QuestionKind::kTaskStep, "", std::nullopt);  // the loop
    ask(QuestionKind::kTaskStep, "", std::nullopt);  // the subtask
    std::set<std::string> described;
    for (ObjectId o : objects)
      if (scenario.subtask_of(o) == &subtask && described.insert(world.universe->info(o).category).second)
        ask(QuestionKind::kSubtaskStep, subtask.verb, o);  // its goal
    ask(QuestionKind::kSubtaskStep, subtask.verb, std::nullopt);  // "You are done."
    ask(QuestionKind::kTaskStep, "", std::nullopt);               // "Repeat."
  }
  ask(QuestionKind::kTaskStep, "", std::nullopt);  // "You are done."
  return dialogue.counts();
}

namespace {

// Copies knowledge into a store, so that a condition's store holds what it
// started from as well as what it learns.
Status save_knowledge(KnowledgeStore& store, const Domain& domain, const Knowledge& knowledge) {
  for (const TaskKnowledge& task : knowledge.tasks)
    if (auto s = store.save_task(task); !s) return s;
  for (const GoalKnowledge& goal : knowledge.goals.all())
    if (auto s = store.save_goal(goal); !s) return s;
  for (const Rule& rule : knowledge.rules.rules())
    if (auto s = store.save_rule(domain, rule); !s) return s;
  return {};
}

// Without an instructor nobody answers yes or no, so relevance is the share
// of adopted LLM goals the instructor would have accepted: those that are
// the intended goal. Unset when no LLM goal was adopted.
std::optional<double> silent_relevance(const Scenario& scenario, const std::vector<ObjectReport>& objects) {
  int adopted = 0, relevant = 0;
  const World& world = scenario.world;
  for (const ObjectReport& o : objects) {
    if (o.goal_source != "llm") continue;
    ++adopted;
    auto id = world.universe->find(o.object);
    auto intended = id ? scenario.intended_goal(o.subtask, *id) : std::nullopt;
    if (intended && format_goal(*world.domain, *world.universe, *intended) == o.goal) ++relevant;
  }
  if (adopted == 0) return std::nullopt;
  return 100.0 * relevant / adopted;
}

}  // namespace

Result<ConditionResult> run_condition(const Scenario& scenario, const Condition& condition,
                                      const ExperimentOptions& options) {
  if (auto s = check_runnable(scenario); !s) return tl::unexpected(s.error());
  auto started = std::chrono::steady_clock::now();
  Knowledge knowledge = options.knowledge_in.value_or(Knowledge{});
  std::optional<KnowledgeStore> store;
  if (options.knowledge_out) {
    std::error_code ec;
    std::filesystem::create_directories(*options.knowledge_out, ec);
    if (ec) return make_error(ErrorCode::kIo, options.knowledge_out->string() + ": " + ec.message());
    // Started over in place, never deleted: refused while another process
    // has it open (KnowledgeStore, StoreAccess::kFresh).
    std::filesystem::path path = *options.knowledge_out / (condition.name + ".sqlite");
    auto opened = KnowledgeStore::open(path, StoreAccess::kFresh);
    if (!opened) return tl::unexpected(opened.error());
    store.emplace(std::move(*opened));
    if (auto s = save_knowledge(*store, *scenario.world.domain, knowledge); !s) return tl::unexpected(s.error());
  }
  std::unique_ptr<LlmAdvisor> advisor;
  if (condition.llm) {
    if (!options.llm)
      return make_error(ErrorCode::kInvalidInput, "condition " + condition.name + " needs an LLM: pass --llm SPEC");
    auto client = options.llm();
    if (!client) return tl::unexpected(client.error());
    auto templates = llm::PromptTemplates::load(options.prompts_dir);
    if (!templates) return tl::unexpected(templates.error());
    LlmAdvisorOptions advice;
    advice.instructed = condition.instruction;
    advice.disabled = options.llm_disabled;
    advice.goal_responses = options.goal_responses;
    advisor = std::make_unique<LlmAdvisor>(std::move(*client), std::move(*templates), advice);
  }
  AgentOptions agent_options;
  agent_options.condition = condition;
  agent_options.generalization = options.generalization;
  agent_options.use_rules = options.use_rules;
  agent_options.goal_repair = options.goal_repair;
  agent_options.max_reprompts = options.max_reprompts;
  agent_options.offer_ungrounded = options.offer_ungrounded;
  TaskLearningAgent agent(agent_options, std::move(knowledge), Understanding(), store ? &*store : nullptr, advisor.get());
  Simulator simulator(scenario.world);
  SimulatedInstructor instructor(scenario);
  Dialogue dialogue(instructor);
  auto report = agent.learn(simulator, dialogue);
  if (!report) return tl::unexpected(report.error());

  ConditionResult result;
  result.condition = condition.name;
  result.assertions_total = static_cast<int>(scenario.goal_assertions().size());
  result.assertions_achieved = count_achieved_assertions(scenario, simulator.state());
  result.completion_rate = completion_percent(result.assertions_achieved, result.assertions_total);
  result.objects_total = static_cast<int>(scenario.objects_to_tidy().size());
  result.objects_done = count_objects_done(scenario, simulator.state());
  result.counts = dialogue.counts();
  if (condition.llm && condition.instruction && result.counts.yes_no > 0)
    result.relevance = 100.0 * result.counts.yes / result.counts.yes_no;
  if (condition.llm && !condition.instruction) result.relevance = silent_relevance(scenario, report->objects);
  result.uses_llm = condition.llm;
  if (advisor) {
    LlmTotals totals = advisor->totals();
    result.llm_calls = totals.calls;
    result.llm_tokens = totals.tokens;
    result.llm_failures = totals.failures;
    result.llm_stopped = totals.stopped;
    result.llm_stopped_after_calls = totals.stopped_after_calls;
    if (totals.stop_error) result.llm_stop_error = totals.stop_error->describe();
    result.llm_ensemble = advisor->pools_sources();
    result.llm_description = advisor->describe();
  }
  result.search_nodes = report->search_nodes;
  result.report = std::move(*report);
  result.transcript = dialogue.transcript_text();
  result.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  return result;
}

std::optional<PaperRow> paper_row(std::string_view condition) {
  static const PaperRow kRows[] = {
      {"instruction", 100.0, std::nullopt, 76, 757, 0},
      {"inst+search4", 100.0, std::nullopt, 40, 603, 0},
      {"search4+llm", 54.3, 53.3, 14, 76, 0},
      {"inst+llm", 100.0, 59.1, 112, 348, 88},
      {"inst+search2+llm", 100.0, 40.3, 94, 384, 67},
      {"inst+search4+llm", 100.0, 30.2, 70, 360, 43},
  };
  for (const PaperRow& row : kRows)
    if (condition == row.condition) return row;
  return std::nullopt;
}

namespace {

std::string percent(std::optional<double> value) {
  if (!value) return "--";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", *value);
  return buffer;
}

// Relevant%: "--" only for a condition that asks the LLM nothing, as in the
// paper; "n/a" for one that asked it but had nothing to measure.
std::string relevance_cell(const ConditionResult& r) {
  if (r.relevance) return percent(r.relevance);
  return r.uses_llm ? "n/a" : "--";
}

std::string row_text(const char* format, auto... args) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, format, args...);
  return buffer;
}

}  // namespace

std::string degraded_why(const ConditionResult& r) {
  if (!r.degraded()) return "";
  if (r.llm_failures == 0) return "the LLM could not be reached and was not asked";
  std::string why = "the LLM failed " + std::to_string(r.llm_failures) + " quer" + (r.llm_failures == 1 ? "y" : "ies");
  if (r.llm_stopped) why += " and was not asked again";
  if (r.llm_stopped_after_calls) why += " after query " + std::to_string(*r.llm_stopped_after_calls);
  return why;
}

std::string format_results_table(const std::vector<ConditionResult>& results, bool beside_paper) {
  // The label column fits "ensemble" only when a row needs it, so that other
  // tables keep their layout.
  const bool any_ensemble =
      std::any_of(results.begin(), results.end(), [](const ConditionResult& r) { return r.llm_ensemble; });
  const int label = any_ensemble ? 8 : 6;
  std::string out = row_text("%-18s %-*s %11s %9s %9s %8s %7s %7s %12s %9s %9s\n", "Condition", label, "",
                             "Completion%", "Objects", "Relevant%", "#Instr.", "#Words", "#Yes/No", "Search nodes",
                             "LLM calls", "Wall ms");
  std::string notes;
  for (const ConditionResult& r : results) {
    const std::string name = r.condition + (r.degraded() ? "*" : "");
    std::string objects = std::to_string(r.objects_done) + "/" + std::to_string(r.objects_total);
    out += row_text("%-18s %-*s %11s %9s %9s %8d %7d %7d %12llu %9d %9.1f\n", name.c_str(), label,
                    r.llm_ensemble ? "ensemble" : "ours", percent(r.completion_rate).c_str(), objects.c_str(),
                    relevance_cell(r).c_str(), r.counts.instructions, r.counts.words, r.counts.yes_no,
                    static_cast<unsigned long long>(r.search_nodes), r.llm_calls, r.wall_ms);
    if (r.degraded()) notes += "* " + r.condition + ": degraded, " + degraded_why(r) + "\n";
    // An ensemble of runs is not what the paper's agent had: not set beside it.
    if (!beside_paper || r.llm_ensemble) continue;
    if (auto paper = paper_row(r.condition))
      out += row_text("%-18s %-*s %11s %9s %9s %8d %7d %7d %12s %9s %9s\n", "", label, "paper",
                      percent(paper->completion).c_str(), "", percent(paper->relevance).c_str(), paper->instructions,
                      paper->words, paper->yes_no, "", "", "");
  }
  return out + notes;
}

}  // namespace apprentice
