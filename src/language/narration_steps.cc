#include "language/narration_steps.h"

#include "language/generation.h"
#include "language/narration.h"
#include "language/narration_conversation.h"

namespace apprentice::language {
namespace {

std::string at_places(std::string_view relation, const World& world, std::span<const ObjectId> places) {
  return std::string(relation) + " " + spoken_places(world, places);
}

}  // namespace

std::string already_know_task(std::string_view task_name) {
  return "I know how to " + task_phrase(task_name) + "; I will ask only about what is new.";
}

std::string read_back_loop(const World& world, std::span<const ObjectId> places) {
  return "So I repeat the next steps while something is " + std::string(relation_word(world, places.front())) + " " +
         spoken_places(world, places) + ".";
}

std::string read_back_task_done(bool part_under_way) {
  return std::string("So the task is done") + (part_under_way ? " once this subtask is." : ".");
}

std::string read_back_part(std::string_view verb, std::string_view relation, const World& world,
                           std::span<const ObjectId> places, bool one_first) {
  const std::string where = at_places(relation, world, places);
  if (one_first) return "So I " + std::string(verb) + " one thing " + where + " at a time.";
  return "So I " + std::string(verb) + " what is " + where + ", one thing at a time.";
}

std::string read_back_the_rest_the_same_way(std::string_view verb, std::string_view relation, const World& world,
                                            std::span<const ObjectId> places) {
  return "So I " + std::string(verb) + " everything else " + at_places(relation, world, places) + " the same way.";
}

std::string read_back_one_was_all(std::string_view verb) {
  return "So that is all there is to " + std::string(verb) + " for one thing.";
}

std::string no_place_for_known_part(std::string_view place_category, std::string_view verb) {
  return "There is no " + spoken_category(place_category) + " here, so I cannot " + std::string(verb) + " it.";
}

std::string nothing_left(std::string_view relation, const World& world, std::span<const ObjectId> places, bool first) {
  return "There is nothing " + std::string(first ? "" : "left ") + at_places(relation, world, places) + ".";
}

std::string could_not_finish(std::string_view verb, long long remaining, std::string_view relation, const World& world,
                             std::span<const ObjectId> places) {
  const std::string objects = remaining == 1 ? "1 object" : std::to_string(remaining) + " objects";
  return "I could not " + std::string(verb) + " " + objects + " still " + at_places(relation, world, places) + ".";
}

std::string rule_parts_not_followed(const std::vector<std::string>& parts) {
  std::vector<std::string> quoted;
  for (const std::string& part : parts) quoted.push_back("\"" + part + "\"");
  return "I did not follow " + list_phrase(quoted) + "; I will ask about those things when I come to them.";
}

std::string nothing_to_undo() { return "There is nothing to undo yet."; }

std::string forgot_last(std::string_view reply) {
  return with_period("I forgot what you told me last: \"" + std::string(reply) + "\"");
}

std::string put_back(const World& world, const std::vector<Action>& actions, bool all) {
  const std::string report = report_actions(world, actions);
  if (report.empty()) return "";
  return std::string(all ? "To put things back as they were, " : "To put things back, ") + report;
}

std::string could_not_put_back() { return "I could not put everything back as it was."; }

std::string need_task_name_first() { return "I need the name of the task first."; }
std::string no_part_taught_yet() { return "I have not been told any part of the task yet, so it cannot be done."; }
std::string nothing_to_repeat_yet() { return "There is nothing to repeat yet."; }
std::string asked_for_next_step() {
  return "I asked for the next step of the task: a subtask and its place, or that the task is done.";
}
std::string asked_whether_more_to_part() { return "I asked whether there is more to this subtask."; }

std::string ask_other_name(std::string_view word, const World& world, ObjectId object) {
  return "By \"" + std::string(word) + "\", do you mean " + spoken_name(world, object) + "?";
}

std::string not_sure_enough(const World& world, ObjectId object, const Goal& goal, std::string_view evidence,
                            std::string_view confidence) {
  const bool plural = is_plural_category(world.universe->info(object).category);
  return "it may be that " + goal_outcome(world, object, goal, plural ? "they" : "it") +
         (evidence.empty() ? "" : ", " + std::string(evidence)) + ", but I am not sure enough (confidence " +
         std::string(confidence) + ")";
}

std::string ask_goal_proposed(const World& world, ObjectId object, const Goal& goal, std::string_view evidence,
                              const std::vector<std::string>& others) {
  // "Do the headphones on the chair go ...: they go in ...?"
  const bool plural = is_plural_category(world.universe->info(object).category);
  return (plural ? "Do " : "Does ") + spoken_name_and_location(world, object) + " go " +
         (evidence.empty() ? std::string("here") : std::string(evidence)) + ": " +
         goal_outcome(world, object, goal, plural ? "they" : "it") +
         (others.empty() ? "?" : ", and " + list_phrase(others) + " too?");
}

namespace {

std::string robot_subject(std::string_view robot) {
  if (robot.empty()) return "Another robot";
  std::string lower;
  for (char c : robot.substr(0, 5)) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  if (lower != "robot") return "Robot " + std::string(robot);
  return "R" + std::string(robot.substr(1));
}

}  // namespace

std::string news_sentence(std::string_view robot, const std::vector<std::string>& kinds) {
  std::string things;
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    if (i > 0) things += i + 1 == kinds.size() ? (kinds.size() > 2 ? ", and " : " and ") : ", ";
    things += "the " + spoken_category(kinds[i]);
  }
  return robot_subject(robot) + " just learned where " + things + (kinds.size() == 1 ? " goes." : " go.");
}

}  // namespace apprentice::language
