// The knowledge store against hostile files and other processes (issue 11):
// stored JSON of the wrong type is refused, never converted; damage that
// SQLite's quick_check sees is refused before anything is written; goals
// that name a predicate the domain lacks, and task structures that are not
// lists of subtasks, are refused; read-only commands never write, and an
// empty or foreign file is "not a knowledge store"; a store another process
// has open is never emptied or deleted ("in use"), and concurrent writers
// both succeed.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>

#include <SQLiteCpp/SQLiteCpp.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "knowledge/store.h"
#include "knowledge_fixtures.h"

namespace apprentice {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;
using namespace apprentice::testing;

class StoreHardening : public KitchenStoreTest {
 protected:

  TaskKnowledge task(std::string name = "tidy kitchen") const {
    return TaskKnowledge{std::move(name), {{"clear", "on", "table"}, {"store", "on", "counter"}}};
  }
  GoalKnowledge goal_for(const std::string& object_id, const std::string& goal_text, const std::string& task_name) const {
    ObjectId object = testing::object(world_, object_id);
    const std::string category = world_.universe->info(object).category;
    auto k = generalize_goal(world_, GoalKey{task_name, "clear", category, "table"}, object,
                             testing::goal(world_, goal_text), Provenance{object_id, "instructor: \"...\""});
    EXPECT_TRUE(k.has_value());
    return *k;
  }
  GoalKnowledge plate_goal() const { return goal_for("ceramic-plate1", std::string(kCeramicPlateGoal), "tidy kitchen"); }

