// Scenario files: the shipped scenarios load with the counts the paper
// gives, and every broken file is refused with its file name, the line of
// the offending entry and what was expected. A failed load returns an
// error and no scenario at all.
#include "world/scenario.h"

#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/scratch.h"

#include "world_fixtures.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;
using testing::fact;
using testing::load_or_die;
using testing::object;
using testing::source_path;
using testing::tidy_kitchen_path;

TEST(ShippedScenarios, TidyKitchenHasThePapersCounts) {
  Scenario s = load_or_die(tidy_kitchen_path());
  EXPECT_EQ(s.name, "tidy-kitchen");
  EXPECT_EQ(s.world.location, "kitchen");
  const Universe& u = *s.world.universe;
  EXPECT_EQ(u.of_kind(ObjectKind::kItem).size(), 30u);
  EXPECT_EQ(u.of_kind(ObjectKind::kSurface).size(), 2u);
  EXPECT_EQ(u.of_kind(ObjectKind::kReceptacle).size(), 9u);
  EXPECT_EQ(s.intent.size(), 26u);
  EXPECT_EQ(s.goal_assertions().size(), 35u);
  ASSERT_EQ(s.task.subtasks.size(), 3u);
  EXPECT_EQ(s.task.name, "tidy kitchen");
  EXPECT_EQ(s.task.subtasks[0].verb, "clear");
  EXPECT_EQ(s.task.subtasks[0].places, std::vector<ObjectId>{object(s.world, "table1")});
  EXPECT_EQ(s.task.subtasks[2].places, std::vector<ObjectId>{object(s.world, "dish-rack1")});

  std::vector<std::string> doors;
  for (ObjectId r : u.of_kind(ObjectKind::kReceptacle)) {
    if (!s.world.state.holds(Fact(s.world.vocabulary.openable, {r}))) continue;
    doors.push_back(u.name(r));
    EXPECT_TRUE(s.world.state.holds(Fact(s.world.vocabulary.closed, {r}))) << u.name(r);
  }
  EXPECT_EQ(doors, (std::vector<std::string>{"dishwasher1", "fridge1", "pantry1", "cupboard1", "drawer1"}));
  EXPECT_TRUE(s.world.state.holds(Fact(s.world.vocabulary.handempty, std::initializer_list<ObjectId>{})));
  EXPECT_EQ(s.domain_path.lexically_normal(), testing::kitchen_domain_path().lexically_normal());
}

TEST(ShippedScenarios, IdsAreCategoryPlusIndexInFileOrder) {
  Scenario s = load_or_die(tidy_kitchen_path());
  const World& w = s.world;
  EXPECT_TRUE(w.state.holds(fact(w, "(on glass-tumbler1 table1)")));
  EXPECT_TRUE(w.state.holds(fact(w, "(in glass-tumbler2 dish-rack1)")));
  EXPECT_TRUE(w.state.holds(fact(w, "(on mug1 counter1)")));
  EXPECT_TRUE(w.state.holds(fact(w, "(in mug2 dish-rack1)")));
  EXPECT_TRUE(w.state.holds(fact(w, "(on ceramic-plate2 table1)")));
  EXPECT_TRUE(w.state.holds(fact(w, "(on soda-can2 table1)")));
  EXPECT_FALSE(w.universe->find("ceramic-plate3").has_value());
  EXPECT_EQ(w.universe->with_category("granola-bars").size(), 2u);
  EXPECT_EQ(w.universe->info(object(w, "metal-fork2")).category, "metal-fork");
  EXPECT_EQ(w.universe->info(object(w, "table1")).kind, ObjectKind::kSurface);
  EXPECT_EQ(w.universe->info(object(w, "fridge1")).kind, ObjectKind::kReceptacle);
  // Every item is grabbable and in exactly one place.
  for (ObjectId o : w.universe->of_kind(ObjectKind::kItem)) {
    EXPECT_TRUE(w.state.holds(Fact(w.vocabulary.grabbable, {o})));
    int places = 0;
    for (const Fact& f : w.state.facts())
      if ((f.predicate == w.vocabulary.on || f.predicate == w.vocabulary.in) && f.args[0] == o) ++places;
    EXPECT_EQ(places, 1) << w.universe->name(o);
  }
}

