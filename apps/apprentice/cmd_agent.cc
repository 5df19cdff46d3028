#include "cmd_agent.h"
#include "cmd_rules.h"

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
#include "face/apprentice.h"
#include "face/llm_setup.h"
#include "instructor/terminal_instructor.h"
#include "language/narration.h"
#include "language/narration_summary.h"
#include "llm/factory.h"
#include "plot.h"
#include "progress.h"
#include "util/json.h"
#include "util/log.h"
#include "util/text.h"
#include "world/pddl.h"

namespace apprentice::cli {

LlmSpec llm_spec(const LlmFlags& flags) {
  LlmSpec spec;
  spec.backend = flags.spec;
  spec.model = flags.model;
  spec.api_key = flags.api_key;
  spec.seed = flags.seed;
  if (flags.timeout_ms) spec.timeout = std::chrono::milliseconds(*flags.timeout_ms);
  if (flags.connect_timeout_ms) spec.connect_timeout = std::chrono::milliseconds(*flags.connect_timeout_ms);
  spec.optional = flags.optional;
  spec.goal_responses = flags.goal_responses;
  return spec;
}

llm::LlmOptions llm_options(const LlmFlags& flags) { return llm_client_options(llm_spec(flags)); }


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
  const std::vector<std::string>& renamed = results.front().agent.renamed;
  if (renamed.empty()) out << "No learned word needed another here.\n";
  else out << "The knowledge brought in, in this world's words (every condition):\n";
  for (const std::string& note : renamed) out << "  " << note << "\n";
  for (const ConditionResult& r : results) {
    if (r.agent.analogies.empty()) continue;
    out << r.condition << ", by analogy:\n";
    for (const std::string& note : r.agent.analogies) out << "  " << note << "\n";
  }
}

