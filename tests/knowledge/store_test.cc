// The knowledge store: what is saved is what is loaded, across reopening;
// a store of another version, another program's database or a file of
// garbage is refused with a clear message and never misread or crashed on.
#include <algorithm>
#include <fstream>
#include <random>

#include <SQLiteCpp/SQLiteCpp.h>
#include <nlohmann/json.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "knowledge/store.h"
#include "knowledge_fixtures.h"

namespace apprentice {
namespace {

using ::testing::AnyOf;
using ::testing::HasSubstr;
using namespace apprentice::testing;

class Store : public KitchenStoreTest {
 protected:

  TaskKnowledge task() const {
    return TaskKnowledge{"tidy kitchen",
                         {{"clear", "on", "table"}, {"store", "on", "counter"}, {"unload", "in", "dish-rack"}}};
  }
  GoalKnowledge plate_goal() const {
    auto k = generalize_goal(world_, GoalKey{"tidy kitchen", "clear", "ceramic-plate", "table"},
                             object(world_, "ceramic-plate1"), goal(world_, kCeramicPlateGoal),
                             Provenance{"ceramic-plate1 (ceramic-plate)", "instructor: \"If the object is ...\""});
    EXPECT_TRUE(k.has_value());
    return *k;
  }
  GoalKnowledge paper_plate_goal() const {
    auto k = generalize_goal(world_, GoalKey{"tidy kitchen", "clear", "paper-plate", "table"},
                             object(world_, "paper-plate1"), goal(world_, "(in paper-plate1 garbage1)"),
                             Provenance{"paper-plate1 (paper-plate)", "llm: \"...\" (confirmed)"});
    EXPECT_TRUE(k.has_value());
    return *k;
  }
  std::vector<Rule> rules() const {
    std::vector<Rule> out = learn(world_, ceramic_plate_episode(world_), Generalization::kPaper);
    for (Rule& r : learn(world_, ceramic_plate_episode(world_), Generalization::kFull)) out.push_back(std::move(r));
    return out;
  }

  KnowledgeStore open_or_die(const fs::path& path) {
    auto store = KnowledgeStore::open(path);
    if (!store) {
      ADD_FAILURE() << store.error().describe();
      std::abort();
    }
    return std::move(*store);
  }

  void fill(KnowledgeStore& store) {
    ASSERT_TRUE(store.save_task(task()));
    ASSERT_TRUE(store.save_goal(plate_goal()));
    ASSERT_TRUE(store.save_goal(paper_plate_goal()));
    for (const Rule& r : rules()) ASSERT_TRUE(store.save_rule(domain_, r));
  }

  void expect_filled(const Knowledge& k) {
    ASSERT_EQ(k.tasks.size(), 1u);
    EXPECT_EQ(k.tasks[0], task());
    ASSERT_NE(k.find_task("tidy kitchen"), nullptr);
    ASSERT_EQ(k.goals.size(), 2u);
    EXPECT_EQ(k.goals.all()[0], plate_goal());
    EXPECT_EQ(k.goals.all()[1], paper_plate_goal());
    EXPECT_EQ(k.rules.rules(), rules());  // same rules, same order, same provenance
  }

  // Sets meta.schema_version in an existing store, as a future version of
  // apprentice would have written it.
  void set_schema_version(const fs::path& path, const std::string& version) {
    SQLite::Database db(path.string(), SQLite::OPEN_READWRITE);
    db.exec("UPDATE meta SET value = '" + version + "' WHERE key = 'schema_version'");
  }

