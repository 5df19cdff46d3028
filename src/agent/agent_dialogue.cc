// The conversation with the teacher: every question is asked through
// converse(), which reads each reply in the context of the question
// (language/reply.h) and handles what is not an answer there: commands
// (help, status, undo, forget, quit), a phrase that fits several things
// (it asks which), and a reply it cannot use (it says why, with replies
// that would work, and asks again).
#include <algorithm>

#include "agent/class_rule_knowledge.h"
#include "agent/explanation.h"
#include "agent/forgetting.h"
#include "agent/goal_proposals.h"
#include "agent/goal_repair.h"
#include "agent/session.h"
#include "agent/teacher_questions.h"
#include "knowledge/goal_memory.h"
#include "language/generation.h"
#include "language/narration.h"
#include "language/narration_conversation.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

// session.h's, for the agent's other files: narration's.
std::string with_period(std::string text) { return language::with_period(std::move(text)); }

Question TaskLearningAgent::Session::question(QuestionKind kind, std::string text, std::optional<ObjectId> object,
                                             std::optional<Goal> goal, std::optional<Action> action) const {
  Question q;
  q.kind = kind;
  q.text = std::move(text);
  q.task = progress_.task.name;
  if (progress_.current) q.subtask = progress_.current->verb;
  q.object = object;
  q.goal = std::move(goal);
  q.action = action;
  return q;
}

language::ReplyContext TaskLearningAgent::Session::context(language::Asked asked, std::optional<ObjectId> object) const {
  language::ReplyContext c;
  c.asked = asked;
  c.object = object;
  c.recent_place = conversation_.recent_place();
  // What "the floor next" and "same with the bucket" do: the verbs of the
  // parts taught so far.
  for (const LearnedSubtask& part : progress_.task.subtasks) c.taught_subtasks.push_back(part.verb);
  // What "same again", "same as the hammer", "the rest" and a class word
  // refer to (language/reply.h).
  const World& w = world();
  if (const GoalKnowledge* last = progress_.last_goal ? agent_.knowledge_.goals.find(*progress_.last_goal) : nullptr) {
    // The thing it was given to: the last of its kind dealt with.
    std::optional<ObjectId> given_to;
    for (auto it = progress_.evaluated_order.rbegin(); it != progress_.evaluated_order.rend() && !given_to; ++it)
      if (w.universe->info(*it).category == last->key.category) given_to = *it;
    for (ObjectId o : w.universe->of_kind(ObjectKind::kItem))
      if (!given_to && w.universe->info(o).category == last->key.category) given_to = o;
    if (given_to)
      if (std::optional<Goal> goal = instantiate_goal(w, *last, *given_to))
        c.last_goal = language::ReplyContext::LastGoal{*given_to, *goal};
  }
  if (progress_.current)
    for (ObjectId o : w.universe->of_kind(ObjectKind::kItem))
      if (o != object && progress_.still_to_come(world(), o)) c.still_to_come.push_back(o);
  c.dealt_with = progress_.evaluated_order;
  c.goal_of_kind = [this](const std::string& kind, ObjectId thing) -> std::optional<Goal> {
    const GoalKnowledge* known = goal_known_for(so_far(), kind);
    if (known == nullptr) return std::nullopt;
    return instantiate_goal(world(), *known, thing);
  };
  return c;
}

void TaskLearningAgent::Session::say(const std::string& statement, Voice voice) {
  conversation_.say(statement, voice);
}

Status TaskLearningAgent::Session::execute(const Action& action) {
  Status status = simulator_.execute(action);
  if (status) conversation_.observe(action, world());
  return status;
}

