// The knowledge store's speed on each engine (docs/benchmarks.md,
// "Knowledge store"):
//
//   bench_store save LOCATION WRITERS GOALS   WRITERS processes at once, each
//                                             saving GOALS goals of its own
//                                             (each save its own durable
//                                             transaction): goals saved per
//                                             second, all writers together
//   bench_store load LOCATION GOALS           a store of GOALS goals (filled
//                                             in one transaction behind the
//                                             engine's back), then load()
//                                             timed three times: the median
//   bench_store live LOCATION SAVES POLL_MS   a watcher process asks its
//                                             store for news (what another
//                                             process saved) every POLL_MS;
//                                             this one saves SAVES goals, one
//                                             every 200 ms: for each, the
//                                             time from the start of its save
//                                             until the watcher has it
//
// LOCATION is an SQLite path or a postgresql:// URL, as --knowledge takes.
// The store should be new (an empty database for PostgreSQL).
#include <libpq-fe.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <SQLiteCpp/SQLiteCpp.h>

#include "knowledge/store.h"
#include "knowledge/store_codec.h"
#include "knowledge/goal_memory.h"
#include "world/goal.h"
#include "world/scenario.h"

namespace {

using apprentice::GoalKnowledge;
using apprentice::KnowledgeStore;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The ceramic plate's goal of the kitchen, under its own category `kind`.
GoalKnowledge goal_of_kind(const apprentice::World& world, const std::string& kind) {
  auto object = world.universe->find("ceramic-plate1");
  auto goal = apprentice::parse_goal(*world.domain, *world.universe, "(and (in ceramic-plate1 dishwasher1) (closed dishwasher1))");
  auto k = apprentice::generalize_goal(world, apprentice::GoalKey{"tidy kitchen", "clear", kind, "table"}, *object, *goal,
                                       apprentice::Provenance{"ceramic-plate1 (ceramic-plate)", "bench_store"});
  if (!k) {
    std::fprintf(stderr, "bench_store: %s\n", k.error().describe().c_str());
    std::exit(1);
  }
  return *k;
}

int save(const std::string& location, int writers, int goals, const apprentice::World& world) {
  // Made once, so that the writers do not race to create it.
  if (auto store = KnowledgeStore::open(location); !store) {
    std::fprintf(stderr, "bench_store: %s\n", store.error().describe().c_str());
    return 1;
  }
  const auto start = Clock::now();
  std::vector<pid_t> children;
  for (int w = 0; w < writers; ++w) {
    pid_t pid = ::fork();
    if (pid == 0) {
      auto store = KnowledgeStore::open(location);
      if (!store) ::_exit(2);
      for (int n = 0; n < goals; ++n)
        if (!store->save_goal(goal_of_kind(world, "kind-" + std::to_string(w) + "-" + std::to_string(n)))) ::_exit(3);
      ::_exit(0);
    }
    children.push_back(pid);
  }
  int failed = 0;
  for (pid_t pid : children) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) ++failed;
  }
  const double elapsed = seconds_since(start);
  // What is in the store, not what was asked for: a writer may have failed.
  auto store = KnowledgeStore::open(location, apprentice::StoreAccess::kReadOnly);
  auto knowledge = store ? store->load(*world.domain) : apprentice::Result<apprentice::Knowledge>(tl::unexpected(store.error()));
  if (!knowledge) {
    std::fprintf(stderr, "bench_store: %s\n", knowledge.error().describe().c_str());
    return 1;
  }
  const int saved = static_cast<int>(knowledge->goals.size());
  std::printf("%s: %d writer(s) x %d goals: %d goals in %.2f s, %.0f goals/s; %d writer(s) failed\n",
              apprentice::scrub_store_location(location).c_str(), writers, goals, saved, elapsed, saved / elapsed,
              failed);
  return failed ? 1 : 0;
}

// Fills the store with `goals` goals in one transaction.
bool fill(const std::string& location, int goals, const apprentice::World& world) {
  if (auto store = KnowledgeStore::open(location); !store) {
    std::fprintf(stderr, "bench_store: %s\n", store.error().describe().c_str());
    return false;
  }
  const GoalKnowledge goal = goal_of_kind(world, "kind");
  const std::string literals = apprentice::store_codec::encode_goal_literals(goal);
  if (!apprentice::is_postgres_location(location)) {
    SQLite::Database db(location, SQLite::OPEN_READWRITE);
    SQLite::Transaction transaction(db);
    SQLite::Statement insert(db, "INSERT INTO goals(household, task, subtask, category, place, literals, object, source) "
                                 "VALUES ('default', 'tidy kitchen', 'clear', ?, 'table', ?, 'ceramic-plate1 (ceramic-plate)', 'bench_store')");
    for (int n = 0; n < goals; ++n) {
      insert.bind(1, "kind-" + std::to_string(n));
      insert.bind(2, literals);
      insert.exec();
      insert.reset();
    }
    transaction.commit();
    return true;
  }
  PGconn* c = PQconnectdb(location.c_str());
  const char* values[] = {literals.c_str(), nullptr};
  const std::string sql =
      "INSERT INTO goals(household, task, subtask, category, place, literals, object, source) SELECT 'default', "
      "'tidy kitchen', 'clear', "
      "'kind-' || n, 'table', $1, 'ceramic-plate1 (ceramic-plate)', 'bench_store' FROM generate_series(0, " +
      std::to_string(goals - 1) + ") AS n";
  PGresult* r = PQexecParams(c, sql.c_str(), 1, nullptr, values, nullptr, nullptr, 0);
  const bool ok = PQresultStatus(r) == PGRES_COMMAND_OK;
  if (!ok) std::fprintf(stderr, "bench_store: %s", PQresultErrorMessage(r));
  PQclear(r);
  PQfinish(c);
  return ok;
}

