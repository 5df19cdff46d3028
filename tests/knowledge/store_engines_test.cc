// The knowledge store's promises (knowledge/store_engine.h), held by both
// engines: every test runs once on an SQLite file and once on a PostgreSQL
// database of the throwaway server (throwaway_postgres.h). What is saved is
// what is loaded, in order; a store of another version, another program's
// database, a missing table or a damaged entry is refused; a store in use is
// never started over; a reader writes nothing.
#include <SQLiteCpp/SQLiteCpp.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <libpq-fe.h>

#include <atomic>
#include <chrono>
#include <set>
#include <thread>

#include "knowledge/store.h"
#include "knowledge/store_codec.h"
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

  KnowledgeStore open_or_die(StoreAccess access = StoreAccess::kReadWrite,
                             const std::string& household = kDefaultHousehold, const std::string& robot = "") {
    auto store = KnowledgeStore::open(location_, access, household, robot);
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

  // meta's schema_version, read behind the engine's back.
  std::string schema_version() {
    if (GetParam() == Engine::kSqlite) {
      SQLite::Database db(path_.string(), SQLite::OPEN_READONLY);
      return db.execAndGet("SELECT value FROM meta WHERE key = 'schema_version'").getString();
    }
    PGconn* c = PQconnectdb(location_.c_str());
    PGresult* r = PQexec(c, "SELECT value FROM meta WHERE key = 'schema_version'");
    std::string value = PQresultStatus(r) == PGRES_TUPLES_OK && PQntuples(r) == 1 ? PQgetvalue(r, 0, 0) : "";
    PQclear(r);
    PQfinish(c);
    return value;
  }

  // A store as version 1 wrote it (one household, no household column),
  // holding task(), plate_goal() and rules(), made behind the engine's back.
  void make_version_1_store() {
    const bool sqlite = GetParam() == Engine::kSqlite;
    const std::string id = sqlite ? "INTEGER" : "BIGSERIAL";
    exec("CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL)");
    exec("CREATE TABLE goals(id " + id + " PRIMARY KEY, task TEXT NOT NULL, subtask TEXT NOT NULL, category TEXT NOT NULL, "
         "place TEXT NOT NULL, literals TEXT NOT NULL, object TEXT NOT NULL, source TEXT NOT NULL, "
         "UNIQUE(task, subtask, category, place))");
    exec("CREATE TABLE tasks(name TEXT PRIMARY KEY, structure TEXT NOT NULL)");
    exec("CREATE TABLE rules(id " + id + " PRIMARY KEY, signature TEXT NOT NULL UNIQUE, body TEXT NOT NULL, "
         "object TEXT NOT NULL, source TEXT NOT NULL)");
    exec("INSERT INTO meta VALUES ('format', 'apprentice-knowledge'), ('schema_version', '1')");
    auto quoted = [](std::string text) {
      for (std::size_t at = text.find('\''); at != std::string::npos; at = text.find('\'', at + 2)) text.insert(at, "'");
      return "'" + text + "'";
    };
    const GoalKnowledge g = plate_goal();
    exec("INSERT INTO goals(task, subtask, category, place, literals, object, source) VALUES (" + quoted(g.key.task) +
         ", " + quoted(g.key.subtask) + ", " + quoted(g.key.category) + ", " + quoted(g.key.place) + ", " +
         quoted(store_codec::encode_goal_literals(g)) + ", " + quoted(g.provenance.object) + ", " +
         quoted(g.provenance.source) + ")");
    exec("INSERT INTO tasks VALUES (" + quoted(task().name) + ", " + quoted(store_codec::encode_subtasks(task())) + ")");
    for (const Rule& r : rules())
      exec("INSERT INTO rules(signature, body, object, source) VALUES (" + quoted(rule_signature(domain_, r)) + ", " +
           quoted(store_codec::encode_rule(domain_, r)) + ", " + quoted(r.provenance.object) + ", " +
           quoted(r.provenance.source) + ")");
  }

  // The store at location_, made by this version, taken back to version
  // 3 behind the engine's back: goals and rules lose their robot.
  void make_version_3_store() {
    exec("ALTER TABLE goals DROP COLUMN robot");
    exec("ALTER TABLE rules DROP COLUMN robot");
    exec("UPDATE meta SET value = '3' WHERE key = 'schema_version'");
  }

  // What make_version_1_store put in, as `store` loads it.
  void expect_version_1_contents(const KnowledgeStore& store) {
    auto k = store.load(domain_);
    ASSERT_TRUE(k) << k.error().describe();
    ASSERT_EQ(k->goals.size(), 1u);
    EXPECT_EQ(k->goals.all()[0], plate_goal());
    ASSERT_EQ(k->tasks.size(), 1u);
    EXPECT_EQ(k->tasks[0], task());
    EXPECT_EQ(k->rules.rules(), rules());
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

// A store of schema version 2 (before class rules): read as it is by a
// reader, which writes nothing; brought up to this version by a writer,
// keeping everything in it.
TEST_P(StoreEngines, AVersion2StoreIsReadAsItIsAndGainsClassRulesWhenOpenedToWrite) {
  {
    KnowledgeStore store = open_or_die();
    fill(store);
  }
  make_version_3_store();
  exec("DROP TABLE class_rules");
  exec("DROP TABLE forgotten_rules");
  exec("UPDATE meta SET value = '2' WHERE key = 'schema_version'");
  {
    KnowledgeStore reader = open_or_die(StoreAccess::kReadOnly);
    auto loaded = reader.load(domain_);
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    expect_filled(*loaded);
    EXPECT_TRUE(loaded->class_rules.empty());
  }
  EXPECT_EQ(schema_version(), "2");
  {
    KnowledgeStore writer = open_or_die();
    EXPECT_EQ(schema_version(), std::to_string(kKnowledgeSchemaVersion));
    ASSERT_TRUE(writer.save_class_rule(said_plastic_rule()));
  }
  Knowledge k = load();
  expect_filled(k);
  EXPECT_EQ(k.class_rules.all(), std::vector<ClassRule>{said_plastic_rule()});
  // Opening again migrates nothing (a second CREATE TABLE would fail).
  KnowledgeStore again = open_or_die();
  EXPECT_TRUE(again.save_class_rule(induced_fruit_rule()));
}

// Class rules are a household's, as its goals are.
TEST_P(StoreEngines, ClassRulesAndForgettingAreEachHouseholdsOwn) {
  KnowledgeStore smiths = open_or_die(StoreAccess::kReadWrite, "smiths");
  KnowledgeStore joneses = open_or_die(StoreAccess::kReadWrite, "joneses");
  ASSERT_TRUE(smiths.save_class_rule(induced_fruit_rule()));
  ASSERT_TRUE(joneses.save_class_rule(induced_fruit_rule()));
  ASSERT_TRUE(joneses.forget_class_rule(induced_fruit_rule()));
  auto smiths_know = open_or_die(StoreAccess::kReadOnly, "smiths").load(domain_);
  auto joneses_know = open_or_die(StoreAccess::kReadOnly, "joneses").load(domain_);
  ASSERT_TRUE(smiths_know && joneses_know);
  EXPECT_EQ(smiths_know->class_rules.all(), std::vector<ClassRule>{induced_fruit_rule()});
  EXPECT_TRUE(smiths_know->forgotten_rules.empty());
  EXPECT_TRUE(joneses_know->class_rules.empty());
  EXPECT_TRUE(joneses_know->forgot(induced_fruit_rule()));
  auto names = smiths.households();
  ASSERT_TRUE(names);
  EXPECT_EQ(*names, (std::vector<std::string>{"joneses", "smiths"}));
  // Copied into the household of the same name.
  const fs::path copy = dir_ / "copy-rules.sqlite";
  auto copied = copy_knowledge(location_, copy.string(), domain_);
  ASSERT_TRUE(copied) << copied.error().describe();
  EXPECT_EQ(copied->class_rules, 1u);
  EXPECT_EQ(copied->forgotten_rules, 1u);
  auto joneses_copy = load_knowledge_read_only(copy.string(), domain_, "joneses");
  ASSERT_TRUE(joneses_copy);
  EXPECT_TRUE(joneses_copy->forgot(induced_fruit_rule()));
}

// Households: goals and task structures are each household's own, rules
// are the fleet's.
TEST_P(StoreEngines, TwoHouseholdsWantingDifferentPlacesForOneKindNeverOverwriteEachOther) {
  KnowledgeStore smiths = open_or_die(StoreAccess::kReadWrite, "smiths");
  KnowledgeStore joneses = open_or_die(StoreAccess::kReadWrite, "joneses");
  // The same key (task, subtask, category, place), two different goals.
  GoalKnowledge in_garbage = goal_for("ceramic-plate1", "(in ceramic-plate1 garbage1)");
  ASSERT_EQ(in_garbage.key, plate_goal().key);
  ASSERT_NE(in_garbage.literals, plate_goal().literals);
  TaskKnowledge shorter{"tidy kitchen", {{"clear", "on", "table"}}};
  ASSERT_TRUE(smiths.save_task(task()));
  ASSERT_TRUE(smiths.save_goal(plate_goal()));
  ASSERT_TRUE(joneses.save_task(shorter));
  ASSERT_TRUE(joneses.save_goal(in_garbage));
  const std::vector<Rule> taught = rules();
  ASSERT_TRUE(smiths.save_rule(domain_, taught[0]));
  ASSERT_TRUE(joneses.save_rule(domain_, taught[1]));
  // Saving again in one household leaves the other's as it was.
  ASSERT_TRUE(smiths.save_goal(plate_goal()));

  auto smiths_know = open_or_die(StoreAccess::kReadOnly, "smiths").load(domain_);
  auto joneses_know = open_or_die(StoreAccess::kReadOnly, "joneses").load(domain_);
  auto default_knows = open_or_die(StoreAccess::kReadOnly).load(domain_);
  ASSERT_TRUE(smiths_know && joneses_know && default_knows);
  ASSERT_EQ(smiths_know->goals.size(), 1u);
  EXPECT_EQ(smiths_know->goals.all()[0], plate_goal());
  ASSERT_EQ(joneses_know->goals.size(), 1u);
  EXPECT_EQ(joneses_know->goals.all()[0], in_garbage);
  ASSERT_EQ(smiths_know->tasks.size(), 1u);
  EXPECT_EQ(smiths_know->tasks[0], task());
  ASSERT_EQ(joneses_know->tasks.size(), 1u);
  EXPECT_EQ(joneses_know->tasks[0], shorter);
  // The rules are shared: each household has both, and so has one that
  // taught nothing.
  const std::vector<Rule> both{taught[0], taught[1]};
  EXPECT_EQ(smiths_know->rules.rules(), both);
  EXPECT_EQ(joneses_know->rules.rules(), both);
  EXPECT_EQ(default_knows->rules.rules(), both);
  EXPECT_EQ(default_knows->goals.size(), 0u);
  EXPECT_TRUE(default_knows->tasks.empty());

  // Forgetting is each household's own too.
  ASSERT_TRUE(joneses.remove_goal(in_garbage.key));
  ASSERT_TRUE(joneses.remove_task("tidy kitchen"));
  auto smiths_after = open_or_die(StoreAccess::kReadOnly, "smiths").load(domain_);
  ASSERT_TRUE(smiths_after);
  EXPECT_EQ(smiths_after->goals.size(), 1u);
  EXPECT_EQ(smiths_after->tasks.size(), 1u);
  auto names = smiths.households();
  ASSERT_TRUE(names) << names.error().describe();
  EXPECT_EQ(*names, std::vector<std::string>{"smiths"});
}

// The fleet's prior: a household loads every other household's goals
// with their household's name, never its own, and what the others chose
// proposes a destination for a kind it never taught.
TEST_P(StoreEngines, EachHouseholdLoadsTheOtherHouseholdsGoalsAsTheFleetsPrior) {
  KnowledgeStore smiths = open_or_die(StoreAccess::kReadWrite, "smiths");
  KnowledgeStore joneses = open_or_die(StoreAccess::kReadWrite, "joneses");
  KnowledgeStore browns = open_or_die(StoreAccess::kReadWrite, "browns");
  GoalKnowledge in_garbage = goal_for("ceramic-plate1", "(in ceramic-plate1 garbage1)");
  ASSERT_TRUE(smiths.save_goal(plate_goal()));
  ASSERT_TRUE(smiths.save_goal(paper_plate_goal()));
  ASSERT_TRUE(joneses.save_goal(in_garbage));
  ASSERT_TRUE(browns.save_goal(plate_goal()));

  auto newcomer = open_or_die(StoreAccess::kReadOnly, "newcomers").load(domain_);
  ASSERT_TRUE(newcomer) << newcomer.error().describe();
  EXPECT_EQ(newcomer->goals.size(), 0u);
  ASSERT_EQ(newcomer->fleet.size(), 4u);
  std::multiset<std::string> households;
  for (const FleetGoal& g : newcomer->fleet.all()) households.insert(g.household);
  EXPECT_EQ(households, (std::multiset<std::string>{"browns", "joneses", "smiths", "smiths"}));
  // Two of three households put the ceramic plate in the dishwasher.
  std::vector<DestinationProposal> plate = newcomer->fleet.propose(plate_goal().key);
  ASSERT_EQ(plate.size(), 2u);
  EXPECT_EQ(plate[0].source, ProposalSource::kFleet);
  EXPECT_EQ(format_destination(plate[0].destination), format_destination(*destination_of(plate_goal().literals)));
  EXPECT_EQ(plate[0].households, 2u);
  EXPECT_EQ(plate[0].of_households, 3u);
  EXPECT_DOUBLE_EQ(plate[0].confidence, 3.0 / 6.0);
  EXPECT_EQ(plate[1].households, 1u);
  EXPECT_DOUBLE_EQ(plate[1].confidence, 2.0 / 6.0);

  // Its own goals are not its prior: the smiths' fleet is the others'.
  auto smiths_know = open_or_die(StoreAccess::kReadOnly, "smiths").load(domain_);
  ASSERT_TRUE(smiths_know);
  EXPECT_EQ(smiths_know->goals.size(), 2u);
  ASSERT_EQ(smiths_know->fleet.size(), 2u);
  for (const FleetGoal& g : smiths_know->fleet.all()) EXPECT_NE(g.household, "smiths");
  // Nothing proposed for a kind no other household taught.
  EXPECT_TRUE(smiths_know->fleet.propose(paper_plate_goal().key).empty());
}

TEST_P(StoreEngines, AHouseholdNameThatCannotBeOneIsRefusedInOneSentence) {
  for (const std::string& bad : std::vector<std::string>{"", "two words", "semi;colon", "quote'd", std::string(65, 'a'), std::string("tab\there")}) {
    auto opened = KnowledgeStore::open(location_, StoreAccess::kReadWrite, bad);
    ASSERT_FALSE(opened.has_value()) << bad;
    EXPECT_EQ(opened.error().code, ErrorCode::kInvalidInput);
    EXPECT_THAT(opened.error().message, HasSubstr("cannot name a household"));
    EXPECT_THAT(opened.error().message, Not(HasSubstr("\n")));
    EXPECT_THAT(opened.error().message, Not(HasSubstr("\t")));
  }
  EXPECT_TRUE(KnowledgeStore::open(location_, StoreAccess::kReadWrite, "flat-2B_east.wing").has_value());
}

TEST_P(StoreEngines, AVersion1StoreIsReadAsItIsAndMigratedWhenOpenedToWrite) {
  make_version_1_store();
  // Read-only: read as it is, as the default household's; nothing written.
  {
    KnowledgeStore reader = open_or_die(StoreAccess::kReadOnly);
    expect_version_1_contents(reader);
    auto other = open_or_die(StoreAccess::kReadOnly, "joneses").load(domain_);
    ASSERT_TRUE(other);
    EXPECT_EQ(other->goals.size(), 0u);
    EXPECT_EQ(other->rules.rules(), rules());
    auto names = reader.households();
    ASSERT_TRUE(names);
    EXPECT_EQ(*names, std::vector<std::string>{kDefaultHousehold});
  }
  EXPECT_EQ(schema_version(), "1");
  // To write: migrated, once, and what it held is the default household's.
  {
    KnowledgeStore joneses = open_or_die(StoreAccess::kReadWrite, "joneses");
    EXPECT_EQ(schema_version(), std::to_string(kKnowledgeSchemaVersion));
    GoalKnowledge in_garbage = goal_for("ceramic-plate1", "(in ceramic-plate1 garbage1)");
    ASSERT_TRUE(joneses.save_goal(in_garbage));
    ASSERT_TRUE(joneses.save_task(TaskKnowledge{"tidy kitchen", {{"clear", "on", "table"}}}));
  }
  KnowledgeStore again = open_or_die();
  expect_version_1_contents(again);
  auto names = again.households();
  ASSERT_TRUE(names);
  EXPECT_EQ(*names, (std::vector<std::string>{kDefaultHousehold, "joneses"}));
}

TEST_P(StoreEngines, AVersion1StoreIsMigratedOnceByTwoOpenersAtOnce) {
  make_version_1_store();
  std::vector<std::thread> openers;
  std::atomic<int> opened{0};
  for (int i = 0; i < 4; ++i)
    openers.emplace_back([&, i] {
      auto store = KnowledgeStore::open(location_, StoreAccess::kReadWrite, "h" + std::to_string(i));
      if (store && store->save_goal(plate_goal())) ++opened;
    });
  for (std::thread& t : openers) t.join();
  EXPECT_EQ(opened.load(), 4);
  EXPECT_EQ(schema_version(), std::to_string(kKnowledgeSchemaVersion));
  KnowledgeStore store = open_or_die();
  auto names = store.households();
  ASSERT_TRUE(names);
  EXPECT_EQ(names->size(), 5u);
  auto k = store.load(domain_);
  ASSERT_TRUE(k);
  EXPECT_EQ(k->goals.size(), 1u);
}

TEST_P(StoreEngines, CopyingAStoreCopiesEveryHouseholdIntoItsOwn) {
  {
    KnowledgeStore smiths = open_or_die(StoreAccess::kReadWrite, "smiths");
    fill(smiths);
    KnowledgeStore joneses = open_or_die(StoreAccess::kReadWrite, "joneses");
    ASSERT_TRUE(joneses.save_goal(goal_for("ceramic-plate1", "(in ceramic-plate1 garbage1)")));
  }
  const fs::path copy = dir_ / "copy.sqlite";
  auto copied = copy_knowledge(location_, copy.string(), domain_);
  ASSERT_TRUE(copied) << copied.error().describe();
  EXPECT_EQ(copied->households, 2u);
  EXPECT_EQ(copied->goals, 3u);
  EXPECT_EQ(copied->tasks, 1u);
  EXPECT_EQ(copied->rules, rules().size());
  auto smiths = load_knowledge_read_only(copy.string(), domain_, "smiths");
  auto joneses = load_knowledge_read_only(copy.string(), domain_, "joneses");
  ASSERT_TRUE(smiths && joneses);
  expect_filled(*smiths);
  ASSERT_EQ(joneses->goals.size(), 1u);
  EXPECT_EQ(joneses->goals.all()[0].literals, goal_for("ceramic-plate1", "(in ceramic-plate1 garbage1)").literals);
}

// Version 3 to 4: a store written before robots were named opens, read as
// it is and migrated to write, with nothing lost; what it held names no
// robot, and what is saved after names its robot.
TEST_P(StoreEngines, AVersion3StoreLosesNothingAndWhatItHeldNamesNoRobot) {
  {
    KnowledgeStore store = open_or_die(StoreAccess::kReadWrite, kDefaultHousehold, "robot-1");
    fill(store);
    ASSERT_TRUE(store.save_class_rule(said_plastic_rule()));
    ASSERT_TRUE(store.forget_class_rule(induced_fruit_rule()));
  }
  make_version_3_store();
  {
    KnowledgeStore reader = open_or_die(StoreAccess::kReadOnly);
    auto loaded = reader.load(domain_);
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    expect_filled(*loaded);
    EXPECT_EQ(loaded->class_rules.all(), std::vector<ClassRule>{said_plastic_rule()});
    EXPECT_EQ(loaded->forgotten_rules.all(), std::vector<ClassRule>{induced_fruit_rule()});
  }
  EXPECT_EQ(schema_version(), "3");
  KnowledgeStore watcher = open_or_die(StoreAccess::kReadWrite, kDefaultHousehold, "watcher");
  EXPECT_EQ(schema_version(), "4");
  auto loaded = watcher.load(domain_);
  ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
  expect_filled(*loaded);
  EXPECT_EQ(loaded->class_rules.all(), std::vector<ClassRule>{said_plastic_rule()});
  EXPECT_EQ(loaded->forgotten_rules.all(), std::vector<ClassRule>{induced_fruit_rule()});
  // Each old row names no robot; a goal saved again now names its robot.
  auto robots = [&](const std::string& table) {
    std::vector<std::string> out;
    if (GetParam() == Engine::kSqlite) {
      SQLite::Database db(path_.string(), SQLite::OPEN_READONLY);
      SQLite::Statement rows(db, "SELECT robot FROM " + table + " ORDER BY id");
      while (rows.executeStep()) out.push_back(rows.getColumn(0).getString());
      return out;
    }
    PGconn* c = PQconnectdb(location_.c_str());
    PGresult* r = PQexec(c, ("SELECT robot FROM " + table + " ORDER BY id").c_str());
    for (int row = 0; PQresultStatus(r) == PGRES_TUPLES_OK && row < PQntuples(r); ++row)
      out.emplace_back(PQgetvalue(r, row, 0));
    PQclear(r);
    PQfinish(c);
    return out;
  };
  EXPECT_EQ(robots("goals"), (std::vector<std::string>{"", ""}));
  EXPECT_EQ(robots("rules"), std::vector<std::string>(rules().size(), ""));
  {
    KnowledgeStore robot2 = open_or_die(StoreAccess::kReadWrite, kDefaultHousehold, "Robot 2");
    ASSERT_TRUE(robot2.save_goal(plate_goal()));
  }
  EXPECT_EQ(robots("goals"), (std::vector<std::string>{"", "Robot 2"}));
  StoreNews got;
  for (int tries = 0; tries < 1000 && got.goals.empty(); ++tries) {
    auto more = watcher.news(domain_);
    ASSERT_TRUE(more) << more.error().describe();
    got = std::move(*more);
    if (got.goals.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_EQ(got.goals.size(), 1u);
  EXPECT_EQ(got.goals[0], plate_goal());
  EXPECT_EQ(got.goal_robots, std::vector<std::string>{"Robot 2"});
}

TEST_P(StoreEngines, ARobotNameThatCannotBeOneIsRefusedInOneSentence) {
  for (const std::string& bad :
       {std::string(" robot"), std::string("robot\n2"), std::string(65, 'r'), std::string("r;DROP TABLE goals")}) {
    auto opened = KnowledgeStore::open(location_, StoreAccess::kReadWrite, kDefaultHousehold, bad);
    ASSERT_FALSE(opened.has_value()) << bad;
    EXPECT_EQ(opened.error().code, ErrorCode::kInvalidInput);
    EXPECT_THAT(opened.error().message, HasSubstr("cannot name a robot"));
    EXPECT_THAT(opened.error().message, Not(HasSubstr("\n")));
  }
  // No name: the host's (or "robot"), never empty.
  KnowledgeStore store = open_or_die();
  EXPECT_EQ(store.robot(), default_robot_name());
  EXPECT_FALSE(store.robot().empty());
  EXPECT_TRUE(check_robot_name(store.robot()));
}

// Live: what another connection saves is news to a running store; its own
// saves and other households' goals are not.
TEST_P(StoreEngines, NewsIsWhatAnotherRobotSavedSinceTheStoreWasOpenedOrLastAsked) {
  KnowledgeStore watcher = open_or_die(StoreAccess::kReadWrite, "smiths");
  ASSERT_TRUE(watcher.load(domain_));
  auto news = watcher.news(domain_);
  ASSERT_TRUE(news) << news.error().describe();
  EXPECT_TRUE(news->empty());
  const std::vector<Rule> taught = rules();
  {
    KnowledgeStore robot2 = open_or_die(StoreAccess::kReadWrite, "smiths", "robot-2");
    KnowledgeStore elsewhere = open_or_die(StoreAccess::kReadWrite, "joneses");
    ASSERT_TRUE(robot2.save_goal(plate_goal()));
    ASSERT_TRUE(elsewhere.save_goal(paper_plate_goal()));
    ASSERT_TRUE(elsewhere.save_rule(domain_, taught[0]));
  }
  // Notifications reach PostgreSQL's listener a moment after the commit:
  // ask until something comes (the benchmark measures how long it takes).
  StoreNews got;
  for (int tries = 0; tries < 1000 && got.goals.size() + got.rules.size() < 2; ++tries) {
    auto more = watcher.news(domain_);
    ASSERT_TRUE(more) << more.error().describe();
    for (GoalKnowledge& g : more->goals) got.goals.push_back(std::move(g));
    for (std::string& r : more->goal_robots) got.goal_robots.push_back(std::move(r));
    for (Rule& r : more->rules) got.rules.push_back(std::move(r));
    if (got.goals.size() + got.rules.size() < 2) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_EQ(got.goals.size(), 1u);
  EXPECT_EQ(got.goals[0], plate_goal());  // the joneses' paper plate is not the smiths' news
  EXPECT_EQ(got.goal_robots, std::vector<std::string>{"robot-2"});  // who learned it
  ASSERT_EQ(got.rules.size(), 1u);        // a rule is the fleet's, whoever taught it
  EXPECT_EQ(got.rules[0], taught[0]);
  // Told once; and what the watcher saves itself is not news to it.
  ASSERT_TRUE(watcher.save_goal(paper_plate_goal()));
  ASSERT_TRUE(watcher.save_rule(domain_, taught[1]));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  auto after = watcher.news(domain_);
  ASSERT_TRUE(after) << after.error().describe();
  EXPECT_TRUE(after->empty());
}

std::string engine_name(const ::testing::TestParamInfo<Engine>& info) {
  return info.param == Engine::kSqlite ? "sqlite" : "postgres";
}

INSTANTIATE_TEST_SUITE_P(, StoreEngines, ::testing::Values(Engine::kSqlite, Engine::kPostgres), engine_name);

}  // namespace
}  // namespace apprentice