TaskLearningAgent::Session::Flow<TaskLearningAgent::Session::Heard> TaskLearningAgent::Session::converse(
    const Question& asked, language::ReplyContext context, const Accept& accept, const Rescue& rescue) {
  APPRENTICE_CHECK(conversation_.with_teacher());
  int unusable = 0;
  std::vector<std::string> refused;
  for (;;) {
    // What was said ahead comes first (agent/conversation.h): the answer
    // said after an undo replies to the question the undo brought back;
    // a step said ahead is not another instruction.
    const bool about_steps =
        context.asked == language::Asked::kTaskStep || context.asked == language::Asked::kSubtaskEnd;
    auto said = conversation_.next_reply(asked, world(), about_steps);
    if (!said) return stop(said.error());
    const bool queued_step = said->said_ahead;
    const std::string& text = said->text;
    language::ReplyActs read = agent_.understanding_.acts(world(), context, text);
    std::optional<language::Reply> answer;
    int undos = 0;
    for (language::Reply& act : read.acts) {
      const auto* command = std::get_if<language::Command>(&act);
      if (command == nullptr) answer = std::move(act);
      else if (command->kind == language::Command::Kind::kUndo) ++undos;
    }
    for (const std::string& note : read.notes) say(note, Voice::kResponse);
    // "undo" asked which one: the reply the question came from is what is
    // taken back, not the lesson before it.
    if (undos > 0 && !answer && context.asked == language::Asked::kWhich)
      return Heard{language::Reply(language::YesNo{false}), text, refused};
    if (undos > 0) conversation_.drop_steps_ahead();
    if (undos > 0) {
      // Each undo goes one lesson back; the loop then asks that lesson's
      // question again, and the answer said with the undo replies to it.
      bool undone = false;
      for (int k = 0; k < undos; ++k) {
        Step s = undo();
        if (s) break;  // nothing (more) to undo
        if (s.error().error) return tl::unexpected(s.error());
        undone = true;
      }
      if (undone) {
        if (!read.after_undo.empty()) conversation_.answer_ahead(read.after_undo);
        return tl::unexpected(Stop{});
      }
      if (!answer) continue;
    }
    // Commands are not instructions and teach nothing: the teacher's
    // questions are answered and one-off actions done, then the reply's
    // answer is taken, or the question asked again.
    for (const language::Reply& act : read.acts)
      if (const auto* command = std::get_if<language::Command>(&act); command && command->kind != language::Command::Kind::kUndo)
        if (auto s = obey(*command, asked, context); !s) return tl::unexpected(s.error());
    context.recent_place = conversation_.recent_place();  // a place a one-off action named
    if (!answer) {
      // "shut the cupboard, then do the piano": the parts said after a
      // one-off action answer the question that comes again.
      conversation_.steps_ahead(read.then);
      continue;
    }
    language::Reply reply = std::move(*answer);
    if (!queued_step) conversation_.count(asked, text);
    // A reply the question's own reading takes whole ("same as the hammer,
    // and shut the drawer") is not asked "which drawer?" about.
    std::optional<language::Reply> rescued;
    if (rescue && std::holds_alternative<language::Ambiguous>(reply)) rescued = rescue(text);
    if (rescued) {
      reply = std::move(*rescued);
    } else if (const auto* ambiguous = std::get_if<language::Ambiguous>(&reply)) {
      auto settled = settle(*ambiguous, asked, context, text);
      if (!settled) return tl::unexpected(settled.error());
      reply = *settled;
      // A one-off action the settled reply asked for: done, and the
      // question asked again.
      if (const auto* command = std::get_if<language::Command>(&reply); command && command->kind == language::Command::Kind::kDo) {
        if (auto s = obey(*command, asked, context); !s) return tl::unexpected(s.error());
        continue;
      }
    }
    if (rescue && std::holds_alternative<language::Unusable>(reply))
      if (auto rescued = rescue(text)) reply = std::move(*rescued);
    // The thing asked about called by a word nothing here is called
    // ("dummy in the top drawer", asked about the pacifier): a person is
    // asked whether that word means it.
    if (person())
      if (auto word = agent_.understanding_.other_name_of_asked(world(), text, reply, context)) {
        auto meant = ask_other_name(*word, text, asked, context);
        if (!meant) return tl::unexpected(meant.error());
        if (*meant) reply = std::move(**meant);
      }
    // A person's rule is kept whatever was asked, and the question asked
    // again (a program is asked at most max_retries times).
    if (auto rule = agent_.understanding_.rule_in_reply(world(), text, reply, context)) {
      if (auto heard_rule = hear_rule(std::move(*rule), text); !heard_rule) return tl::unexpected(heard_rule.error());
      // Asked where a thing goes, the rule may place it: the caller decides
      // again before asking.
      if (context.asked == language::Asked::kGoal && context.object && asked.kind == QuestionKind::kSubtaskStep)
        return Heard{std::nullopt, text, refused, true};
      // "lol no. books go on the shelf and trash in the wastebasket", asked
      // yes or no: the rule is kept and the "no" answers.
      if (const auto* said = std::get_if<language::YesNo>(&reply); said && context.asked == language::Asked::kYesNo) {
        language::YesNo answer = *said;
        answer.rest.clear();
        if (!accept(answer)) return Heard{language::Reply(answer), text, refused};
      }
      refused.push_back(apprentice::quoted(text) + " (a rule, kept, but no answer to the question)");
      if (!person() && ++unusable > agent_.options_.max_retries) return Heard{std::nullopt, text, refused};
      continue;
    }
    std::optional<std::string> why;
    std::vector<std::string> examples;
    if (const auto* u = std::get_if<language::Unusable>(&reply)) {
      why = u->reason;
      examples = u->examples;
      context.topic_places = u->topic_places;
    } else {
      why = accept(reply);
    }
    if (!why) {
      conversation_.steps_ahead(read.then);
      for (const std::string& goals : read.goals_ahead) conversation_.answer_ahead(goals);
      return Heard{reply, text, refused};
    }
    explain(*why, context, examples);
    std::string reason = *why;
    while (!reason.empty() && (reason.back() == '.' || reason.back() == ' ')) reason.pop_back();
    refused.push_back(apprentice::quoted(text) + " (" + reason + ")");
    if (!person() && ++unusable > agent_.options_.max_retries) return Heard{std::nullopt, text, refused};
  }
}

