// The conversation with the teacher: every question is asked through
// converse(), which reads each reply in the context of the question
// (language/reply.h) and handles what is not an answer there: commands
// (help, status, undo, forget, quit), a phrase that fits several things
// (it asks which), and a reply it cannot use (it says why, with replies
// that would work, and asks again).
#include <algorithm>
#include <map>

#include "agent/class_rule_knowledge.h"
#include "agent/goal_proposals.h"
#include "agent/session.h"
#include "knowledge/goal_memory.h"
#include "language/generation.h"
#include "language/narration.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice {

namespace {

std::string kinds_of_answer(language::Asked asked) {
  switch (asked) {
    case language::Asked::kTask: return "Tell me the task you want me to learn";
    case language::Asked::kTaskStep:
      return "Tell me the next step of the task: a subtask with the place it is about, or that the task is done";
    case language::Asked::kSubtaskEnd: return "Tell me whether there is more to this subtask, or that it is done";
    case language::Asked::kGoal:
      return "Tell me where it goes, and anything else that should be so when it is put away";
    case language::Asked::kAction: return "Tell me one thing to do next";
    case language::Asked::kYesNo: return "Answer yes or no";
    case language::Asked::kWhich: return "Tell me which one you mean";
  }
  return "Answer the question";
}

std::string quoted_examples(const std::vector<std::string>& examples, std::size_t most) {
  std::vector<std::string> shown;
  for (std::size_t i = 0; i < examples.size() && i < most; ++i) shown.push_back("\"" + examples[i] + "\"");
  std::string out;
  for (std::size_t i = 0; i < shown.size(); ++i) out += (i == 0 ? "" : (i + 1 == shown.size() ? " or " : ", ")) + shown[i];
  return out;
}

}  // namespace

std::string with_period(std::string text) {
  // A quotation that ends a sentence with its own period needs no other.
  std::size_t end = text.size();
  if (end >= 2 && text[end - 1] == '"' && (text[end - 2] == '.' || text[end - 2] == '?' || text[end - 2] == '!'))
    return text;
  return text + ".";
}

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
  c.recent_place = recent_place_;
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
      if (o != object && still_to_come(o)) c.still_to_come.push_back(o);
  c.goal_of_kind = [this](const std::string& kind, ObjectId thing) -> std::optional<Goal> {
    const GoalKnowledge* known = nullptr;
    if (progress_.current) {
      GoalKey key = goal_key(thing);
      key.category = kind;
      known = agent_.knowledge_.goals.find(key);
    }
    for (const GoalKnowledge& g : agent_.knowledge_.goals.all())
      if (known == nullptr && g.key.category == kind) known = &g;
    if (known == nullptr) return std::nullopt;
    return instantiate_goal(world(), *known, thing);
  };
  return c;
}

void TaskLearningAgent::Session::say(const std::string& statement, Voice voice) {
  if (dialogue_) dialogue_->say(statement, voice);
}

Status TaskLearningAgent::Session::execute(const Action& action) {
  Status status = simulator_.execute(action);
  if (status && dialogue_) dialogue_->observe(action, world());
  return status;
}