TEST(ShippedScenarios, IntentGivesPerObjectGoals) {
  Scenario s = load_or_die(tidy_kitchen_path());
  const World& w = s.world;
  ObjectId ketchup = object(w, "ketchup1");
  const Subtask* subtask = s.subtask_of(ketchup);
  ASSERT_NE(subtask, nullptr);
  EXPECT_EQ(subtask->verb, "clear");
  auto goal = s.intended_goal("clear", ketchup);
  ASSERT_TRUE(goal.has_value());
  EXPECT_EQ(format_goal(*w.domain, *w.universe, *goal), "(and (in ketchup1 fridge1) (closed fridge1))");
  // Garbage has no lid: no (closed ...) part.
  auto paper = s.intended_goal("clear", object(w, "paper-plate1"));
  ASSERT_TRUE(paper.has_value());
  EXPECT_EQ(format_goal(*w.domain, *w.universe, *paper), "(in paper-plate1 garbage1)");
  // The same category means different things in different subtasks.
  EXPECT_EQ(s.find_intent("store", "mug")->place, object(w, "dishwasher1"));
  EXPECT_EQ(s.find_intent("unload", "mug")->place, object(w, "cupboard1"));
  auto mug2 = s.intended_goal(s.subtask_of(object(w, "mug2"))->verb, object(w, "mug2"));
  ASSERT_TRUE(mug2.has_value());
  EXPECT_EQ(format_goal(*w.domain, *w.universe, *mug2), "(and (in mug2 cupboard1) (closed cupboard1))");
  EXPECT_EQ(s.find_intent("clear", "mug"), nullptr);
  EXPECT_FALSE(s.intended_goal("clear", object(w, "mug1")).has_value());
  EXPECT_EQ(s.subtask_of(object(w, "fridge1")), nullptr);
}

TEST(ShippedScenarios, GoalAssertionsAreSortedUniqueAndPositive) {
  Scenario s = load_or_die(tidy_kitchen_path());
  std::vector<Literal> assertions = s.goal_assertions();
  EXPECT_TRUE(std::is_sorted(assertions.begin(), assertions.end()));
  EXPECT_EQ(std::adjacent_find(assertions.begin(), assertions.end()), assertions.end());
  int placements = 0, closings = 0;
  for (const Literal& l : assertions) {
    EXPECT_TRUE(l.positive);
    if (l.fact.predicate == s.world.vocabulary.in) ++placements;
    if (l.fact.predicate == s.world.vocabulary.closed) ++closings;
  }
  EXPECT_EQ(placements, 30);
  EXPECT_EQ(closings, 5);
}

TEST(ShippedScenarios, TidyKitchen35HasOneObjectPerCategory) {
  Scenario s = load_or_die(source_path("data/scenarios/tidy-kitchen-35.yaml"));
  EXPECT_EQ(s.name, "tidy-kitchen-35");
  EXPECT_EQ(s.world.universe->of_kind(ObjectKind::kItem).size(), 35u);
  EXPECT_EQ(s.intent.size(), 35u);
  // Every item has an intended placement.
  for (ObjectId o : s.world.universe->of_kind(ObjectKind::kItem)) {
    const Subtask* subtask = s.subtask_of(o);
    ASSERT_NE(subtask, nullptr) << s.world.universe->name(o);
    EXPECT_TRUE(s.intended_goal(subtask->verb, o).has_value()) << s.world.universe->name(o);
  }
}

TEST(ShippedScenarios, LoadingTwiceGivesEqualWorlds) {
  Scenario a = load_or_die(tidy_kitchen_path());
  Scenario b = load_or_die(tidy_kitchen_path());
  EXPECT_EQ(a.world.state, b.world.state);
  EXPECT_EQ(a.world.state.hash(), b.world.state.hash());
  EXPECT_EQ(a.goal_assertions(), b.goal_assertions());
}

// Broken scenarios. The base file is small and valid; each case edits one
// line and names the line the error must point at.

