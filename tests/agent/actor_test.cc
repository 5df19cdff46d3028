// Acting toward one goal (agent/actor.h), on the paper's kitchen, with a
// help of the test's own in place of the session: the agent's own search
// first, then the LLM, then the teacher; the bound on the agent's own
// actions; advice that cannot be carried out; and the rules an episode
// teaches.
#include "agent/actor.h"

#include <gtest/gtest.h>

#include <deque>

#include "agent_fixtures.h"
#include "world/action.h"
#include "world/goal.h"

namespace apprentice {
namespace {

// Answers the actor as the session would, from scripts: the LLM's and the
// teacher's next actions in order (an empty script: nothing to say), and
// carries actions out by applying them to the world when they apply.
class ScriptedHelp : public ActingHelp {
 public:
  explicit ScriptedHelp(World& world) : world_(world) {}

  Flow<std::optional<Action>> llm_action(teaching::InProgress&, std::string& advice) override {
    ++llm_asked;
    return next_of(llm, advice);
  }
  Flow<std::optional<Action>> instructor_action(teaching::InProgress& work, std::string& advice) override {
    ++instructor_asked;
    auto next = next_of(instructor, advice);
    if (next && !*next) work.report.note = "left as it is, as the instructor said";
    return next;
  }
  Status carry_out(const Action& action) override {
    if (!is_applicable(*world_.domain, world_.state, action))
      return tl::unexpected(Error{ErrorCode::kInvalidInput, "not applicable"});
    world_.state = apply(*world_.domain, world_.state, action);
    return {};
  }
  void could_not_do(const Action& action) override { refused.push_back(action); }

  std::deque<Action> llm;
  std::deque<Action> instructor;
  int llm_asked = 0;
  int instructor_asked = 0;
  std::vector<Action> refused;

 private:
  Flow<std::optional<Action>> next_of(std::deque<Action>& script, std::string& advice) {
    if (script.empty()) return std::optional<Action>();
    Action next = script.front();
    script.pop_front();
    advice = format_action(*world_.domain, *world_.universe, next);
    return std::optional<Action>(next);
  }
  World& world_;
};

class ActorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    kitchen_ = testing::load_or_die(testing::source_path("data/scenarios/tidy-kitchen.yaml"));
    auto goal = parse_goal(*world().domain, *world().universe, "(and (in ketchup1 fridge1) (closed fridge1))");
    ASSERT_TRUE(goal) << goal.error().message;
    work_.object = *world().universe->find("ketchup1");
    work_.goal = *goal;
    work_.start = world().state;
  }
  World& world() { return kitchen_.world; }
  Action action(std::string_view text) {
    auto parsed = parse_action(*world().domain, *world().universe, text);
    EXPECT_TRUE(parsed) << text;
    return *parsed;
  }
  std::deque<Action> the_plan() {
    return {action("(open fridge1)"), action("(pick-up ketchup1 table1)"), action("(put-in ketchup1 fridge1)"),
            action("(close fridge1)")};
  }
  // Whom the actor may ask: the LLM and the teacher as given, ten actions
  // of its own at most, and search to `search_depth` (0: none).
  static ActingPolicy policy(bool llm, bool instructor, int search_depth = 0) {
    ActingPolicy made;
    made.own.search_depth = search_depth;
    made.ask_llm = llm;
    made.ask_instructor = instructor;
    made.max_actions = 10;
    return made;
  }
  Scenario kitchen_;
  teaching::InProgress work_;
};

TEST_F(ActorTest, SearchAloneAchievesTheGoalAndAsksNoOne) {
  ScriptedHelp help(world());
  ActingPolicy policy = ActorTest::policy(true, true, 4);
  Actor actor;
  auto acted = actor.achieve(world(), work_, "clear", policy, help);
  ASSERT_TRUE(acted);
  EXPECT_EQ(*acted, Acted::kAchieved);
  EXPECT_TRUE(work_.goal.satisfied_by(world().state));
  EXPECT_EQ(work_.actions.size(), 4u);
  for (const std::string& source : work_.sources) EXPECT_EQ(source, "search");
  EXPECT_EQ(work_.llm_steps.front(), "Open fridge");
  EXPECT_EQ(help.llm_asked + help.instructor_asked, 0);
  EXPECT_EQ(actor.counts().actions_executed, 4);
  EXPECT_EQ(actor.counts().searches, 1) << "the plan found is carried out without searching again";
  EXPECT_GT(actor.counts().search_nodes, 0u);
}

TEST_F(ActorTest, WithNoWayOfItsOwnTheLlmComesBeforeTheTeacher) {
  ScriptedHelp help(world());
  help.llm = {action("(open fridge1)"), action("(pick-up ketchup1 table1)")};
  help.instructor = {action("(put-in ketchup1 fridge1)"), action("(close fridge1)")};
  ActingPolicy policy = ActorTest::policy(true, true);
  Actor actor;
  auto acted = actor.achieve(world(), work_, "clear", policy, help);
  ASSERT_TRUE(acted);
  EXPECT_EQ(*acted, Acted::kAchieved);
  ASSERT_EQ(work_.sources.size(), 4u);
  EXPECT_EQ(work_.sources[0], "llm: (open fridge1)");
  EXPECT_EQ(work_.sources[1], "llm: (pick-up ketchup1 table1)");
  EXPECT_EQ(work_.sources[2], "instructor: (put-in ketchup1 fridge1)");
  EXPECT_EQ(work_.sources[3], "instructor: (close fridge1)");
  EXPECT_EQ(help.llm_asked, 4) << "the LLM is asked each time before the teacher";
  EXPECT_EQ(actor.counts().searches, 0);
}