TaskLearningAgent::Session::Flow<TaskLearningAgent::Session::Heard> TaskLearningAgent::Session::converse(
    const Question& asked, language::ReplyContext context, const Accept& accept, const Rescue& rescue) {
  APPRENTICE_CHECK(dialogue_ != nullptr);
  int unusable = 0;
  std::vector<std::string> refused;
  for (;;) {
    // The answer said after an undo in the last reply is the reply to the
    // question the undo brought back.
    Result<std::string> text = std::string();
    bool queued_step = false;
    const bool about_steps =
        context.asked == language::Asked::kTaskStep || context.asked == language::Asked::kSubtaskEnd;
    if (!queued_replies_.empty()) {
      text = std::move(queued_replies_.front());
      queued_replies_.pop_front();
    } else if (about_steps && !queued_steps_.empty()) {
      // Said in the reply before: not another instruction.
      text = std::move(queued_steps_.front());
      queued_steps_.pop_front();
      queued_step = true;
    } else {
      text = dialogue_->ask_uncounted(asked, world());
    }
    if (!text) return stop(text.error());
    language::ReplyActs read = agent_.understanding_.acts(world(), context, *text);
    std::optional<language::Reply> answer;
    int undos = 0;
    for (language::Reply& act : read.acts) {
      const auto* command = std::get_if<language::Command>(&act);
      if (command == nullptr) answer = std::move(act);
      else if (command->kind == language::Command::Kind::kUndo) ++undos;
    }
    for (const std::string& note : read.notes) say(note, Voice::kResponse);
    if (undos > 0) queued_steps_.clear();
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
        if (!read.after_undo.empty()) queued_replies_.push_back(read.after_undo);
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
    if (!answer) continue;
    language::Reply reply = std::move(*answer);
    if (!queued_step) dialogue_->count_reply(asked, *text);
    // A reply the question's own reading takes whole ("same as the hammer,
    // and shut the drawer") is not asked "which drawer?" about.
    std::optional<language::Reply> rescued;
    if (rescue && std::holds_alternative<language::Ambiguous>(reply)) rescued = rescue(*text);
    if (rescued) {
      reply = std::move(*rescued);
    } else if (const auto* ambiguous = std::get_if<language::Ambiguous>(&reply)) {
      auto settled = settle(*ambiguous, asked, context, *text);
      if (!settled) return tl::unexpected(settled.error());
      reply = *settled;
    }
    if (rescue && std::holds_alternative<language::Unusable>(reply))
      if (auto rescued = rescue(*text)) reply = std::move(*rescued);
    // The thing asked about called by a word nothing here is called
    // ("dummy in the top drawer", asked about the pacifier): a person is
    // asked whether that word means it.
    if (person())
      if (auto word = other_name_of_thing(*text, reply, context)) {
        auto meant = ask_other_name(*word, *text, asked, context);
        if (!meant) return tl::unexpected(meant.error());
        if (*meant) reply = std::move(**meant);
      }
    // A person's rule is kept whatever was asked, and the question asked
    // again (a program is asked at most max_retries times).
    if (auto rule = rule_in_reply(*text, reply, context)) {
      hear_rule(*rule, *text);
      // Asked where a thing goes, the rule may place it: the caller decides
      // again before asking.
      if (context.asked == language::Asked::kGoal && context.object && asked.kind == QuestionKind::kSubtaskStep)
        return Heard{std::nullopt, *text, refused, true};
      refused.push_back(apprentice::quoted(*text) + " (a rule, kept, but no answer to the question)");
      if (!person() && ++unusable > agent_.options_.max_retries) return Heard{std::nullopt, *text, refused};
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
      queued_steps_.insert(queued_steps_.end(), read.then.begin(), read.then.end());
      return Heard{reply, *text, refused};
    }
    explain(*why, context, examples);
    std::string reason = *why;
    while (!reason.empty() && (reason.back() == '.' || reason.back() == ' ')) reason.pop_back();
    refused.push_back(apprentice::quoted(*text) + " (" + reason + ")");
    if (!person() && ++unusable > agent_.options_.max_retries) return Heard{std::nullopt, *text, refused};
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
        return language::Reply(language::Unusable{"I still cannot tell which " + ambiguous.phrase + " you mean.",
                                                  agent_.understanding_.example_replies(world(), context), {}});
    language::ReplyContext which = this->context(language::Asked::kWhich, context.object);
    which.choices = ambiguous.candidates;
    Question q = question(QuestionKind::kWhich, ambiguous.question, asked.object, asked.goal, asked.action);
    q.choices = ambiguous.candidates;
    auto heard = converse(q, which, [&](const language::Reply& r) -> std::optional<std::string> {
      if (const auto* chosen = std::get_if<language::Chosen>(&r))
        if (std::find(ambiguous.candidates.begin(), ambiguous.candidates.end(), chosen->object) !=
            ambiguous.candidates.end())
          return std::nullopt;
      return "I asked which one you mean.";
    });
    if (!heard) return tl::unexpected(heard.error());
    if (!heard->reply)
      return language::Reply(language::Unusable{"I could not tell which " + ambiguous.phrase + " you mean.", {}, {}});
    context.settled.push_back({ambiguous.phrase, std::get<language::Chosen>(*heard->reply).object});
    language::Reply again = agent_.understanding_.reply(world(), context, text);
    const auto* still = std::get_if<language::Ambiguous>(&again);
    if (still == nullptr) return again;
    ambiguous = *still;
  }
}

