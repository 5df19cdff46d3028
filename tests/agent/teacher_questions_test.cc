// The teacher's "why?" (agent/teacher_questions.h), answered from a world,
// the goals known and how far the teaching has come, without a session or
// a teacher: about a thing named, a door named, the agent's own decision,
// or the last lesson.
#include "agent/teacher_questions.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/paths.h"
#include "world/scenario.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

constexpr const char* kMudroom = R"(name: mudroom
domain: data/domains/kitchen.pddl
location: mudroom
places:
  - {category: bench, kind: surface}
  - {category: closet, kind: receptacle, door: open}
  - {category: cabinet, kind: receptacle, door: closed}
  - {category: basket, kind: receptacle, properties: [left]}
  - {category: basket, kind: receptacle, properties: [right]}
objects:
  - {category: glove, at: basket2}
  - {category: umbrella, at: closet1}
  - {category: scarf, at: bench1}
  - {category: mitten, at: basket1}
)";

class TeacherQuestions : public ::testing::Test {
 protected:
  void SetUp() override {
    auto scenario = parse_scenario(kMudroom, apprentice::testing::source_path("mudroom.yaml"));
    ASSERT_TRUE(scenario) << scenario.error().describe();
    scenario_ = std::move(*scenario);
    progress_.task.name = "tidy mudroom";
  }
  const World& world() const { return scenario_.world; }
  ObjectId id(const char* name) const { return *world().universe->find(name); }
  // Learns that `thing` goes in `place`, from `source`; `door` adds the
  // place's door state ("closed" or "open").
  void learn(const char* thing, const char* place, const std::string& source, const char* door = nullptr) {
    const Vocabulary& v = world().vocabulary;
    std::vector<Literal> literals{Literal{Fact(v.in, {id(thing), id(place)}), true}};
    if (door != nullptr) literals.push_back(Literal{Fact(v.closed, {id(place)}), std::string(door) == "closed"});
    GoalKey key{"tidy mudroom", "clear", world().universe->info(id(thing)).category, "bench"};
    auto known = generalize_goal(world(), key, id(thing), Goal(literals), Provenance{thing, source});
    ASSERT_TRUE(known) << known.error().describe();
    goals_.add(std::move(*known));
  }
  // `thing` was dealt with, given `goal` by `source`, said back with `because`.
  void dealt_with(const char* thing, const char* goal, GoalSource source, const char* because) {
    ObjectReport dealt;
    dealt.object = thing;
    dealt.goal = goal;
    dealt.goal_source = source;
    dealt.because = because;
    progress_.objects.push_back(dealt);
  }
  std::string why(std::vector<ObjectId> named) const {
    return answer_why(TeachingSoFar{world(), goals_, progress_, last_reply_.empty() ? nullptr : &last_reply_}, named);
  }

  Scenario scenario_;
  GoalMemory goals_;
  teaching::Curriculum progress_;
  std::string last_reply_;
};

TEST_F(TeacherQuestions, AThingNamedIsAnsweredByItsGoalAndWhereItCameFrom) {
  learn("glove1", "basket2", "instructor: \"gloves in the right one\"");
  EXPECT_EQ(why({id("glove1"), id("basket2")}),
            "The glove goes in the right basket: I learned that from the instructor, who said \"gloves in the right "
            "one\". If that was wrong, tell me where it goes.");
  learn("mitten1", "basket1", "decision: mittens go in the left basket, as said: \"mittens left\"");
  EXPECT_THAT(why({id("mitten1")}), StartsWith("Because I decided where the mitten goes from weighing what I knew"));
}

