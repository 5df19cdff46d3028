#include "language/narration_conversation.h"

#include <algorithm>
#include <map>

#include "language/narration.h"
#include "language/reference.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {

namespace {

// "\"a\"", "\"a\" or \"b\"", "\"a\", \"b\" or \"c\"": the first `most`.
std::string quoted_examples(const std::vector<std::string>& examples, std::size_t most) {
  std::vector<std::string> shown;
  for (std::size_t i = 0; i < examples.size() && i < most; ++i) shown.push_back("\"" + examples[i] + "\"");
  std::string out;
  for (std::size_t i = 0; i < shown.size(); ++i) out += (i == 0 ? "" : (i + 1 == shown.size() ? " or " : ", ")) + shown[i];
  return out;
}

std::string answer_wanted(Asked asked) {
  switch (asked) {
    case Asked::kTask: return "Tell me the task you want me to learn";
    case Asked::kTaskStep:
      return "Tell me the next step of the task: a subtask with the place it is about, or that the task is done";
    case Asked::kSubtaskEnd: return "Tell me whether there is more to this subtask, or that it is done";
    case Asked::kGoal: return "Tell me where it goes, and anything else that should be so when it is put away";
    case Asked::kAction: return "Tell me one thing to do next";
    case Asked::kYesNo: return "Answer yes or no";
    case Asked::kWhich: return "Tell me which one you mean";
  }
  return "Answer the question";
}

// "on the table", "in the bags": where a subtask's things are.
std::string subtask_places(const World& world, const SubtaskUnderWay& subtask) {
  return subtask.relation + " " + spoken_places(world, subtask.places);
}

// "it" for one thing named in the singular, else "them".
std::string pronoun_for(const World& world, std::span<const ObjectId> things) {
  return things.size() == 1 ? object_pronoun(world, things.front()) : std::string("them");
}

}  // namespace

std::string with_period(std::string text) {
  // A quotation that ends a sentence with its own period needs no other.
  std::size_t end = text.size();
  if (end >= 2 && text[end - 1] == '"' && (text[end - 2] == '.' || text[end - 2] == '?' || text[end - 2] == '!'))
    return text;
  return text + ".";
}

std::string i_asked(std::string_view question) { return "I asked: " + std::string(question); }

std::string kinds_of_answer(Asked asked, const std::vector<std::string>& examples) {
  return answer_wanted(asked) + (examples.empty() ? "." : ", for example " + with_period(quoted_examples(examples, 3)));
}

std::string commands_at_any_question() {
  return "You can also type: help; status (what I see and what I have learned); undo (forget what your last answer "
         "taught me); forget <kind of object> (forget where that kind of thing goes); quit, or Ctrl-D (stop; what I "
         "learned is kept).";
}

std::string reply_refused(std::string_view reason, const std::vector<std::string>& examples) {
  std::string text(reason);
  if (!text.empty() && text.back() != '.' && text.back() != '?' && text.back() != '!') text += ".";
  if (!examples.empty()) text += " You could say, for example, " + with_period(quoted_examples(examples, 2));
  return text;
}

std::string what_i_see(const World& w) {
  const Universe& u = *w.universe;
  const Vocabulary& v = w.vocabulary;
  std::vector<std::string> doors;
  for (ObjectId p : u.of_kind(ObjectKind::kReceptacle)) {
    if (!w.state.holds(Fact(v.openable, {p}))) continue;
    doors.push_back(spoken_name(w, p) + " is " + (w.state.holds(Fact(v.closed, {p})) ? "closed" : "open"));
  }
  std::string seen = "I see this: " + (doors.empty() ? std::string() : list_phrase(doors) + ".");
  for (ObjectId place = 0; place < u.size(); ++place) {
    if (u.info(place).kind == ObjectKind::kItem) continue;
    std::vector<ObjectId> items;
    for (PredicateId relation : {v.on, v.in})
      for (const Fact& f : w.state.facts_with_second(relation, 2, place)) items.push_back(f.args[0]);
    if (!items.empty())
      seen += " " + capitalize(std::string(relation_word(w, place))) + " " + spoken_name(w, place) + ": " +
              spoken_things(w, items) + ".";
  }
  for (const Fact& f : w.state.facts_of(v.holding))
    if (f.arity == 1) seen += " I am holding " + spoken_name(w, f.args[0]) + ".";
  return seen;
}

