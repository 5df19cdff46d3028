#include "cmd_interpret.h"

#include <ostream>

#include <nlohmann/json.hpp>

#include "face/apprentice.h"
#include "language/corpus.h"
#include "language/generation.h"
#include "language/grounding.h"
#include "language/reply.h"
#include "util/json.h"
#include "util/text.h"
#include "world/scenario.h"

namespace apprentice::cli {
namespace {

using language::Interpretation;

// --object as an id, else as a category (at the --subtask's place if given).
Result<std::optional<ObjectId>> object_option(const Scenario& scenario, const InterpretOptions& options) {
  if (!options.object) return std::optional<ObjectId>();
  const Universe& universe = *scenario.world.universe;
  if (auto id = universe.find(*options.object)) return std::optional<ObjectId>(*id);
  language::CorpusLine line;
  line.object = *options.object;
  line.subtask = options.subtask.value_or("");
  if (auto id = language::object_for_line(scenario, line)) return std::optional<ObjectId>(*id);
  return make_error(ErrorCode::kNotFound, "no object or category " + *options.object + " in " + options.scenario);
}

std::string english(const World& world, const Interpretation& interpretation) {
  if (const auto* goal = std::get_if<Goal>(&interpretation.result)) return language::describe_goal(world, *goal);
  if (const auto* action = std::get_if<Action>(&interpretation.result))
    return language::describe_action(world, *action);
  return "";
}

void print_text(const World& world, std::string_view sentence, const Interpretation& in, std::ostream& out) {
  out << "sentence: " << sentence << "\n";
  if (in.form) out << "form: " << language::format_logical_form(*in.form) << "\n";
  out << "result: " << language::format_grounding(world, in.result) << "\n";
  if (const auto* failure = in.failure()) out << "reason: " << failure->message << "\n";
  if (std::string words = english(world, in); !words.empty()) out << "english: " << words << "\n";
  for (const language::Reference& r : in.references)
    out << "reference: \"" << r.phrase << "\" -> " << world.universe->name(r.object) << " by "
        << language::to_string(r.method) << " (" << r.reason << ")\n";
}

void print_json(const World& world, std::string_view sentence, const Interpretation& in, std::ostream& out) {
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
  out << dump_json(j) << "\n";
}

// --asked: the sentence as a teacher's reply.
CommandResult run_reply(const Scenario& scenario, const language::Grounder& grounder,
                        std::optional<ObjectId> object, const InterpretOptions& options, std::ostream& out) {
  const World& world = scenario.world;
  language::ReplyContext context;
  bool known = false;
  for (language::Asked a : {language::Asked::kTask, language::Asked::kTaskStep, language::Asked::kSubtaskEnd,
                            language::Asked::kGoal, language::Asked::kAction, language::Asked::kYesNo,
                            language::Asked::kWhich})
    if (language::to_string(a) == *options.asked) {
      context.asked = a;
      known = true;
    }
  if (!known)
    return make_error(ErrorCode::kInvalidInput,
                      "--asked takes task, task-step, subtask-end, goal, action, yes-no or which, not " +
                          apprentice::quoted(*options.asked));
  context.object = object;
  auto id = [&](const std::string& name) -> Result<ObjectId> {
    if (auto found = world.universe->find(name)) return *found;
    return make_error(ErrorCode::kNotFound, "no object " + name + " in " + options.scenario);
  };
  if (options.recent) {
    auto recent = id(*options.recent);
    if (!recent) return tl::unexpected(recent.error());
    context.recent_place = *recent;
  }
  for (const std::string& name : options.choices) {
    auto choice = id(name);
    if (!choice) return tl::unexpected(choice.error());
    context.choices.push_back(*choice);
  }
  language::Reply reply = language::read_reply(grounder, world, context, *options.sentence);
  std::string meaning = language::format_reply(world, reply);
  std::string reason, question;
  std::vector<std::string> examples;
  if (const auto* unusable = std::get_if<language::Unusable>(&reply)) {
    reason = unusable->reason;
    examples = unusable->examples;
  }
  if (const auto* ambiguous = std::get_if<language::Ambiguous>(&reply)) question = ambiguous->question;
  if (options.json) {
    nlohmann::ordered_json j;
    j["reply"] = *options.sentence;
    j["asked"] = *options.asked;
    j["meaning"] = meaning;
    if (!reason.empty()) j["reason"] = reason;
    if (!question.empty()) j["question"] = question;
    if (!examples.empty()) j["examples"] = examples;
    out << dump_json(j) << "\n";
  } else {
    out << "reply: " << *options.sentence << "\nasked: " << *options.asked << "\nmeaning: " << meaning << "\n";
    if (!reason.empty()) out << "reason: " << reason << "\n";
    if (!question.empty()) out << "question: " << question << "\n";
    for (const std::string& e : examples) out << "example: " << e << "\n";
  }
  bool usable = !std::holds_alternative<language::Unusable>(reply) && !std::holds_alternative<language::Ambiguous>(reply);
  return usable ? Outcome::kSuccess : Outcome::kGoalNotReached;
}

CommandResult run_corpus(const Scenario& scenario, const language::Grounder& grounder,
                         const InterpretOptions& options, std::ostream& out) {
  auto lines = language::read_corpus(*options.corpus);
  if (!lines) return tl::unexpected(lines.error());
  auto results = language::ground_corpus(grounder, scenario, *lines);
  language::CorpusReport report = language::summarize(results);
  out << (options.json ? language::format_report_json(report) + "\n" : language::format_report(report));
  return Outcome::kSuccess;
}

}  // namespace

CommandResult run_interpret(const InterpretOptions& options, std::ostream& out) {
  if (options.sentence.has_value() == options.corpus.has_value())
    return make_error(ErrorCode::kInvalidInput, "interpret takes either a sentence or --corpus FILE");
  auto scenario = load_world(options.scenario);
  if (!scenario) return tl::unexpected(scenario.error());
  language::Grounder grounder(language::Lexicon::open_default());
  if (options.corpus) return run_corpus(*scenario, grounder, options, out);
  auto object = object_option(*scenario, options);
  if (!object) return tl::unexpected(object.error());
  if (options.asked) return run_reply(*scenario, grounder, *object, options, out);
  const World& world = scenario->world;
  Interpretation in = grounder.interpret(*options.sentence, world, *object);
  if (options.json) {
    print_json(world, *options.sentence, in, out);
  } else {
    print_text(world, *options.sentence, in, out);
  }
  if (const auto* failure = in.failure()) {
    if (failure->kind == language::FailureKind::kUninterpretable)
      return make_error(ErrorCode::kInvalidInput, "the sentence is outside the grammar: " + failure->detail);
    return Outcome::kGoalNotReached;
  }
  return Outcome::kSuccess;
}

}  // namespace apprentice::cli
