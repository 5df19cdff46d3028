// A person teaches at the terminal in everyday English, never in the
// script's fixed sentences: a scripted teacher who reads each question the
// agent asks, sees which object it names and where, and answers as people
// do ("First, clear the table.", "put it in the fridge and close the
// fridge", "That's all."). It must teach each task to 100% and exit 0, in
// no more turns than the floor plus 10%: the floor is the task structure
// (the task, one reply per subtask, the end) plus one goal per goal type.
//
// The teacher knows what it wants from the scenario's intent; it never
// sees the agent's knowledge.
#include <cstdlib>
#include <iostream>
#include <regex>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "agent_fixtures.h"
#include "language/narration.h"
#include "pty.h"

namespace apprentice {
namespace {

class EverydayTeacher {
 public:
  // `messy`: the teacher of issue 21's pty test, who also uses fillers,
  // gives one goal wrong and corrects it at the next question ("no wait,
  // ..."), says an ending mid-part once ("hmm i'm done") and answers "no"
  // when asked whether to leave the rest, asks "what's left?" between
  // parts and at a goal question, asks for a one-off closing with an
  // answer ("..., oh and close the cupboard"), and ends the task with a
  // one-off thanks.
  explicit EverydayTeacher(const Scenario& scenario, bool messy = false) : scenario_(scenario), messy_(messy) {}

  // The reply to `question`, or "" (with a test failure) if the teacher
  // does not know what the agent is asking.
  std::string reply(const std::string& question) {
    static const std::regex kWhere("Where should the (.+) (on|in) the (.+) go\\?");
    std::smatch m;
    if (question == "What task should I learn?") return (messy_ ? "um, ok so " : "") + task_reply();
    if (question.rfind("What should I do first to ", 0) == 0 || question.rfind("What should I do next to ", 0) == 0) {
      if (messy_ && subtask_ == 1 && !asked_left_between_) {
        asked_left_between_ = true;
        return "hmm, what's left?";
      }
      return next_step();
    }
    if (std::regex_match(question, m, kWhere)) return messy_ ? messy_goal_reply(m[1], m[3]) : goal_reply(m[1], m[3]);
    // The ask-back of an ending said mid-part: the teacher goes on.
    static const std::regex kLeaveThem("There (is|are) still .+\\. Shall I leave (it|them)\\?");
    if (messy_ && said_ending_ && std::regex_match(question, kLeaveThem)) {
      asked_to_leave_ = true;
      return "no";
    }
    ADD_FAILURE() << "the teacher does not know what the agent asks: " << question;
    return "";
  }

  // Whether the ending said mid-part was asked back.
  bool asked_to_leave() const { return asked_to_leave_; }

  // The fewest replies that can teach the task: the task, one per
  // subtask, the end, and one goal per (subtask, category).
  int floor() const {
    return 1 + static_cast<int>(scenario_.task.subtasks.size()) + 1 + static_cast<int>(scenario_.intent.size());
  }

 private:
  std::string task_reply() {
    std::string name = language::task_phrase(scenario_.task.name);
    return next_form_++ % 2 == 0 ? "I want you to " + name : "your job is to " + name;
  }

  std::string next_step() {
    const auto& subtasks = scenario_.task.subtasks;
    if (subtask_ >= subtasks.size()) return messy_ ? "ok that's everything, thanks!" : "That's all.";
    const Subtask& s = subtasks[subtask_];
    const World& w = scenario_.world;
    std::string place = language::spoken_places(w, s.places);
    std::string reply;
    if (subtask_ == 0) reply = "First, " + s.verb + " " + place + ".";
    else if (subtask_ % 2 == 1)
      reply = "Then " + s.verb + " the things " + std::string(language::relation_word(w, s.places.front())) + " " + place + ".";
    else
      reply = "Now " + s.verb + " " + place + ".";
    ++subtask_;
    return reply;
  }