std::string what_i_am_doing(const World& w, const WhatIAmDoing& doing) {
  std::string said = doing.task.empty() ? "I have not been given a task yet" : "I am learning to " + task_phrase(doing.task);
  if (doing.subtask)
    said += "; now I " + doing.subtask->verb + " what is " + subtask_places(w, *doing.subtask);
  if (doing.working_on) said += ", working on " + spoken_name(w, *doing.working_on);
  else if (doing.asking_about) said += ", asking about " + spoken_name(w, *doing.asking_about);
  return said + ". So far I know " + count_phrase(doing.goals, "goal") + " and " + count_phrase(doing.rules, "rule") +
         ", after " + count_phrase(doing.instructions, "instruction") + " this session.";
}

std::string no_task_yet() { return "I have not been given a task yet."; }

std::string whats_left_of_subtask(const World& world, const SubtaskUnderWay& subtask, std::span<const ObjectId> left) {
  const std::string where = subtask_places(world, subtask);
  if (left.empty()) return "Nothing else is left " + where + ".";
  return "Still " + where + ": " + spoken_things(world, left) + ".";
}

std::string whats_left_of_task(const World& w, std::span<const PartLearned> parts,
                               std::span<const ObjectId> not_dealt_with) {
  std::vector<std::string> learned;
  for (const PartLearned& p : parts)
    learned.push_back(p.verb + " what is " + p.relation + " the " + spoken_category(p.place_category));
  std::string said = learned.empty() ? "No part of the task is done yet."
                                     : "So far I have learned to " + list_phrase(learned) + ".";
  std::vector<ObjectId> places;
  std::map<ObjectId, std::vector<ObjectId>> at;
  for (ObjectId o : not_dealt_with) {
    std::optional<ObjectId> place = place_of(w, o);
    if (!place) continue;
    if (!at.count(*place)) places.push_back(*place);
    at[*place].push_back(o);
  }
  if (places.empty()) return said + " Every thing here has been dealt with; say \"that's all\" if the task is done.";
  std::vector<std::string> groups;
  for (ObjectId place : places)
    groups.push_back(std::string(relation_word(w, place)) + " " + spoken_name(w, place) + ", " +
                     spoken_things(w, at[place]));
  return said + " Not dealt with yet: " + join(groups, "; ") + ". Tell me what to do next, or say \"that's all\".";
}

std::vector<std::string> where_things_are(const World& w, std::string_view phrase, std::span<const ObjectId> things) {
  if (things.empty()) {
    std::vector<std::string> words = split_words(phrase);
    while (!words.empty() && is_determiner(words.front())) words.erase(words.begin());
    // "where is that now": no thing named.
    if (words.empty() || (words.size() == 1 && is_object_pronoun(words.front()))) {
      const auto& items = w.universe->of_kind(ObjectKind::kItem);
      const std::string example = items.empty() ? std::string("mug") : spoken_category(w, items.front());
      return {"Which thing do you mean? Name it, for example \"where is the " + example + "?\"."};
    }
    return {not_seen_message(join(words, " "), w)};
  }
  std::vector<std::string> said;
  // Things of one kind at one place are said once: "Both slippers are on
  // the shoe rack.", not the same sentence twice.
  std::vector<std::pair<std::string, ObjectId>> done;
  for (ObjectId o : things) {
    if (said.size() == 3) break;
    if (w.state.holds(Fact(w.vocabulary.holding, {o}))) {
      said.push_back("I am holding " + spoken_name(w, o) + ".");
      continue;
    }
    std::optional<ObjectId> at = place_of(w, o);
    if (!at) continue;
    const std::string& kind = w.universe->info(o).category;
    if (std::find(done.begin(), done.end(), std::pair{kind, *at}) != done.end()) continue;
    done.emplace_back(kind, *at);
    const auto alike = std::count_if(things.begin(), things.end(), [&](ObjectId other) {
      return w.universe->info(other).category == kind && place_of(w, other) == at &&
             spoken_name(w, other) == spoken_name(w, o);
    });
    const std::string where = std::string(relation_word(w, *at)) + " " + spoken_name(w, *at) + ".";
    if (alike == 1) said.push_back(capitalize(spoken_name(w, o)) + " is " + where);
    else
      said.push_back((alike == 2 ? std::string("Both ") : "All " + std::to_string(alike) + " ") +
                     spoken_plural(kind) + " are " + where);
  }
  if (said.empty()) return {"I don't know where " + std::string(phrase) + " is."};
  return said;
}

