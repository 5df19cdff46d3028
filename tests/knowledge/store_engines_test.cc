// The knowledge store's promises (knowledge/store_engine.h), held by both
// engines: every test runs once on an SQLite file and once on a PostgreSQL
// database of the throwaway server (throwaway_postgres.h). What is saved is
// what is loaded, in order; a store of another version, another program's
// database, a missing table or a damaged entry is refused; a store in use is
// never started over; a reader writes nothing.
#include <SQLiteCpp/SQLiteCpp.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "knowledge/store.h"
#include "knowledge_fixtures.h"
#include "throwaway_postgres.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using namespace apprentice::testing;

enum class Engine { kSqlite, kPostgres };
void PrintTo(Engine engine, std::ostream* out) { *out << (engine == Engine::kSqlite ? "sqlite" : "postgres"); }

class StoreEngines : public KitchenStoreTest, public ::testing::WithParamInterface<Engine> {
 protected:
  void SetUp() override {
    if (GetParam() == Engine::kSqlite) {
      location_ = path_.string();
      return;
    }
    APPRENTICE_REQUIRE_POSTGRES(server_);
    database_.emplace(*server_);
    ASSERT_EQ(database_->error(), "");
    location_ = database_->url();
  }

  // Runs SQL on the store behind the engine's back, as another program
  // (or damage) would.
  void exec(const std::string& sql) {
    if (GetParam() == Engine::kSqlite) {
      SQLite::Database db(path_.string(), SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE);
      db.exec(sql);
    } else {
      ASSERT_EQ(database_->exec(sql), "") << sql;
    }
  }

  KnowledgeStore open_or_die(StoreAccess access = StoreAccess::kReadWrite) {
    auto store = KnowledgeStore::open(location_, access);
    if (!store) {
      ADD_FAILURE() << store.error().describe();
      std::abort();
    }
    return std::move(*store);
  }

  TaskKnowledge task() const {
    return TaskKnowledge{"tidy kitchen",
                         {{"clear", "on", "table"}, {"store", "on", "counter"}, {"unload", "in", "dish-rack"}}};
  }
  GoalKnowledge goal_for(const std::string& object_id, const std::string& goal_text) const {
    ObjectId object = testing::object(world_, object_id);
    const std::string category = world_.universe->info(object).category;
    auto k = generalize_goal(world_, GoalKey{"tidy kitchen", "clear", category, "table"}, object,
                             testing::goal(world_, goal_text), Provenance{object_id + " (" + category + ")", "instructor"});
    EXPECT_TRUE(k.has_value());
    return *k;
  }
  GoalKnowledge plate_goal() const { return goal_for("ceramic-plate1", std::string(kCeramicPlateGoal)); }
  GoalKnowledge paper_plate_goal() const { return goal_for("paper-plate1", "(in paper-plate1 garbage1)"); }
  std::vector<Rule> rules() const {
    std::vector<Rule> out = learn(world_, ceramic_plate_episode(world_), Generalization::kPaper);
    for (Rule& r : learn(world_, ceramic_plate_episode(world_), Generalization::kFull)) out.push_back(std::move(r));
    return out;
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
    ASSERT_EQ(k.goals.size(), 2u);
    EXPECT_EQ(k.goals.all()[0], plate_goal());
    EXPECT_EQ(k.goals.all()[1], paper_plate_goal());
    EXPECT_EQ(k.rules.rules(), rules());
  }
  Knowledge load(StoreAccess access = StoreAccess::kReadOnly) {
    KnowledgeStore store = open_or_die(access);
    auto loaded = store.load(domain_);
    EXPECT_TRUE(loaded.has_value()) << loaded.error().describe();
    return loaded ? std::move(*loaded) : Knowledge{};
  }
  Error open_error(StoreAccess access = StoreAccess::kReadWrite) {
    auto opened = KnowledgeStore::open(location_, access);
    EXPECT_FALSE(opened.has_value()) << "opened a store it should refuse";
    return opened ? Error{} : opened.error();
  }

  std::optional<ThrowawayPostgres> server_;
  std::optional<TestDatabase> database_;
  std::string location_;
};

TEST_P(StoreEngines, WhatIsSavedIsLoadedInOrderAcrossReopening) {
  {
    KnowledgeStore store = open_or_die();
    fill(store);
    auto loaded = store.load(domain_);
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    expect_filled(*loaded);
  }
  expect_filled(load());
}