  void fill() {
    auto store = KnowledgeStore::open(path_);
    ASSERT_TRUE(store.has_value()) << store.error().describe();
    ASSERT_TRUE(store->save_task(task()));
    ASSERT_TRUE(store->save_goal(plate_goal()));
    for (const Rule& r : learn(world_, ceramic_plate_episode(world_), Generalization::kFull))
      ASSERT_TRUE(store->save_rule(domain_, r));
  }
  void exec(const std::string& sql) {
    SQLite::Database db(path_.string(), SQLite::OPEN_READWRITE);
    db.exec(sql);
  }
  Error load_error(StoreAccess access = StoreAccess::kReadOnly) {
    auto store = KnowledgeStore::open(path_, access);
    if (!store) return store.error();
    auto loaded = store->load(domain_);
    EXPECT_FALSE(loaded.has_value()) << "misread a damaged store";
    return loaded ? Error{ErrorCode::kCancelled, "loaded"} : loaded.error();
  }
  Invocation cli(const std::vector<std::string>& args) { return run_cli(dir_.path(), args); }
  std::vector<std::string> run_args() const {
    return {"run", "--scenario", scenario_path("tidy-kitchen").string(), "--knowledge", path_.string()};
  }
};

// ---- Stored JSON is read strictly (defect 1, stores) ----

TEST_F(StoreHardening, ANumberWhereAWholeNumberBelongsIsDataLossNotConverted) {
  // Before, 1e300 became an int by a cast, and 0.5 became variable 0.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"steps", "1e300"}, {"steps", "-4"}, {"steps", "4.5"}, {"action_args", "[0.5]"}, {"action_args", "[1e400]"}};
  for (const auto& [key, raw] : cases) {
    SCOPED_TRACE(key + ": " + raw);
    fs::remove(path_);
    fill();
    {
      SQLite::Database db(path_.string(), SQLite::OPEN_READWRITE);
      SQLite::Statement read(db, "SELECT id, body FROM rules ORDER BY id LIMIT 1");
      ASSERT_TRUE(read.executeStep());
      nlohmann::json body = nlohmann::json::parse(read.getColumn(1).getString());
      body[key] = "@@";
      // The raw text goes in as written, so that 1e400 reaches the reader.
      std::string text = body.dump();
      text.replace(text.find("\"@@\""), 4, raw);
      SQLite::Statement update(db, "UPDATE rules SET body = ? WHERE id = ?");
      update.bind(1, text);
      update.bind(2, read.getColumn(0).getInt());
      update.exec();
    }
    Error e = load_error();
    EXPECT_EQ(e.code, ErrorCode::kDataLoss) << e.describe();
    EXPECT_THAT(e.message, HasSubstr(path_.string()));
  }
}

// ---- Corruption (defect 5) ----

TEST_F(StoreHardening, ACorruptIndexPageIsRefusedOnOpenAndNotWrittenTo) {
  fill();
  int page_size = 0, root = 0;
  {
    SQLite::Database db(path_.string(), SQLite::OPEN_READONLY);
    page_size = db.execAndGet("PRAGMA page_size").getInt();
    root = db.execAndGet("SELECT rootpage FROM sqlite_master WHERE type = 'index' AND tbl_name = 'goals'").getInt();
  }
  ASSERT_GT(root, 1);
  {
    // An index b-tree leaf page's type byte is 0x0a; 0x07 is no page type.
    std::fstream file(path_, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(static_cast<std::streamoff>(page_size) * (root - 1));
    file.put('\x07');
  }
  const std::string damaged = read_text(path_);
  for (StoreAccess access : {StoreAccess::kReadOnly, StoreAccess::kReadWrite, StoreAccess::kFresh}) {
    auto store = KnowledgeStore::open(path_, access);
    ASSERT_FALSE(store.has_value()) << "a corrupt store opened";
    EXPECT_EQ(store.error().code, ErrorCode::kDataLoss);
    EXPECT_THAT(store.error().message, AllOf(HasSubstr(path_.string()), HasSubstr("damaged")));
  }
  EXPECT_EQ(read_text(path_), damaged) << "the damaged store was written to";
  Invocation r = cli({"knowledge", "--knowledge", path_.string()});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_THAT(r.err, HasSubstr("damaged"));
}

TEST_F(StoreHardening, AGoalUsingAPredicateTheDomainLacksIsRefused) {
  fill();
  exec(R"(UPDATE goals SET literals = '[{"predicate":"sparkling","positive":true,"args":[{"interest":true}]}]')");
  Error e = load_error();
  EXPECT_EQ(e.code, ErrorCode::kFailedPrecondition) << e.describe();
  EXPECT_THAT(e.message, AllOf(HasSubstr("sparkling"), HasSubstr("goal"), HasSubstr(domain_.name)));
  // The wrong number of arguments is damage.
  exec(R"(UPDATE goals SET literals = '[{"predicate":"closed","positive":true,"args":[{"interest":true},{"category":"table"}]}]')");
  EXPECT_EQ(load_error().code, ErrorCode::kDataLoss);
  Invocation r = cli(run_args());
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
}

TEST_F(StoreHardening, ATaskStructureThatIsNotAListOfSubtasksIsRefused) {
  fill();
  for (const char* structure : {"null", "[]", "{}", R"([{"verb":"clear","relation":"under","place":"table"}])",
                                R"([{"verb":"clear","relation":"on"}])", R"([{"verb":7,"relation":"on","place":"t"}])"}) {
    SCOPED_TRACE(structure);
    exec(std::string("UPDATE tasks SET structure = '") + structure + "'");
    Error e = load_error();
    EXPECT_EQ(e.code, ErrorCode::kDataLoss) << e.describe();
    EXPECT_THAT(e.message, HasSubstr("tidy kitchen"));
  }
  // Before, `run` took a null structure for a task of no subtasks and said
  // "No help was needed" at 11%.
  exec("UPDATE tasks SET structure = 'null'");
  Invocation r = cli(run_args());
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_THAT(r.out, Not(HasSubstr("No help was needed")));
  EXPECT_THAT(r.err, HasSubstr("task structure"));
}

// ---- Read-only commands never write; empty and foreign files (defect 6) ----

TEST_F(StoreHardening, AnEmptyFileIsNotAKnowledgeStoreAndStaysEmpty) {
  std::ofstream(path_, std::ios::binary).close();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"knowledge", "--knowledge", path_.string()}, run_args()}) {
    Invocation r = cli(args);
    EXPECT_EQ(r.exit_code, 2) << args[0] << ": " << r.err;
    EXPECT_THAT(r.err, AllOf(HasSubstr(path_.string()), HasSubstr("not an apprentice knowledge store"),
                             HasSubstr("empty")))
        << args[0];
    EXPECT_EQ(fs::file_size(path_), 0u) << args[0] << " wrote to the file";
  }
}

TEST_F(StoreHardening, AnEmptySqliteDatabaseIsNotAStoreForAReader) {
  { SQLite::Database db(path_.string(), SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE); }
  const std::string before = read_text(path_);
  auto store = KnowledgeStore::open(path_, StoreAccess::kReadOnly);
  ASSERT_FALSE(store.has_value());
  EXPECT_EQ(store.error().code, ErrorCode::kFailedPrecondition);
  EXPECT_EQ(read_text(path_), before);
}