// "why did you put the glove in the left basket?" and "why'd you put the
// glove away before?", once the teacher has said it goes elsewhere: how it
// came to go there when it was dealt with (its report), and where it goes
// now; not the goal of now, which the teacher just gave.
// "why did you ask if the blanket goes with clean diapers?", found by a
// fresh user, was answered with where the blanket goes now. A question the
// agent asked is answered with what it proposed and the evidence it
// showed: about the thing named, else a thing of its kind, else the yes/no
// whose evidence names what was said ("why do you keep asking about
// scarves"), else the last one; a thing never asked about is answered as
// "why" is.
TEST_F(TeacherQuestions, AQuestionTheAgentAskedIsAnsweredByItsEvidence) {
  const Vocabulary& v = world().vocabulary;
  std::vector<ProposalAsked> asked{
      {id("umbrella1"), Goal({Literal{Fact(v.in, {id("umbrella1"), id("cabinet1")}), true}}), "with scarves, as you said"},
      {id("scarf1"), Goal({Literal{Fact(v.in, {id("scarf1"), id("basket1")}), true}}), "like the mitten"}};
  auto why_asked = [&](std::vector<ObjectId> named) {
    return answer_why(TeachingSoFar{world(), goals_, progress_, nullptr, asked}, named, WhyAbout::kAsking);
  };
  EXPECT_EQ(why_asked({id("umbrella1")}),
            "I asked whether the umbrella goes in the cabinet, with scarves, as you said: it seemed likely, but not "
            "enough to do it without asking.");
  EXPECT_THAT(why_asked({}), StartsWith("I asked whether the scarf goes in the left basket, like the mitten:"));
  // Since then taught otherwise: where it goes now is said too.
  learn("scarf1", "closet1", "instructor: \"closet\"");
  EXPECT_THAT(why_asked({id("scarf1")}), HasSubstr("without asking. Now the scarf goes in the closet."));
  // Never asked about the glove: its own why.
  learn("glove1", "basket2", "instructor: \"gloves in the right one\"");
  EXPECT_THAT(why_asked({id("glove1")}), StartsWith("The glove goes in the right basket: I learned that"));
  // Nothing asked yet: as "why" is.
  EXPECT_EQ(answer_why(TeachingSoFar{world(), goals_, progress_, nullptr}, std::vector<ObjectId>{id("glove1")},
                       WhyAbout::kAsking),
            why({id("glove1")}));
}

TEST_F(TeacherQuestions, AnEarlierPlacementIsAnsweredByHowItWasDecided) {
  dealt_with("glove1", "(in glove1 basket1)", GoalSource::kLikeness, "like the mitten");
  learn("glove1", "basket2", "instructor: \"no the glove goes in the right one\" (a correction)");
  const std::string earlier =
      "Earlier I decided the glove goes in the left basket, like the mitten; since then, the glove goes in the right "
      "basket.";
  EXPECT_EQ(why({id("glove1"), id("basket1")}), earlier);
  EXPECT_EQ(answer_why(TeachingSoFar{world(), goals_, progress_, nullptr}, std::vector<ObjectId>{id("glove1")}, WhyAbout::kEarlier),
            earlier);
  // Asked about where it goes now, or with no word of before: its goal now.
  EXPECT_THAT(why({id("glove1"), id("basket2")}), StartsWith("The glove goes in the right basket: I learned that"));
  EXPECT_THAT(why({id("glove1")}), StartsWith("The glove goes in the right basket: I learned that"));
  // Without the words said then, how it was decided.
  progress_.objects.back().because.clear();
  EXPECT_THAT(why({id("glove1"), id("basket1")}), HasSubstr("left basket, because it is like things you taught me;"));
}

// "why did you put the towel on the hook before?", of a clean and a dirty
// towel, and "ok but why the hook at first" (a fresh user, stop 40): the
// thing that went to a place named, told apart by what was done, and a
// place alone asked about before. Both were answered with the goal of now,
// or the last reply.
TEST_F(TeacherQuestions, BeforeIsAboutTheThingThatWentThere) {
  dealt_with("glove1", "(in glove1 basket1)", GoalSource::kInstructor, "as you told me then");
  learn("glove1", "basket2", "instructor: \"no the glove goes in the right one\" (a correction)");
  const std::string earlier = "Earlier I decided the glove goes in the left basket, as you told me then; since then, "
                              "the glove goes in the right basket.";
  const TeachingSoFar so_far{world(), goals_, progress_, nullptr};
  // The baskets alone, both named by "the basket".
  EXPECT_EQ(answer_why(so_far, std::vector<ObjectId>{id("basket1"), id("basket2")}, WhyAbout::kEarlier), earlier);
  // The mitten named with the left basket: no mitten went there, but the
  // mitten is no look-alike of the glove either.
  EXPECT_NE(answer_why(so_far, std::vector<ObjectId>{id("mitten1"), id("basket1")}, WhyAbout::kEarlier), earlier);
}

