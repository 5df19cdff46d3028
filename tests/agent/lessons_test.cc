// The teacher's lessons and undo (agent/lessons.h), without a dialogue or
// an agent: a lesson keeps the progress and the knowledge as they were, and
// undoing it reverts its writes to the store, latest first, and cuts the
// records that only grow back to their sizes then.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "agent/lessons.h"
#include "common/scenarios.h"
#include "common/scratch.h"
#include "knowledge/store.h"

namespace apprentice {
namespace {

using ::testing::ElementsAre;

class LessonsTest : public ::testing::Test {
 protected:
  Scenario scenario_ = testing::shipped_scenario("tidy-kitchen");
  testing::ScratchDir dir_{true};
  std::string path_ = (dir_ / "knowledge.sqlite").string();

  static GoalKnowledge goal(const std::string& kind, const std::string& place) {
    GoalKnowledge g;
    g.key = GoalKey{"tidy kitchen", "clear", kind, "table"};
    g.literals = {GoalTemplateLiteral{"in", true, {GoalTemplateArgument{true, "", {}}, GoalTemplateArgument{false, place, {}}}}};
    g.provenance = Provenance{kind + "1 (" + kind + ")", "instructor"};
    return g;
  }
  Knowledge stored() const {
    auto loaded = load_knowledge_read_only(path_, *scenario_.world.domain);
    EXPECT_TRUE(loaded.has_value()) << loaded.error().describe();
    return loaded ? std::move(*loaded) : Knowledge{};
  }
};

TEST_F(LessonsTest, UndoRevertsTheLastLessonsWritesAndPutsTheProgressBack) {
  auto store = KnowledgeStore::open(path_);
  ASSERT_TRUE(store.has_value()) << store.error().describe();
  Lessons lessons(&*store, *scenario_.world.domain);
  teaching::Curriculum progress;
  Knowledge knowledge;

  // Lesson 1: the task's name; the ketchup's goal.
  lessons.begin("Tidy kitchen.", progress, knowledge, scenario_.world.state, 0);
  progress.task = TaskKnowledge{"tidy kitchen", {LearnedSubtask{"clear", "on", "table"}}};
  ASSERT_TRUE(lessons.learn_task(knowledge, progress.task));
  ASSERT_TRUE(lessons.learn_goal(knowledge, goal("ketchup", "fridge")));
  // One call each: the knowledge has what the store has.
  EXPECT_THAT(knowledge.goals.all(), ElementsAre(goal("ketchup", "fridge")));
  ASSERT_EQ(knowledge.tasks.size(), 1u);
  EXPECT_EQ(stored().tasks.size(), 1u);
  progress.evaluated.insert(7);
  progress.evaluated_order.push_back(7);
  progress.objects.push_back(ObjectReport{});
  progress.goals_learned = 1;

  // Lesson 2: the ketchup goes in the cupboard instead.
  lessons.begin("the ketchup goes in the cupboard", progress, knowledge, scenario_.world.state, 4);
  ASSERT_TRUE(lessons.learn_goal(knowledge, goal("ketchup", "cupboard")));
  EXPECT_THAT(knowledge.goals.all(), ElementsAre(goal("ketchup", "cupboard")));
  progress.evaluated.insert(9);
  progress.evaluated_order.push_back(9);
  progress.objects.push_back(ObjectReport{});
  progress.goals_learned = 2;
  ASSERT_EQ(stored().goals.all().front(), goal("ketchup", "cupboard"));
  ASSERT_NE(lessons.last_reply(), nullptr);
  EXPECT_EQ(*lessons.last_reply(), "the ketchup goes in the cupboard");

  auto undone = lessons.undo(progress, knowledge);
  ASSERT_TRUE(undone.has_value()) << undone.error().describe();
  ASSERT_TRUE(undone->has_value());
  EXPECT_EQ((*undone)->reply, "the ketchup goes in the cupboard");
  EXPECT_EQ((*undone)->history, 4u);
  // The store and the knowledge have the fridge again; the progress is
  // that of before lesson 2, its records cut back.
  EXPECT_THAT(stored().goals.all(), ElementsAre(goal("ketchup", "fridge")));
  EXPECT_THAT(knowledge.goals.all(), ElementsAre(goal("ketchup", "fridge")));
  EXPECT_EQ(progress.goals_learned, 1);
  EXPECT_THAT(progress.evaluated_order, ElementsAre(7));
  EXPECT_EQ(progress.evaluated.count(9), 0u);
  EXPECT_EQ(progress.objects.size(), 1u);

  // Lesson 1 undone: nothing is left in the store; then nothing to undo.
  ASSERT_TRUE(lessons.undo(progress, knowledge).has_value());
  EXPECT_TRUE(stored().goals.all().empty());
  EXPECT_TRUE(stored().tasks.empty());
  EXPECT_TRUE(progress.task.name.empty());
  EXPECT_TRUE(progress.objects.empty());
  auto none = lessons.undo(progress, knowledge);
  ASSERT_TRUE(none.has_value());
  EXPECT_FALSE(none->has_value());
  EXPECT_EQ(lessons.last_reply(), nullptr);
}

TEST_F(LessonsTest, APersonsRuleSaidInALessonIsNamedByItsUndo) {
  Lessons lessons(nullptr, *scenario_.world.domain);
  teaching::Curriculum progress;
  Knowledge knowledge;
  knowledge.goals.add(goal("ketchup", "fridge"));
  ClassRule rule;
  rule.class_name = "fruit";
  rule.source = RuleSource::kPerson;
  knowledge.forgotten_rules.add(rule);
  lessons.begin("fruit goes in the bowl", progress, knowledge, scenario_.world.state, 0);
  // Without a store nothing is written, but a person's rule is still kept
  // in the lesson, so that undo can name it.
  ASSERT_TRUE(lessons.learn_class_rule(knowledge, rule));
  // Said again, it is no longer forgotten.
  EXPECT_FALSE(knowledge.forgot(rule));
  EXPECT_NE(knowledge.class_rules.find(rule), nullptr);
  auto undone = lessons.undo(progress, knowledge);
  ASSERT_TRUE(undone.has_value() && undone->has_value());
  EXPECT_THAT(knowledge.goals.all(), ElementsAre(goal("ketchup", "fridge")));
  EXPECT_EQ(knowledge.class_rules.find(rule), nullptr);
  EXPECT_TRUE(knowledge.forgot(rule)) << "forgotten again, as before the lesson";
  ASSERT_EQ((*undone)->class_rules.size(), 1u);
  EXPECT_EQ((*undone)->class_rules.front().class_name, "fruit");
}

TEST_F(LessonsTest, AGoalForgottenComesBackWithTheUndoRightAfter) {
  auto store = KnowledgeStore::open(path_);
  ASSERT_TRUE(store.has_value()) << store.error().describe();
  Lessons lessons(&*store, *scenario_.world.domain);
  teaching::Curriculum progress;
  Knowledge knowledge;
  lessons.begin("fridge", progress, knowledge, scenario_.world.state, 0);
  ASSERT_TRUE(lessons.learn_goal(knowledge, goal("ketchup", "fridge")));
  // "forget ketchup", a lesson of its own.
  lessons.begin("forget ketchup", progress, knowledge, scenario_.world.state, 4);
  ASSERT_TRUE(lessons.forget_goal(knowledge, goal("ketchup", "fridge").key));
  EXPECT_TRUE(knowledge.goals.all().empty());
  EXPECT_TRUE(stored().goals.all().empty());
  // Forgetting what is not known writes nothing.
  ASSERT_TRUE(lessons.forget_goal(knowledge, goal("mustard", "fridge").key));

  auto undone = lessons.undo(progress, knowledge);
  ASSERT_TRUE(undone.has_value() && undone->has_value());
  ASSERT_EQ((*undone)->remembered.size(), 1u);
  EXPECT_EQ((*undone)->remembered.front().category, "ketchup");
  EXPECT_THAT(knowledge.goals.all(), ElementsAre(goal("ketchup", "fridge")));
  EXPECT_THAT(stored().goals.all(), ElementsAre(goal("ketchup", "fridge")));
  // The lesson that taught it, undone next: gone from both.
  auto first = lessons.undo(progress, knowledge);
  ASSERT_TRUE(first.has_value() && first->has_value());
  EXPECT_TRUE((*first)->remembered.empty());
  EXPECT_TRUE(knowledge.goals.all().empty());
  EXPECT_TRUE(stored().goals.all().empty());
}

}  // namespace
}  // namespace apprentice