std::string why_without_a_reply() {
  return "I have only done what I already knew; you have not told me anything yet this session.";
}

std::string because_i_decided(const World& world, ObjectId object, std::string_view from) {
  return with_period("Because I decided where " + spoken_name(world, object) + " goes from " + std::string(from)) +
         " If that was wrong, tell me where it goes.";
}

std::string because_of_last_reply(std::string_view reply) {
  return with_period("Because of what you told me last: \"" + std::string(reply) + "\"") +
         " If that was wrong, say undo, or tell me what you meant.";
}

std::string because_goal_from(const World& world, ObjectId thing, const Goal& goal, std::string_view from) {
  return capitalize(goal_outcome(world, thing, goal, spoken_name(world, thing))) + ": I learned that from " +
         with_period(std::string(from)) + " If that was wrong, tell me where it goes.";
}

std::string left_as_told(const World& world, ObjectId thing) {
  return "You told me to leave " + spoken_name(world, thing) + " where it is.";
}

std::string why_door_is(const World& world, ObjectId place, bool closed,
                        const std::optional<std::pair<ObjectId, std::string>>& left_open_for) {
  const std::string name = spoken_name(world, place);
  if (closed) return capitalize(name) + " is closed: I close what I open.";
  if (left_open_for)
    return with_period(capitalize(name) + " is open because " + spoken_name(world, left_open_for->first) +
                       " goes there with it left open; I learned that from " + left_open_for->second) +
           " Say \"close " + name + "\" to close it now.";
  return capitalize(name) + " is open: nothing I learned says to close it. Say \"close " + name +
         "\" to close it now.";
}

std::string already_open_or_closed(const World& world, ObjectId thing, bool closed) {
  return capitalize(spoken_name(world, thing)) + " is already " + (closed ? "closed" : "open") + ".";
}

std::string could_not(const World& world, const Action& action) {
  return "I could not " + action_phrase(world, action) + ".";
}

std::string which_kind_to_forget(const std::vector<std::string>& categories) {
  std::vector<std::string> named;
  for (const std::string& c : categories) named.push_back("the " + spoken_category(c));
  return "Which kind do you mean: " + list_phrase(named) + "? Say, for example, \"forget " +
         spoken_category(categories.front()) + "\".";
}

std::string nothing_to_forget(std::optional<std::string_view> category, std::string_view said) {
  return "I have not learned where to put " +
         (category ? "the " + spoken_category(*category) : std::string(trim(said))) + ", so there is nothing to forget.";
}

std::string forgot_where_kind_goes(std::string_view category) {
  return "I forgot where " + kind_goes(category) + "; I will ask when I meet one.";
}

std::string why_earlier_placement(const World& world, ObjectId thing, const Goal& then, std::string_view how,
                                  const Goal& now) {
  const std::string name = spoken_name(world, thing);
  std::string earlier = goal_outcome(world, thing, then, name);
  return "Earlier I decided " + earlier + (how.empty() ? "" : ", " + std::string(how)) + "; since then, " +
         goal_outcome(world, thing, now, name) + ".";
}

std::string why_i_asked(const World& world, ObjectId thing, const Goal& proposed, std::string_view evidence,
                        const std::optional<Goal>& now) {
  const std::string name = spoken_name(world, thing);
  std::string out = "I asked whether " + goal_outcome(world, thing, proposed, name) +
                    (evidence.empty() ? "" : ", " + std::string(evidence)) +
                    ": it seemed likely, but not enough to do it without asking.";
  if (now) out += " Now " + goal_outcome(world, thing, *now, name) + ".";
  return out;
}

std::string door_left_open_as_told(const World& world, ObjectId place) {
  return capitalize(spoken_name(world, place)) + " is open: you told me to leave it open from now on.";
}

std::string will_keep_doors(const World& world, const std::vector<ObjectId>& places,
                            const std::vector<std::string>& kinds, bool open) {
  std::vector<std::string> doors, things;
  for (ObjectId place : places) doors.push_back(spoken_name(world, place));
  for (const std::string& kind : kinds) things.push_back("the " + spoken_category(kind));
  std::string out = (open ? "I will leave " + list_phrase(doors) + " open" : "I will close " + list_phrase(doors)) +
                    " from now on";
  if (!things.empty()) out += ", also after putting " + list_phrase(things) + (places.size() == 1 ? " in it" : " in them");
  return out + ".";
}