int load(const std::string& location, int goals, const apprentice::World& world) {
  if (!fill(location, goals, world)) return 1;
  std::vector<double> times;
  std::size_t loaded = 0;
  for (int trial = 0; trial < 3; ++trial) {
    const auto start = Clock::now();
    auto store = KnowledgeStore::open(location, apprentice::StoreAccess::kReadOnly);
    if (!store) return 1;
    auto knowledge = store->load(*world.domain);
    if (!knowledge) {
      std::fprintf(stderr, "bench_store: %s\n", knowledge.error().describe().c_str());
      return 1;
    }
    loaded = knowledge->goals.size();
    times.push_back(seconds_since(start));
  }
  std::sort(times.begin(), times.end());
  std::printf("%s: open and load %zu goals: median %.3f s (of %.3f, %.3f, %.3f)\n",
              apprentice::scrub_store_location(location).c_str(), loaded, times[1], times[0], times[1], times[2]);
  return 0;
}

// Nanoseconds of the steady clock (CLOCK_MONOTONIC: the same in every
// process of the machine).
long long now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count();
}

int live(const std::string& location, int saves, int poll_ms, const apprentice::World& world) {
  if (auto store = KnowledgeStore::open(location); !store) {
    std::fprintf(stderr, "bench_store: %s\n", store.error().describe().c_str());
    return 1;
  }
  int ready[2], seen[2];
  if (::pipe(ready) != 0 || ::pipe(seen) != 0) return 1;
  const pid_t watcher = ::fork();
  if (watcher == 0) {
    // Each goal saved carries the time its save started as its source.
    auto store = KnowledgeStore::open(location);
    if (!store || !store->load(*world.domain)) ::_exit(2);
    if (::write(ready[1], "r", 1) != 1) ::_exit(2);
    const long long deadline = now_ns() + 120'000'000'000LL;
    for (int got = 0; got < saves && now_ns() < deadline;) {
      auto news = store->news(*world.domain);
      if (!news) ::_exit(3);
      const long long now = now_ns();
      for (const GoalKnowledge& g : news->goals) {
        const std::string line = std::to_string(now - std::stoll(g.provenance.source)) + "\n";
        if (::write(seen[1], line.data(), line.size()) != static_cast<ssize_t>(line.size())) ::_exit(4);
        ++got;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(poll_ms));
    }
    ::_exit(0);
  }
  ::close(seen[1]);
  char byte = 0;
  if (::read(ready[0], &byte, 1) != 1) return 1;
  auto store = KnowledgeStore::open(location);
  if (!store) return 1;
  for (int n = 0; n < saves; ++n) {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    GoalKnowledge goal = goal_of_kind(world, "live-" + std::to_string(n));
    goal.provenance.source = std::to_string(now_ns());
    if (auto s = store->save_goal(goal); !s) {
      std::fprintf(stderr, "bench_store: %s\n", s.error().describe().c_str());
      return 1;
    }
  }
  int status = 0;
  ::waitpid(watcher, &status, 0);
  std::string text;
  char buffer[4096];
  for (ssize_t n; (n = ::read(seen[0], buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
  std::vector<double> ms;
  for (std::size_t at = 0, end; (end = text.find('\n', at)) != std::string::npos; at = end + 1)
    ms.push_back(std::stoll(text.substr(at, end - at)) / 1e6);
  std::sort(ms.begin(), ms.end());
  if (ms.empty()) {
    std::fprintf(stderr, "bench_store: the watcher saw none of the %d goals\n", saves);
    return 1;
  }
  std::printf("%s: %zu of %d goals seen by a running watcher (asking every %d ms): from the start of the save, "
              "median %.1f ms, 90th percentile %.1f ms, most %.1f ms\n",
              apprentice::scrub_store_location(location).c_str(), ms.size(), saves, poll_ms, ms[ms.size() / 2],
              ms[ms.size() * 9 / 10], ms.back());
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 && static_cast<int>(ms.size()) == saves ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  auto scenario = apprentice::load_scenario(std::string(APPRENTICE_SOURCE_DIR) + "/data/scenarios/tidy-kitchen.yaml");
  if (!scenario) {
    std::fprintf(stderr, "bench_store: %s\n", scenario.error().describe().c_str());
    return 1;
  }
  try {
    if (args.size() == 4 && args[0] == "save")
      return save(args[1], std::stoi(args[2]), std::stoi(args[3]), scenario->world);
    if (args.size() == 3 && args[0] == "load") return load(args[1], std::stoi(args[2]), scenario->world);
    if (args.size() == 4 && args[0] == "live")
      return live(args[1], std::stoi(args[2]), std::stoi(args[3]), scenario->world);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_store: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr,
               "usage: bench_store save LOCATION WRITERS GOALS | bench_store load LOCATION GOALS | bench_store live "
               "LOCATION SAVES POLL_MS\n");
  return 2;
}
