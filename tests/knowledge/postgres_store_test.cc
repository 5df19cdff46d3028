// What only the PostgreSQL engine has to show: a server that cannot be
// reached at start is exit 3 with one line naming HOST:PORT/DB; a password
// is never printed; several processes writing into one database lose no
// goal, nor do writers killed mid-write; a server restart mid-session costs
// no write.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <optional>
#include <random>
#include <set>
#include <thread>
#include <utility>
#include <vector>

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

TEST(StoreLocation, APostgresUrlIsShownWithoutItsPassword) {
  EXPECT_TRUE(is_postgres_location("postgresql://robot@db/fleet"));
  EXPECT_TRUE(is_postgres_location("postgres://robot@db/fleet"));
  EXPECT_FALSE(is_postgres_location("fleet.sqlite"));
  EXPECT_FALSE(is_postgres_location("./postgresql://x"));
  EXPECT_EQ(scrub_store_location("postgresql://robot:s3cret@db:5432/fleet"), "postgresql://robot@db:5432/fleet");
  EXPECT_EQ(scrub_store_location("postgres://robot:p@ss:w@rd@db/fleet"), "postgres://robot@db/fleet");
  EXPECT_EQ(scrub_store_location("postgresql://db/fleet?password=s3cret&sslmode=disable"),
            "postgresql://db/fleet?sslmode=disable");
  EXPECT_EQ(scrub_store_location("postgresql://robot:s3cret@db"), "postgresql://robot@db");
  EXPECT_EQ(scrub_store_location("/tmp/k.sqlite"), "/tmp/k.sqlite");
}

class PostgresStore : public KitchenStoreTest {
 protected:
  void SetUp() override {
    APPRENTICE_REQUIRE_POSTGRES(server_);
    database_.emplace(*server_);
    ASSERT_EQ(database_->error(), "");
  }
  GoalKnowledge goal_numbered(int writer, int n) const {
    auto k = generalize_goal(world_, GoalKey{"tidy kitchen", "clear", "kind-" + std::to_string(writer) + "-" + std::to_string(n), "table"},
                             object(world_, "ceramic-plate1"), goal(world_, kCeramicPlateGoal),
                             Provenance{"writer " + std::to_string(writer), "test"});
    EXPECT_TRUE(k.has_value());
    return *k;
  }
  std::set<std::string> stored_categories() {
    auto store = KnowledgeStore::open(database_->url(), StoreAccess::kReadOnly);
    EXPECT_TRUE(store.has_value()) << store.error().describe();
    if (!store) return {};
    auto loaded = store->load(domain_);
    EXPECT_TRUE(loaded.has_value()) << loaded.error().describe();
    std::set<std::string> out;
    if (loaded)
      for (const GoalKnowledge& g : loaded->goals.all()) out.insert(g.key.category);
    return out;
  }
  // Forks a writer that saves `count` goals, writing each one's category
  // and '\n' to `confirmed` once its save has returned; exits 0 when all
  // were saved.
  pid_t spawn_writer(int writer, int count, int confirmed) {
    pid_t pid = ::fork();
    if (pid != 0) return pid;
    // A writer that fails says why on stderr (the test's output) before
    // its exit status says where.
    auto store = KnowledgeStore::open(database_->url());
    if (!store) {
      std::fprintf(stderr, "writer %d: %s\n", writer, store.error().describe().c_str());
      ::_exit(10);
    }
    for (int n = 0; n < count; ++n) {
      GoalKnowledge g = goal_numbered(writer, n);
      if (auto saved = store->save_goal(g); !saved) {
        std::fprintf(stderr, "writer %d: %s\n", writer, saved.error().describe().c_str());
        ::_exit(11);
      }
      const std::string line = g.key.category + "\n";
      if (::write(confirmed, line.data(), line.size()) != static_cast<ssize_t>(line.size())) ::_exit(12);
    }
    ::_exit(0);
  }
  static std::set<std::string> read_lines(int fd) {
    std::string text;
    char buffer[4096];
    for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
    std::set<std::string> out;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) out.insert(line);
    return out;
  }

  std::optional<ThrowawayPostgres> server_;
  std::optional<TestDatabase> database_;
  ScratchDir scratch_;
};