TaskLearningAgent::Session::Flow<language::Reply> TaskLearningAgent::Session::settle(
    const language::Ambiguous& first, const Question& asked, language::ReplyContext& context,
    const std::string& text) {
  language::Ambiguous ambiguous = first;
  // Each phrase is asked about once; a reader that still finds a settled
  // phrase ambiguous gets an honest "I still cannot tell".
  for (;;) {
    for (const auto& s : context.settled)
      if (s.phrase == ambiguous.phrase)
        return language::Reply(language::Unusable{language::still_cannot_tell_which(ambiguous.phrase),
                                                  agent_.understanding_.example_replies(world(), context), {}});
    language::ReplyContext which = this->context(language::Asked::kWhich, context.object);
    which.choices = ambiguous.candidates;
    Question q = question(QuestionKind::kWhich, ambiguous.question, asked.object, asked.goal, asked.action);
    q.choices = ambiguous.candidates;
    auto heard = converse(q, which, chosen_among(ambiguous.candidates));
    if (!heard) return tl::unexpected(heard.error());
    if (!heard->reply)
      return language::Reply(language::Unusable{language::could_not_tell_which(ambiguous.phrase), {}, {}});
    // "neither", "skip it": none of them; the reply is set aside and its
    // question asked again.
    if (!std::holds_alternative<language::Chosen>(*heard->reply))
      return language::Reply(language::Unusable{language::reply_set_aside(text), {}, {}});
    context.settled.push_back({ambiguous.phrase, std::get<language::Chosen>(*heard->reply).object});
    // Read again as a whole reply: its answer, or else the one-off action
    // it asked for ("open the drawer", then "the top one"), for the caller
    // to do.
    const std::vector<language::Reply> acts = agent_.understanding_.acts(world(), context, text).acts;
    auto answer = std::find_if(acts.begin(), acts.end(),
                               [](const language::Reply& r) { return !std::holds_alternative<language::Command>(r); });
    auto one_off = std::find_if(acts.begin(), acts.end(), [](const language::Reply& r) {
      const auto* command = std::get_if<language::Command>(&r);
      return command != nullptr && command->kind == language::Command::Kind::kDo;
    });
    const language::Reply again = answer != acts.end() ? *answer : one_off != acts.end() ? *one_off : acts.front();
    const auto* still = std::get_if<language::Ambiguous>(&again);
    if (still == nullptr) return again;
    ambiguous = *still;
  }
}