TEST_F(StoreHardening, ReadOnlyCommandsLeaveTheFileAsItWas) {
  fill();
  const std::string before = read_text(path_);
  struct stat info_before {};
  ASSERT_EQ(::stat(path_.c_str(), &info_before), 0);
  Invocation k = cli({"knowledge", "--knowledge", path_.string()});
  EXPECT_EQ(k.exit_code, 0) << k.err;
  Invocation r = cli(run_args());
  EXPECT_THAT(r.exit_code, ::testing::AnyOf(0, 1)) << r.err;
  struct stat info_after {};
  ASSERT_EQ(::stat(path_.c_str(), &info_after), 0);
  EXPECT_EQ(read_text(path_), before);
  EXPECT_EQ(info_after.st_mtim.tv_sec, info_before.st_mtim.tv_sec);
  EXPECT_EQ(info_after.st_mtim.tv_nsec, info_before.st_mtim.tv_nsec);
}

TEST_F(StoreHardening, AMissingTableIsDamageNotAnIoError) {
  fill();
  exec("DROP TABLE goals");
  Error e = load_error();
  EXPECT_EQ(e.code, ErrorCode::kDataLoss) << e.describe();
  EXPECT_THAT(e.message, AllOf(HasSubstr("goals"), HasSubstr("damaged")));
  Invocation r = cli({"knowledge", "--knowledge", path_.string()});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_THAT(r.err, Not(HasSubstr("i/o error")));
  EXPECT_THAT(r.err, HasSubstr("goals table"));
}

TEST_F(StoreHardening, AReaderRollsBackWhatAKilledWriterLeft) {
  fill();
  const std::size_t goals_before = 1;
  pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // A writer killed mid-transaction, after SQLite spilled pages to the
    // database file: a hot journal.
    SQLite::Database db(path_.string(), SQLite::OPEN_READWRITE);
    db.exec("PRAGMA cache_size = 1");
    db.exec("BEGIN");
    for (int i = 0; i < 2000; ++i)
      db.exec("INSERT INTO goals(household, task, subtask, category, place, literals, object, source) VALUES ('default', 't', 's', 'c" +
              std::to_string(i) + "', 'p', '" + std::string(200, 'x') + "', 'o', 's')");
    ::raise(SIGKILL);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  ASSERT_TRUE(fs::exists(path_.string() + "-journal")) << "no hot journal to test with";
  auto store = KnowledgeStore::open(path_, StoreAccess::kReadOnly);
  ASSERT_TRUE(store.has_value()) << store.error().describe();
  auto loaded = store->load(domain_);
  ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
  EXPECT_EQ(loaded->goals.size(), goals_before);
}

// ---- Invalid UTF-8 in --json (defect 2) ----