// A port of 127.0.0.1 nothing listens on.
int closed_port() {
  int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address);
  socklen_t size = sizeof address;
  ::getsockname(s, reinterpret_cast<sockaddr*>(&address), &size);
  ::close(s);
  return ntohs(address.sin_port);
}

TEST_F(PostgresStore, AnUnreachableServerAtStartIsExitThreeWithOneLineNamingItAndNoPassword) {
  const std::string port = std::to_string(closed_port());
  const std::string url = "postgresql://robot:hunter2-secret@127.0.0.1:" + port + "/fleet";
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"knowledge", "--knowledge", url},
        std::vector<std::string>{"run", "--scenario", scenario_path("tidy-kitchen").string(), "--knowledge", url},
        std::vector<std::string>{"teach", "--scenario", scenario_path("tidy-kitchen").string(), "--knowledge", url}}) {
    Invocation r = run_cli(scratch_.path(), args);
    EXPECT_EQ(r.exit_code, 3) << args[0] << ": " << r.out << r.err;
    EXPECT_THAT(r.err, HasSubstr("127.0.0.1:" + port + "/fleet")) << args[0];
    EXPECT_THAT(r.err, HasSubstr("cannot connect to the PostgreSQL server")) << args[0];
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args[0] << ": " << r.err;
    EXPECT_THAT(r.out + r.err, Not(HasSubstr("hunter2"))) << args[0];
  }
}

TEST_F(PostgresStore, APasswordIsNeverPrintedRightOrWrong) {
  // A store to read, over TCP with the password.
  {
    auto store = KnowledgeStore::open(database_->url());
    ASSERT_TRUE(store.has_value()) << store.error().describe();
    ASSERT_TRUE(store->save_goal(goal_numbered(0, 0)));
    EXPECT_THAT(store->location(), Not(HasSubstr(server_->password)));
  }
  const std::string right = database_->tcp_url();
  auto opened = KnowledgeStore::open(right, StoreAccess::kReadOnly);
  ASSERT_TRUE(opened.has_value()) << opened.error().describe();
  EXPECT_THAT(opened->location(), Not(HasSubstr(server_->password)));
  EXPECT_THAT(opened->location(), HasSubstr("127.0.0.1"));
  Invocation shown = run_cli(scratch_.path(), {"knowledge", "--knowledge", right});
  EXPECT_EQ(shown.exit_code, 0) << shown.err;
  EXPECT_THAT(shown.out, HasSubstr("1 goal"));
  Invocation experiment = run_cli(scratch_.path(), {"experiment", "--scenario", scenario_path("tidy-kitchen").string(),
                                                    "--conditions", "instruction", "--knowledge-in", right, "-v"});
  EXPECT_EQ(experiment.exit_code, 0) << experiment.err;
  EXPECT_THAT(experiment.out, HasSubstr("starts from the knowledge in postgresql://apprentice@127.0.0.1"));
  // A task that is not there: the message names the store.
  Invocation missing = run_cli(scratch_.path(), {"run", "--scenario", scenario_path("tidy-kitchen").string(),
                                                 "--knowledge", right, "--task", "wash the car"});
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_THAT(missing.err, HasSubstr("127.0.0.1"));
  // A refused store: the message names it.
  ASSERT_EQ(database_->exec("UPDATE meta SET value = '999' WHERE key = 'schema_version'"), "");
  Invocation refused = run_cli(scratch_.path(), {"knowledge", "--knowledge", right});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_THAT(refused.err, HasSubstr("schema version 999"));
  // A wrong password: refused, exit 3, and neither password shown.
  const std::string wrong = "postgresql://apprentice:wrong-horse-battery@127.0.0.1:" + server_->port + "/" + database_->name();
  Invocation denied = run_cli(scratch_.path(), {"knowledge", "--knowledge", wrong});
  EXPECT_EQ(denied.exit_code, 3) << denied.err;
  EXPECT_THAT(denied.err, HasSubstr("password authentication failed"));
  for (const Invocation& r : {shown, experiment, missing, refused, denied}) {
    EXPECT_THAT(r.out + r.err, Not(HasSubstr(server_->password)));
    EXPECT_THAT(r.out + r.err, Not(HasSubstr("wrong-horse-battery")));
  }
}

