// The agent's own sentences (language/narration.h) and its knowledge in
// English (agent/explanation.h): things named as people name them,
// look-alikes by their properties, pronouns where a person would use them,
// refusals that say why, and correct plurals.
#include "language/narration.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "agent/explanation.h"
#include "agent_fixtures.h"

namespace apprentice {
namespace {

using namespace language;
using testing::load_or_die;
using testing::source_path;

class Narration : public ::testing::Test {
 protected:
  ObjectId id(std::string_view name) const { return *kitchen_.world.universe->find(name); }
  Action action(const World& world, std::string_view text) const {
    auto parsed = parse_action(*world.domain, *world.universe, text);
    EXPECT_TRUE(parsed.has_value()) << text;
    return *parsed;
  }
  // The kitchen after `steps`.
  World after(std::initializer_list<const char*> steps) const {
    World world = kitchen_.world;
    for (const char* step : steps) world.state = apply(*world.domain, world.state, action(world, step));
    return world;
  }
  Goal goal(std::initializer_list<std::pair<const char*, std::vector<const char*>>> facts) const {
    std::vector<Literal> literals;
    for (const auto& [predicate, args] : facts) {
      std::vector<ObjectId> ids;
      for (const char* a : args) ids.push_back(id(a));
      literals.push_back(Literal{Fact(*kitchen_.world.domain->find_predicate(predicate), ids), true});
    }
    return Goal(std::move(literals));
  }