TEST_P(StoreEngines, SavingAgainReplacesOrIgnoresAndAReplacedGoalMovesToTheEnd) {
  KnowledgeStore store = open_or_die();
  fill(store);
  fill(store);
  GoalKnowledge corrected = plate_goal();
  corrected.literals.pop_back();
  corrected.provenance.source = "instructor: corrected";
  ASSERT_TRUE(store.save_goal(corrected));
  TaskKnowledge shorter{"tidy kitchen", {{"clear", "on", "table"}}};
  ASSERT_TRUE(store.save_task(shorter));
  Knowledge k = load();
  EXPECT_EQ(k.rules.size(), rules().size());
  ASSERT_EQ(k.goals.size(), 2u);
  EXPECT_EQ(k.goals.all()[0], paper_plate_goal());
  EXPECT_EQ(k.goals.all()[1], corrected);
  ASSERT_EQ(k.tasks.size(), 1u);
  EXPECT_EQ(k.tasks[0], shorter);
}

TEST_P(StoreEngines, RemovingForgetsAndRemovingWhatIsAbsentIsNoError) {
  KnowledgeStore store = open_or_die();
  fill(store);
  ASSERT_TRUE(store.remove_goal(plate_goal().key));
  ASSERT_TRUE(store.remove_goal(plate_goal().key));
  ASSERT_TRUE(store.remove_rule(domain_, rules()[0]));
  ASSERT_TRUE(store.remove_task("tidy kitchen"));
  ASSERT_TRUE(store.remove_task("no such task"));
  Knowledge k = load();
  EXPECT_TRUE(k.tasks.empty());
  ASSERT_EQ(k.goals.size(), 1u);
  EXPECT_EQ(k.goals.all()[0], paper_plate_goal());
  EXPECT_EQ(k.rules.size(), rules().size() - 1);
}

TEST_P(StoreEngines, AStoreOfAnotherSchemaVersionIsRefusedNamingBothVersionsAndLeftAsItWas) {
  {
    KnowledgeStore store = open_or_die();
    fill(store);
  }
  exec("UPDATE meta SET value = '999' WHERE key = 'schema_version'");
  for (StoreAccess access : {StoreAccess::kReadWrite, StoreAccess::kReadOnly, StoreAccess::kFresh}) {
    Error e = open_error(access);
    EXPECT_EQ(e.code, ErrorCode::kFailedPrecondition);
    EXPECT_THAT(e.message, HasSubstr("schema version 999"));
    EXPECT_THAT(e.message, HasSubstr("reads version " + std::to_string(kKnowledgeSchemaVersion)));
  }
  exec("UPDATE meta SET value = '" + std::to_string(kKnowledgeSchemaVersion) + "' WHERE key = 'schema_version'");
  expect_filled(load());  // not even kFresh emptied it
}

TEST_P(StoreEngines, AnotherProgramsDatabaseIsRefusedAndLeftAsItWas) {
  exec("CREATE TABLE recipes(name TEXT, steps TEXT)");
  exec("INSERT INTO recipes VALUES ('pancakes', 'mix, fry')");
  for (StoreAccess access : {StoreAccess::kReadWrite, StoreAccess::kReadOnly, StoreAccess::kFresh}) {
    Error e = open_error(access);
    EXPECT_EQ(e.code, ErrorCode::kFailedPrecondition);
    EXPECT_THAT(e.message, HasSubstr("another program"));
  }
  exec("DELETE FROM recipes WHERE name = 'pancakes'");  // the table is still there, and no other was made
  Error e = open_error();
  EXPECT_THAT(e.message, HasSubstr("another program"));
}

TEST_P(StoreEngines, AMetaOfAnotherFormatIsRefused) {
  exec("CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL)");
  exec("INSERT INTO meta VALUES ('format', 'somebody-elses-format'), ('schema_version', '1')");
  Error e = open_error();
  EXPECT_EQ(e.code, ErrorCode::kFailedPrecondition);
  EXPECT_THAT(e.message, HasSubstr("not an apprentice knowledge store"));
}