CommandResult run_experiment(const ExperimentOptions& options, const std::string& program, std::ostream& out) {
  (void)program;
  auto scenario = load_world(options.scenario);
  if (!scenario) return tl::unexpected(scenario.error());
  if (auto s = check_runnable(*scenario); !s) return tl::unexpected(s.error());
  auto generalization = parse_generalization(options.generalization);
  if (!generalization) return tl::unexpected(generalization.error());
  ExperimentRequest request;
  if (!options.knowledge_in.empty()) {
    auto knowledge = load_knowledge_read_only(options.knowledge_in, *scenario->world.domain, options.household);
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
  request.options.household = options.household;
  if (!options.transcript_dir.empty())
    request.on_result = [&](const ConditionResult& result) { return write_transcript(options.transcript_dir, result); };
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

CommandResult run_teach(const TeachOptions& options, const std::string& program, std::FILE* in, std::ostream& out) {
  (void)program;
  auto scenario = load_world(options.scenario);
  if (!scenario) return tl::unexpected(scenario.error());
  AgentSpec spec = default_agent_spec();
  spec.condition = options.condition;
  spec.instructed_always = true;  // a person is teaching
  spec.generalization = options.generalization;
  spec.knowledge = options.knowledge;
  spec.household = options.household;
  spec.robot = options.robot;
  spec.goal_repair = options.llm.goal_repair;
  spec.offer_ungrounded = options.llm.offer_ungrounded;
  spec.llm = llm_spec(options.llm);
  // While the LLM is asked, a progress line on a terminal's stderr.
  TerminalProgress progress(stderr, !options.quiet, TerminalProgress::Mode::kLlmQueries);
  if (progress.active())
    spec.llm.wrap = [&progress](std::unique_ptr<llm::LlmClient> client) { return observe_llm(std::move(client), progress); };
  auto session = make_agent_session(spec, *scenario);
  if (!session) return tl::unexpected(session.error());
  TerminalInstructor instructor(in, out, TerminalOptions{options.quiet, true});
  if (!options.quiet)
    out << "Teaching in " << scenario->name << " (" << spec.condition
        << "). Answer in your own words; type help at any question. Ctrl-D or quit stops and keeps what you "
           "taught.\n";
  auto report = (*session)->learn(instructor);
  if (!report) return tl::unexpected(report.error());
  const std::optional<std::filesystem::path> store = (*session)->store_path();
  if (instructor.interrupted()) {
    out << "Interrupted. "
        << (store ? "What you taught me is kept in " + store->string() + "."
                  : std::string("Nothing was saved (no --knowledge)."))
        << "\n";
    out.flush();
    return Outcome::kInterrupted;
  }
  language::TeachingEnd end;
  end.finished = !report->stopped;
  end.instructions = report->counts.instructions;
  if (store) end.store = store->string();
  end.how_to_keep = "apprentice teach --scenario " + scenario->source.string() + " --knowledge FILE (for example kitchen.sqlite)";
  out << language::teaching_summary(*scenario, report->end, end);
  if (!scenario->has_intent || report->assertions_total == 0)
    return report->stopped ? Outcome::kGoalNotReached : Outcome::kSuccess;
  return report->assertions_achieved == report->assertions_total ? Outcome::kSuccess : Outcome::kGoalNotReached;
}

CommandResult run_run(const RunOptions& options, std::ostream& out) {
  auto scenario = load_world(options.scenario);
  if (!scenario) return tl::unexpected(scenario.error());
  AgentSpec spec = default_agent_spec();
  spec.condition = "knowledge-only";
  spec.knowledge = options.knowledge;
  spec.household = options.household;
  spec.store_access = StoreAccess::kReadOnly;
  auto session = make_agent_session(spec, *scenario);
  if (!session) return tl::unexpected(session.error());
  auto report = (*session)->perform(options.task);
  if (!report) return tl::unexpected(report.error());
  if (options.json) out << to_json(*report) << "\n";
  else out << report->summary;
  const bool reached = !report->measured || report->assertions_achieved == report->assertions_total;
  return reached && report->agent.help_needed.empty() ? Outcome::kSuccess : Outcome::kGoalNotReached;
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
  if (!options.household.empty())
    return make_error(ErrorCode::kInvalidInput, "knowledge " + options.action +
                                                    " copies every household of the store; --household is for printing one");
  const std::string& from = exporting ? options.knowledge : other;
  const std::string& to = exporting ? other : options.knowledge;
  auto copied = copy_knowledge(from, to, domain);
  if (!copied) return tl::unexpected(copied.error());
  if (options.json) {
    out << dump_json(nlohmann::json{{"from", scrub_store_location(from)}, {"to", scrub_store_location(to)},
                                    {"tasks", copied->tasks}, {"goals", copied->goals}, {"rules", copied->rules},
                                    {"households", copied->households}, {"class_rules", copied->class_rules},
                                    {"forgotten_rules", copied->forgotten_rules}},
                     2)
        << "\n";
    return Outcome::kSuccess;
  }
  out << "Copied " << language::count_phrase(static_cast<long long>(copied->tasks), "task") << ", "
      << language::count_phrase(static_cast<long long>(copied->goals), "goal") << " and "
      << language::count_phrase(static_cast<long long>(copied->rules), "rule");
  if (copied->class_rules + copied->forgotten_rules > 0)
    out << " (and " << language::count_phrase(static_cast<long long>(copied->class_rules), "rule")
        << " about classes of things, and " << language::count_phrase(static_cast<long long>(copied->forgotten_rules), "rule")
        << " forgotten)";
  out << " from " << scrub_store_location(from)
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
  if (options.action == "forget") return forget_class_rules(options, *domain, out);
  if (!options.what.empty())
    return make_error(ErrorCode::kInvalidInput, "only 'knowledge forget' takes words after it: " + join(options.what, " "));
  if (!options.action.empty()) return copy_between_stores(options, *domain, out);
  if (!options.to.empty() || !options.from.empty())
    return make_error(ErrorCode::kInvalidInput, "--to is for 'knowledge export' and --from for 'knowledge import'");
  const std::string household = options.household.empty() ? std::string(kDefaultHousehold) : options.household;
  auto store = KnowledgeStore::open(options.knowledge, StoreAccess::kReadOnly, household);
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
    Understanding understanding;
    LexicalConcepts concepts(understanding.lexicon(), understanding.vectors());
    nlohmann::json all{{"household", household}, {"tasks", tasks}, {"goals", goals}, {"rules", rules}};
    all.update(class_rules_json(*knowledge, concepts));
    out << dump_json(all, 2) << "\n";
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
  if (!options.household.empty()) out << "Household " << household << " (the rules are shared by every household):\n";
  if (knowledge->tasks.empty() && knowledge->goals.size() == 0 && knowledge->rules.size() == 0 &&
      knowledge->class_rules.empty() && knowledge->forgotten_rules.empty()) {
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
  // The classes a person said and the goals support, for things never
  // taught (induced anew from the goals: forgetting a goal changes them),
  // and the rules forgotten.
  Understanding understanding;
  LexicalConcepts concepts(understanding.lexicon(), understanding.vectors());
  print_class_rules(*knowledge, concepts, options.all, out);
  return Outcome::kSuccess;
}

}  // namespace apprentice::cli