TEST_F(ActorTest, AloneWithNoWayTheGoalIsNotReached) {
  ScriptedHelp help(world());
  Actor actor;
  ActingPolicy policy = ActorTest::policy(false, false);
  auto acted = actor.achieve(world(), work_, "clear", policy, help);
  ASSERT_TRUE(acted);
  EXPECT_EQ(*acted, Acted::kNoWay);
  EXPECT_EQ(work_.report.note, "no way to reach the goal");
  EXPECT_TRUE(work_.actions.empty());
}

TEST_F(ActorTest, PastTheBoundAProgramGivesUpAndAPersonIsAskedForEachAction) {
  ActingPolicy policy;
  policy.own.search_depth = 4;
  policy.ask_instructor = true;
  policy.max_actions = 2;
  {
    ScriptedHelp help(world());
    Actor actor;
    auto acted = actor.achieve(world(), work_, "clear", policy, help);
    ASSERT_TRUE(acted);
    EXPECT_EQ(*acted, Acted::kGaveUp);
    EXPECT_EQ(work_.report.note, "gave up after 2 actions");
    EXPECT_EQ(work_.actions.size(), 2u);
  }
  // The same bound with a person teaching: the two actions search found,
  // then only the person's.
  world().state = work_.start;
  work_ = teaching::InProgress{work_.object, work_.goal, {}, work_.start, {}, {}, {}};
  policy.ask_only_teacher_past_bound = true;
  ScriptedHelp help(world());
  std::deque<Action> plan = the_plan();
  help.instructor.assign(plan.begin() + 2, plan.end());
  Actor actor;
  auto acted = actor.achieve(world(), work_, "clear", policy, help);
  ASSERT_TRUE(acted);
  EXPECT_EQ(*acted, Acted::kAchieved);
  ASSERT_EQ(work_.sources.size(), 4u);
  EXPECT_EQ(work_.sources[1], "search");
  EXPECT_EQ(work_.sources[2], "instructor: (put-in ketchup1 fridge1)");
  EXPECT_EQ(help.instructor_asked, 2);
}

TEST_F(ActorTest, AdviceThatCannotBeCarriedOutIsRefusedAndTheLoopGoesOn) {
  ScriptedHelp help(world());
  // Into the fridge before it is open: not applicable.
  help.llm = {action("(put-in ketchup1 fridge1)")};
  help.instructor = the_plan();
  ActingPolicy policy = ActorTest::policy(true, true);
  Actor actor;
  auto acted = actor.achieve(world(), work_, "clear", policy, help);
  ASSERT_TRUE(acted);
  EXPECT_EQ(*acted, Acted::kAchieved);
  ASSERT_EQ(help.refused.size(), 1u);
  EXPECT_EQ(format_action(*world().domain, *world().universe, help.refused.front()), "(put-in ketchup1 fridge1)");
  EXPECT_EQ(work_.actions.size(), 4u) << "what was refused is not among what was done";
  EXPECT_EQ(actor.counts().actions_executed, 4);
}

TEST_F(ActorTest, TheTeacherSayingToLeaveItEndsTheGoal) {
  ScriptedHelp help(world());
  ActingPolicy policy = ActorTest::policy(false, true);
  Actor actor;
  auto acted = actor.achieve(world(), work_, "clear", policy, help);
  ASSERT_TRUE(acted);
  EXPECT_EQ(*acted, Acted::kLeftByTeacher);
  EXPECT_EQ(work_.report.note, "left as it is, as the instructor said");
}

TEST_F(ActorTest, AnEpisodeTeachesRulesUnlessEveryActionCameFromARule) {
  ScriptedHelp help(world());
  ActingPolicy policy = ActorTest::policy(false, false, 4);
  Actor actor;
  ASSERT_TRUE(actor.achieve(world(), work_, "clear", policy, help));
  std::vector<Rule> rules = rules_taught(world(), work_, "clear", "ketchup1 (ketchup)", Generalization::kFull);
  EXPECT_EQ(rules.size(), 4u) << "one rule per action";
  teaching::InProgress from_rules = work_;
  from_rules.sources.assign(from_rules.actions.size(), "rule");
  EXPECT_TRUE(rules_taught(world(), from_rules, "clear", "ketchup1 (ketchup)", Generalization::kFull).empty());
  teaching::InProgress nothing_done = work_;
  nothing_done.actions.clear();
  nothing_done.sources.clear();
  EXPECT_TRUE(rules_taught(world(), nothing_done, "clear", "ketchup1 (ketchup)", Generalization::kFull).empty());
}

}  // namespace
}  // namespace apprentice
