#include "experiment/experiment.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <set>

#include "instructor/simulated_instructor.h"

namespace apprentice {

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

// Without an instructor nobody answers yes or no, so relevance is the share
// of adopted LLM goals the instructor would have accepted: those that are
// the intended goal. Unset when no LLM goal was adopted.
std::optional<double> silent_relevance(const Scenario& scenario, const std::vector<ObjectReport>& objects) {
  int adopted = 0, relevant = 0;
  const World& world = scenario.world;
  for (const ObjectReport& o : objects) {
    if (o.goal_source != GoalSource::kLlm) continue;
    ++adopted;
    auto id = world.universe->find(o.object);
    auto intended = id ? scenario.intended_goal(o.subtask, *id) : std::nullopt;
    if (intended && format_goal(*world.domain, *world.universe, *intended) == o.goal) ++relevant;
  }
  if (adopted == 0) return std::nullopt;
  return 100.0 * relevant / adopted;
}

}  // namespace

ConditionResult condition_result(const Scenario& scenario, const Condition& condition, SessionReport report) {
  ConditionResult result;
  static_cast<SessionReport&>(result) = std::move(report);
  result.condition = condition.name;
  if (condition.llm && condition.instruction && result.counts.yes_no > 0)
    result.relevance = 100.0 * result.counts.yes / result.counts.yes_no;
  if (condition.llm && !condition.instruction) result.relevance = silent_relevance(scenario, result.agent.objects);
  result.uses_llm = condition.llm;
  return result;
}

Result<ConditionResult> run_condition(const Scenario& scenario, const Condition& condition,
                                      const ExperimentOptions& options) {
  if (auto s = check_runnable(scenario); !s) return tl::unexpected(s.error());
  auto started = std::chrono::steady_clock::now();
  AgentSpec spec = default_agent_spec();
  spec.condition = condition.name;
  spec.condition_parts = condition;
  spec.generalization = std::string(to_string(options.generalization));
  spec.use_rules = options.use_rules;
  spec.goal_repair = format_goal_repair(options.goal_repair);
  spec.max_reprompts = options.max_reprompts;
  spec.offer_ungrounded = options.offer_ungrounded;
  if (options.knowledge_in) spec.start_from = std::make_shared<const Knowledge>(*options.knowledge_in);
  if (options.knowledge_out) {
    std::error_code ec;
    std::filesystem::create_directories(*options.knowledge_out, ec);
    if (ec) return make_error(ErrorCode::kIo, options.knowledge_out->string() + ": " + ec.message());
    // Started over in place, never deleted: refused while another process
    // has it open (KnowledgeStore, StoreAccess::kFresh).
    spec.knowledge = (*options.knowledge_out / (condition.name + ".sqlite")).string();
    spec.store_access = StoreAccess::kFresh;
    spec.household = options.household;
    if (!spec.start_from) spec.start_from = std::make_shared<const Knowledge>();
  }
  if (!options.prompts_dir.empty()) spec.data = options.prompts_dir.parent_path();
  if (condition.llm && !options.llm)
    return make_error(ErrorCode::kInvalidInput, "condition " + condition.name + " needs an LLM: pass --llm SPEC");
  spec.llm.make_client = options.llm;
  spec.llm.check_first = false;  // run_experiment checked the server once for all conditions
  spec.llm.off = options.llm_disabled;
  spec.llm.goal_responses = options.goal_responses;
  auto session = make_agent_session(spec, scenario);
  if (!session) return tl::unexpected(session.error());
  SimulatedInstructor instructor(scenario);
  auto report = (*session)->learn(instructor);
  if (!report) return tl::unexpected(report.error());
  if (report->stopped) return make_error(ErrorCode::kCancelled, report->stop_reason);

  ConditionResult result = condition_result(scenario, condition, std::move(*report));
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
                    static_cast<unsigned long long>(r.agent.search_nodes), r.llm_calls, r.wall_ms);
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