TaskLearningAgent::Session::Accept TaskLearningAgent::Session::chosen_among(std::vector<ObjectId> choices) {
  return [choices = std::move(choices)](const language::Reply& r) -> std::optional<std::string> {
    if (const auto* chosen = std::get_if<language::Chosen>(&r))
      if (std::find(choices.begin(), choices.end(), chosen->object) != choices.end()) return std::nullopt;
    if (const auto* said = std::get_if<language::YesNo>(&r); said && !said->yes) return std::nullopt;  // none of them
    return language::asked_which_one();
  };
}

TaskLearningAgent::Session::Flow<bool> TaskLearningAgent::Session::confirm(const Question& asked) {
  auto heard = converse(asked, context(language::Asked::kYesNo, asked.object),
                        [](const language::Reply& r) -> std::optional<std::string> {
                          if (std::holds_alternative<language::YesNo>(r)) return std::nullopt;
                          return language::asked_yes_or_no();
                        });
  if (!heard) return tl::unexpected(heard.error());
  if (!heard->reply) return false;
  bool yes = std::get<language::YesNo>(*heard->reply).yes;
  if (yes) begin_lesson(heard->text);
  return yes;
}

void TaskLearningAgent::Session::explain(const std::string& reason, const language::ReplyContext& context,
                                         std::vector<std::string> examples) {
  if (examples.empty()) examples = agent_.understanding_.example_replies(world(), context);
  say(language::reply_refused(reason, examples), Voice::kResponse);
}

TaskLearningAgent::Session::Step TaskLearningAgent::Session::obey(const language::Command& command,
                                                                  const Question& asked,
                                                                  const language::ReplyContext& context) {
  switch (command.kind) {
    case language::Command::Kind::kHelp:
      say(language::i_asked(asked.text), Voice::kResponse);
      say(language::kinds_of_answer(context.asked, agent_.understanding_.example_replies(world(), context)),
          Voice::kResponse);
      say(language::commands_at_any_question(), Voice::kResponse);
      return {};
    case language::Command::Kind::kStatus: {
      const StatusCounts counts{static_cast<long long>(agent_.knowledge_.rules.size()), conversation_.instructions()};
      for (const std::string& line : answer_status(so_far(), asked.object, counts)) say(line, Voice::kResponse);
      return {};
    }
    case language::Command::Kind::kUndo: return undo();
    case language::Command::Kind::kForget: {
      auto known = [&] { return agent_.knowledge_.goals.size() + sources_.rules_in_use().size(); };
      const std::size_t before = known();
      if (auto s = forget(command.argument); !s) return stop(s.error());
      // "forget paper", asked whether the box goes with paper things: what
      // the question rested on is gone, and the thing is decided again.
      if (asked.kind == QuestionKind::kConfirmGoal && known() != before) return tl::unexpected(Stop{});
      return {};
    }
    case language::Command::Kind::kQuit: return stop(Error{ErrorCode::kCancelled, "the instructor quit"});
    case language::Command::Kind::kWhatsLeft: say(answer_whats_left(so_far()), Voice::kResponse); return {};
    case language::Command::Kind::kWhere:
      for (const std::string& line : language::where_things_are(world(), command.argument, command.things))
        say(line, Voice::kResponse);
      return {};
    case language::Command::Kind::kWhy: {
      const WhyAbout about = command.asking ? WhyAbout::kAsking : command.earlier ? WhyAbout::kEarlier : WhyAbout::kNow;
      say(answer_why(so_far(), command.things, about), Voice::kResponse);
      return {};
    }
    case language::Command::Kind::kDo:
      if (!command.left_open.empty())
        if (auto s = keep_doors(command.left_open, command.argument, true); !s) return stop(s.error());
      if (!command.kept_closed.empty())
        if (auto s = keep_doors(command.kept_closed, command.argument, false); !s) return stop(s.error());
      do_now(command.actions);
      return {};
  }
  return {};
}

