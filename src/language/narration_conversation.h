// The agent's sentences in conversation, part of its narration
// (narration.h): help and status, answers to the teacher's own questions
// ("what's left?", "where is the mug?", "why?"), forgetting, replies it
// cannot use, things it will come back to, and what it leaves alone. The
// agent (agent_dialogue.cc, agent_goals.cc, agent_actions.cc) decides what
// to say and passes the facts; every word is chosen here.
//
// Each function returns whole sentences, each ending in ".", "?" or "!",
// unless its comment says it returns a reason or a phrase.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "language/reply.h"  // Asked
#include "world/action.h"
#include "world/goal.h"
#include "world/world.h"

namespace apprentice::language {

// `text` ending in a period: a quotation that ends with its own ".", "?" or
// "!" ("... said \"Clear the table.\"") gets none.
std::string with_period(std::string text);

// --- Help and status ---------------------------------------------------------

// "I asked: Where should the ketchup on the table go?"
std::string i_asked(std::string_view question);
// What kind of answer works at `asked`, with up to three of `examples`:
// "Tell me one thing to do next, for example "open the fridge"."
std::string kinds_of_answer(Asked asked, const std::vector<std::string>& examples);
// The commands a person can type at any question.
std::string commands_at_any_question();
// A reply the agent cannot use: `reason`, with up to two of `examples`
// ("... You could say, for example, "a" or "b".").
std::string reply_refused(std::string_view reason, const std::vector<std::string>& examples);
// What the agent sees: the doors, what is on or in each place, what it
// holds ("I see this: the fridge is closed. On the table: the ketchup.").
std::string what_i_see(const World& world);

// The subtask under way, as status and "what's left?" name it.
struct SubtaskUnderWay {
  std::string verb;      // "clear"
  std::string relation;  // "on"
  std::vector<ObjectId> places;
};
// What the agent is doing and knows, for status: "I am learning to tidy the
// kitchen; now I clear what is on the table, working on the ketchup. So far
// I know 3 goals and 2 rules, after 5 instructions this session."
struct WhatIAmDoing {
  std::string task;  // "" before one is given
  std::optional<SubtaskUnderWay> subtask;
  std::optional<ObjectId> working_on;    // the thing being put away
  std::optional<ObjectId> asking_about;  // else the thing the question is about
  long long goals = 0, rules = 0, instructions = 0;
};
std::string what_i_am_doing(const World& world, const WhatIAmDoing& doing);

// --- The teacher's own questions ----------------------------------------------

// "I have not been given a task yet."
std::string no_task_yet();
// Within a subtask: "Nothing else is left on the table." or "Still on the
// table: the mug and the pen."
std::string whats_left_of_subtask(const World& world, const SubtaskUnderWay& subtask, std::span<const ObjectId> left);
// A part of the task learned: "clear" what is "on" the "dinner-table".
struct PartLearned {
  std::string verb, relation, place_category;
};
// Between parts of the task: the parts learned, and the things not dealt
// with yet grouped by where they are ("Not dealt with yet: on the desk, the
// mug and the pen; in the bag, the apple."), or that every thing has been.
std::string whats_left_of_task(const World& world, std::span<const PartLearned> parts,
                               std::span<const ObjectId> not_dealt_with);
// Where the things a phrase named are, one sentence each, at most three
// ("The mug is on the counter.", "I am holding the pen."); that the agent
// does not see `phrase` here, or does not know where it is.
std::vector<std::string> where_things_are(const World& world, std::string_view phrase,
                                          std::span<const ObjectId> things);
// "Why?" before the teacher has said anything this session.
std::string why_without_a_reply();
// "Because of what you told me last: "..." If that was wrong, say undo, or
// tell me what you meant."
std::string because_of_last_reply(std::string_view reply);
// "The glove goes in the right basket: I learned that from the instructor,
// who said "gloves in the right one". If that was wrong, tell me where it
// goes." `from` is where the goal came from, in words.
std::string because_goal_from(const World& world, ObjectId thing, const Goal& goal, std::string_view from);
// "You told me to leave the coffee mug where it is."
std::string left_as_told(const World& world, ObjectId thing);
// Why a door is open or closed: "The closet is open because the umbrella's
// goal leaves it open, from the instructor, who said "..."", "The closet is
// open: nothing I learned says to close it; say "close the closet" if it
// should be.", "The closet is closed: I close what I open."
std::string why_door_is(const World& world, ObjectId place, bool closed,
                        const std::optional<std::pair<ObjectId, std::string>>& left_open_for);
// "why did you do that?" after the agent placed a thing by its own
// decision: "Because I decided where the sticky note goes from weighing
// what I knew: ... If that was wrong, tell me where it goes."
std::string because_i_decided(const World& world, ObjectId object, std::string_view from);

// --- Doing what the teacher says now ------------------------------------------

// "The fridge is already closed."
std::string already_open_or_closed(const World& world, ObjectId thing, bool closed);
// "I could not open the fridge."
std::string could_not(const World& world, const Action& action);

// --- Forgetting ----------------------------------------------------------------

// Several known kinds fit what was named: "Which kind do you mean: the red
// cup and the blue cup? Say, for example, "forget red cup"."
std::string which_kind_to_forget(const std::vector<std::string>& categories);
// "I have not learned where to put the mug, so there is nothing to
// forget." `kind` is a category when known, else the words said.
std::string nothing_to_forget(std::optional<std::string_view> category, std::string_view said);
// "I forgot where the mug goes; I will ask when I meet one."
std::string forgot_where_kind_goes(std::string_view category);
// "why did you put the water bottle in the wastebasket?", where it no
// longer goes: "Earlier I put the water bottle in the wastebasket,
// because it is like things you taught me; since then, the water bottle
// goes on the desk." `then` is the goal it had, `how` how it came by it
// (may be empty), `now` its goal now.
std::string why_earlier_placement(const World& world, ObjectId thing, const Goal& then, std::string_view how,
                                  const Goal& now);
// "why did you ask if the blanket goes with clean diapers?": "I asked
// whether the blanket goes in the bottom drawer, with clean diapers, as
// you said: it seemed likely, but not enough to do it without asking."
// `proposed` is the goal asked about, `evidence` what the question showed
// (may be empty), `now` the thing's goal since, if it differs.
std::string why_i_asked(const World& world, ObjectId thing, const Goal& proposed, std::string_view evidence,
                        const std::optional<Goal>& now);
// "why is the washer open?", after "leave the washer open from now on":
// "The washer is open: you told me to leave it open from now on."
std::string door_left_open_as_told(const World& world, ObjectId place);
// A standing wish about doors, read back. `open`: "leave the washer open
// from now on": "I will leave the washer open from now on, also after
// putting the towel and the jeans in it."; else "this one stays closed":
// "I will close the locker from now on, also after putting the headphones
// in it." `kinds`: the kinds whose goals change with it (may be empty).
std::string will_keep_doors(const World& world, const std::vector<ObjectId>& places,
                            const std::vector<std::string>& kinds, bool open);
// An undo of "forget mug": "I know again where the mug goes."
std::string remember_again(std::string_view category);
// Several rules fit what was named: "I have several rules about fruit: ...;
// .... Say which, for example "forget fruit on the table"."
std::string which_rule_to_forget(std::string_view what, const std::vector<std::string>& rules,
                                 std::string_view first_to_forget);
// "I forgot that fruit goes on the table; I will ask where such things go."
std::string forgot_rule(std::string_view rule);

// --- Reasons a reply is not an answer (for Unusable and refusals) ---------------

// "I asked a yes-or-no question."
std::string asked_yes_or_no();
// "I asked which one you mean."
std::string asked_which_one();
// "I asked what to do next."
std::string asked_what_to_do_next();
// "I asked where the ketchup goes."
std::string asked_where_it_goes(const World& world, ObjectId object);
// A goal given for other things than the one asked about: "That says what
// becomes of the milk, but I asked about the ketchup on the table."
std::string says_what_becomes_of_others(const World& world, std::span<const ObjectId> others, ObjectId asked);
// "I still cannot tell which mug you mean.": the phrase stays ambiguous
// after the teacher chose.
std::string still_cannot_tell_which(std::string_view phrase);
// "I could not tell which mug you mean.": no usable choice was given.
std::string could_not_tell_which(std::string_view phrase);
// "Then I leave "the hook" aside.": none of the choices was meant, so the
// reply the question came from (`said`) is not taken.
std::string reply_set_aside(std::string_view said);
// A goal said for this time only (GoalGiven::this_time_only): "This time
// only: I will not remember it as where that goes."
std::string this_time_only_note();
// Why a thing is where the teacher had it put this time only: "You told me
// to put the blanket there this time only."
std::string placed_this_time_only(const World& world, ObjectId thing);

// --- Goals and actions ------------------------------------------------------------

// "I could not reach the language model (timeout), so I will ask." (without
// ", so I will ask" when there is no one to ask).
std::string could_not_reach_llm(std::string_view failure, bool will_ask);
// "I will leave the ketchup on the table as it is." (`say_where`), or "I
// will leave the ketchup as it is."
std::string will_leave_as_it_is(const World& world, ObjectId object, bool say_where);
// A goal given for a thing ahead, read back: "So the mug goes in the sink.
// I will do that when I come to it."
std::string read_back_goal_for_later(const World& world, ObjectId thing, const Goal& goal);
// Goals given for other things besides the one asked about: those that go
// the same way (`same`) or were learned otherwise (`learned`, read back
// already), and those of a part of the task not reached yet (`later`):
// "The same goes for the fork, when I come to it." "I will ask about the
// pen when I come to it."
std::vector<std::string> goals_for_others(const World& world, std::span<const ObjectId> same,
                                          std::span<const ObjectId> learned, std::span<const ObjectId> later);
// A reason (for Unusable): the reply is about `other`, of a part of the
// task not reached yet, while the agent asked about `asked` in `subtask`.
std::string will_ask_about_later(const World& world, ObjectId other, const SubtaskUnderWay& subtask, ObjectId asked);
// For the report's help needed (a phrase, no period): "where the paper
// plate on the table goes (clear); the replies I could not use: "x" (...)".
std::string help_needed_for_goal(const World& world, ObjectId object, std::string_view verb,
                                 const std::vector<std::string>& refused);

// For the report's help needed (a phrase, no period): "how to make it so
// that the ketchup is in the fridge".
std::string help_needed_for_goal_to_hold(const World& world, const Goal& goal);

}  // namespace apprentice::language