TEST_P(StoreEngines, AStoreMissingATableIsDamaged) {
  {
    KnowledgeStore store = open_or_die();
    fill(store);
  }
  exec("DROP TABLE rules");
  for (StoreAccess access : {StoreAccess::kReadWrite, StoreAccess::kReadOnly}) {
    Error e = open_error(access);
    EXPECT_EQ(e.code, ErrorCode::kDataLoss) << e.describe();
    EXPECT_THAT(e.message, HasSubstr("damaged"));
  }
}

TEST_P(StoreEngines, ADamagedEntryIsDataLossWhenLoaded) {
  {
    KnowledgeStore store = open_or_die();
    fill(store);
  }
  exec("UPDATE goals SET literals = '[{\"predicate\": \"in\"}]'");
  KnowledgeStore store = open_or_die(StoreAccess::kReadOnly);
  auto loaded = store.load(domain_);
  ASSERT_FALSE(loaded.has_value());
  EXPECT_EQ(loaded.error().code, ErrorCode::kDataLoss);
  EXPECT_THAT(loaded.error().message, HasSubstr("unreadable"));
}

TEST_P(StoreEngines, AReaderNeedsAStoreAndWritesNothing) {
  Error missing = open_error(StoreAccess::kReadOnly);
  EXPECT_EQ(missing.code, ErrorCode::kNotFound) << missing.describe();
  {
    KnowledgeStore store = open_or_die();
    fill(store);
  }
  KnowledgeStore reader = open_or_die(StoreAccess::kReadOnly);
  GoalKnowledge other = plate_goal();
  other.key.category = "hammer";
  EXPECT_FALSE(reader.save_goal(other).has_value());
  expect_filled(load());
}

TEST_P(StoreEngines, AStoreInUseIsNeverStartedOver) {
  {
    KnowledgeStore store = open_or_die();
    fill(store);
  }
  {
    KnowledgeStore holder = open_or_die();  // as another process's teach would
    Error e = open_error(StoreAccess::kFresh);
    EXPECT_EQ(e.code, ErrorCode::kIo);
    EXPECT_THAT(e.message, HasSubstr("in use"));
  }
  expect_filled(load());
  {
    KnowledgeStore fresh = open_or_die(StoreAccess::kFresh);
    for (StoreAccess access : {StoreAccess::kReadWrite, StoreAccess::kReadOnly}) {
      Error e = open_error(access);
      EXPECT_THAT(e.message, HasSubstr("in use"));
    }
    auto loaded = fresh.load(domain_);
    ASSERT_TRUE(loaded.has_value());
    EXPECT_EQ(loaded->goals.size(), 0u);
    EXPECT_EQ(loaded->rules.size(), 0u);
    EXPECT_TRUE(loaded->tasks.empty());
  }
  KnowledgeStore after = open_or_die();
  EXPECT_TRUE(after.save_goal(plate_goal()));
}

ClassRule induced_fruit_rule() {
  ClassRule rule;
  rule.class_name = "edible fruit";
  rule.class_id = "wordnet:07705931";
  rule.destination = Destination{"in", GoalTemplateArgument{false, "fridge", {}},
                                 {GoalTemplateLiteral{"closed", true, {GoalTemplateArgument{false, "fridge", {}}}}}};
  rule.exceptions = {"pear"};
  rule.evidence = {"banana", "apple"};
  rule.confidence = 0.8312345678901234;
  rule.scope = GoalScope{"tidy kitchen", "clear", "table"};
  return rule;
}

ClassRule said_plastic_rule() {
  ClassRule rule;
  rule.class_name = "toys";
  rule.modifiers = {"plastic"};
  rule.rest = true;
  rule.destination = Destination{"on", GoalTemplateArgument{false, "counter", {"left"}}, {}};
  rule.source = RuleSource::kPerson;
  rule.said = "Put the other plastic toys on the left counter";
  rule.confidence = 0.95;
  return rule;
}

