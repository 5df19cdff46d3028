#include "language/reply.h"

#include "language/generation.h"
#include "language/parser.h"
#include "util/text.h"

namespace apprentice::language {
namespace {

std::optional<Command> command(std::string_view text) {
  std::vector<std::string> words = tokenize(text);
  if (words.empty()) return std::nullopt;
  if (words.size() == 1) {
    if (words[0] == "help") return Command{Command::Kind::kHelp, ""};
    if (words[0] == "status") return Command{Command::Kind::kStatus, ""};
    if (words[0] == "undo") return Command{Command::Kind::kUndo, ""};
    if (words[0] == "quit" || words[0] == "exit") return Command{Command::Kind::kQuit, ""};
  }
  if (words[0] == "forget" && words.size() > 1)
    return Command{Command::Kind::kForget, join(std::vector<std::string>(words.begin() + 1, words.end()), " ")};
  return std::nullopt;
}

Unusable unusable(const World& world, const ReplyContext& context, std::string reason,
                  std::optional<GroundingFailure> failure = std::nullopt) {
  return Unusable{std::move(reason), example_replies(world, context), std::move(failure)};
}

Reply from_step(const TaskStep& step) {
  switch (step.kind) {
    case TaskStep::Kind::kTaskName: return TaskNamed{step.name};
    case TaskStep::Kind::kRepeatWhile: return LoopNamed{step.relation, {*step.place}};
    case TaskStep::Kind::kSubtask: return SubtaskNamed{step.name, step.relation, {*step.place}};
    case TaskStep::Kind::kDone: return Finished{};
    case TaskStep::Kind::kRepeat: return Proceed{};
    case TaskStep::Kind::kAnswer: return YesNo{step.yes};
  }
  return Finished{};
}

}  // namespace

std::string_view to_string(Asked asked) {
  switch (asked) {
    case Asked::kTask: return "task";
    case Asked::kTaskStep: return "task-step";
    case Asked::kSubtaskEnd: return "subtask-end";
    case Asked::kGoal: return "goal";
    case Asked::kAction: return "action";
    case Asked::kYesNo: return "yes-no";
    case Asked::kWhich: return "which";
  }
  return "task";
}

// A first reading: the script's grammar only. docs/language.md says what is
// understood.
Reply read_reply(const Grounder& grounder, const World& world, const ReplyContext& context, std::string_view text) {
  if (auto c = command(text)) return *c;
  Interpretation interpretation = grounder.interpret(text, world, context.object);
  if (const auto* failure = interpretation.failure()) return unusable(world, context, failure->message, *failure);
  if (const auto* goal = std::get_if<Goal>(&interpretation.result)) return GoalGiven{*goal};
  if (const auto* action = std::get_if<Action>(&interpretation.result)) return ActionGiven{*action};
  return from_step(std::get<TaskStep>(interpretation.result));
}

std::vector<std::string> example_replies(const World& world, const ReplyContext& context) {
  switch (context.asked) {
    case Asked::kTask: return {"Tidy kitchen.", "tidy the kitchen"};
    case Asked::kTaskStep:
      return {"Repeat the following tasks while an object is on the table.", "Clear an object that is on the table.",
              "You are done."};
    case Asked::kSubtaskEnd: return {"You are done.", "Repeat."};
    case Asked::kGoal:
      if (context.object) {
        const std::string& category = world.universe->info(*context.object).category;
        return {"If the object is " + std::string(article_for(category)) + " " + category +
                " then the goal is that the object is in the fridge and the fridge is closed."};
      }
      return {"If the object is a ketchup then the goal is that the object is in the fridge."};
    case Asked::kAction: return {"Open the fridge.", "Pick up the ketchup.", "Put the ketchup in the fridge."};
    case Asked::kYesNo: return {"yes", "no"};
    case Asked::kWhich: {
      std::vector<std::string> out;
      for (ObjectId id : context.choices) out.push_back(noun_for(world, id));
      return out;
    }
  }
  return {};
}

std::string format_reply(const World& world, const Reply& reply) {
  const Universe& u = *world.universe;
  auto places = [&](const std::vector<ObjectId>& ids) {
    std::vector<std::string> names;
    for (ObjectId id : ids) names.push_back(u.name(id));
    return join(names, " ");
  };
  struct Formatter {
    const World& world;
    const Universe& u;
    decltype(places)& list;
    std::string operator()(const TaskNamed& r) const { return "task " + r.name; }
    std::string operator()(const SubtaskNamed& r) const {
      return "subtask " + r.verb + " " + std::string(to_string(r.relation)) + " " + list(r.places);
    }
    std::string operator()(const LoopNamed& r) const {
      return "loop " + std::string(to_string(r.relation)) + " " + list(r.places);
    }
    std::string operator()(const Finished&) const { return "finished"; }
    std::string operator()(const Proceed&) const { return "proceed"; }
    std::string operator()(const GoalGiven& r) const { return "goal " + format_goal(*world.domain, u, r.goal); }
    std::string operator()(const ActionGiven& r) const {
      return "action " + format_action(*world.domain, u, r.action);
    }
    std::string operator()(const YesNo& r) const { return r.yes ? "yes" : "no"; }
    std::string operator()(const Chosen& r) const { return "chosen " + u.name(r.object); }
    std::string operator()(const Command& r) const {
      switch (r.kind) {
        case Command::Kind::kHelp: return "command help";
        case Command::Kind::kStatus: return "command status";
        case Command::Kind::kUndo: return "command undo";
        case Command::Kind::kForget: return "command forget " + r.argument;
        case Command::Kind::kQuit: return "command quit";
      }
      return "command";
    }
    std::string operator()(const Ambiguous& r) const { return "ambiguous " + r.phrase + ": " + list(r.candidates); }
    std::string operator()(const Unusable& r) const {
      return "unusable" + (r.failure ? " " + std::string(to_string(r.failure->kind)) + " " + r.failure->detail : "");
    }
  };
  return std::visit(Formatter{world, u, places}, reply);
}

}  // namespace apprentice::language