std::vector<std::string> base_scenario() {
  return {
      "name: small",                                                                  // 1
      "domain: " + testing::kitchen_domain_path().string(),                           // 2
      "location: kitchen",                                                            // 3
      "places:",                                                                      // 4
      "  - {category: table, kind: surface}",                                         // 5
      "  - {category: sink, kind: receptacle}",                                       // 6
      "  - {category: fridge, kind: receptacle, door: closed}",                       // 7
      "  - {category: garbage, kind: receptacle}",                                    // 8
      "objects:",                                                                     // 9
      "  - {category: ketchup, at: table1}",                                          // 10
      "  - {category: cup, at: table1, count: 2}",                                    // 11
      "  - {category: plate, at: sink1}",                                             // 12
      "task:",                                                                        // 13
      "  name: tidy",                                                                 // 14
      "  subtasks:",                                                                  // 15
      "    - {verb: clear, place: table1}",                                           // 16
      "intent:",                                                                      // 17
      "  - {subtask: clear, category: ketchup, receptacle: fridge1, closed: true}",  // 18
      "  - {subtask: clear, category: cup, receptacle: garbage1}",                   // 19
  };
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

constexpr const char* kSource = "/tmp/broken/small.yaml";

TEST(ScenarioErrors, BaseScenarioLoads) {
  auto s = parse_scenario(join_lines(base_scenario()), kSource);
  ASSERT_TRUE(s.has_value()) << s.error().describe();
  EXPECT_EQ(s->world.universe->size(), 8u);
  EXPECT_EQ(s->intent.size(), 2u);
  EXPECT_TRUE(s->world.universe->find("cup2").has_value());
  EXPECT_TRUE(s->world.state.holds(fact(s->world, "(in plate1 sink1)")));
  EXPECT_TRUE(s->world.state.holds(fact(s->world, "(closed fridge1)")));
  EXPECT_FALSE(s->world.state.holds(fact(s->world, "(openable garbage1)")));
  EXPECT_EQ(s->source, kSource);
  // Three placements and one closing.
  EXPECT_EQ(s->goal_assertions().size(), 4u);
}

// Aliases (*name) are the node their anchor (&name) made: twelve levels of
// nine aliases each, under 1 KB, are 9^12 lists when walked through
// every alias. Each is checked once, and the unknown key is told.
TEST(ScenarioErrors, AliasesOfAliasesAreReadOnce) {
  std::string bomb = "a0: &a0 [x, x, x, x, x, x, x, x, x]\n";
  for (int level = 1; level <= 12; ++level) {
    const std::string below = "*a" + std::to_string(level - 1);
    bomb += "a" + std::to_string(level) + ": &a" + std::to_string(level) + " [" + below;
    for (int i = 1; i < 9; ++i) bomb += ", " + below;
    bomb += "]\n";
  }
  ASSERT_LT(bomb.size(), 1000u);
  auto s = parse_scenario(bomb + join_lines(base_scenario()), kSource);
  ASSERT_FALSE(s.has_value());
  EXPECT_THAT(s.error().message, HasSubstr("small.yaml:1:1: unknown key 'a0'"));
}

// A scenario may still use aliases, and a key given twice in an anchored
// mapping is still found.
TEST(ScenarioErrors, AliasesAreReadAndTheirMappingsChecked) {
  std::vector<std::string> lines = base_scenario();
  lines[4] = "  - {category: table, kind: surface, properties: &wooden [wooden]}";
  lines[5] = "  - {category: sink, kind: receptacle, properties: *wooden}";
  auto s = parse_scenario(join_lines(lines), kSource);
  ASSERT_TRUE(s.has_value()) << s.error().describe();
  EXPECT_EQ(s->world.universe->info(object(s->world, "sink1")).properties, std::vector<std::string>{"wooden"});
  EXPECT_EQ(s->world.universe->info(object(s->world, "table1")).properties, std::vector<std::string>{"wooden"});
  lines[4] = "  - &table {category: table, kind: surface, kind: receptacle}";
  lines[5] = "  - *table";
  s = parse_scenario(join_lines(lines), kSource);
  ASSERT_FALSE(s.has_value());
  EXPECT_THAT(s.error().message, HasSubstr("small.yaml:5:"));
  EXPECT_THAT(s.error().message, HasSubstr("the key 'kind' is given twice in one mapping"));
}

TEST(ScenarioErrors, OpenDoorAndDefaultLocation) {
  std::vector<std::string> lines = base_scenario();
  lines[6] = "  - {category: fridge, kind: receptacle, door: open}";
  lines[2] = "# no location";
  auto s = parse_scenario(join_lines(lines), kSource);
  ASSERT_TRUE(s.has_value()) << s.error().describe();
  EXPECT_TRUE(s->world.state.holds(fact(s->world, "(openable fridge1)")));
  EXPECT_FALSE(s->world.state.holds(fact(s->world, "(closed fridge1)")));
  EXPECT_EQ(s->world.location, "kitchen");
}

struct BrokenCase {
  const char* name;
  std::size_t line;  // the line to replace (1-based); its text may hold '\n'
  std::string text;
  std::size_t error_line;  // the line the message must name
  const char* expected;    // a part of the message
  ErrorCode code = ErrorCode::kInvalidInput;
  std::size_t last = 0;    // if set, lines line..last are all replaced
};

std::vector<BrokenCase> broken_cases() {
  return {
      {"missing_comma", 10, "  - {category: ketchup at: table1}", 10, "end of map flow not found"},
      {"stray_brace", 10, "  - {category: ketchup, at: table1}}", 10, "illegal flow end"},
      {"tab_indentation", 10, "\t- {category: ketchup, at: table1}", 10, "illegal block entry"},
      {"colon_in_plain_value", 3, "location: kitchen: big", 3, "illegal map value"},
      // "name" indented by three, so "subtasks" at two no longer lines up.
      {"bad_indentation", 14, "   name: tidy", 15, "end of map not found"},
      {"unknown_top_key", 3, "locale: kitchen", 3, "unknown key 'locale' (expected one of: name, domain, location"},
      {"unknown_object_key", 10, "  - {category: ketchup, at: table1, colour: red}", 10, "unknown key 'colour'"},
      {"unknown_place_key", 5, "  - {category: table, kind: surface, lid: no}", 5, "unknown key 'lid'"},
      {"missing_domain", 2, "# no domain", 1, "missing key 'domain'"},
      {"missing_name", 1, "# no name", 2, "missing key 'name'"},
      {"domain_file_missing", 2, "domain: /nonexistent/kitchen.pddl", 2,
       "cannot load the domain: /nonexistent/kitchen.pddl: no such file", ErrorCode::kNotFound},
      {"unknown_place_in_at", 10, "  - {category: ketchup, at: shelf1}", 10,
       "expected the id of a place, such as table1; there is no place 'shelf1'"},
      {"item_as_place", 11, "  - {category: cup, at: ketchup1, count: 2}", 11, "there is no place 'ketchup1'"},
      {"door_on_a_surface", 5, "  - {category: table, kind: surface, door: closed}", 5,
       "only a receptacle can have a door"},
      {"bad_door", 7, "  - {category: fridge, kind: receptacle, door: ajar}", 7, "expected door: open or door: closed"},
      {"bad_kind", 6, "  - {category: sink, kind: shelf}", 6, "expected kind 'surface' or 'receptacle', not 'shelf'"},
      {"item_kind_place", 6, "  - {category: sink, kind: item}", 6, "expected kind 'surface' or 'receptacle'"},
      {"closed_lidless", 19, "  - {subtask: clear, category: cup, receptacle: garbage1, closed: true}", 19,
       "garbage1 has no door, so it cannot end closed"},
      {"closed_not_bool", 18, "  - {subtask: clear, category: ketchup, receptacle: fridge1, closed: maybe}", 18,
       "expected true or false for 'closed'"},
      {"intent_unknown_subtask", 19, "  - {subtask: store, category: cup, receptacle: garbage1}", 19,
       "no subtask 'store' in the task"},
      {"intent_on_a_surface", 19, "  - {subtask: clear, category: cup, receptacle: table1}", 19,
       "expected a receptacle; table1 is a surface"},
      {"intent_twice", 19,
       "  - {subtask: clear, category: cup, receptacle: garbage1}\n"
       "  - {subtask: clear, category: cup, receptacle: sink1}",
       20, "intent for (clear, cup) is given twice"},
      {"object_without_intent", 19, "# cup has no intent", 11, "the intent says nothing about cup for subtask clear"},
      {"count_zero", 11, "  - {category: cup, at: table1, count: 0}", 11, "expected a count between 1 and 100000"},
      {"count_not_a_number", 11, "  - {category: cup, at: table1, count: many}", 11,
       "expected a count between 1 and 100000"},
      // A verb may come again with another place; the intent says which.
      {"verb_twice_intent_not_saying_which", 16,
       "    - {verb: clear, place: table1}\n"
       "    - {verb: clear, place: sink1}",
       19, "the task has 2 subtasks 'clear'; say which with 'from', the place it empties (table1 or sink1)"},
      {"intent_from_another_place", 18,
       "  - {subtask: clear, from: sink1, category: ketchup, receptacle: fridge1, closed: true}", 18,
       "no subtask 'clear' empties sink1"},
      {"ids_clash", 10,
       "  - {category: cup1, at: table1}\n"
       "  - {category: cup, at: table1, count: 11}",
       11, "two objects would have the id cup11", ErrorCode::kInvalidInput, 11},
      {"subtask_unknown_place", 16, "    - {verb: clear, place: bench1}", 16, "there is no place 'bench1'"},
      {"upper_case_category", 10, "  - {category: Ketchup, at: table1}", 10,
       "expected a lower-case hyphenated name for 'category', not 'Ketchup'"},
      {"empty_places", 4, "places: []", 4, "expected 'places': a list of surfaces and receptacles",
       ErrorCode::kInvalidInput, 8},
      {"objects_not_a_list", 9, "objects: {category: ketchup}", 9, "expected 'objects': a list",
       ErrorCode::kInvalidInput, 12},
      {"no_subtasks", 15, "  subtasks: []", 15, "expected 'subtasks': a list of {verb, place}",
       ErrorCode::kInvalidInput, 16},
      {"place_not_a_map", 5, "  - table", 5, "expected a place such as {category: fridge"},
      {"name_not_text", 1, "name: [a, b]", 1, "expected a text value for 'name'"},
      // yaml-cpp keeps the first of two equal keys; we refuse the file.
      {"duplicate_top_key", 3, "name: again", 3, "the key 'name' is given twice in one mapping (first at line 1, column 1)"},
      {"duplicate_flow_key", 10, "  - {category: ketchup, at: table1, at: sink1}", 10,
       "the key 'at' is given twice in one mapping (first at line 10, column 25)"},
      {"duplicate_nested_key", 14, "  name: tidy\n  name: tidy up", 15, "the key 'name' is given twice"},
      {"place_and_receptacle", 19, "  - {subtask: clear, category: cup, place: garbage1, receptacle: garbage1}", 19,
       "give either 'place' or 'receptacle', not both"},
      {"intent_without_place", 19, "  - {subtask: clear, category: cup}", 19, "missing key 'place'"},
      {"intent_closed_surface", 19, "  - {subtask: clear, category: cup, place: table1, closed: true}", 19,
       "table1 has no door, so it cannot end closed"},
      {"properties_not_a_list", 8, "  - {category: garbage, kind: receptacle, properties: top}", 8,
       "expected 'properties': a list of words"},
      {"property_upper_case", 8, "  - {category: garbage, kind: receptacle, properties: [Top]}", 8,
       "expected a property: a lower-case word"},
      {"property_twice", 8, "  - {category: garbage, kind: receptacle, properties: [top, top]}", 8,
       "the property 'top' is given twice"},
      {"look_alikes_alike", 8,
       "  - {category: garbage, kind: receptacle, properties: [green]}\n"
       "  - {category: garbage, kind: receptacle, properties: [green]}",
       9, "garbage2 has the same properties as garbage1, so no one could tell them apart"},
      {"subtask_place_twice", 16, "    - {verb: clear, place: table1}\n    - {verb: wipe, place: table}", 17,
       "table1 is already the place of subtask 'clear'"},
      {"subtask_no_such_category", 16, "    - {verb: clear, place: shelf}", 16,
       "or a category of places, such as bag; there is no place 'shelf'"},
      {"intent_without_task", 13, "# no task", 15, "an intent needs a 'task' whose subtasks it names",
       ErrorCode::kInvalidInput, 16},
      {"bad_reference", 3, "reference: table4", 3, "expected reference: table3"},
  };
}

class ScenarioErrorTable : public ::testing::TestWithParam<BrokenCase> {};

TEST_P(ScenarioErrorTable, RefusesWithFileLineAndReason) {
  const BrokenCase& c = GetParam();
  std::vector<std::string> lines = base_scenario();
  lines.at(c.line - 1) = c.text;
  if (c.last > c.line) lines.erase(lines.begin() + static_cast<long>(c.line), lines.begin() + static_cast<long>(c.last));
  auto s = parse_scenario(join_lines(lines), kSource);
  ASSERT_FALSE(s.has_value()) << c.name << " loaded";
  EXPECT_EQ(s.error().code, c.code) << s.error().message;
  EXPECT_THAT(s.error().message, ::testing::StartsWith(std::string(kSource) + ":" + std::to_string(c.error_line) + ":"));
  EXPECT_THAT(s.error().message, HasSubstr(c.expected));
}

INSTANTIATE_TEST_SUITE_P(Table, ScenarioErrorTable, ::testing::ValuesIn(broken_cases()),
                         [](const ::testing::TestParamInfo<BrokenCase>& info) { return std::string(info.param.name); });

// --- Surfaces as destinations, properties, subtasks over several places,
// and a scenario without an intent.

TEST(ScenarioFormat, ASurfaceIsADestinationGivingOn) {
  std::vector<std::string> lines = base_scenario();
  lines[4] = "  - {category: table, kind: surface}\n  - {category: shelf, kind: surface}";
  lines[18] = "  - {subtask: clear, category: cup, place: shelf1}";
  auto s = parse_scenario(join_lines(lines), kSource);
  ASSERT_TRUE(s.has_value()) << s.error().describe();
  const World& w = s->world;
  EXPECT_EQ(s->find_intent("clear", "cup")->place, object(w, "shelf1"));
  auto goal = s->intended_goal("clear", object(w, "cup2"));
  ASSERT_TRUE(goal.has_value());
  EXPECT_EQ(format_goal(*w.domain, *w.universe, *goal), "(on cup2 shelf1)");
  // `receptacle:` is still read, and `place:` may name a receptacle too.
  goal = s->intended_goal("clear", object(w, "ketchup1"));
  ASSERT_TRUE(goal.has_value());
  EXPECT_EQ(format_goal(*w.domain, *w.universe, *goal), "(and (in ketchup1 fridge1) (closed fridge1))");
  lines[17] = "  - {subtask: clear, category: ketchup, place: fridge1, closed: true}";
  auto again = parse_scenario(join_lines(lines), kSource);
  ASSERT_TRUE(again.has_value()) << again.error().describe();
  EXPECT_EQ(again->goal_assertions(), s->goal_assertions());
  EXPECT_EQ(s->goal_assertions().size(), 4u);  // ketchup in, fridge closed, two cups on the shelf
}

TEST(ScenarioFormat, PropertiesTellLookAlikesApart) {
  std::vector<std::string> lines = base_scenario();
  lines[7] =
      "  - {category: garbage, kind: receptacle}\n"
      "  - {category: drawer, kind: receptacle, door: closed, properties: [top]}\n"
      "  - {category: drawer, kind: receptacle, door: closed, properties: [bottom, wooden]}";
  lines[9] = "  - {category: ketchup, at: table1, properties: [red]}";
  auto s = parse_scenario(join_lines(lines), kSource);
  ASSERT_TRUE(s.has_value()) << s.error().describe();
  const Universe& u = *s->world.universe;
  EXPECT_EQ(u.info(object(s->world, "drawer1")).properties, std::vector<std::string>{"top"});
  EXPECT_EQ(u.info(object(s->world, "drawer2")).properties, (std::vector<std::string>{"bottom", "wooden"}));
  EXPECT_EQ(u.info(object(s->world, "ketchup1")).properties, std::vector<std::string>{"red"});
  EXPECT_TRUE(u.info(object(s->world, "garbage1")).properties.empty());
  // Ids do not change: the properties are words, not names.
  EXPECT_EQ(u.with_category("drawer").size(), 2u);
}

TEST(ScenarioFormat, ASubtaskPlaceMayNameEveryPlaceOfACategory) {
  std::vector<std::string> lines = base_scenario();
  lines[5] =
      "  - {category: sink, kind: receptacle}\n"
      "  - {category: bag, kind: receptacle, properties: [blue]}\n"
      "  - {category: bag, kind: receptacle, properties: [green]}";
  lines[11] = "  - {category: plate, at: bag1}\n  - {category: plate, at: bag2}";
  lines[15] = "    - {verb: clear, place: table1}\n    - {verb: unload, place: bag}";
  lines[18] = "  - {subtask: clear, category: cup, receptacle: garbage1}\n  - {subtask: unload, category: plate, place: sink1}";
  auto s = parse_scenario(join_lines(lines), kSource);
  ASSERT_TRUE(s.has_value()) << s.error().describe();
  const World& w = s->world;
  ASSERT_EQ(s->task.subtasks.size(), 2u);
  EXPECT_EQ(s->task.subtasks[0].places, std::vector<ObjectId>{object(w, "table1")});
  EXPECT_EQ(s->task.subtasks[1].places, (std::vector<ObjectId>{object(w, "bag1"), object(w, "bag2")}));
  EXPECT_TRUE(s->task.subtasks[1].covers(object(w, "bag2")));
  EXPECT_FALSE(s->task.subtasks[1].covers(object(w, "sink1")));
  EXPECT_EQ(s->subtask_of(object(w, "plate2")), &s->task.subtasks[1]);
  EXPECT_EQ(s->objects_to_tidy().size(), 5u);  // ketchup, two cups, two plates
  // An id still names one place, even where its category has several.
  lines[15] = "    - {verb: clear, place: table1}\n    - {verb: unload, place: bag2}";
  lines[11] = "  - {category: plate, at: bag2}";
  auto one = parse_scenario(join_lines(lines), kSource);
  ASSERT_TRUE(one.has_value()) << one.error().describe();
  EXPECT_EQ(one->task.subtasks[1].places, std::vector<ObjectId>{object(one->world, "bag2")});
}

TEST(ScenarioFormat, WithoutAnIntentTheWorldStillLoads) {
  std::vector<std::string> lines = base_scenario();
  lines.resize(16);  // no intent
  auto s = parse_scenario(join_lines(lines), kSource);
  ASSERT_TRUE(s.has_value()) << s.error().describe();
  EXPECT_FALSE(s->has_intent);
  EXPECT_TRUE(s->intent.empty());
  EXPECT_TRUE(s->goal_assertions().empty());
  EXPECT_EQ(s->task.subtasks.size(), 1u);
  // Nor is a task needed for a world a person teaches in.
  lines.resize(12);
  auto bare = parse_scenario(join_lines(lines), kSource);
  ASSERT_TRUE(bare.has_value()) << bare.error().describe();
  EXPECT_FALSE(bare->has_intent);
  EXPECT_TRUE(bare->task.subtasks.empty());
  EXPECT_EQ(bare->world.universe->size(), 8u);
  // An empty intent is an intent: the check that it covers every object runs.
  lines = base_scenario();
  lines.resize(17);
  auto empty = parse_scenario(join_lines(lines), kSource);
  ASSERT_FALSE(empty.has_value());
  EXPECT_THAT(empty.error().message, HasSubstr("expected 'intent': a list"));
  lines.back() = "intent: []";
  empty = parse_scenario(join_lines(lines), kSource);
  ASSERT_FALSE(empty.has_value());
  EXPECT_THAT(empty.error().message, HasSubstr("the intent says nothing about ketchup"));
}

TEST(ScenarioFormat, TheReferenceKeyMarksThePapersKitchen) {
  EXPECT_EQ(load_or_die(tidy_kitchen_path()).reference, "table3");
  EXPECT_EQ(load_or_die(source_path("data/scenarios/tidy-kitchen-35.yaml")).reference, "");
  auto s = parse_scenario(join_lines(base_scenario()), kSource);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->reference, "");
  EXPECT_TRUE(s->has_intent);
}

