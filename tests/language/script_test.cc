// Every sentence of the STARS instructor script parses and grounds in
// tidy-kitchen-35.yaml to what the instructor intends, and the generators
// say each of those sentences exactly as the script does.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "language/generation.h"
#include "language/parser.h"
#include "language/reply.h"
#include "language_fixtures.h"
#include "util/text.h"

namespace apprentice::language {
namespace {

using testing::grounder;
using testing::kitchen35;
using testing::shared_path;
using testing::world35;

std::vector<std::string> script_lines() {
  std::ifstream in(shared_path("data/stars-tidy-kitchen/instructor_script.txt"));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // the file has CRLF line ends
    if (!line.empty()) lines.push_back(line);
  }
  return lines;
}

class InstructorScript : public ::testing::Test {
 protected:
  void SetUp() override {
    APPRENTICE_REQUIRE_SHARED(shared_path("data/stars-tidy-kitchen/instructor_script.txt"));
    lines_ = script_lines();
    ASSERT_FALSE(lines_.empty()) << "instructor_script.txt is empty";
  }
  std::vector<std::string> lines_;
};

// Walks the script as the agent would hear it: the current subtask's place
// decides which object a goal description is about (two mugs, two
// ceramic plates, ...), and the goal must be the scenario's intent.
TEST_F(InstructorScript, EverySentenceGroundsToTheIntendedMeaning) {
  const Scenario& scenario = kitchen35();
  const World& world = world35();
  std::string subtask;
  std::optional<ObjectId> place;
  std::size_t goals = 0;
  for (const std::string& line : lines_) {
    SCOPED_TRACE(line);
    auto form = parse(line);
    ASSERT_TRUE(form.has_value()) << form.error().message;
    std::optional<ObjectId> object;
    if (const auto* g = std::get_if<GoalDescription>(&*form)) {
      ASSERT_TRUE(g->category.has_value());
      ASSERT_TRUE(place.has_value()) << "a goal before any subtask";
      for (ObjectId id : world.universe->with_category(g->category->text()))
        if (world.state.holds(Fact(world.vocabulary.on, {id, *place})) ||
            world.state.holds(Fact(world.vocabulary.in, {id, *place})))
          object = id;
      ASSERT_TRUE(object.has_value()) << "no " << g->category->text() << " at the subtask's place";
    }
    Interpretation in = grounder().ground(*form, world, object);
    ASSERT_TRUE(in.ok()) << format_grounding(world, in.result);
    if (const auto* step = std::get_if<TaskStep>(&in.result)) {
      if (step->kind == TaskStep::Kind::kSubtask) {
        subtask = step->name;
        place = step->place;
        const Subtask* expected = nullptr;
        for (const Subtask& s : scenario.task.subtasks)
          if (s.verb == subtask) expected = &s;
        ASSERT_NE(expected, nullptr) << "subtask " << subtask;
        EXPECT_EQ(std::vector<ObjectId>{*step->place}, expected->places);
      }
      if (step->kind == TaskStep::Kind::kRepeatWhile) place = step->place;
      continue;
    }
    const Goal* goal = std::get_if<Goal>(&in.result);
    ASSERT_NE(goal, nullptr) << format_grounding(world, in.result);
    auto intended = scenario.intended_goal(subtask, *object);
    ASSERT_TRUE(intended.has_value()) << subtask << " " << world.universe->name(*object);
    EXPECT_EQ(format_goal(*world.domain, *world.universe, *goal),
              format_goal(*world.domain, *world.universe, *intended));
    ++goals;
  }
  EXPECT_EQ(goals, 35u);
}

// read_reply, at the question each line answers, gives every line the
// meaning the grammar gives it.
TEST_F(InstructorScript, EveryLineReadsAsTheGrammarReadsIt) {
  const World& world = world35();
  std::optional<ObjectId> place;
  bool after_goal = false;
  for (const std::string& line : lines_) {
    SCOPED_TRACE(line);
    auto form = parse(line);
    ASSERT_TRUE(form.has_value());
    ReplyContext context;
    std::string expected;
    if (std::holds_alternative<Answer>(*form)) {
      context.asked = Asked::kYesNo;
      expected = std::get<Answer>(*form).yes ? "yes" : "no";
    } else if (const auto* task = std::get_if<TaskName>(&*form)) {
      context.asked = Asked::kTask;
      expected = "task " + join(task->words, " ");
    } else if (const auto* goal = std::get_if<GoalDescription>(&*form)) {
      context.asked = Asked::kGoal;
      for (ObjectId id : world.universe->with_category(goal->category->text()))
        if (world.state.holds(Fact(world.vocabulary.on, {id, *place})) ||
            world.state.holds(Fact(world.vocabulary.in, {id, *place})))
          context.object = id;
      ASSERT_TRUE(context.object.has_value());
      expected = format_grounding(world, grounder().ground(*form, world, context.object).result);
      after_goal = true;
    } else {
      context.asked = after_goal ? Asked::kSubtaskEnd : Asked::kTaskStep;
      after_goal = false;
      Interpretation in = grounder().ground(*form, world, std::nullopt);
      const auto& step = std::get<TaskStep>(in.result);
      if (step.place) place = step.place;
      std::string where = step.place ? std::string(to_string(step.relation)) + " " + world.universe->name(*step.place) : "";
      switch (step.kind) {
        case TaskStep::Kind::kRepeatWhile: expected = "loop " + where; break;
        case TaskStep::Kind::kSubtask: expected = "subtask " + step.name + " " + where; break;
        case TaskStep::Kind::kDone: expected = "finished"; break;
        case TaskStep::Kind::kRepeat: expected = "proceed"; break;
        default: FAIL() << "unexpected step";
      }
    }
    EXPECT_EQ(format_reply(world, read_reply(grounder(), world, context, line)), expected);
  }
}

// The simulated instructor speaks with the generators; they must say the
// script's sentences word for word.
TEST_F(InstructorScript, GeneratorsSayTheScriptsSentences) {
  const Scenario& scenario = kitchen35();
  const World& world = world35();
  std::vector<std::string> said{say_answer(true), say_answer(false), say_task_name(scenario.task.name)};
  for (std::size_t i = 0; i < scenario.task.subtasks.size(); ++i) {
    const Subtask& s = scenario.task.subtasks[i];
    if (i > 0) said.push_back(say_repeat());
    said.push_back(say_repeat_while(world, s.places));
    said.push_back(say_subtask(s.verb, world, s.places));
    for (const IntentEntry& entry : scenario.intent) {
      if (entry.subtask != s.verb) continue;
      std::optional<ObjectId> object;
      for (ObjectId id : world.universe->with_category(entry.category))
        if (scenario.subtask_of(id) == &s) object = id;
      ASSERT_TRUE(object.has_value()) << entry.category;
      said.push_back(describe_goal_instruction(world, *object, *scenario.intended_goal(s.verb, *object)));
    }
    said.push_back(say_done());
  }
  said.push_back(say_repeat());
  said.push_back(say_done());
  // The script lists each subtask's goals in alphabetical order of category.
  auto sorted_goals = [](std::vector<std::string> lines) {
    auto begin = lines.begin();
    while (begin != lines.end()) {
      auto first = std::find_if(begin, lines.end(), [](const std::string& l) { return l.starts_with("If "); });
      auto last = std::find_if(first, lines.end(), [](const std::string& l) { return !l.starts_with("If "); });
      std::sort(first, last);
      begin = last;
    }
    return lines;
  };
  EXPECT_EQ(sorted_goals(said), sorted_goals(lines_));
}

}  // namespace
}  // namespace apprentice::language