TEST_F(TeacherQuestions, ADoorNamedIsAnsweredByWhatLeftItOpenOrTheNorm) {
  // A closed door: the norm.
  EXPECT_EQ(why({id("cabinet1")}), "The cabinet is closed: I close what I open.");
  // An open one, with no goal that leaves it so, then with the umbrella's.
  EXPECT_EQ(why({id("closet1")}),
            "The closet is open: nothing I learned says to close it. Say \"close the closet\" to close it now.");
  learn("umbrella1", "closet1", "instructor: \"umbrella in the closet, leave it open so it can dry\"", "open");
  EXPECT_THAT(why({id("closet1")}), StartsWith("The closet is open because the umbrella goes there with it left "
                                               "open; I learned that from the instructor, who said"));
}

TEST_F(TeacherQuestions, WithNothingNamedTheLastLessonOrNothingYet) {
  EXPECT_EQ(why({}), "I have only done what I already knew; you have not told me anything yet this session.");
  last_reply_ = "scarf on the bench";
  EXPECT_THAT(why({}), HasSubstr("Because of what you told me last: \"scarf on the bench\"."));
  // A thing named with no goal known falls back the same way.
  EXPECT_THAT(why({id("scarf1")}), HasSubstr("Because of what you told me last"));
  // A thing the teacher said to leave.
  progress_.left_by_teacher.push_back(id("scarf1"));
  EXPECT_EQ(why({id("scarf1")}), "You told me to leave the scarf where it is.");
}

// "what's left?": before a task, none; within a part, what is still on its
// places but the thing being worked on; between parts, the parts done and
// every thing not dealt with, where it is.
TEST_F(TeacherQuestions, WhatsLeftFollowsHowFarTheTeachingHasCome) {
  const TeachingSoFar so_far{world(), goals_, progress_};
  teaching::Curriculum none;
  EXPECT_EQ(answer_whats_left(TeachingSoFar{world(), goals_, none}), "I have not been given a task yet.");
  progress_.current = teaching::Current{"clear", "on", {id("bench1")}};
  EXPECT_EQ(answer_whats_left(so_far), "Still on the bench: the scarf.");
  progress_.in_progress.emplace();
  progress_.in_progress->object = id("scarf1");
  EXPECT_EQ(answer_whats_left(so_far), "Nothing else is left on the bench.");
  progress_.in_progress.reset();
  progress_.evaluated.insert(id("scarf1"));
  progress_.task.subtasks.push_back(LearnedSubtask{"clear", "on", "bench"});
  progress_.current.reset();
  const std::string between = answer_whats_left(so_far);
  EXPECT_THAT(between, HasSubstr("bench")) << between;
  EXPECT_THAT(between, HasSubstr("glove")) << between;
  EXPECT_THAT(between, Not(HasSubstr("scarf"))) << between;
}

// "status": what it sees, then the part under way and the counts.
TEST_F(TeacherQuestions, StatusSaysWhatItSeesAndWhatItIsDoing) {
  progress_.current = teaching::Current{"clear", "on", {id("bench1")}};
  learn("glove1", "basket2", "instructor: \"right basket\"");
  const std::vector<std::string> lines =
      answer_status(TeachingSoFar{world(), goals_, progress_}, id("scarf1"), StatusCounts{4, 7});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_THAT(lines[0], HasSubstr("scarf")) << lines[0];
  EXPECT_THAT(lines[1], HasSubstr("scarf")) << lines[1];
  EXPECT_THAT(lines[1], HasSubstr("1 goal")) << lines[1];
  EXPECT_THAT(lines[1], HasSubstr("4 rules")) << lines[1];
  EXPECT_THAT(lines[1], HasSubstr("7 instructions")) << lines[1];
}

// "forget gloves" names the glove's kind by its plural, and "forget
// baskets" none; a kind named by the last word of its name counts too.
TEST_F(TeacherQuestions, KindsKnownAreNamedByPluralsAndLastWords) {
  learn("glove1", "basket2", "instructor: \"right basket\"");
  EXPECT_EQ(kinds_known_by(goals_, "gloves"), std::vector<std::string>{"glove"});
  EXPECT_EQ(kinds_known_by(goals_, "the glove"), std::vector<std::string>{"glove"});
  EXPECT_TRUE(kinds_known_by(goals_, "baskets").empty());
  EXPECT_TRUE(kinds_known_by(goals_, "").empty());
  GoalMemory more;
  for (const char* kind : {"ceramic-plate", "paper-plate", "mug"})
    more.add(GoalKnowledge{GoalKey{"t", "clear", kind, "table"}, {}, {}});
  EXPECT_EQ(kinds_known_by(more, "plates"), (std::vector<std::string>{"ceramic-plate", "paper-plate"}));
}

}  // namespace
}  // namespace apprentice
