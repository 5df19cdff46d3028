// Reading a teacher's reply in the context of the question it answers.
//
// The agent asks one kind of question at a time (what the task is, what
// comes next in it, where an object goes, what to do next, yes or no, which
// of several things). `read_reply` says what a reply means in that context
// and the current world: a step of the task structure, a goal, an action, an
// answer, a command to the agent, a request to tell look-alikes apart, or
// why it cannot be used, in plain English, with replies that would work.
//
// The grammar of the paper's script (language/parser.h) is one of the forms
// understood; everyday English is read too (docs/language.md). The reader
// never guesses: a reply that could mean two things is `Ambiguous`, and a
// goal that does not mention the object asked about (and is not "it") is
// `Unusable`, so that the agent asks back instead of storing it silently.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "language/grounding.h"
#include "language/logical_form.h"
#include "world/action.h"
#include "world/goal.h"
#include "world/world.h"

namespace apprentice::language {

// The question a reply answers.
enum class Asked {
  kTask,        // "What task should I learn?"
  kTaskStep,    // what comes next in the task: a subtask, a loop, or the end
  kSubtaskEnd,  // the first object of a subtask is done: more to it, or is it done?
  kGoal,        // where should `object` go (its goal)?
  kAction,      // what should I do next for `object`?
  kYesNo,       // a yes/no question: a proposed goal, action or analogy
  kWhich,       // which of `choices` is meant?
};

std::string_view to_string(Asked asked);
// Every kind of question, in the order help and the docs list them: the one
// vocabulary of `interpret --asked` and of Python.
inline constexpr Asked kEveryAsked[] = {Asked::kTask, Asked::kTaskStep, Asked::kSubtaskEnd, Asked::kGoal,
                                        Asked::kAction, Asked::kYesNo, Asked::kWhich};
// The kind `name` names ("goal"), if any.
std::optional<Asked> asked_named(std::string_view name);

struct ReplyContext {
  Asked asked = Asked::kTask;
  // The object asked about: what "it", "this" and "that one" mean.
  std::optional<ObjectId> object;
  // The place named last in the conversation: what "the door" and "close
  // it" (after a placement) mean.
  std::optional<ObjectId> recent_place;
  // The places the agent's last answer asked about (Unusable::topic_places):
  // what "clear it", "empty them", or a verb alone ("clear"), is about.
  std::vector<ObjectId> topic_places = {};
  // kWhich: the things the agent offered.
  std::vector<ObjectId> choices;
  // Phrases the teacher has already settled: after `Ambiguous{"mug", ...}`
  // and the answer to "Which do you mean ...?", read the same reply again
  // with {"mug", mug2} here and "mug" means mug2.
  struct Settled {
    std::string phrase;  // Ambiguous::phrase
    ObjectId object = 0;
  };
  std::vector<Settled> settled = {};
  // The verbs of the subtasks taught so far, in order ("clear", "store"):
  // what "do the same with the counter" and "the counter next" do. Empty
  // when unknown; such replies then get a question back.
  std::vector<std::string> taught_subtasks = {};