// The example of docs/scenarios.md is a scenario that loads, with the
// meaning the document gives it.
TEST(ScenarioFormat, TheDocumentedExampleLoads) {
  std::ifstream doc(source_path("docs/scenarios.md"));
  std::string text((std::istreambuf_iterator<char>(doc)), std::istreambuf_iterator<char>());
  auto start = text.find("```yaml\n");
  ASSERT_NE(start, std::string::npos);
  start += 8;
  std::string yaml = text.substr(start, text.find("```", start) - start);
  auto s = parse_scenario(yaml, source_path("data/scenarios/example.yaml"));
  ASSERT_TRUE(s.has_value()) << s.error().describe();
  const World& w = s->world;
  EXPECT_EQ(w.location, "garage");
  EXPECT_EQ(w.universe->info(object(w, "drawer2")).properties, std::vector<std::string>{"bottom"});
  EXPECT_EQ(s->task.subtasks[1].places, (std::vector<ObjectId>{object(w, "bin1"), object(w, "bin2")}));
  auto goal = s->intended_goal("empty", object(w, "paint-can1"));
  ASSERT_TRUE(goal.has_value());
  EXPECT_EQ(format_goal(*w.domain, *w.universe, *goal), "(on paint-can1 shelf1)");
  EXPECT_EQ(s->find_intent("empty", "rag")->place, object(w, "trash-can1"));
}