std::string remember_again(std::string_view category) { return "I know again where " + kind_goes(category) + "."; }

std::string which_rule_to_forget(std::string_view what, const std::vector<std::string>& rules,
                                 std::string_view first_to_forget) {
  return "I have several rules about " + std::string(trim(what)) + ": " + join(rules, "; ") +
         ". Say which, for example \"forget " + std::string(first_to_forget) + "\".";
}

std::string forgot_rule(std::string_view rule) {
  return "I forgot that " + std::string(rule) + "; I will ask where such things go.";
}

std::string asked_yes_or_no() { return "I asked a yes-or-no question."; }

std::string asked_which_one() { return "I asked which one you mean."; }

std::string asked_what_to_do_next() { return "I asked what to do next."; }

std::string asked_where_it_goes(const World& world, ObjectId object) {
  return "I asked where " + spoken_name(world, object) + " goes.";
}

std::string says_what_becomes_of_others(const World& world, std::span<const ObjectId> others, ObjectId asked) {
  std::vector<std::string> names;
  for (ObjectId o : others) names.push_back(spoken_name(world, o));
  return "That says what becomes of " + (names.empty() ? "other things" : list_phrase(names)) + ", but I asked about " +
         spoken_name_and_location(world, asked) + ".";
}

std::string still_cannot_tell_which(std::string_view phrase) {
  return "I still cannot tell which " + std::string(phrase) + " you mean.";
}

std::string could_not_tell_which(std::string_view phrase) {
  return "I could not tell which " + std::string(phrase) + " you mean.";
}

std::string reply_set_aside(std::string_view said) { return "Then I leave " + apprentice::quoted(said) + " aside."; }

std::string this_time_only_note() { return "This time only: I will not remember it as where that goes."; }

std::string placed_this_time_only(const World& world, ObjectId thing) {
  return "You told me to put " + spoken_name(world, thing) + " there this time only.";
}

std::string could_not_reach_llm(std::string_view failure, bool will_ask) {
  return "I could not reach the language model (" + std::string(failure) + ")" + (will_ask ? ", so I will ask." : ".");
}

std::string will_leave_as_it_is(const World& world, ObjectId object, bool say_where) {
  return "I will leave " + (say_where ? spoken_name_and_location(world, object) : spoken_name(world, object)) +
         " as it is.";
}

std::string read_back_goal_for_later(const World& world, ObjectId thing, const Goal& goal) {
  return read_back_goal(world, thing, goal) + " I will do that when I come to " + object_pronoun(world, thing) + ".";
}

std::vector<std::string> goals_for_others(const World& w, std::span<const ObjectId> same,
                                          std::span<const ObjectId> learned, std::span<const ObjectId> later) {
  std::vector<std::string> said;
  if (!same.empty()) {
    std::vector<std::string> names;
    for (ObjectId o : same) names.push_back(spoken_name(w, o));
    said.push_back("The same goes for " + list_phrase(names) + ", when I come to " + pronoun_for(w, learned) + ".");
  } else if (!learned.empty()) {
    said.push_back("I will do that when I come to " + pronoun_for(w, learned) + ".");
  }
  if (!later.empty()) {
    std::vector<std::string> names;
    for (ObjectId o : later) names.push_back(spoken_name(w, o));
    said.push_back("I will ask about " + list_phrase(names) + " when I come to " + pronoun_for(w, later) + ".");
  }
  return said;
}

std::string will_ask_about_later(const World& w, ObjectId other, const SubtaskUnderWay& subtask, ObjectId asked) {
  return "I will ask about " + spoken_name(w, other) + " when I come to " + object_pronoun(w, other) + "; now I " +
         subtask.verb + " what is " + subtask_places(w, subtask) + ". Where should " + spoken_name(w, asked) + " go?";
}

std::string help_needed_for_goal(const World& world, ObjectId object, std::string_view verb,
                                 const std::vector<std::string>& refused) {
  const bool plural = is_plural_category(world.universe->info(object).category);
  std::string help =
      "where " + spoken_name_and_location(world, object) + (plural ? " go (" : " goes (") + std::string(verb) + ")";
  if (!refused.empty()) help += "; the replies I could not use: " + join(refused, ", ");
  return help;
}

std::string help_needed_for_goal_to_hold(const World& world, const Goal& goal) {
  return "how to make it so that " + goal_facts(world, goal);
}

}  // namespace apprentice::language
