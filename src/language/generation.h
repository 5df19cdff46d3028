// What the agent and the simulated instructor say, in the paper's words and
// exactly as ../shared/data/stars-tidy-kitchen/instructor_script.txt says
// it. Items keep their hyphenated category ("the ceramic-plate"); places are
// spoken with spaces ("the recycling bin", "the dish rack"), as the script
// does. Every sentence here parses back (language/parser.h) to what it says.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "world/action.h"
#include "world/goal.h"
#include "world/world.h"

namespace apprentice::language {

// "glass-tumbler" -> "glass tumbler".
std::string spoken_category(std::string_view category);
// "Tidy the kitchen" from "tidy the kitchen".
std::string capitalize(std::string text);
// "an" before a vowel, else "a": "an apple-juice", "a ketchup".
std::string_view article_for(std::string_view word);
// "the ketchup", "the recycling bin"; an object with properties is named
// by them too: "the top drawer", "the blue bag".
std::string noun_for(const World& world, ObjectId object);
// "on the table" / "in the dish rack": where the object is now; "" if it is
// on or in nothing (held).
std::string location_phrase(const World& world, ObjectId object);
// The place the object is on or in now; none if it is held.
std::optional<ObjectId> place_of(const World& world, ObjectId object);
// Whether the thing has a door or lid: (openable id) holds.
bool openable(const World& world, ObjectId id);

// --- Everyday names, for a person ------------------------------------------
// The category with spaces: "glass tumbler", "walk in pantry".
std::string spoken_category(const World& world, ObjectId object);
// "the top drawer", "the glass tumbler on the table": the object as a
// person tells it apart from the others of `among` that are like it: by
// category when no other shares it, then by its properties, then by where
// it is (a place that has look-alikes of its own is named by its
// properties: "the mug in the top drawer").
std::string distinct_noun_for(const World& world, ObjectId object, std::span<const ObjectId> among);
// The same among every object of the world.
std::string distinct_noun_for(const World& world, ObjectId object);
// "Which do you mean: the mug on the counter or the mug in the dish rack?";
// "Which drawer: the top drawer or the bottom drawer?" when look-alikes of
// one category differ by their properties alone.
std::string say_which_question(const World& world, std::span<const ObjectId> candidates);
// "the top drawer or the bottom drawer", "A, B or C".
std::string say_alternatives(const std::vector<std::string>& options, std::string_view conjunction = "or");

// --- The instructor's task structure -------------------------------------
// "Tidy kitchen."
std::string say_task_name(std::string_view name);
// "Repeat the following tasks while an object is on the table." ("in" for
// a receptacle: "... is in the dish rack.")
std::string say_repeat_while(const World& world, ObjectId place);
// The same over several places of one category: "... while an object is
// in a bag." (one place: as above).
std::string say_repeat_while(const World& world, std::span<const ObjectId> places);
// "Clear an object that is on the table."
std::string say_subtask(std::string_view verb, const World& world, ObjectId place);
// "Unload an object that is in a bag." over several places of a category.
std::string say_subtask(std::string_view verb, const World& world, std::span<const ObjectId> places);
std::string say_done();    // "You are done."
std::string say_repeat();  // "Repeat."
// "yes." / "no." (the script's answers).
std::string say_answer(bool yes);

// --- Goals and actions in English ----------------------------------------
// "the ketchup is in the fridge and the fridge is closed": placements
// first, then doors, in the goal's order otherwise.
std::string describe_goal(const World& world, const Goal& goal);
// "If the object is a ketchup then the goal is that the object is in the
// fridge and the fridge is closed." — `object` is spoken as "the object".
std::string describe_goal_instruction(const World& world, ObjectId object, const Goal& goal);
// "Open the fridge.", "Pick up the ketchup.", "Put the ketchup in the
// fridge.", "Put the mug on the counter.", "Close the fridge."
std::string describe_action(const World& world, const Action& action);
// The actions' sentences, space-separated, for transcripts.
std::string describe_plan(const World& world, std::span<const Action> actions);

// --- The agent's questions -------------------------------------------------
// "What is the next goal or subtask of clear?"
std::string say_next_goal_request(std::string_view subtask_verb);
// "What do I do next for clear?"
std::string say_next_action_request(std::string_view subtask_verb);
// "[LM] For a ceramic plate on the table, is the goal that the ceramic
// plate is in the cupboard and the cupboard is closed?" — `goal_statement`
// is the LLM's text ("the goal is that ..." or just what follows "that"),
// with the kind as a person says it ("ceramic-plate" in it becomes
// "ceramic plate"); the tag marks words that came from the language model.
std::string say_goal_question(const World& world, ObjectId object, std::string_view goal_statement,
                              bool from_language_model = true);
// The same for a goal the agent holds: "... is the goal that <describe_goal>?"
std::string say_goal_question(const World& world, ObjectId object, const Goal& goal,
                              bool from_language_model);
// "[LM] For the ceramic plate, should I 'Pick up ceramic plate'?"
std::string say_action_question(const World& world, ObjectId object, std::string_view action_text,
                                bool from_language_model = true);

}  // namespace apprentice::language