TEST(ScenarioErrors, NotAMappingOrEmpty) {
  for (const char* text : {"- a\n- b\n", "", "just text\n"}) {
    auto s = parse_scenario(text, kSource);
    ASSERT_FALSE(s.has_value()) << text;
    EXPECT_EQ(s.error().code, ErrorCode::kInvalidInput);
    EXPECT_THAT(s.error().message, ::testing::StartsWith(kSource));
    EXPECT_THAT(s.error().message, HasSubstr("expected a mapping"));
  }
}

TEST(ScenarioErrors, MissingScenarioFileIsNotFound) {
  auto s = load_scenario("/nonexistent/scenario.yaml");
  ASSERT_FALSE(s.has_value());
  EXPECT_EQ(s.error().code, ErrorCode::kNotFound);
  EXPECT_THAT(s.error().message, HasSubstr("/nonexistent/scenario.yaml"));
}

TEST(ScenarioErrors, RelativeDomainResolvesAgainstTheScenarioDirectory) {
  std::vector<std::string> lines = base_scenario();
  lines[1] = "domain: ../domains/kitchen.pddl";
  auto good = parse_scenario(join_lines(lines), source_path("data/scenarios/inline.yaml"));
  ASSERT_TRUE(good.has_value()) << good.error().describe();
  auto bad = parse_scenario(join_lines(lines), "/tmp/elsewhere/inline.yaml");
  ASSERT_FALSE(bad.has_value());
  EXPECT_EQ(bad.error().code, ErrorCode::kNotFound);
  EXPECT_THAT(bad.error().message, HasSubstr("/tmp/elsewhere/inline.yaml:2:"));
}

