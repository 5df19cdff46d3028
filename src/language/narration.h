// The agent's own sentences to a person: its questions, what it understood
// (read-backs), what it did (reports), why it cannot do something
// (refusals), and summaries, in plain English.
//
// language/generation.h speaks the paper's script, word for word, for the
// simulated instructor and the LLM; this file speaks to people. Things are
// named as a person names them: categories with spaces ("the glass
// tumbler"), look-alikes by their properties ("the top drawer"), and where
// they are when that matters ("the mug on the counter").
//
// Every question is one line ending in "?"; every statement is one or more
// full sentences. Nothing here is ever parsed back.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "language/generation.h"  // capitalize, spoken_category
#include "world/action.h"
#include "world/goal.h"
#include "world/world.h"
#include "world/unreachable.h"

namespace apprentice::language {

// --- Words -----------------------------------------------------------------

// Whether a kind is named in the plural ("crackers", "granola-bars"), for
// verb agreement: the last word ends in "s" but not in "ss", "us" or "is".
bool is_plural_category(std::string_view category);
// "buckets", "boxes", "shelves", "batteries": a noun's regular plural (and
// "-lf"/"-fe" to "-ves"); enough for the kinds of places and things.
std::string plural_noun(std::string_view noun);
// "glass tumblers": a kind in the plural; a kind named in the plural
// ("crackers") stays as it is.
std::string spoken_plural(std::string_view category);
// "the ketchup goes", "the crackers go": a kind as the subject of "go".
std::string kind_goes(std::string_view category);
// "the glass tumbler"; a look-alike (another object of its category exists)
// with properties is named by them: "the top drawer".
std::string spoken_name(const World& world, ObjectId object);
// "on the table", "in the dish rack", "in my hand", or "" if it is nowhere.
std::string spoken_location(const World& world, ObjectId object);
// "the ketchup on the table".
std::string spoken_name_and_location(const World& world, ObjectId object);
// The places of a subtask: "the table", "the bags" (all places of one
// category, when there are several), or "the shelf and the bench".
std::string spoken_places(const World& world, std::span<const ObjectId> places);
// Things as a list, a name said more than once counted: "the hammer, two
// screwdrivers and the tape measure" (not "the screwdriver, and the
// screwdriver"). Names in the order first given.
std::string spoken_things(const World& world, std::span<const ObjectId> things);
// "it", or "them" for a thing named in the plural ("the jeans").
std::string object_pronoun(const World& world, ObjectId object);
// "on" or "in": how things are at the place.
std::string_view relation_word(const World& world, ObjectId place);
// "tidy kitchen" -> "tidy the kitchen"; "tidy up kitchen" -> "tidy up the
// kitchen"; "clean up after party" -> "clean up after the party"; a name
// that already has a determiner is kept.
std::string task_phrase(std::string_view task_name);
// "1 instruction", "2 instructions", "0 goals"; `plural` defaults to the
// singular plus "s".
std::string count_phrase(long long n, std::string_view singular, std::string_view plural = "");
// "a", "a and b", "a, b, and c".
std::string list_phrase(const std::vector<std::string>& items);

// --- Questions (one line, ending in "?") -----------------------------------

// "What task should I learn?"
std::string ask_task();
// "What should I do first to tidy the kitchen?" / "What should I do next
// to tidy the kitchen?"
std::string ask_task_step(std::string_view task_name, bool first);
// "Where should the ketchup on the table go?"
std::string ask_goal(const World& world, ObjectId object);
// "Is there more to clear on the table, or is that all?"
std::string ask_subtask_end(std::string_view verb, const World& world, std::span<const ObjectId> places);
// "What should I do next so that the ketchup is in the fridge and the
// fridge is closed?"
std::string ask_next_action(const World& world, const Goal& goal);

// --- An ending said in the middle of a part -------------------------------

// "There are still 3 things on the table: the mug, the fork and the bowl.
// Shall I leave them?": asked back when the teacher says an ending ("I'm
// done", "that's it") at a goal question while `things` (the one asked
// about among them) are still to come at `places`, the part's places.
std::string ask_leave_the_rest(const World& world, std::span<const ObjectId> things, std::span<const ObjectId> places);
// "So I leave them on the table, and this part of the task is done." (yes)
std::string read_back_part_left(const World& world, std::span<const ObjectId> things,
                                std::span<const ObjectId> places);
// "So I go on with the metal fork." (no)
std::string read_back_going_on(const World& world, ObjectId object);

// --- Goals -----------------------------------------------------------------

// "the ketchup is in the fridge and the fridge is closed": the goal as
// facts, in the present tense.
std::string goal_facts(const World& world, const Goal& goal);
// "the ketchup goes in the fridge, and the fridge ends closed": the goal as
// what becomes of `object` and the things around it. `subject` names the
// object ("the ketchup", or "it").
std::string goal_outcome(const World& world, ObjectId object, const Goal& goal, std::string_view subject);
// "So the ketchup goes in the fridge, and the fridge ends closed."
std::string read_back_goal(const World& world, ObjectId object, const Goal& goal);
// Said once a session, after the first read-back whose closing the agent
// added by the norm "close what you opened": why, and how to say otherwise.
std::string closing_norm_note();
// "Next, the milk on the table: it goes in the fridge, and the fridge ends
// closed."
std::string announce_known_goal(const World& world, ObjectId object, const Goal& goal);
// "the paper plate should be in the garbage", "the fridge should be
// closed": an assertion that does not hold.
std::string expected_fact(const World& world, const Literal& literal);

// --- What was done ----------------------------------------------------------

// "I opened the fridge, put the ketchup in it, and closed it." for actions
// executed in this order; "" when there are none. Picking an item up from a
// surface and then putting it somewhere is said as one step.
std::string report_actions(const World& world, std::span<const Action> actions);
// "open the fridge", "put the ketchup in the fridge": the action as a
// person would ask for it, without a final period.
std::string action_phrase(const World& world, const Action& action);
// A plan as steps a person reads, numbered, one a line: "1. Open the
// fridge.\n2. Pick up the ketchup from the table.\n..." Each step is said
// in the world as the steps before it leave it, starting from `world`; ""
// for no step.
std::string plan_steps(const World& world, std::span<const Action> plan);
// Why the action cannot be done now, or "" if it can: "I am not holding
// the stapler, so I cannot put it in the drawer."
std::string refusal(const World& world, const Action& action);

// --- What can never be -------------------------------------------------------

// Why a goal can never hold, from search/unreachable.h's analysis: one
// sentence per link of the chain. "The garbage will never be closed: it has
// no door, so I cannot close it." "" for an empty chain.
std::string never_holds(const World& world, const UnreachableChain& chain);

}  // namespace apprentice::language