TeachingSoFar TaskLearningAgent::Session::so_far() const {
  return TeachingSoFar{world(), agent_.knowledge_.goals, progress_, lessons_.last_reply(), proposals_asked_};
}

Status TaskLearningAgent::Session::keep_doors(const std::vector<ObjectId>& places, const std::string& text, bool open) {
  const World& w = world();
  begin_lesson(text);
  std::vector<std::string> kinds;
  for (ObjectId place : places) {
    if (open) progress_.doors_left_open.insert(door_key(w, place));
    else progress_.doors_left_open.erase(door_key(w, place));
    const std::vector<GoalKnowledge> again = open ? goals_leaving_open(w, agent_.knowledge_.goals, place, text)
                                                  : goals_closing(w, agent_.knowledge_.goals, place, text);
    for (const GoalKnowledge& g : again) {
      if (auto s = lessons_.learn_goal(agent_.knowledge_, g); !s) return s;
      if (std::find(kinds.begin(), kinds.end(), g.key.category) == kinds.end()) kinds.push_back(g.key.category);
    }
  }
  say(language::will_keep_doors(w, places, kinds, open), Voice::kResponse);
  return {};
}

void TaskLearningAgent::Session::do_now(const std::vector<Action>& actions) {
  std::vector<Action> done;
  for (const Action& action : actions) {
    const std::string& name = world().domain->actions[action.schema].name;
    const ObjectId thing = action.arguments()[0];
    bool closed = world().state.holds(Fact(world().vocabulary.closed, {thing}));
    if ((name == "close" && closed) || (name == "open" && !closed)) {
      say(language::already_open_or_closed(world(), thing, closed), Voice::kResponse);
      continue;
    }
    std::string why = language::refusal(world(), action);
    if (!why.empty() || !execute(action)) {
      say(why.empty() ? language::could_not(world(), action) : why, Voice::kResponse);
      continue;
    }
    done.push_back(action);
    conversation_.named_place(thing);  // "open the cabinet", then "close it"
  }
  if (!done.empty()) say(language::report_actions(world(), done), Voice::kResponse);
}

Status TaskLearningAgent::Session::forget(const std::string& what) {
  const std::vector<ClassRule> rules = sources_.rules_in_use();
  const ForgetDecision decided =
      decide_forget(what, agent_.understanding_.category(world(), what), agent_.knowledge_.goals, rules);
  if (decided.kind == ForgetDecision::Kind::kGoals) {
    // A lesson of its own, so that "undo" right after brings it back.
    begin_lesson("forget " + what);
    for (const GoalKey& key : decided.goals)
      if (auto s = lessons_.forget_goal(agent_.knowledge_, key); !s) return s;
  }
  for (const ClassRule& rule : decided.rules) {
    if (auto s = forget_rule(agent_.knowledge_, agent_.store_, rule); !s) return s;
    // An undo must not bring it back either.
    lessons_.forget_class_rule(rule);
    sources_.forget_rule(rule);
  }
  say(decided.reply, Voice::kResponse);
  return {};
}

}  // namespace apprentice