class ScenarioWithBadDomain : public testing::ScratchTest {};

TEST_F(ScenarioWithBadDomain, PddlSyntaxErrorNamesBothFiles) {
  std::filesystem::path domain = write("broken.pddl", "(define (domain kitchen)\n  (:requirements :fluents))\n");
  std::vector<std::string> lines = base_scenario();
  lines[1] = "domain: " + domain.string();
  auto s = parse_scenario(join_lines(lines), kSource);
  ASSERT_FALSE(s.has_value());
  EXPECT_EQ(s.error().code, ErrorCode::kInvalidInput);
  EXPECT_THAT(s.error().message, HasSubstr(std::string(kSource) + ":2:"));
  EXPECT_THAT(s.error().message, HasSubstr(domain.string() + ":2:18: expected :strips"));
}

TEST_F(ScenarioWithBadDomain, DomainWithoutTheKitchenVocabularyIsRefused) {
  std::filesystem::path domain = write("novocab.pddl",
                                       "(define (domain tiny) (:requirements :strips :typing)\n"
                                       "  (:types item receptacle surface)\n"
                                       "  (:predicates (on ?o - item ?s - surface)))\n");
  std::vector<std::string> lines = base_scenario();
  lines[1] = "domain: " + domain.string();
  auto s = parse_scenario(join_lines(lines), kSource);
  ASSERT_FALSE(s.has_value());
  EXPECT_THAT(s.error().message, HasSubstr(std::string(kSource) + ":2:"));
  EXPECT_THAT(s.error().message, HasSubstr("domain tiny lacks the predicate (in)"));
}

TEST_F(ScenarioWithBadDomain, FileOnDiskErrorsNameTheFile) {
  std::vector<std::string> lines = base_scenario();
  lines[9] = "  - {category: ketchup, at: shelf1}";
  std::filesystem::path path = write("broken.yaml", join_lines(lines));
  auto s = load_scenario(path);
  ASSERT_FALSE(s.has_value());
  EXPECT_THAT(s.error().message, ::testing::StartsWith(path.string() + ":10:"));
}

}  // namespace
}  // namespace apprentice