TEST_P(StoreEngines, ClassRulesAreKeptWithTheirEvidenceAndAForgottenOneStaysForgotten) {
  {
    KnowledgeStore store = open_or_die();
    fill(store);
    ASSERT_TRUE(store.save_class_rule(induced_fruit_rule()));
    ASSERT_TRUE(store.save_class_rule(said_plastic_rule()));
  }
  Knowledge k = load();
  expect_filled(k);
  EXPECT_EQ(k.class_rules.all(), (std::vector<ClassRule>{induced_fruit_rule(), said_plastic_rule()}));
  EXPECT_TRUE(k.forgotten_rules.empty());
  {
    // Saved again with more evidence: replaced, and last.
    KnowledgeStore store = open_or_die();
    ClassRule more = induced_fruit_rule();
    more.evidence.push_back("orange");
    more.confidence = 0.9;
    ASSERT_TRUE(store.save_class_rule(more));
    EXPECT_EQ(load().class_rules.all(), (std::vector<ClassRule>{said_plastic_rule(), more}));
    ASSERT_TRUE(store.forget_class_rule(more));
    ASSERT_TRUE(store.remove_class_rule(said_plastic_rule()));
    ASSERT_TRUE(store.remove_class_rule(said_plastic_rule()));  // not there: no error
  }
  k = load();
  EXPECT_TRUE(k.class_rules.empty());
  ASSERT_EQ(k.forgotten_rules.size(), 1u);
  EXPECT_EQ(k.forgotten_rules.all().front().evidence, (std::vector<std::string>{"banana", "apple", "orange"}));
  EXPECT_TRUE(k.forgot(induced_fruit_rule()));  // by its key, whatever its evidence
  EXPECT_FALSE(k.forgot(said_plastic_rule()));
  {
    // Said again, it is meant again.
    KnowledgeStore store = open_or_die();
    ASSERT_TRUE(store.save_class_rule(induced_fruit_rule()));
  }
  k = load();
  EXPECT_TRUE(k.forgotten_rules.empty());
  EXPECT_EQ(k.class_rules.all(), std::vector<ClassRule>{induced_fruit_rule()});
  // Started over, none are left.
  {
    KnowledgeStore store = open_or_die();
    ASSERT_TRUE(store.forget_class_rule(said_plastic_rule()));
  }
  {
    KnowledgeStore fresh = open_or_die(StoreAccess::kFresh);
    auto loaded = fresh.load(domain_);
    ASSERT_TRUE(loaded.has_value());
    EXPECT_TRUE(loaded->class_rules.empty());
    EXPECT_TRUE(loaded->forgotten_rules.empty());
  }
}

TEST_P(StoreEngines, AClassRuleThatDoesNotReadIsDataLossWhenLoaded) {
  {
    KnowledgeStore store = open_or_die();
    ASSERT_TRUE(store.save_class_rule(induced_fruit_rule()));
  }
  exec("UPDATE class_rules SET body = '{\"class\": \"fruit\", \"confidence\": 7}'");
  KnowledgeStore store = open_or_die(StoreAccess::kReadOnly);
  auto loaded = store.load(domain_);
  ASSERT_FALSE(loaded.has_value());
  EXPECT_EQ(loaded.error().code, ErrorCode::kDataLoss);
  EXPECT_THAT(loaded.error().message, HasSubstr("a class rule"));
}

// A store of schema version 1 (before class rules): read as it is by a
// reader; brought up to this version by a writer,
// keeping everything in it.
TEST_P(StoreEngines, AStoreOfVersionOneIsReadAsItIsAndMigratedByAWriter) {
  {
    KnowledgeStore store = open_or_die();
    fill(store);
  }
  exec("DROP TABLE class_rules");
  exec("DROP TABLE forgotten_rules");
  exec("UPDATE meta SET value = '1' WHERE key = 'schema_version'");
  {
    KnowledgeStore reader = open_or_die(StoreAccess::kReadOnly);
    auto loaded = reader.load(domain_);
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    expect_filled(*loaded);
    EXPECT_TRUE(loaded->class_rules.empty());
  }
  {
    KnowledgeStore writer = open_or_die();
    ASSERT_TRUE(writer.save_class_rule(said_plastic_rule()));
  }
  Knowledge k = load();
  expect_filled(k);
  EXPECT_EQ(k.class_rules.all(), std::vector<ClassRule>{said_plastic_rule()});
  // The migration recorded the version: opening again migrates nothing
  // (a second CREATE TABLE would fail).
  KnowledgeStore again = open_or_die();
  EXPECT_TRUE(again.save_class_rule(induced_fruit_rule()));
}

std::string engine_name(const ::testing::TestParamInfo<Engine>& info) {
  return info.param == Engine::kSqlite ? "sqlite" : "postgres";
}

INSTANTIATE_TEST_SUITE_P(, StoreEngines, ::testing::Values(Engine::kSqlite, Engine::kPostgres), engine_name);

}  // namespace
}  // namespace apprentice