TaskLearningAgent::Session::Flow<bool> TaskLearningAgent::Session::confirm(const Question& asked) {
  auto heard = converse(asked, context(language::Asked::kYesNo, asked.object),
                        [](const language::Reply& r) -> std::optional<std::string> {
                          if (std::holds_alternative<language::YesNo>(r)) return std::nullopt;
                          return "I asked a yes-or-no question.";
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
  std::string text = reason;
  if (!text.empty() && text.back() != '.' && text.back() != '?' && text.back() != '!') text += ".";
  if (!examples.empty()) text += " You could say, for example, " + with_period(quoted_examples(examples, 2));
  say(text, Voice::kResponse);
}

TaskLearningAgent::Session::Step TaskLearningAgent::Session::obey(const language::Command& command,
                                                                  const Question& asked,
                                                                  const language::ReplyContext& context) {
  switch (command.kind) {
    case language::Command::Kind::kHelp: help(asked, context); return {};
    case language::Command::Kind::kStatus: status(asked); return {};
    case language::Command::Kind::kUndo: return undo();
    case language::Command::Kind::kForget:
      if (auto s = forget(command.argument); !s) return stop(s.error());
      return {};
    case language::Command::Kind::kQuit: return stop(Error{ErrorCode::kCancelled, "the instructor quit"});
    case language::Command::Kind::kWhatsLeft: answer_whats_left(); return {};
    case language::Command::Kind::kWhere: answer_where(command); return {};
    case language::Command::Kind::kWhy: answer_why(); return {};
    case language::Command::Kind::kDo: do_now(command.actions); return {};
  }
  return {};
}

void TaskLearningAgent::Session::help(const Question& asked, const language::ReplyContext& context) {
  say("I asked: " + asked.text, Voice::kResponse);
  std::vector<std::string> examples = agent_.understanding_.example_replies(world(), context);
  std::string kinds = kinds_of_answer(context.asked);
  say(kinds + (examples.empty() ? "." : ", for example " + with_period(quoted_examples(examples, 3))), Voice::kResponse);
  say("You can also type: help; status (what I see and what I have learned); undo (forget what your last answer "
      "taught me); forget <kind of object> (forget where that kind of thing goes); quit, or Ctrl-D (stop; what I "
      "learned is kept).",
      Voice::kResponse);
}

void TaskLearningAgent::Session::status(const Question& asked) {
  const World& w = world();
  const Universe& u = *w.universe;
  const Vocabulary& v = w.vocabulary;
  std::vector<std::string> doors;
  for (ObjectId p : u.of_kind(ObjectKind::kReceptacle)) {
    if (!w.state.holds(Fact(v.openable, {p}))) continue;
    doors.push_back(language::spoken_name(w, p) + " is " + (w.state.holds(Fact(v.closed, {p})) ? "closed" : "open"));
  }
  std::string seen = "I see this: " + (doors.empty() ? std::string() : language::list_phrase(doors) + ".");
  for (ObjectId place = 0; place < u.size(); ++place) {
    if (u.info(place).kind == ObjectKind::kItem) continue;
    std::vector<ObjectId> items;
    for (PredicateId relation : {v.on, v.in})
      for (const Fact& f : w.state.facts_with_second(relation, 2, place)) items.push_back(f.args[0]);
    if (!items.empty())
      seen += " " + language::capitalize(std::string(language::relation_word(w, place))) + " " +
              language::spoken_name(w, place) + ": " + language::spoken_things(w, items) + ".";
  }
  for (const Fact& f : w.state.facts_of(v.holding))
    if (f.arity == 1) seen += " I am holding " + language::spoken_name(w, f.args[0]) + ".";
  say(seen, Voice::kResponse);
  std::string doing = "I am learning ";
  if (progress_.task.name.empty()) doing = "I have not been given a task yet";
  else doing += "to " + language::task_phrase(progress_.task.name);
  if (progress_.current)
    doing += "; now I " + progress_.current->verb + " what is " + progress_.current->relation + " " +
             language::spoken_places(w, progress_.current->places);
  if (progress_.in_progress) doing += ", working on " + language::spoken_name(w, progress_.in_progress->object);
  else if (asked.object) doing += ", asking about " + language::spoken_name(w, *asked.object);
  const DialogueCounts& counts = dialogue_->counts();
  doing += ". So far I know " + language::count_phrase(static_cast<long long>(agent_.knowledge_.goals.size()), "goal") +
           " and " + language::count_phrase(static_cast<long long>(agent_.knowledge_.rules.size()), "rule") +
           ", after " + language::count_phrase(counts.instructions, "instruction") + " this session.";
  say(doing, Voice::kResponse);
}

void TaskLearningAgent::Session::answer_whats_left() {
  const World& w = world();
  if (!progress_.current) {
    if (progress_.task.name.empty()) say("I have not been given a task yet.", Voice::kResponse);
    else say(whats_left_of_task(), Voice::kResponse);
    return;
  }
  std::vector<ObjectId> left;
  for (ObjectId o : w.universe->of_kind(ObjectKind::kItem))
    if (still_to_come(o) && (!progress_.in_progress || progress_.in_progress->object != o)) left.push_back(o);
  std::string where = current().relation + " " + language::spoken_places(w, current().places);
  if (left.empty()) say("Nothing else is left " + where + ".", Voice::kResponse);
  else say("Still " + where + ": " + language::spoken_things(w, left) + ".", Voice::kResponse);
}

// Between parts of the task: the parts done, and the things not dealt with
// yet where they are ("Not dealt with yet: on the desk, the mug and the
// pen; in the bag, the apple."). The agent cannot know which of them the
// task means, so it says all of them and leaves the choice to the teacher.
std::string TaskLearningAgent::Session::whats_left_of_task() const {
  const World& w = world();
  std::vector<std::string> parts;
  for (const LearnedSubtask& s : progress_.task.subtasks)
    parts.push_back(s.verb + " what is " + s.relation + " the " + language::spoken_category(s.place_category));
  std::string said = parts.empty() ? "No part of the task is done yet."
                                   : "So far I have learned to " + language::list_phrase(parts) + ".";
  std::vector<ObjectId> places;
  std::map<ObjectId, std::vector<ObjectId>> at;
  for (ObjectId o : w.universe->of_kind(ObjectKind::kItem)) {
    if (progress_.evaluated.count(o)) continue;
    std::optional<ObjectId> place = language::place_of(w, o);
    if (!place) continue;
    if (!at.count(*place)) places.push_back(*place);
    at[*place].push_back(o);
  }
  if (places.empty()) return said + " Every thing here has been dealt with; say \"that's all\" if the task is done.";
  std::vector<std::string> groups;
  for (ObjectId place : places)
    groups.push_back(std::string(language::relation_word(w, place)) + " " + language::spoken_name(w, place) + ", " +
                     language::spoken_things(w, at[place]));
  std::string list;
  for (std::size_t i = 0; i < groups.size(); ++i) list += (i == 0 ? "" : "; ") + groups[i];
  return said + " Not dealt with yet: " + list + ". Tell me what to do next, or say \"that's all\".";
}

void TaskLearningAgent::Session::answer_where(const language::Command& command) {
  const World& w = world();
  if (command.things.empty()) {
    say("I don't see " + command.argument + " here.", Voice::kResponse);
    return;
  }
  std::vector<std::string> said;
  for (ObjectId o : command.things) {
    if (said.size() == 3) break;
    if (w.state.holds(Fact(w.vocabulary.holding, {o}))) {
      said.push_back("I am holding " + language::spoken_name(w, o));
      continue;
    }
    std::optional<ObjectId> at = language::place_of(w, o);
    if (!at) continue;
    said.push_back(language::capitalize(language::spoken_name(w, o)) + " is " +
                   std::string(language::relation_word(w, *at)) + " " + language::spoken_name(w, *at));
  }
  if (said.empty()) say("I don't know where " + command.argument + " is.", Voice::kResponse);
  for (const std::string& line : said) say(line + ".", Voice::kResponse);
}

void TaskLearningAgent::Session::answer_why() {
  const std::string* last = lessons_.last_reply();
  if (last == nullptr) {
    say("I have only done what I already knew; you have not told me anything yet this session.", Voice::kResponse);
    return;
  }
  say(with_period("Because of what you told me last: \"" + *last + "\"") +
          " If that was wrong, say undo, or tell me what you meant.",
      Voice::kResponse);
}

void TaskLearningAgent::Session::do_now(const std::vector<Action>& actions) {
  std::vector<Action> done;
  for (const Action& action : actions) {
    const std::string& name = world().domain->actions[action.schema].name;
    const ObjectId thing = action.arguments()[0];
    bool closed = world().state.holds(Fact(world().vocabulary.closed, {thing}));
    if ((name == "close" && closed) || (name == "open" && !closed)) {
      say(language::capitalize(language::spoken_name(world(), thing)) + " is already " + (closed ? "closed" : "open") +
              ".",
          Voice::kResponse);
      continue;
    }
    std::string why = language::refusal(world(), action);
    if (!why.empty() || !execute(action)) {
      say(why.empty() ? "I could not " + language::action_phrase(world(), action) + "." : why, Voice::kResponse);
      continue;
    }
    done.push_back(action);
  }
  if (!done.empty()) say(language::report_actions(world(), done), Voice::kResponse);
}

std::vector<std::string> TaskLearningAgent::Session::known_kinds(std::string_view phrase) const {
  std::string key = to_lower(trim(phrase));
  for (std::string_view article : {"the ", "a ", "an "})
    if (key.starts_with(article)) key = key.substr(article.size());
  std::replace(key.begin(), key.end(), ' ', '-');
  std::vector<std::string> singular = {key};
  if (key.size() > 1 && key.back() == 's') singular.push_back(key.substr(0, key.size() - 1));
  if (key.size() > 2 && key.ends_with("es")) singular.push_back(key.substr(0, key.size() - 2));
  std::vector<std::string> fits;
  for (const GoalKnowledge& g : agent_.knowledge_.goals.all()) {
    const std::string& c = g.key.category;
    bool fit = std::any_of(singular.begin(), singular.end(), [&](const std::string& k) {
      return !k.empty() && (c == k || (c.size() > k.size() && c.ends_with("-" + k)));
    });
    if (fit && std::find(fits.begin(), fits.end(), c) == fits.end()) fits.push_back(c);
  }
  return fits;
}

Status TaskLearningAgent::Session::forget(const std::string& kind) {
  std::optional<std::string> category = agent_.understanding_.category(world(), kind);
  if (!category) {
    // A kind that is not here may still be known.
    std::vector<std::string> fits = known_kinds(kind);
    if (fits.size() > 1) {
      std::vector<std::string> named;
      for (const std::string& c : fits) named.push_back("the " + language::spoken_category(c));
      say("Which kind do you mean: " + language::list_phrase(named) + "? Say, for example, \"forget " +
              language::spoken_category(fits.front()) + "\".",
          Voice::kResponse);
      return {};
    }
    if (fits.size() == 1) category = fits.front();
  }
  std::vector<GoalKey> keys;
  if (category)
    for (const GoalKnowledge& g : agent_.knowledge_.goals.all())
      if (g.key.category == *category) keys.push_back(g.key);
  if (keys.empty()) {
    auto rule = forget_rule_named(kind);
    if (!rule) return tl::unexpected(rule.error());
    if (*rule) return {};
    say("I have not learned where to put " +
            (category ? "the " + language::spoken_category(*category) : std::string(trim(kind))) +
            ", so there is nothing to forget.",
        Voice::kResponse);
    return {};
  }
  for (const GoalKey& key : keys) {
    agent_.knowledge_.goals.remove(key);
    // An undo must not bring it back either.
    lessons_.forget_goal(key);
    if (agent_.store_) {
      if (auto s = agent_.store_->remove_goal(key); !s) return s;
    }
  }
  say("I forgot where " + language::kind_goes(*category) + "; I will ask when I meet one.",
      Voice::kResponse);
  return {};
}

Result<bool> TaskLearningAgent::Session::forget_rule_named(const std::string& what) {
  std::vector<ClassRule> in_use;
  for (const ClassRule& rule : said_rules_.all())
    if (rule.source == RuleSource::kPerson) in_use.push_back(rule);
  for (const ClassRule& rule : proposer_.all_induced()) in_use.push_back(rule);
  std::vector<ClassRule> named = rules_named(in_use, what);
  if (named.empty()) return false;
  std::vector<std::string> said;
  for (const ClassRule& rule : named)
    if (std::find(said.begin(), said.end(), say_class_rule(rule)) == said.end()) said.push_back(say_class_rule(rule));
  if (said.size() > 1) {
    std::vector<std::string> subjects;
    for (const ClassRule& rule : named) subjects.push_back("\"forget " + rule_subject(rule) + " " + rule_destination(rule) + "\"");
    say("I have several rules about " + std::string(trim(what)) + ": " + join(said, "; ") + ". Say which, for example " +
            subjects.front() + ".",
        Voice::kResponse);
    return true;
  }
  for (const ClassRule& rule : named) {
    if (auto s = forget_rule(agent_.knowledge_, agent_.store_, rule); !s) return tl::unexpected(s.error());
    // An undo must not bring it back either.
    lessons_.forget_class_rule(rule);
    said_rules_.remove(rule);
    proposer_.forget(rule);
  }
  say("I forgot that " + said.front() + "; I will ask where such things go.", Voice::kResponse);
  return true;
}

}  // namespace apprentice
