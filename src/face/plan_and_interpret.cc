// Planning and reading English without an agent (face/apprentice.h): what
// `apprentice plan` and `apprentice interpret` print, built once here for
// the CLI and the Python module.
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

#include "face/apprentice.h"
#include "language/corpus.h"
#include "language/generation.h"
#include "language/grounding.h"
#include "language/narration.h"
#include "language/reply.h"
#include "search/greedy_best_first.h"
#include "search/iterative_deepening.h"
#include "search/unreachable.h"
#include "util/json.h"
#include "util/text.h"
#include "world/pddl.h"

namespace apprentice {
namespace {

// The plan in PDDL, one action a line, and the search's figures on a ";;" line.
std::string plan_in_pddl(const World& world, const PlanResult& result, bool greedy) {
  const SearchStatistics& s = result.statistics;
  std::ostringstream out;
  for (const Action& a : result.plan) out << format_action(*world.domain, *world.universe, a) << "\n";
  out << ";; status " << to_string(result.status) << ", " << result.plan.size() << " steps, ";
  if (greedy) {
    out << "greedy best-first search, " << s.nodes_expanded << " nodes expanded, " << s.nodes_generated
        << " generated, " << s.states_registered << " states, heuristic " << s.initial_heuristic
        << " at the start, " << s.steps_removed << " steps removed afterwards, ";
  } else {
    out << s.nodes_expanded << " nodes expanded, " << s.nodes_generated << " generated, depth limit "
        << s.depth_limit_reached << ", ";
  }
  out << s.relevant_objects << " relevant objects, " << s.ground_actions << " ground actions, " << s.elapsed_ms
      << " ms\n";
  return out.str();
}

// What the search found, and what it took, in one sentence: "Greedy
// best-first search found a plan of 4 steps in 3 ms: 12 nodes expanded
// and 40 generated, ...".
std::string plan_summary(const PlanResult& result, bool greedy, std::optional<int> depth) {
  const SearchStatistics& s = result.statistics;
  using language::count_phrase;
  std::string search = greedy ? "Greedy best-first search" : "Iterative deepening to depth " + std::to_string(*depth);
  std::ostringstream ms;
  ms << std::fixed << std::setprecision(1) << s.elapsed_ms;
  const std::string in = " in " + ms.str() + " ms";
  std::string found;
  switch (result.status) {
    case SearchStatus::kSolved:
      found = result.plan.empty()
                  ? "found" + in + " that the goal holds already, so no step is needed"
                  : "found a plan of " + count_phrase(static_cast<long long>(result.plan.size()), "step") + in;
      break;
    case SearchStatus::kExhausted: found = "found" + in + " that no plan reaches the goal"; break;
    case SearchStatus::kBudgetExhausted: found = "reached its limit without a plan" + in; break;
    case SearchStatus::kInProgress: found = "stopped without a plan" + in; break;
  }
  std::string how = count_phrase(static_cast<long long>(s.nodes_expanded), "node") + " expanded and " +
                    std::to_string(s.nodes_generated) + " generated";
  if (greedy) {
    how += ", " + count_phrase(static_cast<long long>(s.states_registered), "state");
    // -1: the start is a dead end, or the goal holds there; no value to give.
    if (s.initial_heuristic >= 0) how += ", a heuristic value of " + std::to_string(s.initial_heuristic) + " at the start";
    how += ", " + count_phrase(static_cast<long long>(s.steps_removed), "step") + " removed afterwards";
  }
  how += ", " + std::to_string(s.relevant_objects) + " of the objects relevant and " +
         count_phrase(static_cast<long long>(s.ground_actions), "ground action");
  return search + " " + found + ": " + how + ".";
}

std::string plan_json(const World& world, const PlanResult& result, bool greedy, const std::string& never_holds) {
  const SearchStatistics& s = result.statistics;
  nlohmann::json plan = nlohmann::json::array();
  for (const Action& a : result.plan) plan.push_back(format_action(*world.domain, *world.universe, a));
  nlohmann::json j{{"status", to_string(result.status)}, {"plan", plan},
                   {"planner", greedy ? "greedy-best-first" : "iterative-deepening"},
                   {"nodes_expanded", s.nodes_expanded}, {"nodes_generated", s.nodes_generated},
                   {"relevant_objects", s.relevant_objects}, {"ground_actions", s.ground_actions},
                   {"elapsed_ms", s.elapsed_ms}, {"relevance", result.notes}};
  if (!never_holds.empty()) j["never_holds"] = never_holds;
  if (greedy) {
    j["nodes_evaluated"] = s.nodes_evaluated;
    j["dead_ends"] = s.dead_ends;
    j["states_registered"] = s.states_registered;
    j["propositions"] = s.propositions;
    j["initial_heuristic"] = s.initial_heuristic;
    j["best_heuristic"] = s.best_heuristic;
    j["steps_removed"] = s.steps_removed;
    j["grounding_ms"] = s.grounding_ms;
  } else {
    j["depth_limit"] = s.depth_limit_reached;
  }
  return dump_json(j, 2) + "\n";
}

// Why no plan reaches the goal, in one sentence: a part of it that can
// never hold ("The garbage can never be closed: it has no door, so I cannot
// close it."), else what the search could and could not tell.
std::string why_no_plan(const std::string& never_holds, bool greedy, std::optional<int> depth) {
  if (!never_holds.empty()) return never_holds;
  if (greedy)
    return "no sequence of actions reaches the goal from this state, though each part of it could hold on its own: "
           "its parts cannot all hold at once here";
  return "no plan of at most " + std::to_string(*depth) +
         " steps reaches the goal; try a larger --depth, or leave --depth out for greedy best-first search";
}

SearchOptions search_options(const PlanRequest& request) {
  SearchOptions search;
  if (request.depth) search.max_depth = *request.depth;
  if (request.node_limit) search.max_nodes = static_cast<std::uint64_t>(*request.node_limit);
  if (request.time_limit_s)
    search.max_time = std::chrono::milliseconds(static_cast<std::int64_t>(*request.time_limit_s * 1000.0));
  search.prune_irrelevant = request.pruning;
  if (request.progress) {
    search.progress = [progress = request.progress](const SearchProgress& p) {
      std::ostringstream line;
      line << "searching: " << p.nodes_expanded << " nodes in " << std::fixed << std::setprecision(1)
           << p.elapsed_ms / 1000.0 << " s (" << std::setprecision(0) << p.nodes_per_second
           << " nodes/s), best heuristic value " << p.best_heuristic;
      progress(line.str());
    };
  }
  return search;
}

// An object named by id, else by category (at the subtask's place if given).
Result<std::optional<ObjectId>> object_named(const Scenario& scenario, const std::optional<std::string>& object,
                                             const std::optional<std::string>& subtask) {
  if (!object) return std::optional<ObjectId>();
  const Universe& universe = *scenario.world.universe;
  if (auto id = universe.find(*object)) return std::optional<ObjectId>(*id);
  language::CorpusLine line;
  line.object = *object;
  line.subtask = subtask.value_or("");
  if (auto id = language::object_for_line(scenario, line)) return std::optional<ObjectId>(*id);
  return make_error(ErrorCode::kNotFound, "no object or category " + *object + " in " + scenario.source.string());
}

std::string english(const World& world, const language::Interpretation& interpretation) {
  if (const auto* goal = std::get_if<Goal>(&interpretation.result)) return language::describe_goal(world, *goal);
  if (const auto* action = std::get_if<Action>(&interpretation.result))
    return language::describe_action(world, *action);
  return "";
}

std::string sentence_text(const World& world, std::string_view sentence, const language::Interpretation& in) {
  std::ostringstream out;
  out << "sentence: " << sentence << "\n";
  if (in.form) out << "form: " << language::format_logical_form(*in.form) << "\n";
  out << "result: " << language::format_grounding(world, in.result) << "\n";
  if (const auto* failure = in.failure()) out << "reason: " << failure->message << "\n";
  if (std::string words = english(world, in); !words.empty()) out << "english: " << words << "\n";
  for (const language::Reference& r : in.references)
    out << "reference: \"" << r.phrase << "\" -> " << world.universe->name(r.object) << " by "
        << language::to_string(r.method) << " (" << r.reason << ")\n";
  return out.str();
}

std::string sentence_json(const World& world, std::string_view sentence, const language::Interpretation& in) {
  nlohmann::ordered_json j;
  j["sentence"] = std::string(sentence);
  j["form"] = in.form ? nlohmann::ordered_json(language::format_logical_form(*in.form)) : nullptr;
  j["result"] = language::format_grounding(world, in.result);
  if (const auto* failure = in.failure()) {
    j["failure"] = {{"kind", std::string(language::to_string(failure->kind))},
                    {"detail", failure->detail},
                    {"message", failure->message}};
  }
  if (std::string words = english(world, in); !words.empty()) j["english"] = words;
  nlohmann::ordered_json refs = nlohmann::ordered_json::array();
  for (const language::Reference& r : in.references)
    refs.push_back({{"phrase", r.phrase},
                    {"object", world.universe->name(r.object)},
                    {"method", std::string(language::to_string(r.method))},
                    {"reason", r.reason}});
  j["references"] = refs;
  return dump_json(j) + "\n";
}

// "task, task-step, ..., yes-no or which".
std::string kinds_or() {
  std::vector<std::string> kinds = question_kinds();
  std::string last = kinds.back();
  kinds.pop_back();
  return join(kinds, ", ") + " or " + last;
}

void render(ReplyReading& reading) {
  nlohmann::ordered_json j;
  j["reply"] = reading.reply;
  j["asked"] = reading.asked;
  j["meaning"] = reading.meaning;
  if (!reading.reason.empty()) j["reason"] = reading.reason;
  if (!reading.question.empty()) j["question"] = reading.question;
  if (!reading.examples.empty()) j["examples"] = reading.examples;
  if (!reading.notes.empty()) j["notes"] = reading.notes;
  if (!reading.then.empty()) j["then"] = reading.then;
  if (!reading.goals_ahead.empty()) j["goals_ahead"] = reading.goals_ahead;
  reading.json = dump_json(j) + "\n";
  std::string text = "reply: " + reading.reply + "\nasked: " + reading.asked + "\nmeaning: " + reading.meaning + "\n";
  if (!reading.reason.empty()) text += "reason: " + reading.reason + "\n";
  if (!reading.question.empty()) text += "question: " + reading.question + "\n";
  for (const std::string& e : reading.examples) text += "example: " + e + "\n";
  for (const std::string& n : reading.notes) text += "note: " + n + "\n";
  for (const std::string& t : reading.then) text += "then: " + t + "\n";
  for (const std::string& g : reading.goals_ahead) text += "then, where things go: " + g + "\n";
  reading.text = std::move(text);
}

}  // namespace

Result<Goal> parse_goal_or_intent(const Scenario& scenario, const std::string& text) {
  if (text == kIntentGoal) return Goal(scenario.goal_assertions());
  if (std::string_view t = trim(text); !t.empty() && t.front() != '(')
    return make_error(ErrorCode::kInvalidInput,
                      "--goal " + apprentice::quoted(text) + " is not a goal: a goal is PDDL, such as (in ketchup1 fridge1) or "
                      "(and (in ketchup1 fridge1) (closed fridge1)), or 'intent' for the whole task; "
                      "'apprentice interpret' reads English");
  return parse_goal(*scenario.world.domain, *scenario.world.universe, text);
}

Result<PlanFound> plan(const Scenario& scenario, const PlanRequest& request) {
  const World& world = scenario.world;
  auto goal = parse_goal_or_intent(scenario, request.goal);
  if (!goal) return tl::unexpected(goal.error());
  const SearchOptions search = search_options(request);
  const bool greedy = !request.depth.has_value();
  PlanResult result = greedy ? find_greedy_plan(*world.domain, *world.universe, world.state, *goal, search)
                             : find_plan(*world.domain, *world.universe, world.state, *goal, search);
  std::string never_holds;
  if (result.status == SearchStatus::kExhausted)
    never_holds = language::never_holds(world, explain_unreachable(*world.domain, *world.universe, world.state, *goal));
  PlanFound found;
  found.solved = result.status == SearchStatus::kSolved;
  found.status = std::string(to_string(result.status));
  for (const Action& a : result.plan) found.actions.push_back(format_action(*world.domain, *world.universe, a));
  found.text = language::plan_steps(world, result.plan) + plan_summary(result, greedy, request.depth) + "\n";
  found.pddl = plan_in_pddl(world, result, greedy);
  found.json = plan_json(world, result, greedy, never_holds);
  if (result.status == SearchStatus::kExhausted) found.why_not = why_no_plan(never_holds, greedy, request.depth);
  found.notes = result.notes;
  return found;
}

std::vector<std::string> question_kinds() {
  std::vector<std::string> kinds;
  for (language::Asked asked : language::kEveryAsked) kinds.emplace_back(language::to_string(asked));
  return kinds;
}

std::string question_kind(const Question& question) {
  using language::Asked;
  Asked asked = Asked::kTask;
  switch (question.kind) {
    case QuestionKind::kTaskName: asked = Asked::kTask; break;
    case QuestionKind::kTaskStep: asked = Asked::kTaskStep; break;
    case QuestionKind::kSubtaskStep: asked = question.object ? Asked::kGoal : Asked::kSubtaskEnd; break;
    case QuestionKind::kNextAction: asked = Asked::kAction; break;
    case QuestionKind::kConfirmGoal:
    case QuestionKind::kConfirmAction:
    case QuestionKind::kConfirm: asked = Asked::kYesNo; break;
    case QuestionKind::kWhich: asked = Asked::kWhich; break;
  }
  return std::string(language::to_string(asked));
}

Result<ReplyReading> interpret_reply(const Scenario& scenario, std::string_view reply, const AskedQuestion& asked) {
  const World& world = scenario.world;
  std::optional<language::Asked> kind = language::asked_named(asked.kind);
  if (!kind)
    return make_error(ErrorCode::kInvalidInput, "--asked takes " + kinds_or() + ", not " + apprentice::quoted(asked.kind));
  auto object = object_named(scenario, asked.object, asked.subtask);
  if (!object) return tl::unexpected(object.error());
  language::ReplyContext context;
  context.asked = *kind;
  context.object = *object;
  auto id = [&](const std::string& name) -> Result<ObjectId> {
    if (auto found = world.universe->find(name)) return *found;
    return make_error(ErrorCode::kNotFound, "no object " + name + " in " + scenario.source.string());
  };
  if (asked.recent) {
    auto recent = id(*asked.recent);
    if (!recent) return tl::unexpected(recent.error());
    context.recent_place = *recent;
  }
  for (const std::string& name : asked.choices) {
    auto choice = id(name);
    if (!choice) return tl::unexpected(choice.error());
    context.choices.push_back(*choice);
  }
  language::Grounder grounder(language::Lexicon::open_default());
  // The agent's own reading: the reply's dialogue acts (an undo, the
  // answer, a one-off action, ...), not the question's reader alone.
  const language::ReplyActs read = language::read_acts(grounder, world, context, reply);
  ReplyReading reading;
  reading.reply = std::string(reply);
  reading.asked = asked.kind;
  reading.usable = true;
  std::vector<std::string> meanings;
  for (const language::Reply& act : read.acts) {
    meanings.push_back(language::format_reply(world, act));
    if (const auto* unusable = std::get_if<language::Unusable>(&act); unusable && reading.reason.empty()) {
      reading.reason = unusable->reason;
      reading.examples = unusable->examples;
    }
    if (const auto* ambiguous = std::get_if<language::Ambiguous>(&act); ambiguous && reading.question.empty())
      reading.question = ambiguous->question;
    reading.usable = reading.usable && !std::holds_alternative<language::Unusable>(act) &&
                     !std::holds_alternative<language::Ambiguous>(act);
  }
  reading.meaning = join(meanings, " ; ");
  reading.notes = read.notes;
  reading.then = read.then;
  reading.goals_ahead = read.goals_ahead;
  render(reading);
  return reading;
}

Result<SentenceReading> interpret_sentence(const Scenario& scenario, std::string_view sentence,
                                           const std::optional<std::string>& object,
                                           const std::optional<std::string>& subtask) {
  auto about = object_named(scenario, object, subtask);
  if (!about) return tl::unexpected(about.error());
  const World& world = scenario.world;
  language::Grounder grounder(language::Lexicon::open_default());
  language::Interpretation in = grounder.interpret(sentence, world, *about);
  SentenceReading reading;
  reading.grounded = in.failure() == nullptr;
  if (const auto* failure = in.failure()) {
    reading.outside_grammar = failure->kind == language::FailureKind::kUninterpretable;
    reading.detail = failure->detail;
  }
  reading.text = sentence_text(world, sentence, in);
  reading.json = sentence_json(world, sentence, in);
  return reading;
}

Result<std::string> interpret_corpus(const Scenario& scenario, const std::filesystem::path& corpus, bool json) {
  auto lines = language::read_corpus(corpus);
  if (!lines) return tl::unexpected(lines.error());
  language::Grounder grounder(language::Lexicon::open_default());
  auto results = language::ground_corpus(grounder, scenario, *lines);
  language::CorpusReport report = language::summarize(results);
  return json ? language::format_report_json(report) + "\n" : language::format_report(report);
}

}  // namespace apprentice
