// What the agent says about the task's parts as it learns them, and about
// undoing a lesson: the read-backs of a part named, a loop, the task's end,
// and of what was put back. Plain sentences, each ending with a period.
// `relation` is the part's relation as the agent keeps it: "on" or "in".
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "world/action.h"
#include "world/goal.h"
#include "world/world.h"

namespace apprentice::language {

// "I know how to tidy the kitchen; I will ask only about what is new."
std::string already_know_task(std::string_view task_name);
// "So I repeat the next steps while something is on the table."
std::string read_back_loop(const World& world, std::span<const ObjectId> places);
// "So the task is done." or, with a part under way, "So the task is done
// once this subtask is."
std::string read_back_task_done(bool part_under_way);
// "So I clear what is on the table, one thing at a time." or, for the
// first thing of a part (`one_first`), "So I clear one thing on the table
// at a time."
std::string read_back_part(std::string_view verb, std::string_view relation, const World& world,
                           std::span<const ObjectId> places, bool one_first);
// "So I clear everything else on the table the same way."
std::string read_back_the_rest_the_same_way(std::string_view verb, std::string_view relation, const World& world,
                                            std::span<const ObjectId> places);
// "So that is all there is to clear for one thing."
std::string read_back_one_was_all(std::string_view verb);
// "There is no dish rack here, so I cannot empty it."
std::string no_place_for_known_part(std::string_view place_category, std::string_view verb);
// The end of a part: "There is nothing left on the table." ("There is
// nothing on the table." after its first thing, `first`), or, when things
// are still there, "I could not clear 2 objects still on the table."
std::string nothing_left(std::string_view relation, const World& world, std::span<const ObjectId> places, bool first);
std::string could_not_finish(std::string_view verb, long long remaining, std::string_view relation, const World& world,
                             std::span<const ObjectId> places);
// After a person's rule: "I did not follow "heavy items"; I will ask about
// those things when I come to them." (`parts` as said, unquoted).
std::string rule_parts_not_followed(const std::vector<std::string>& parts);
// What the agent would have done alone, and why it did not: "it may be
// that they go in the hamper, like the socks, but I am not sure enough
// (confidence 0.63)". `evidence` may be empty.
std::string not_sure_enough(const World& world, ObjectId object, const Goal& goal, std::string_view evidence,
                            std::string_view confidence);
// Undo: "There is nothing to undo yet.", "I forgot what you told me last:
// "the mug goes in the sink"."
std::string nothing_to_undo();
std::string forgot_last(std::string_view reply);
// The actions that put the world back: "To put things back as they were,
// I took the mug out of the sink." (`all`), or, when not all could be
// undone, "To put things back, I ..." (empty when `actions` is), followed
// by could_not_put_back().
std::string put_back(const World& world, const std::vector<Action>& actions, bool all);
std::string could_not_put_back();

// Why a reply was not taken, at each question of the task's structure.
std::string need_task_name_first();         // "I need the name of the task first."
std::string no_part_taught_yet();           // "I have not been told any part of the task yet, so it cannot be done."
std::string nothing_to_repeat_yet();        // "There is nothing to repeat yet."
std::string asked_for_next_step();          // "I asked for the next step of the task: ..."
std::string asked_whether_more_to_part();   // "I asked whether there is more to this subtask."


// "By "dummy", do you mean the pacifier?"
std::string ask_other_name(std::string_view word, const World& world, ObjectId object);
// "Does the mug on the table go like the cup: in the cupboard?" (`evidence`
// "like the cup"; "here" when empty), with "and the fork and the plate too"
// for `others` (spoken names).
std::string ask_goal_proposed(const World& world, ObjectId object, const Goal& goal, std::string_view evidence,
                              const std::vector<std::string>& others);
// What another robot learned: "Robot kitchen-2 just learned where the
// ketchup goes." ("Another robot" when the store does not name it; a name
// that says "robot" already is said as it is.)
std::string news_sentence(std::string_view robot, const std::vector<std::string>& kinds);

}  // namespace apprentice::language