  // --- What the dialogue knows, read-only: what "same again", "the rest",
  // "same as the hammer" and a class word ("clothes") refer to. Left empty,
  // such replies are asked back.
  // The goal given last, and the thing it was given to.
  struct LastGoal {
    ObjectId object = 0;
    Goal goal;
  };
  std::optional<LastGoal> last_goal = {};
  // The things still to come in the part of the task under way, in order.
  std::vector<ObjectId> still_to_come = {};
  // The things already dealt with this session: where one of their kinds
  // goes, said at a question about the task's steps, corrects its goal
  // ("the notebook goes on the bookshelf").
  std::vector<ObjectId> dealt_with = {};
  // The goal learned for a kind of thing (a category, here or not), made
  // for `object`; nullopt when none was learned.
  std::function<std::optional<Goal>(const std::string& kind, ObjectId object)> goal_of_kind = {};
  // kYesNo: the goal proposed, which "yes, and close the lid" adds to.
  std::optional<Goal> proposal = {};
};

// --- What a reply can mean --------------------------------------------------

// "Tidy kitchen.", "I want you to tidy the kitchen": the task's name, verb
// first ("tidy kitchen").
struct TaskNamed {
  std::string name;
  // How a verb said was taken as a known one ("I took \"clean up\" as
  // tidying."; language/known_verbs.h); empty when it was kept as said.
  std::string note = {};
};

// "Clear an object that is on the table.", "First, clear the table.": a
// subtask over the objects at `places` (several when a category names every
// place of that kind: "unload the bags").
struct SubtaskNamed {
  std::string verb;  // "clear"
  Relation relation = Relation::kOn;
  std::vector<ObjectId> places;  // never empty
  // As TaskNamed::note: "I took \"pick up\" as clearing."
  std::string note = {};
};

// "Repeat the following tasks while an object is on the table."
struct LoopNamed {
  Relation relation = Relation::kOn;
  std::vector<ObjectId> places;  // never empty
};

// "You are done.", "That's all.", "Done.", "We're finished.": the end of
// whatever is being taught (the subtask or the task). At a goal question,
// "skip it", "leave it" or "done" leave the one thing asked about; an
// ending said there ("I'm done", "that's it", "we're done here") is
// `ending`: it may end the part under way, which the dialogue asks back
// while things of the part are still to come, and never names a subtask.
struct Finished {
  bool ending = false;
};

// "Repeat.", "next", "keep going": go on.
struct Proceed {};

struct GoalGiven {
  Goal goal;
  // The goals the same reply gave other things, one each ("plates and forks
  // go in the dishwasher", asked about a plate: the fork's).
  std::vector<Goal> others = {};
  // "just for tonight put the shaker in the locker": done now, never
  // learned as where such things go (read_acts).
  bool this_time_only = false;
};

struct ActionGiven {
  Action action;
  // Further steps said in the same reply, in order ("open the fridge and
  // put the ketchup in it"), each grounded in the world as it is now.
  std::vector<Action> more = {};
};

struct YesNo {
  bool yes = false;
  // What follows the answer, for the caller to read at the question that
  // follows it: "no, it goes in the pantry" -> "it goes in the pantry".
  // Empty when the rest only repeats the answer ("yes, exactly").
  std::string rest = {};
};

// kWhich: the one meant.
struct Chosen {
  ObjectId object = 0;
};

// A command to the agent rather than an answer. These are never counted as
// instructions.
// The teacher's own questions ("what's left?", "where is the soap?", "why
// did you close it?") and one-off actions to do now ("close the top
// drawer", "oh and shut the fridge"), at any question, are commands too.
struct Command {
  enum class Kind { kHelp, kStatus, kUndo, kForget, kQuit, kWhatsLeft, kWhere, kWhy, kDo };
  Kind kind = Kind::kHelp;
  std::string argument;  // kForget: the kind of object ("ketchup"); kWhere: the thing as said
  // kWhere: what the words may name. kWhy: the things and places the
  // question names ("why did you put the glove in the right basket": the
  // gloves, then the right basket), none for "why did you do that".
  std::vector<ObjectId> things = {};
  std::vector<Action> actions = {};   // kDo: in order
  // kWhy: asked about what was done before ("why'd you throw out the bottle
  // before?"), not about how things are now.
  bool earlier = false;
  // kDo: the doors the teacher wants left open from now on ("leave the
  // washer open from now on"); `actions` opens those closed now.
  std::vector<ObjectId> left_open = {};
  // kDo: the doors the teacher wants closed from now on ("this one stays
  // closed", "the bottom drawer should always be shut"); `actions` closes
  // those open now.
  std::vector<ObjectId> kept_closed = {};
  // kWhy: asked about a question the agent asked ("why did you ask if the
  // blanket goes with clean diapers?", "why do you keep asking about
  // diapers"), not about where things went.
  bool asking = false;
};

// A phrase that fits several things: the agent should ask which.
struct Ambiguous {
  std::string phrase;               // as the teacher wrote it: "mug"
  std::vector<ObjectId> candidates;  // at least two
  std::string question;             // "Which do you mean: the mug on the counter or the mug in the dish rack?"
};

// A reply the agent cannot use here.
struct Unusable {
  std::string reason;                 // plain English: "The recycling bin has no lid, so it can't be closed."
  std::vector<std::string> examples;  // replies that would work at this question
  // The grounder's failure, where the reply parsed but did not ground.
  std::optional<GroundingFailure> failure;
  // The places the reason asks about ("What should I do with the things on
  // the coffee table?", "... in the buckets?"): ReplyContext::topic_places
  // of the next reply.
  std::vector<ObjectId> topic_places = {};
};

using Reply = std::variant<TaskNamed, SubtaskNamed, LoopNamed, Finished, Proceed, GoalGiven, ActionGiven, YesNo,
                           Chosen, Command, Ambiguous, Unusable>;

// What `text` means as an answer to `context.asked` in `world`. Never
// throws; every reply gets a meaning, if only `Unusable`.
Reply read_reply(const Grounder& grounder, const World& world, const ReplyContext& context, std::string_view text);

// A reply as the acts it holds, in the order they take effect: "oops
// scratch that, the wrench goes in the bottom one" is an undo and then the
// wrench's goal; "shelf. oh and close the top drawer" a goal and a one-off
// closing; "undo undo" two undos. Words it does not know are skipped when
// the rest is whole, and `notes` say how they were taken.
struct ReplyActs {
  std::vector<Reply> acts;  // never empty
  // After an undo: the words of the answer that follows it, to be read at
  // the question the undo brings back (the answer in `acts` is read as if
  // that were the question: about the thing of the last goal).
  std::string after_undo = {};
  // "I took \"nah\" as a filler.", "I took \"hampr\" as \"hamper\"."
  std::vector<std::string> notes = {};
  // At a question about the task's steps, the parts said after the first
  // ("clear the counter, then the table", "the desk is done, now sort the
  // bookshelf"), to be read at the next question about the task's steps,
  // with the first part's verb where they have none ("clear the table").
  std::vector<std::string> then = {};
  // Where things go, said after a part of the task ("the folding table
  // next. detergent and stain remover go in the cabinet"): to be read at
  // the next question, about the part's first thing.
  std::vector<std::string> goals_ahead = {};
};
ReplyActs read_acts(const Grounder& grounder, const World& world, const ReplyContext& context, std::string_view text);

// The one yes/no reader: whether a reply answers yes or no ("sure", "yep,
// go ahead", "nope", "no, the pantry"), as read_reply reads it at a yes/no
// question; nullopt when it starts with neither. The dialogue counts the
// yeses of Table 3 with it too.
std::optional<bool> yes_or_no(std::string_view text);

// What the rest of a yes or no at a proposed goal says of the thing's goal,
// read as the answer to where it goes: "no, it goes in the pantry" -> the
// pantry; "yes, and close it" -> the place proposed, closed; "yes but leave
// the door open" -> the place proposed, open. nullopt when the rest says
// no goal, or only the one proposed ("yes, same place"). `context` is the
// yes/no question's, with `object` and `proposal`.
std::optional<GoalGiven> goal_in_rest(const Grounder& grounder, const World& world, const ReplyContext& context,
                                      const YesNo& answer);

// Two or more replies that would work at this question, for help and after
// an unusable reply: "the ketchup goes in the fridge".
std::vector<std::string> example_replies(const World& world, const ReplyContext& context);

// One line for golden files: "subtask clear on table1", "goal (and ...)",
// "finished", "command undo", "ambiguous mug: mug1 mug2", "unusable ...".
std::string format_reply(const World& world, const Reply& reply);

}  // namespace apprentice::language