  void write_bytes(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  }
};

TEST_F(Store, RoundTripOfTasksGoalsAndRules) {
  KnowledgeStore store = open_or_die(path_);
  fill(store);
  auto loaded = store.load(domain_);
  ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
  expect_filled(*loaded);
}

// A goal naming one of two look-alike places keeps the properties that
// tell it apart (the top drawer) through the store.
TEST_F(Store, APlacesPropertiesSurviveTheStore) {
  KnowledgeStore store = open_or_die(path_);
  GoalKnowledge goal = plate_goal();
  goal.key.category = "hammer";
  goal.literals[0].arguments[1] = GoalTemplateArgument{false, "drawer", {"top"}};
  ASSERT_TRUE(store.save_goal(goal));
  auto loaded = store.load(domain_);
  ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
  ASSERT_EQ(loaded->goals.size(), 1u);
  EXPECT_EQ(loaded->goals.all()[0], goal);
  EXPECT_EQ(loaded->goals.all()[0].literals[0].arguments[1].properties, std::vector<std::string>{"top"});
}

TEST_F(Store, ANewStoreIsEmpty) {
  KnowledgeStore store = open_or_die(path_);
  auto loaded = store.load(domain_);
  ASSERT_TRUE(loaded.has_value());
  EXPECT_TRUE(loaded->tasks.empty());
  EXPECT_EQ(loaded->goals.size(), 0u);
  EXPECT_EQ(loaded->rules.size(), 0u);
  EXPECT_EQ(store.path(), path_);
}

TEST_F(Store, ReopenedStoreHoldsTheSameKnowledge) {
  {
    KnowledgeStore store = open_or_die(path_);
    fill(store);
  }
  KnowledgeStore reopened = open_or_die(path_);
  auto loaded = reopened.load(domain_);
  ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
  expect_filled(*loaded);
  // And it can be extended.
  Episode ketchup = make_episode(world_, world_.state, "ketchup1", "(and (in ketchup1 fridge1) (closed fridge1))",
                                 "clear", {"(open fridge1)", "(pick-up ketchup1 table1)", "(put-in ketchup1 fridge1)",
                                           "(close fridge1)"});
  std::vector<Rule> more = learn(world_, ketchup, Generalization::kPaper);
  for (const Rule& r : more) ASSERT_TRUE(reopened.save_rule(domain_, r));
  auto extended = reopened.load(domain_);
  ASSERT_TRUE(extended.has_value());
  // The ketchup's pick-up rule is the plate's (same signature): 3 new.
  EXPECT_EQ(extended->rules.size(), rules().size() + 3);
}

TEST_F(Store, SavingAgainReplacesOrIgnoresButNeverDuplicates) {
  KnowledgeStore store = open_or_die(path_);
  fill(store);
  fill(store);
  GoalKnowledge corrected = plate_goal();
  corrected.literals.pop_back();
  corrected.provenance.source = "instructor: corrected";
  ASSERT_TRUE(store.save_goal(corrected));
  TaskKnowledge shorter{"tidy kitchen", {{"clear", "on", "table"}}};
  ASSERT_TRUE(store.save_task(shorter));
  auto loaded = store.load(domain_);
  ASSERT_TRUE(loaded.has_value());
  EXPECT_EQ(loaded->rules.size(), rules().size());
  ASSERT_EQ(loaded->goals.size(), 2u);
  ASSERT_NE(loaded->goals.find(corrected.key), nullptr);
  EXPECT_EQ(*loaded->goals.find(corrected.key), corrected);
  ASSERT_EQ(loaded->tasks.size(), 1u);
  EXPECT_EQ(loaded->tasks[0], shorter);
}

TEST_F(Store, RefusesAStoreOfAnotherSchemaVersionNamingBothVersions) {
  {
    KnowledgeStore store = open_or_die(path_);
    fill(store);
  }
  set_schema_version(path_, "999");
  std::string before = read_text(path_);
  auto refused = KnowledgeStore::open(path_);
  ASSERT_FALSE(refused.has_value());
  EXPECT_EQ(refused.error().code, ErrorCode::kFailedPrecondition);
  EXPECT_THAT(refused.error().message, HasSubstr("schema version 999"));
  EXPECT_THAT(refused.error().message, HasSubstr("reads version " + std::to_string(kKnowledgeSchemaVersion)));
  EXPECT_THAT(refused.error().message, HasSubstr(path_.string()));
  // Refusing does not touch the file.
  EXPECT_EQ(read_text(path_), before);
  // An older version, or a missing one, is refused the same way.
  set_schema_version(path_, "0");
  ASSERT_FALSE(KnowledgeStore::open(path_).has_value());
  EXPECT_EQ(KnowledgeStore::open(path_).error().code, ErrorCode::kFailedPrecondition);
  {
    SQLite::Database db(path_.string(), SQLite::OPEN_READWRITE);
    db.exec("DELETE FROM meta WHERE key = 'schema_version'");
  }
  ASSERT_FALSE(KnowledgeStore::open(path_).has_value());
  EXPECT_EQ(KnowledgeStore::open(path_).error().code, ErrorCode::kFailedPrecondition);
}

TEST_F(Store, RefusesAForeignSqliteDatabase) {
  {
    SQLite::Database db(path_.string(), SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE);
    db.exec("CREATE TABLE recipes(name TEXT, steps TEXT)");
    db.exec("INSERT INTO recipes VALUES ('pancakes', 'mix, fry')");
  }
  std::string before = read_text(path_);
  auto refused = KnowledgeStore::open(path_);
  ASSERT_FALSE(refused.has_value());
  EXPECT_EQ(refused.error().code, ErrorCode::kFailedPrecondition);
  EXPECT_THAT(refused.error().message, HasSubstr("another program"));
  EXPECT_EQ(read_text(path_), before);
}

TEST_F(Store, RefusesADatabaseWithAMetaTableOfAnotherFormat) {
  {
    SQLite::Database db(path_.string(), SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE);
    db.exec("CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL)");
    db.exec("INSERT INTO meta VALUES ('format', 'somebody-elses-format'), ('schema_version', '1')");
  }
  auto refused = KnowledgeStore::open(path_);
  ASSERT_FALSE(refused.has_value());
  EXPECT_EQ(refused.error().code, ErrorCode::kFailedPrecondition);
  EXPECT_THAT(refused.error().message, HasSubstr("not an apprentice knowledge store"));
}

TEST_F(Store, RandomBytesAreRefusedClearlyNeverMisread) {
  std::mt19937 random(20240605);
  for (std::size_t size : {1u, 100u, 512u, 4096u, 65536u}) {
    for (bool sqlite_header : {false, true}) {
      std::string bytes(size, '\0');
      for (char& c : bytes) c = static_cast<char>(random());
      if (sqlite_header) {
        const std::string header("SQLite format 3\0", 16);
        bytes.replace(0, std::min(size, header.size()), header.substr(0, std::min(size, header.size())));
      }
      write_bytes(path_, bytes);
      auto opened = KnowledgeStore::open(path_);
      std::string what = std::to_string(size) + " random bytes" + (sqlite_header ? " after an SQLite header" : "");
      if (opened) {
        // Only possible if SQLite took it for an empty database; then there
        // is nothing to misread.
        auto loaded = opened->load(domain_);
        ASSERT_FALSE(loaded.has_value()) << what << " loaded as knowledge";
        EXPECT_THAT(loaded.error().code, AnyOf(ErrorCode::kDataLoss, ErrorCode::kFailedPrecondition)) << what;
        continue;
      }
      EXPECT_THAT(opened.error().code, AnyOf(ErrorCode::kDataLoss, ErrorCode::kFailedPrecondition))
          << what << ": " << opened.error().describe();
      EXPECT_THAT(opened.error().message, HasSubstr(path_.string())) << what;
      EXPECT_THAT(opened.error().message,
                  AnyOf(HasSubstr("not an apprentice knowledge store"), HasSubstr("knowledge store is damaged")))
          << what;
    }
  }
}

TEST_F(Store, CorruptedStoreIsRefusedOrReadNeverCrashedOn) {
  // Overwrite runs of bytes of a real store at random places: SQLite
  // notices a malformed page, or a damaged entry no longer parses; either
  // way the error says the data is unreadable, or the damage missed
  // everything that is read.
  {
    KnowledgeStore store = open_or_die(path_);
    fill(store);
  }
  const std::string pristine = read_text(path_);
  std::mt19937 random(7);
  int refused = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::string bytes = pristine;
    std::size_t at = 100 + random() % (bytes.size() - 116);
    for (std::size_t i = 0; i < 16; ++i) bytes[at + i] = static_cast<char>(random());
    write_bytes(path_, bytes);
    auto opened = KnowledgeStore::open(path_);
    Status status;
    if (!opened) status = tl::unexpected(opened.error());
    else if (auto loaded = opened->load(domain_); !loaded) status = tl::unexpected(loaded.error());
    if (status) continue;
    ++refused;
    EXPECT_THAT(status.error().code, AnyOf(ErrorCode::kDataLoss, ErrorCode::kFailedPrecondition))
        << "trial " << trial << " at " << at << ": " << status.error().describe();
  }
  EXPECT_GT(refused, 0);
}

class StoreWithARule : public Store {
 protected:
  // Writes a store with the plate's open rule, then replaces its body.
  void with_body(const std::string& body) {
    {
      KnowledgeStore store = open_or_die(path_);
      ASSERT_TRUE(store.save_rule(domain_, rules()[3]));
    }
    SQLite::Database db(path_.string(), SQLite::OPEN_READWRITE);
    SQLite::Statement update(db, "UPDATE rules SET body = ?");
    update.bind(1, body);
    update.exec();
  }
  Error load_error() {
    KnowledgeStore store = open_or_die(path_);
    auto loaded = store.load(domain_);
    EXPECT_FALSE(loaded.has_value()) << "misread a damaged rule";
    return loaded ? Error{} : loaded.error();
  }
  // The open rule's body with one part replaced.
  std::string open_rule_with(const std::string& key, const nlohmann::json& value) {
    return open_rule_with(nlohmann::json{{key, value}});
  }
  std::string open_rule_with(const nlohmann::json& changes) {
    nlohmann::json body = {
        {"variables", {{{"name", "?o"}, {"interest", true}}, {{"name", "?r"}, {"interest", false}},
                       {{"name", "?s"}, {"interest", false}}}},
        {"goal", {{{"predicate", "in"}, {"positive", true}, {"args", {0, 1}}},
                  {{"predicate", "closed"}, {"positive", true}, {"args", {1}}}}},
        {"conditions", {{{"predicate", "closed"}, {"positive", true}, {"args", {1}}},
                        {{"predicate", "on"}, {"positive", true}, {"args", {0, 2}}}}},
        {"action", "open"},
        {"action_args", {1}},
        {"steps", 4}};
    for (const auto& [key, value] : changes.items()) body[key] = value;
    return body.dump();
  }
};

TEST_F(StoreWithARule, ABodyThatIsNotJsonIsDataLoss) {
  with_body("{\"variables\": [");
  Error e = load_error();
  EXPECT_EQ(e.code, ErrorCode::kDataLoss);
  EXPECT_THAT(e.message, HasSubstr("unreadable"));
}

TEST_F(StoreWithARule, ABodyOfTheWrongShapeIsDataLoss) {
  with_body(open_rule_with("variables", "?o ?r ?s"));
  EXPECT_EQ(load_error().code, ErrorCode::kDataLoss);
  with_body(open_rule_with("steps", "four"));
  EXPECT_EQ(load_error().code, ErrorCode::kDataLoss);
}

TEST_F(StoreWithARule, AnUndeclaredVariableIsDataLoss) {
  with_body(open_rule_with("action_args", {7}));
  EXPECT_EQ(load_error().code, ErrorCode::kDataLoss);
  with_body(open_rule_with("action_args", {-1}));
  EXPECT_EQ(load_error().code, ErrorCode::kDataLoss);
}

TEST_F(StoreWithARule, AnActionArgumentNothingBindsIsDataLoss) {
  // ?s appears in no goal literal and no positive condition: the rule could
  // never say which object to act on.
  with_body(open_rule_with(nlohmann::json{
      {"action", "close"},
      {"action_args", {2}},
      {"conditions", {{{"predicate", "closed"}, {"positive", true}, {"args", {1}}},
                      {{"predicate", "on"}, {"positive", false}, {"args", {0, 2}}}}}}));
  Error e = load_error();
  EXPECT_EQ(e.code, ErrorCode::kDataLoss);
  EXPECT_THAT(e.message, HasSubstr("?s"));
}

TEST_F(StoreWithARule, AnActionOrPredicateTheDomainLacksIsAFailedPrecondition) {
  with_body(open_rule_with("action", "teleport"));
  Error e = load_error();
  EXPECT_EQ(e.code, ErrorCode::kFailedPrecondition);
  EXPECT_THAT(e.message, HasSubstr("teleport"));
  with_body(open_rule_with("goal", {{{"predicate", "sparkling"}, {"positive", true}, {"args", {1}}}}));
  e = load_error();
  EXPECT_EQ(e.code, ErrorCode::kFailedPrecondition);
  EXPECT_THAT(e.message, HasSubstr("sparkling"));
}

TEST_F(StoreWithARule, WrongArityIsDataLoss) {
  with_body(open_rule_with("action_args", {1, 2}));
  EXPECT_EQ(load_error().code, ErrorCode::kDataLoss);
  with_body(open_rule_with("goal", {{{"predicate", "closed"}, {"positive", true}, {"args", {1, 0}}}}));
  EXPECT_EQ(load_error().code, ErrorCode::kDataLoss);
}

TEST_F(Store, ADamagedGoalIsDataLoss) {
  {
    KnowledgeStore store = open_or_die(path_);
    fill(store);
  }
  {
    SQLite::Database db(path_.string(), SQLite::OPEN_READWRITE);
    db.exec("UPDATE goals SET literals = '[{\"predicate\": \"in\"}]'");
  }
  KnowledgeStore store = open_or_die(path_);
  auto loaded = store.load(domain_);
  ASSERT_FALSE(loaded.has_value());
  EXPECT_EQ(loaded.error().code, ErrorCode::kDataLoss);
}

TEST_F(Store, AStoreInAMissingDirectoryCannotBeCreated) {
  auto opened = KnowledgeStore::open(dir_ / "no" / "such" / "dir" / "k.sqlite");
  ASSERT_FALSE(opened.has_value());
  EXPECT_EQ(opened.error().code, ErrorCode::kIo);
}

TEST_F(Store, AnEmptyFileIsAnEmptyStoreForAWriter) {
  // What a crash between creating the file and writing the schema leaves.
  // (A reader refuses it: store_hardening_test.cc.)
  write_bytes(path_, "");
  KnowledgeStore store = open_or_die(path_);
  auto loaded = store.load(domain_);
  ASSERT_TRUE(loaded.has_value());
  EXPECT_EQ(loaded->rules.size(), 0u);
}

class StoreCli : public Store {
 protected:
  void SetUp() override {
    KnowledgeStore store = open_or_die(path_);
    fill(store);
  }
};

TEST_F(StoreCli, KnowledgePrintsWhatWasLearned) {
  Invocation r = run_cli(dir_.path(), {"knowledge", "--knowledge", path_.string(), "--pddl"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("2 goals:"));
  EXPECT_THAT(r.out, HasSubstr("8 rules:"));
  EXPECT_THAT(r.out, HasSubstr("propose action open(?r) (4 steps to the goal)"));
  // In English by default.
  Invocation english = run_cli(dir_.path(), {"knowledge", "--knowledge", path_.string()});
  ASSERT_EQ(english.exit_code, 0) << english.err;
  EXPECT_THAT(english.out, HasSubstr("2 goals:"));
  EXPECT_THAT(english.out, HasSubstr("8 rules:"));
  EXPECT_THAT(english.out, HasSubstr(": open the receptacle (4 steps from the goal)."));
}

TEST_F(StoreCli, KnowledgePrintsOneHouseholdsGoalsAndTheSharedRules) {
  {
    auto smiths = KnowledgeStore::open(path_, StoreAccess::kReadWrite, "smiths");
    ASSERT_TRUE(smiths) << smiths.error().describe();
    ASSERT_TRUE(smiths->save_goal(paper_plate_goal()));
  }
  Invocation r = run_cli(dir_.path(), {"knowledge", "--knowledge", path_.string(), "--household", "smiths", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["household"], "smiths");
  EXPECT_EQ(json["goals"].size(), 1u);
  EXPECT_EQ(json["tasks"].size(), 0u);
  EXPECT_EQ(json["rules"].size(), rules().size());
  Invocation plain = run_cli(dir_.path(), {"knowledge", "--knowledge", path_.string(), "--json"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(nlohmann::json::parse(plain.out)["household"], kDefaultHousehold);
  EXPECT_EQ(nlohmann::json::parse(plain.out)["goals"].size(), 2u);
  Invocation english = run_cli(dir_.path(), {"knowledge", "--knowledge", path_.string(), "--household", "smiths"});
  ASSERT_EQ(english.exit_code, 0) << english.err;
  EXPECT_THAT(english.out, HasSubstr("Household smiths (the rules are shared by every household):"));
  EXPECT_THAT(english.out, HasSubstr("1 goal:"));
}

TEST_F(StoreCli, AHouseholdThatCannotBeNamedExitsTwoInOneLine) {
  const std::string scenario = scenario_path("tidy-kitchen").string();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"knowledge", "--knowledge", path_.string(), "--household", "the smiths"},
        std::vector<std::string>{"run", "--scenario", scenario, "--knowledge", path_.string(), "--household", ""},
        std::vector<std::string>{"teach", "--scenario", scenario, "--knowledge", path_.string(), "--household", "a/b"}}) {
    Invocation r = run_cli(dir_.path(), args);
    EXPECT_EQ(r.exit_code, 2) << args[0] << ": " << r.out << r.err;
    EXPECT_THAT(r.err, HasSubstr("cannot name a household")) << args[0];
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  Invocation copy = run_cli(dir_.path(), {"knowledge", "export", "--knowledge", path_.string(), "--to",
                                          (dir_ / "copy.sqlite").string(), "--household", "smiths"});
  EXPECT_EQ(copy.exit_code, 2) << copy.err;
  EXPECT_THAT(copy.err, HasSubstr("copies every household"));
}

TEST_F(StoreCli, ARobotThatCannotBeNamedExitsTwoInOneLine) {
  const std::string scenario = scenario_path("tidy-kitchen").string();
  for (const std::string& robot : {std::string("robot;1"), std::string(" robot"), std::string(65, 'r')}) {
    Invocation r = run_cli(dir_.path(), {"teach", "--scenario", scenario, "--knowledge", path_.string(), "--robot", robot});
    EXPECT_EQ(r.exit_code, 2) << robot << ": " << r.out << r.err;
    EXPECT_THAT(r.err, HasSubstr("cannot name a robot")) << robot;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

TEST_F(StoreCli, RefusedStoreExitsTwoNamingBothVersions) {
  set_schema_version(path_, "999");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"knowledge", "--knowledge", path_.string()},
        std::vector<std::string>{"run", "--scenario", scenario_path("tidy-kitchen").string(), "--knowledge",
                                 path_.string()}}) {
    Invocation r = run_cli(dir_.path(), args);
    EXPECT_EQ(r.exit_code, 2) << args[0] << ": " << r.out << r.err;
    EXPECT_THAT(r.err, HasSubstr("schema version 999")) << args[0];
    EXPECT_THAT(r.err, HasSubstr("reads version " + std::to_string(kKnowledgeSchemaVersion))) << args[0];
  }
}

TEST_F(StoreCli, ForeignDatabaseExitsTwo) {
  fs::path foreign = dir_ / "foreign.sqlite";
  {
    SQLite::Database db(foreign.string(), SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE);
    db.exec("CREATE TABLE recipes(name TEXT)");
  }
  Invocation r = run_cli(dir_.path(), {"knowledge", "--knowledge", foreign.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("another program"));
}

TEST_F(StoreCli, AFileOfAnotherKindExitsTwo) {
  // Not "data loss": nothing was lost, the file was never a store.
  write_bytes(path_, std::string(4096, '\x5a'));
  Invocation r = run_cli(dir_.path(), {"knowledge", "--knowledge", path_.string()});
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_THAT(r.err, HasSubstr("not an apprentice knowledge store"));
  EXPECT_THAT(r.err, ::testing::Not(HasSubstr("data loss")));
}

}  // namespace
}  // namespace apprentice