TEST_F(PostgresStore, EightProcessesWritingAtOnceLoseNoGoal) {
  constexpr int kWriters = 8, kGoals = 40;
  int pipe_fds[2];
  ASSERT_EQ(::pipe(pipe_fds), 0);
  std::vector<pid_t> writers;
  for (int w = 0; w < kWriters; ++w) writers.push_back(spawn_writer(w, kGoals, pipe_fds[1]));
  ::close(pipe_fds[1]);
  std::set<std::string> confirmed = read_lines(pipe_fds[0]);
  ::close(pipe_fds[0]);
  for (pid_t pid : writers) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "writer exit status " << status;
  }
  EXPECT_EQ(confirmed.size(), static_cast<std::size_t>(kWriters * kGoals));
  EXPECT_EQ(stored_categories(), confirmed);
}

TEST_F(PostgresStore, WritersKilledMidWriteLoseNoConfirmedGoal) {
  // Eight writers that would write for ever, each SIGKILLed a seeded
  // random 0 to 150 ms after its first goal was confirmed (not after a
  // fixed time from its start: on a loaded machine a writer may not have
  // connected yet, and a kill before any save tests nothing). Every goal a
  // writer was told was saved is in the store, and the store still loads.
  constexpr int kWriters = 8, kGoals = 1000000;
  std::mt19937 random(23);
  int pipe_fds[2];
  ASSERT_EQ(::pipe(pipe_fds), 0);
  std::vector<pid_t> writers;
  for (int w = 0; w < kWriters; ++w) writers.push_back(spawn_writer(w, kGoals, pipe_fds[1]));
  ::close(pipe_fds[1]);
  std::set<std::string> confirmed;
  std::vector<int> saved_by(kWriters, 0);
  std::vector<std::optional<std::chrono::steady_clock::time_point>> kill_at(kWriters);
  std::vector<bool> killed_mid_run(kWriters, false);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  std::string partial;
  // Reads what the writers confirm until every writer was killed (or
  // ended on its own) and the pipe is closed.
  for (bool open = true; open;) {
    pollfd in{pipe_fds[0], POLLIN, 0};
    if (::poll(&in, 1, 5) > 0) {
      char buffer[4096];
      const ssize_t n = ::read(pipe_fds[0], buffer, sizeof buffer);
      if (n <= 0) open = false;
      else partial.append(buffer, static_cast<std::size_t>(n));
      for (std::size_t end; (end = partial.find('\n')) != std::string::npos; partial.erase(0, end + 1)) {
        const std::string line = partial.substr(0, end);
        confirmed.insert(line);
        const int w = std::stoi(line.substr(5));  // "kind-W-N"
        if (saved_by[w]++ == 0)
          kill_at[w] = std::chrono::steady_clock::now() + std::chrono::milliseconds(random() % 150);
      }
    }
    const auto now = std::chrono::steady_clock::now();
    for (int w = 0; w < kWriters; ++w)
      if (kill_at[w] && now >= *kill_at[w]) {
        kill_at[w].reset();
        killed_mid_run[w] = ::kill(writers[w], SIGKILL) == 0;
      }
    if (now > give_up) {
      ADD_FAILURE() << "a writer confirmed nothing in 120 s";
      for (pid_t pid : writers) ::kill(pid, SIGKILL);
      break;
    }
    // The pipe closes when every writer has ended, killed or not.
    if (!open) break;
  }
  ::close(pipe_fds[0]);
  int killed = 0;
  for (pid_t pid : writers) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) ++killed;
  }
  std::set<std::string> stored = stored_categories();
  for (const std::string& category : confirmed) EXPECT_TRUE(stored.count(category)) << category << " was confirmed and lost";
  // Every kill landed mid-run, after its writer's first confirmed goal.
  EXPECT_EQ(killed, kWriters);
  for (int w = 0; w < kWriters; ++w) {
    EXPECT_TRUE(killed_mid_run[w]) << "writer " << w;
    EXPECT_GT(saved_by[w], 0) << "writer " << w;
  }
  std::cout << killed << " of " << kWriters << " writers killed; " << confirmed.size() << " goals confirmed, "
            << stored.size() << " stored\n";
}