  Scenario kitchen_ = load_or_die(source_path("data/scenarios/tidy-kitchen.yaml"));
};

TEST_F(Narration, NamesThingsAsPeopleDo) {
  const World& w = kitchen_.world;
  EXPECT_EQ(spoken_category("glass-tumbler"), "glass tumbler");
  EXPECT_EQ(spoken_name(w, id("glass-tumbler1")), "the glass tumbler");
  EXPECT_EQ(spoken_name_and_location(w, id("glass-tumbler1")), "the glass tumbler on the table");
  EXPECT_EQ(spoken_name_and_location(w, id("mug2")), "the mug in the dish rack");
  EXPECT_EQ(spoken_location(after({"(pick-up ketchup1 table1)"}), id("ketchup1")), "in my hand");
}

TEST_F(Narration, NamesLookAlikesByTheirProperties) {
  World w = kitchen_.world;
  auto universe = std::make_shared<Universe>(*w.universe);
  Universe drawers;
  for (const ObjectInfo& info : universe->objects()) drawers.add(info);
  ObjectInfo top{"drawer2", "drawer", ObjectKind::kReceptacle, w.universe->info(id("drawer1")).type, {"top"}};
  ObjectId second = drawers.add(top);
  w.universe = std::make_shared<Universe>(drawers);
  EXPECT_EQ(spoken_name(w, second), "the top drawer");
  // A thing without properties keeps its plain name.
  EXPECT_EQ(spoken_name(w, id("drawer1")), "the drawer");
  // Without a look-alike, properties are not needed.
  World one = kitchen_.world;
  Universe single;
  for (const ObjectInfo& info : one.universe->objects()) {
    ObjectInfo copy = info;
    if (copy.id == "fridge1") copy.properties = {"big"};
    single.add(copy);
  }
  one.universe = std::make_shared<Universe>(single);
  EXPECT_EQ(spoken_name(one, id("fridge1")), "the fridge");
}

TEST_F(Narration, TasksCountsAndLists) {
  EXPECT_EQ(task_phrase("tidy kitchen"), "tidy the kitchen");
  EXPECT_EQ(task_phrase("tidy up kitchen"), "tidy up the kitchen");
  EXPECT_EQ(task_phrase("set the table"), "set the table");
  EXPECT_EQ(task_phrase("clean"), "clean");
  EXPECT_EQ(count_phrase(1, "instruction"), "1 instruction");
  EXPECT_EQ(count_phrase(0, "instruction"), "0 instructions");
  EXPECT_EQ(count_phrase(2, "box", "boxes"), "2 boxes");
  EXPECT_EQ(list_phrase({"a"}), "a");
  EXPECT_EQ(list_phrase({"a", "b"}), "a and b");
  EXPECT_EQ(list_phrase({"a", "b", "c"}), "a, b, and c");
}

TEST_F(Narration, PluralsOfKindsAndPlaces) {
  EXPECT_EQ(plural_noun("bucket"), "buckets");
  EXPECT_EQ(plural_noun("box"), "boxes");
  EXPECT_EQ(plural_noun("dish"), "dishes");
  EXPECT_EQ(plural_noun("battery"), "batteries");
  EXPECT_EQ(plural_noun("tray"), "trays");
  EXPECT_EQ(plural_noun("shelf"), "shelves");
  EXPECT_EQ(spoken_plural("glass-tumbler"), "glass tumblers");
  EXPECT_EQ(spoken_plural("crackers"), "crackers");
  // Every place of a kind is "the bags", which reads right after "nothing
  // left in" as well as after "what is in" ("every bag" did not).
  Scenario groceries = load_or_die(source_path("data/scenarios/unpack-groceries.yaml"));
  const World& g = groceries.world;
  std::vector<ObjectId> bags = g.universe->with_category("bag");
  ASSERT_EQ(bags.size(), 3u);
  EXPECT_EQ(spoken_places(g, bags), "the bags");
  std::vector<ObjectId> two(bags.begin(), bags.begin() + 2);
  EXPECT_EQ(spoken_places(g, two), spoken_name(g, bags[0]) + " and " + spoken_name(g, bags[1]));
}

TEST_F(Narration, ThingsSaidTwiceAreCounted) {
  const World& w = kitchen_.world;
  std::vector<ObjectId> things{id("ketchup1"), id("mug1"), id("mug2"), id("glass-tumbler1"), id("glass-tumbler2")};
  EXPECT_EQ(spoken_things(w, things), "the ketchup, two mugs, and two glass tumblers");
  EXPECT_EQ(spoken_things(w, std::vector<ObjectId>{id("mug2")}), "the mug");
  EXPECT_EQ(spoken_things(w, std::vector<ObjectId>{id("mug1"), id("ketchup1"), id("mug2")}), "two mugs and the ketchup");
}

TEST_F(Narration, QuestionsAreOneLineAndEndInAQuestionMark) {
  const World& w = kitchen_.world;
  EXPECT_EQ(ask_task(), "What task should I learn?");
  EXPECT_EQ(ask_task_step("tidy kitchen", true), "What should I do first to tidy the kitchen?");
  EXPECT_EQ(ask_task_step("tidy kitchen", false), "What should I do next to tidy the kitchen?");
  EXPECT_EQ(ask_goal(w, id("ketchup1")), "Where should the ketchup on the table go?");
  std::vector<ObjectId> table{id("table1")};
  EXPECT_EQ(ask_subtask_end("clear", w, table), "Is there more to clear on the table, or is that all?");
  EXPECT_EQ(ask_next_action(w, goal({{"in", {"ketchup1", "fridge1"}}, {"closed", {"fridge1"}}})),
            "What should I do next so that the ketchup is in the fridge and the fridge is closed?");
}

TEST_F(Narration, ReadsGoalsBack) {
  const World& w = kitchen_.world;
  Goal fridge = goal({{"closed", {"fridge1"}}, {"in", {"ketchup1", "fridge1"}}});
  EXPECT_EQ(read_back_goal(w, id("ketchup1"), fridge), "So the ketchup goes in the fridge, and the fridge ends closed.");
  EXPECT_EQ(announce_known_goal(w, id("ketchup1"), fridge),
            "Next, the ketchup on the table: it goes in the fridge, and the fridge ends closed.");
  EXPECT_EQ(read_back_goal(w, id("paper-plate1"), goal({{"in", {"paper-plate1", "garbage1"}}})),
            "So the paper plate goes in the garbage.");
  Literal closed{Fact(*w.domain->find_predicate("closed"), {id("fridge1")}), false};
  EXPECT_EQ(expected_fact(w, closed), "the fridge should be open");
  EXPECT_EQ(expected_fact(w, Literal{Fact(*w.domain->find_predicate("in"), {id("milk1"), id("fridge1")}), true}),
            "the milk should be in the fridge");
}

TEST_F(Narration, PluralThingsTakePluralVerbsAndPronouns) {
  const World& w = kitchen_.world;
  Goal pantry = goal({{"in", {"crackers1", "pantry1"}}, {"closed", {"pantry1"}}});
  EXPECT_EQ(read_back_goal(w, id("crackers1"), pantry), "So the crackers go in the pantry, and the pantry ends closed.");
  EXPECT_EQ(announce_known_goal(w, id("granola-bars1"), goal({{"in", {"granola-bars1", "pantry1"}}})),
            "Next, the granola bars on the counter: they go in the pantry.");
  EXPECT_EQ(ask_next_action(w, pantry), "What should I do next so that the crackers are in the pantry and the pantry is closed?");
  std::vector<Action> steps = {action(w, "(pick-up crackers1 counter1)"), action(w, "(put-on crackers1 table1)"),
                               action(w, "(pick-up crackers1 table1)")};
  EXPECT_EQ(report_actions(w, steps), "I put the crackers on the table and picked them up.");
  // "glass" and "half and half" are not plurals.
  EXPECT_EQ(read_back_goal(w, id("half-and-half1"), goal({{"in", {"half-and-half1", "fridge1"}}})),
            "So the half and half goes in the fridge.");
}

TEST_F(Narration, ReportsWhatWasDoneWithPronouns) {
  const World& w = kitchen_.world;
  std::vector<Action> steps = {action(w, "(open fridge1)"), action(w, "(pick-up ketchup1 table1)"),
                               action(w, "(put-in ketchup1 fridge1)"), action(w, "(close fridge1)")};
  EXPECT_EQ(report_actions(w, steps), "I opened the fridge, put the ketchup in it, and closed it.");
  std::vector<Action> back = {action(w, "(open fridge1)"), action(w, "(pick-up-from ketchup1 fridge1)"),
                              action(w, "(put-on ketchup1 table1)"), action(w, "(close fridge1)")};
  EXPECT_EQ(report_actions(w, back),
            "I opened the fridge, took the ketchup out of it, put it on the table, and closed the fridge.");
  EXPECT_EQ(report_actions(w, {}), "");
  EXPECT_EQ(report_actions(w, std::vector<Action>{action(w, "(pick-up ketchup1 table1)")}), "I picked up the ketchup.");
}

// Things of one name done alike in a row are said once; things of other
// names, or done otherwise, are not.
TEST_F(Narration, ThingsOfOneNameDoneAlikeAreSaidOnce) {
  Scenario shed = load_or_die(testing::source_path("tests/agent/data/fresh-users/shed.yaml"));
  const World& w = shed.world;
  std::vector<Action> both = {action(w, "(pick-up gardening-glove1 potting-bench1)"),
                              action(w, "(put-on gardening-glove1 hook2)"),
                              action(w, "(pick-up gardening-glove2 potting-bench1)"),
                              action(w, "(put-on gardening-glove2 hook2)")};
  EXPECT_EQ(report_actions(w, both), "I put two gardening gloves on the right hook.");
  std::vector<Action> apart = {action(w, "(pick-up gardening-glove1 potting-bench1)"),
                               action(w, "(put-on gardening-glove1 hook1)"),
                               action(w, "(pick-up gardening-glove2 potting-bench1)"),
                               action(w, "(put-on gardening-glove2 hook2)")};
  EXPECT_EQ(report_actions(w, apart),
            "I put the gardening glove on the left hook and put the gardening glove on the right hook.");
  std::vector<Action> others = {action(w, "(pick-up gardening-glove1 potting-bench1)"),
                                action(w, "(put-on gardening-glove1 hook2)"),
                                action(w, "(pick-up trowel1 potting-bench1)"), action(w, "(put-on trowel1 hook2)")};
  EXPECT_EQ(report_actions(w, others), "I put the gardening glove on the right hook and put the trowel on it.");
}

TEST_F(Narration, RefusalsSayWhyInPlainEnglish) {
  const World& w = kitchen_.world;
  EXPECT_EQ(refusal(w, action(w, "(put-in ketchup1 fridge1)")),
            "I am not holding the ketchup, so I cannot put it in the fridge.");
  World holding = after({"(pick-up ketchup1 table1)"});
  EXPECT_EQ(refusal(holding, action(holding, "(put-in ketchup1 fridge1)")),
            "The fridge is closed, so I cannot put the ketchup in it.");
  EXPECT_EQ(refusal(holding, action(holding, "(open fridge1)")), "I am holding the ketchup, so I cannot open the fridge.");
  EXPECT_EQ(refusal(w, action(w, "(pick-up-from ketchup1 fridge1)")),
            "The ketchup is not in the fridge, so I cannot take it out of the fridge.");
  EXPECT_EQ(refusal(w, action(w, "(open fridge1)")), "");  // it can
}

TEST_F(Narration, GoalsThatCanNeverHoldSayWhyInPlainEnglish) {
  const World& w = kitchen_.world;
  const Domain& d = *w.domain;
  auto literal = [&](const char* predicate, std::vector<const char*> args, bool positive = true) {
    std::vector<ObjectId> ids;
    for (const char* a : args) ids.push_back(id(a));
    return Literal{Fact(*d.find_predicate(predicate), ids), positive};
  };
  using Kind = UnreachableBlocker::Kind;
  using Reason = UnreachableLiteral::Reason;
  EXPECT_EQ(never_holds(w, {}), "");
  EXPECT_EQ(never_holds(w, {{literal("openable", {"garbage1"}), Reason::kNoAction, {}}}),
            "The garbage will never be something with a door: nothing I can do makes that so.");
  EXPECT_EQ(never_holds(w, {{literal("closed", {"fridge1"}, false), Reason::kNoAction, {}}}),
            "The fridge will never be open: nothing I can do undoes that.");

  UnreachableBlocker no_door{Kind::kStaticPrecondition, *d.find_action("close"), action(w, "(close garbage1)"), 0, 0,
                             literal("openable", {"garbage1"})};
  EXPECT_EQ(never_holds(w, {{literal("closed", {"garbage1"}), Reason::kNoActionApplies, {no_door}}}),
            "The garbage will never be closed: it has no door, so I cannot close it.");
  // The same reason from a second action is said once.
  UnreachableBlocker outer = no_door;
  outer.action.reset();
  EXPECT_EQ(never_holds(w, {{literal("closed", {"garbage1"}), Reason::kNoActionApplies, {no_door, outer}}}),
            "The garbage will never be closed: it has no door, so I cannot close it.");

  UnreachableBlocker wrong_type{Kind::kWrongType, *d.find_action("close"), action(w, "(close garbage1)"), id("garbage1"),
                                *d.find_type("surface-place"), {}};
  EXPECT_EQ(never_holds(w, {{literal("closed", {"garbage1"}), Reason::kNoActionApplies, {wrong_type}}}),
            "The garbage will never be closed: it is not a surface place, so I cannot close it.");

  // A chain: the precondition that blocks, then why it can never hold.
  UnreachableBlocker must_hold{Kind::kPreconditionNeverHolds, *d.find_action("put-in"),
                               action(w, "(put-in ketchup1 garbage1)"), 0, 0, literal("holding", {"ketchup1"})};
  UnreachableBlocker not_grabbable{Kind::kStaticPrecondition, *d.find_action("pick-up"), std::nullopt, 0, 0,
                                   literal("grabbable", {"ketchup1"})};
  EXPECT_EQ(never_holds(w, {{literal("in", {"ketchup1", "garbage1"}), Reason::kNoActionApplies, {must_hold}},
                            {literal("holding", {"ketchup1"}), Reason::kNoActionApplies, {not_grabbable}}}),
            "The ketchup will never be in the garbage: for that, I would have to be holding the ketchup. "
            "I will never be holding the ketchup: it cannot be picked up.");
}

TEST(Explanation, KnowledgeReadsAsEnglish) {
  TaskKnowledge task{"tidy kitchen", {{"clear", "on", "table"}, {"unload", "in", "dish-rack"}}};
  EXPECT_EQ(explain_task(task),
            "To tidy the kitchen: clear what is on the table, then unload what is in the dish rack.");
  GoalKnowledge goal{GoalKey{"tidy kitchen", "clear", "ceramic-plate", "table"},
                     {GoalTemplateLiteral{"closed", true, {GoalTemplateArgument{false, "dishwasher"}}},
                      GoalTemplateLiteral{"in", true, {GoalTemplateArgument{true, ""}, GoalTemplateArgument{false, "dishwasher"}}}},
                     Provenance{"ceramic-plate1 (ceramic-plate)", "instructor: \"...\""}};
  EXPECT_EQ(explain_goal(goal),
            "When I clear the table (to tidy the kitchen), the ceramic plate goes in the dishwasher, and the dishwasher "
            "ends closed.");
  EXPECT_EQ(explain_provenance(goal.provenance), "learned on the ceramic plate from the instructor, who said \"...\"");
}

// Where a rule or goal came from, as the store keeps it ("search: (close
// diaper-pail1)"), reads as English: no PDDL atom, no object id.
TEST(Explanation, ProvenanceHasNoPddl) {
  auto said = [](const std::string& object, const std::string& source) {
    return explain_provenance(Provenance{object, source});
  };
  EXPECT_EQ(said("diaper-pail1 (diaper-pail)", "search: (close diaper-pail1)"),
            "learned on the diaper pail from my own search, which chose to close the diaper pail");
  EXPECT_EQ(said("ceramic-bowl1 (ceramic-bowl)", "search: (pick-up-from ceramic-bowl1 dish-rack1)"),
            "learned on the ceramic bowl from my own search, which chose to take the ceramic bowl out of the dish rack");
  EXPECT_EQ(said("mug2 (mug)", "rule: (put-in mug2 cupboard1)"),
            "learned on the mug from a rule I had learned, which chose to put the mug in the cupboard");
  EXPECT_EQ(said("crackers1 (crackers)", "llm: \"Open pantry\""),
            "learned on the crackers from the language model, which said \"Open pantry\"");
  EXPECT_EQ(said("ketchup1 (ketchup)", "decision: fleet: 3 of 4 other households put it in the fridge (closed fridge)"),
            "learned on the ketchup from weighing what I knew: other households: 3 of 4 other households put it in "
            "the fridge, with the fridge closed");
  EXPECT_EQ(said("mug1 (mug)", "decision: like the cup (not (closed cupboard))"),
            "learned on the mug from weighing what I knew: like the cup, with the cupboard open");
  EXPECT_EQ(said("mug1 (mug)", "analogy: like the cup"), "learned on the mug from analogy, like the cup");
}

// The party's sideboard has a top and a bottom drawer: the goal learned
// keeps which one, and so does its English.
TEST(Explanation, AGoalKeepsTheLookAlikeItNames) {
  Scenario party = load_or_die(source_path("data/scenarios/party-cleanup.yaml"));
  const World& world = party.world;
  auto remote = world.universe->find("remote-control1");
  ASSERT_TRUE(remote.has_value());
  for (const auto& [drawer, words] : {std::pair{"drawer1", "top"}, std::pair{"drawer2", "bottom"}}) {
    auto goal = parse_goal(*world.domain, *world.universe,
                           std::string("(and (in remote-control1 ") + drawer + ") (closed " + drawer + "))");
    ASSERT_TRUE(goal.has_value()) << goal.error().message;
    auto learned = generalize_goal(world, GoalKey{"clean living room", "clear", "remote-control", "coffee-table"},
                                   *remote, *goal, Provenance{"remote-control1", "test"});
    ASSERT_TRUE(learned.has_value()) << learned.error().message;
    EXPECT_EQ(explain_goal(*learned), std::string("When I clear the coffee table (to clean the living room), the remote "
                                                  "control goes in the ") +
                                          words + " drawer, and the " + words + " drawer ends closed.");
  }
}

TEST(Explanation, RulesReadAsEnglish) {
  Scenario kitchen = load_or_die(source_path("data/scenarios/tidy-kitchen.yaml"));
  const Domain& d = *kitchen.world.domain;
  Rule rule;
  rule.variables = {RuleVariable{"?o", std::nullopt, true}, RuleVariable{"?r", std::nullopt, false}};
  auto lit = [&](const char* predicate, std::vector<VariableId> args, bool positive = true) {
    LiteralPattern p;
    p.atom.predicate = *d.find_predicate(predicate);
    for (VariableId v : args) p.atom.args[p.atom.arity++] = v;
    p.positive = positive;
    return p;
  };
  rule.goal = {lit("in", {0, 1}), lit("closed", {1})};
  rule.conditions = {lit("closed", {1}), lit("handempty", {}), lit("openable", {1}), lit("receptacle", {1})};
  rule.action = *d.find_action("open");
  rule.action_args = {1};
  rule.steps_to_goal = 4;
  EXPECT_EQ(explain_rule(d, rule),
            "When the goal is that the object is in the receptacle and the receptacle is closed, and the receptacle is "
            "closed, my hand is empty, and the receptacle has a door: open the receptacle (4 steps from the goal).");
  rule.steps_to_goal = 1;
  rule.subtask = "clear";
  EXPECT_THAT(explain_rule(d, rule), ::testing::StartsWith("While I clear, when the goal is"));
  EXPECT_THAT(explain_rule(d, rule), ::testing::EndsWith("(1 step from the goal)."));
}

}  // namespace
}  // namespace apprentice
