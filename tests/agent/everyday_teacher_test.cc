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
  explicit EverydayTeacher(const Scenario& scenario) : scenario_(scenario) {}

  // The reply to `question`, or "" (with a test failure) if the teacher
  // does not know what the agent is asking.
  std::string reply(const std::string& question) {
    static const std::regex kWhere("Where should the (.+) (on|in) the (.+) go\\?");
    std::smatch m;
    if (question == "What task should I learn?") return task_reply();
    if (question.rfind("What should I do first to ", 0) == 0 || question.rfind("What should I do next to ", 0) == 0)
      return next_step();
    if (std::regex_match(question, m, kWhere)) return goal_reply(m[1], m[3]);
    ADD_FAILURE() << "the teacher does not know what the agent asks: " << question;
    return "";
  }

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
    if (subtask_ >= subtasks.size()) return "That's all.";
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

  std::string goal_reply(const std::string& thing, const std::string& place_words) {
    const World& w = scenario_.world;
    const IntentEntry* wanted = nullptr;
    for (const Subtask& s : scenario_.task.subtasks) {
      if (language::spoken_places(w, s.places) != "the " + place_words) continue;
      for (const IntentEntry& e : scenario_.intent)
        if (e.subtask == s.verb && language::spoken_category(e.category) == thing) wanted = &e;
    }
    if (wanted == nullptr) {
      ADD_FAILURE() << "the teacher wants nothing for the " << thing << " " << place_words;
      return "";
    }
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
  std::size_t subtask_ = 0;
  int next_form_ = 0;
};

struct Taught {
  int exit_code = -1;
  int turns = 0;
  std::string screen;
};

Taught teach_at_terminal(const Scenario& scenario, const std::string& scenario_path) {
  EverydayTeacher teacher(scenario);
  testing::Terminal terminal({APPRENTICE_BINARY, "teach", "--scenario", scenario_path});
  Taught taught;
  size_t from = 0;
  // A bound only so that a broken agent cannot hang the test.
  for (int guard = 0; guard < 4 * teacher.floor(); ++guard) {
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

TEST(EverydayTeacher, TeachesTheKitchenAtTheTerminal) { expect_taught_within_floor("data/scenarios/tidy-kitchen.yaml"); }

TEST(EverydayTeacher, TeachesAnOfficeAtTheTerminal) { expect_taught_within_floor("tests/agent/data/tidy-office.yaml"); }

}  // namespace
}  // namespace apprentice