// Two households writing the same kinds at the same moment, each with its
// own place for them: each keeps its own, none of the other's.
TEST_F(PostgresStore, TwoHouseholdsWritingTheSameKindsAtOnceEachKeepTheirOwn) {
  constexpr int kKinds = 60;
  const std::vector<std::pair<std::string, std::string>> households{
      {"smiths", std::string(kCeramicPlateGoal)}, {"joneses", "(in ceramic-plate1 garbage1)"}};
  auto goal_of = [&](const std::string& goal_text, int n) {
    auto k = generalize_goal(world_, GoalKey{"tidy kitchen", "clear", "kind-" + std::to_string(n), "table"},
                             object(world_, "ceramic-plate1"), goal(world_, goal_text), Provenance{"", "test"});
    EXPECT_TRUE(k.has_value());
    return *k;
  };
  int go[2];
  ASSERT_EQ(::pipe(go), 0);
  std::vector<pid_t> writers;
  for (const auto& [household, goal_text] : households) {
    pid_t pid = ::fork();
    if (pid == 0) {
      ::close(go[1]);
      auto store = KnowledgeStore::open(database_->url(), StoreAccess::kReadWrite, household);
      if (!store) {
        std::fprintf(stderr, "%s: %s\n", household.c_str(), store.error().describe().c_str());
        ::_exit(10);
      }
      char byte;
      (void)::read(go[0], &byte, 1);  // both start when the pipe closes
      for (int n = 0; n < kKinds; ++n)
        if (auto saved = store->save_goal(goal_of(goal_text, n)); !saved) {
          std::fprintf(stderr, "%s: %s\n", household.c_str(), saved.error().describe().c_str());
          ::_exit(11);
        }
      ::_exit(0);
    }
    writers.push_back(pid);
  }
  ::close(go[0]);
  ::close(go[1]);
  for (pid_t pid : writers) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "writer exit status " << status;
  }
  for (const auto& [household, goal_text] : households) {
    auto store = KnowledgeStore::open(database_->url(), StoreAccess::kReadOnly, household);
    ASSERT_TRUE(store.has_value()) << store.error().describe();
    auto loaded = store->load(domain_);
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    ASSERT_EQ(loaded->goals.size(), static_cast<std::size_t>(kKinds)) << household;
    for (int n = 0; n < kKinds; ++n) {
      const GoalKnowledge wanted = goal_of(goal_text, n);
      const GoalKnowledge* kept = loaded->goals.find(wanted.key);
      ASSERT_NE(kept, nullptr) << household << " lost kind-" << n;
      EXPECT_EQ(kept->literals, wanted.literals) << household << ", kind-" << n;
    }
    // The other household's goals are its fleet's prior, not its own.
    EXPECT_EQ(loaded->fleet.size(), static_cast<std::size_t>(kKinds)) << household;
  }
}