  // The goal questions of the messy teacher, in turn: the first answered
  // wrongly (an open place that is not the thing's), the second with a
  // correction of the first, then the same question again answered, a
  // "what's left?", a one-off closing with the answer, fillers.
  std::string messy_goal_reply(const std::string& thing, const std::string& place_words) {
    const World& w = scenario_.world;
    // Once, after the correction, an ending said mid-part ("I'm done"),
    // which the agent asks back; the teacher answers "no" and goes on.
    if (goal_questions_ == 2 && !said_ending_) {
      said_ending_ = true;
      return "hmm i'm done";
    }
    ++goal_questions_;
    if (goal_questions_ == 1) {
      const IntentEntry* wanted = wanted_for(thing, place_words);
      if (wanted == nullptr) return "";
      for (ObjectId p = 0; p < w.universe->size(); ++p) {
        if (p == wanted->place || w.universe->info(p).kind != ObjectKind::kReceptacle || openable(w, p)) continue;
        wrong_ = {thing, place_words};
        return "lol ok, the " + thing + " goes in the " + language::spoken_category(w.universe->info(p).category);
      }
      ADD_FAILURE() << "no open place for a wrong goal";
      return "";
    }
    if (goal_questions_ == 2 && wrong_) return "no wait, " + goal_reply(wrong_->first, wrong_->second);
    if (goal_questions_ == 4) return "hold on, what's left?";
    std::string answer = goal_reply(thing, place_words);
    if (goal_questions_ == 6) {
      const IntentEntry* wanted = wanted_for(thing, place_words);
      for (ObjectId p = 0; wanted && p < w.universe->size(); ++p)
        if (p != wanted->place && openable(w, p))
          return answer + ". oh and close the " + language::spoken_category(w.universe->info(p).category);
    }
    return goal_questions_ % 2 == 1 ? "um, " + answer : answer;
  }

  static bool openable(const World& w, ObjectId p) {
    return w.state.holds(Fact(w.vocabulary.openable, {p}));
  }

  const IntentEntry* wanted_for(const std::string& thing, const std::string& place_words) const {
    const World& w = scenario_.world;
    const IntentEntry* wanted = nullptr;
    for (const Subtask& s : scenario_.task.subtasks) {
      if (language::spoken_places(w, s.places) != "the " + place_words) continue;
      for (const IntentEntry& e : scenario_.intent)
        if (e.subtask == s.verb && language::spoken_category(e.category) == thing) wanted = &e;
    }
    if (wanted == nullptr) ADD_FAILURE() << "the teacher wants nothing for the " << thing << " " << place_words;
    return wanted;
  }

  std::string goal_reply(const std::string& thing, const std::string& place_words) {
    const World& w = scenario_.world;
    const IntentEntry* wanted = wanted_for(thing, place_words);
    if (wanted == nullptr) return "";
    std::string r = language::spoken_category(w.universe->info(wanted->place).category);
    // "in the fridge", "on the shelf".
    std::string at = std::string(language::relation_word(w, wanted->place));
    int form = next_form_++;
    if (wanted->closed) {
      switch (form % 4) {
        case 0: return "the " + thing + " goes in the " + r + " and the " + r + " should be closed";
        case 1: return "put it in the " + r + " and close the " + r;
        case 2: return "it should end up in the " + r + " with the door closed";
        default: return "put the " + thing + " away in the " + r + ", then close it";
      }
    }
    switch (form % 4) {
      case 0: return "the " + thing + " goes " + at + " the " + r;
      case 1: return thing + " belongs " + at + " the " + r;
      case 2: return at + " the " + r;
      default: return "put it " + at + " the " + r;
    }
  }