TEST_F(StoreHardening, KnowledgeJsonOfATaskNameWithABadByteDoesNotAbort) {
  {
    auto store = KnowledgeStore::open(path_);
    ASSERT_TRUE(store.has_value());
    ASSERT_TRUE(store->save_task(task("tidy \xff kitchen")));
    ASSERT_TRUE(store->save_goal(goal_for("ceramic-plate1", std::string(kCeramicPlateGoal), "tidy \xff kitchen")));
  }
  Invocation r = cli({"knowledge", "--knowledge", path_.string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto json = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(json.is_discarded()) << r.out;
  EXPECT_EQ(json["tasks"][0]["name"], "tidy \xef\xbf\xbd kitchen");
}

// ---- Sharing a store between processes (defect 4) ----

TEST_F(StoreHardening, AStoreOpenElsewhereIsNeverStartedOver) {
  fill();
  auto reader = KnowledgeStore::open(path_, StoreAccess::kReadOnly);
  ASSERT_TRUE(reader.has_value());
  auto fresh = KnowledgeStore::open(path_, StoreAccess::kFresh);
  ASSERT_FALSE(fresh.has_value());
  EXPECT_EQ(fresh.error().code, ErrorCode::kIo);
  EXPECT_THAT(fresh.error().message, AllOf(HasSubstr(path_.string()), HasSubstr("in use")));
  auto loaded = reader->load(domain_);
  ASSERT_TRUE(loaded.has_value());
  EXPECT_EQ(loaded->goals.size(), 1u);
}

TEST_F(StoreHardening, AStoreBeingStartedOverIsInUseForOthers) {
  fill();
  auto fresh = KnowledgeStore::open(path_, StoreAccess::kFresh);
  ASSERT_TRUE(fresh.has_value()) << fresh.error().describe();
  auto loaded = fresh->load(domain_);
  ASSERT_TRUE(loaded.has_value());
  EXPECT_EQ(loaded->goals.size(), 0u) << "kFresh starts the store over";
  for (StoreAccess access : {StoreAccess::kReadOnly, StoreAccess::kReadWrite, StoreAccess::kFresh}) {
    auto other = KnowledgeStore::open(path_, access);
    ASSERT_FALSE(other.has_value());
    EXPECT_THAT(other.error().message, HasSubstr("in use"));
  }
}

TEST_F(StoreHardening, ExperimentIntoADirectoryWhoseStoreIsOpenExitsThreeAndKeepsIt) {
  const fs::path out = dir_ / "out";
  fs::create_directories(out);
  path_ = out / "instruction.sqlite";
  fill();
  auto holder = KnowledgeStore::open(path_);  // as another process's teach would
  ASSERT_TRUE(holder.has_value());
  Invocation r = cli({"experiment", "--scenario", scenario_path("tidy-kitchen").string(), "--conditions",
                      "instruction", "--knowledge-out", out.string()});
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_THAT(r.err, AllOf(HasSubstr("instruction.sqlite"), HasSubstr("in use")));
  auto loaded = holder->load(domain_);
  ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
  EXPECT_EQ(loaded->goals.size(), 1u) << "the store in use was emptied";
}

TEST_F(StoreHardening, TwoExperimentsIntoOneDirectoryLoseNothing) {
  const fs::path out = dir_ / "out";
  auto spawn = [&](const std::string& name) {
    std::string command = shell_quote(APPRENTICE_BINARY) + " experiment --scenario " +
                          shell_quote(scenario_path("tidy-kitchen").string()) +
                          " --conditions instruction --knowledge-out " + shell_quote(out.string()) + " >" +
                          shell_quote((dir_ / (name + ".out")).string()) + " 2>" +
                          shell_quote((dir_ / (name + ".err")).string());
    pid_t pid = ::fork();
    if (pid == 0) {
      ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    return pid;
  };
  pid_t a = spawn("a"), b = spawn("b");
  int status_a = 0, status_b = 0;
  ::waitpid(a, &status_a, 0);
  ::waitpid(b, &status_b, 0);
  const int exit_a = WEXITSTATUS(status_a), exit_b = WEXITSTATUS(status_b);
  // Each either ran (0) or was told the store is in use (3); at least one ran.
  for (auto [exit, name] : {std::pair{exit_a, "a"}, {exit_b, "b"}}) {
    EXPECT_TRUE(exit == 0 || exit == 3) << name << " exited " << exit << ": " << read_text(dir_ / (std::string(name) + ".err"));
    if (exit == 3) {
      EXPECT_THAT(read_text(dir_ / (std::string(name) + ".err")), HasSubstr("in use"));
    }
  }
  EXPECT_TRUE(exit_a == 0 || exit_b == 0);
  // The store holds a complete run: every goal the instructor gave.
  auto store = KnowledgeStore::open(out / "instruction.sqlite", StoreAccess::kReadOnly);
  ASSERT_TRUE(store.has_value()) << store.error().describe();
  auto loaded = store->load(domain_);
  ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
  EXPECT_EQ(loaded->goals.size(), 26u);
}

TEST_F(StoreHardening, TwoConcurrentWritersBothSucceedAndLoseNothing) {
  { ASSERT_TRUE(KnowledgeStore::open(path_).has_value()); }
  // Two processes, each saving 40 goals of its own task, interleaved.
  std::vector<GoalKnowledge> goals;
  for (const char* task_name : {"task a", "task b"}) {
    for (int i = 0; i < 40; ++i) {
      GoalKnowledge g = plate_goal();
      g.key.task = task_name;
      g.key.category = "category" + std::to_string(i);
      goals.push_back(g);
    }
  }
  std::vector<pid_t> children;
  for (int writer = 0; writer < 2; ++writer) {
    pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      auto store = KnowledgeStore::open(path_);
      if (!store) ::_exit(10);
      for (int i = 0; i < 40; ++i)
        if (!store->save_goal(goals[static_cast<std::size_t>(writer * 40 + i)])) ::_exit(11);
      if (!store->save_task(task(writer == 0 ? "task a" : "task b"))) ::_exit(12);
      ::_exit(0);
    }
    children.push_back(pid);
  }
  for (pid_t pid : children) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "a writer failed: " << WEXITSTATUS(status);
  }
  auto store = KnowledgeStore::open(path_, StoreAccess::kReadOnly);
  ASSERT_TRUE(store.has_value());
  auto loaded = store->load(domain_);
  ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
  EXPECT_EQ(loaded->goals.size(), 80u);
  EXPECT_EQ(loaded->tasks.size(), 2u);
}

}  // namespace
}  // namespace apprentice