// Knowledge learned into SQLite, exported into PostgreSQL and imported back
// into a new SQLite file, is the same knowledge; and a run from the
// PostgreSQL store does the task alone.
TEST_F(PostgresStore, ExportAndImportMoveKnowledgeBetweenTheEnginesUnchanged) {
  const std::string kitchen = scenario_path("tidy-kitchen").string();
  Invocation learned = run_cli(scratch_.path(), {"experiment", "--scenario", kitchen, "--conditions", "instruction",
                                                 "--knowledge-out", (scratch_ / "learned").string()});
  ASSERT_EQ(learned.exit_code, 0) << learned.err;
  const std::string sqlite = (scratch_ / "learned" / "instruction.sqlite").string();
  const std::string back = (scratch_ / "back.sqlite").string();
  Invocation exported = run_cli(scratch_.path(), {"knowledge", "export", "--knowledge", sqlite, "--to", database_->url()});
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_THAT(exported.out, HasSubstr("Copied 1 task, 26 goals and 8 rules"));
  Invocation imported = run_cli(scratch_.path(), {"knowledge", "import", "--knowledge", back, "--from", database_->url()});
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  EXPECT_THAT(imported.out, HasSubstr("Copied 1 task, 26 goals and 8 rules"));
  auto json_of = [&](const std::string& store) {
    Invocation r = run_cli(scratch_.path(), {"knowledge", "--knowledge", store, "--json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.out;
  };
  const std::string original = json_of(sqlite);
  EXPECT_THAT(original, HasSubstr("\"goals\""));
  EXPECT_EQ(json_of(database_->url()), original);
  EXPECT_EQ(json_of(back), original);
  // Exporting again changes nothing: the copy is idempotent.
  ASSERT_EQ(run_cli(scratch_.path(), {"knowledge", "export", "--knowledge", sqlite, "--to", database_->url()}).exit_code, 0);
  EXPECT_EQ(json_of(database_->url()), original);
  Invocation run = run_cli(scratch_.path(), {"run", "--scenario", kitchen, "--knowledge", database_->url()});
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_THAT(run.out, HasSubstr("No help was needed."));
  // Asked the wrong way, it says how.
  Invocation wrong = run_cli(scratch_.path(), {"knowledge", "export", "--knowledge", sqlite, "--from", back});
  EXPECT_EQ(wrong.exit_code, 2);
  EXPECT_THAT(wrong.err, HasSubstr("--to STORE"));
}

// A server of its own, restarted while a store is open: the next save and
// load make the connection again, and nothing confirmed is lost.
TEST(PostgresRestart, AServerRestartMidSessionCostsNoWrite) {
  std::optional<ThrowawayPostgres> shared;
  APPRENTICE_REQUIRE_POSTGRES(shared);
  ScratchDir scratch;
  const std::string script = source_path("scripts/pg-throwaway.sh").string();
  const std::string state = (scratch / "pg").string();
  ASSERT_EQ(std::system(("bash " + shell_quote(script) + " start " + shell_quote(state) + " >/dev/null").c_str()), 0);
  struct Stop {
    std::string command;
    ~Stop() { (void)std::system(command.c_str()); }
  } stop{"bash " + shell_quote(script) + " stop " + shell_quote(state)};
  const std::string url = "postgresql://apprentice@/postgres?host=" + first_line_of(scratch / "pg" / "server") +
                          "&port=" + first_line_of(scratch / "pg" / "port");
  Scenario kitchen = tidy_kitchen();
  const World& world = kitchen.world;
  auto goal_of = [&](const std::string& category) {
    auto k = generalize_goal(world, GoalKey{"tidy kitchen", "clear", category, "table"}, object(world, "ceramic-plate1"),
                             goal(world, kCeramicPlateGoal), Provenance{"", "test"});
    EXPECT_TRUE(k.has_value());
    return *k;
  };
  auto store = KnowledgeStore::open(url);
  ASSERT_TRUE(store.has_value()) << store.error().describe();
  ASSERT_TRUE(store->save_goal(goal_of("before")));
  ASSERT_EQ(std::system(("bash " + shell_quote(script) + " restart " + shell_quote(state)).c_str()), 0);
  auto saved = store->save_goal(goal_of("after"));
  ASSERT_TRUE(saved.has_value()) << saved.error().describe();
  auto loaded = store->load(*world.domain);
  ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
  ASSERT_EQ(loaded->goals.size(), 2u);
  EXPECT_EQ(loaded->goals.all()[0].key.category, "before");
  EXPECT_EQ(loaded->goals.all()[1].key.category, "after");
}

}  // namespace
}  // namespace apprentice