  const Scenario& scenario_;
  bool messy_ = false;
  std::size_t subtask_ = 0;
  int next_form_ = 0;
  int goal_questions_ = 0;
  bool asked_left_between_ = false;
  bool said_ending_ = false;     // an ending said mid-part
  bool asked_to_leave_ = false;  // and asked back whether to leave the rest
  std::optional<std::pair<std::string, std::string>> wrong_;  // the thing answered wrongly, and where it was
};

struct Taught {
  int exit_code = -1;
  int turns = 0;
  std::string screen;
  bool asked_to_leave = false;  // the messy teacher's ending mid-part was asked back
};

Taught teach_at_terminal(const Scenario& scenario, const std::string& scenario_path, bool messy = false) {
  EverydayTeacher teacher(scenario, messy);
  testing::Terminal terminal({APPRENTICE_BINARY, "teach", "--scenario", scenario_path});
  Taught taught;
  size_t from = 0;
  // A bound only so that a broken agent cannot hang the test.
  for (int guard = 0; guard < 4 * teacher.floor() + 10; ++guard) {
    std::string question = terminal.next_question(from);
    if (question.empty()) break;
    std::string reply = teacher.reply(question);
    if (reply.empty()) break;
    from = terminal.screen().size();
    terminal.type(reply + "\r");
    ++taught.turns;
  }
  // If the agent is still asking, the teacher has nothing more to say.
  terminal.type("\x04");
  taught.exit_code = terminal.wait();
  taught.screen = terminal.screen();
  taught.asked_to_leave = teacher.asked_to_leave();
  return taught;
}

void expect_taught_within_floor(const std::string& relative_path) {
  std::string path = testing::source_path(relative_path).string();
  Scenario scenario = testing::load_or_die(path);
  Taught taught = teach_at_terminal(scenario, path);
  EverydayTeacher counter(scenario);
  const int floor = counter.floor();
  EXPECT_EQ(taught.exit_code, 0) << taught.screen;
  std::string total = std::to_string(scenario.goal_assertions().size());
  EXPECT_THAT(taught.screen, ::testing::HasSubstr("The task is learned: " + total + " of " + total + " parts of the goal are met"))
      << taught.screen;
  EXPECT_LE(taught.turns * 10, floor * 11) << "turns " << taught.turns << ", floor " << floor << "\n" << taught.screen;
  EXPECT_GE(taught.turns, floor) << taught.screen;
}

// Issue 21's pty test: a teacher who uses fillers, corrects a wrong goal
// at the next question, says an ending mid-part and answers "no" to the
// ask-back, asks "what's left?" between parts and at a goal question,
// asks for a one-off closing and ends with a thanks, in two worlds: each
// is taught to 100% and the program exits 0.
void expect_taught_by_a_messy_teacher(const std::string& relative_path) {
  std::string path = testing::source_path(relative_path).string();
  Scenario scenario = testing::load_or_die(path);
  Taught taught = teach_at_terminal(scenario, path, true);
  // APPRENTICE_SHOW_SCREEN=1 prints the whole exchange, to read it.
  if (std::getenv("APPRENTICE_SHOW_SCREEN") != nullptr) std::cout << taught.screen << "\n";
  EXPECT_EQ(taught.exit_code, 0) << taught.screen;
  std::string total = std::to_string(scenario.goal_assertions().size());
  EXPECT_THAT(taught.screen, ::testing::HasSubstr("The task is learned: " + total + " of " + total + " parts of the goal are met"))
      << taught.screen;
  // The answers to "what's left?": between parts, and within one.
  EXPECT_THAT(taught.screen, ::testing::HasSubstr("So far I have learned to ")) << taught.screen;
  EXPECT_THAT(taught.screen, ::testing::HasSubstr("Not dealt with yet: ")) << taught.screen;
  EXPECT_THAT(taught.screen, ::testing::ContainsRegex("Still (on|in) the ")) << taught.screen;
  EXPECT_THAT(taught.screen, ::testing::Not(::testing::HasSubstr("I do not know the word"))) << taught.screen;
  // The ending said mid-part was asked back, and "no" went on.
  EXPECT_TRUE(taught.asked_to_leave) << taught.screen;
  EXPECT_THAT(taught.screen, ::testing::HasSubstr("Agent: So I go on with the ")) << taught.screen;
}

TEST(EverydayTeacher, AMessyTeacherTeachesTheKitchenAtTheTerminal) {
  expect_taught_by_a_messy_teacher("data/scenarios/tidy-kitchen.yaml");
}

TEST(EverydayTeacher, AMessyTeacherTeachesAnOfficeAtTheTerminal) {
  expect_taught_by_a_messy_teacher("tests/agent/data/tidy-office.yaml");
}

TEST(EverydayTeacher, TeachesTheKitchenAtTheTerminal) { expect_taught_within_floor("data/scenarios/tidy-kitchen.yaml"); }

TEST(EverydayTeacher, TeachesAnOfficeAtTheTerminal) { expect_taught_within_floor("tests/agent/data/tidy-office.yaml"); }

}  // namespace
}  // namespace apprentice
