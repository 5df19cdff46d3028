// The throwaway PostgreSQL server the tests of the PostgreSQL knowledge
// store use: scripts/pg-throwaway.sh, started once per ctest run by the
// fixture postgres.start (tests/knowledge/CMakeLists.txt), which writes its
// URLs into the folder APPRENTICE_PG_STATE. Each test makes a database of
// its own (TestDatabase) and drops it at the end.
//
// Without the server binaries the tests skip saying why; under CI=true they
// fail instead: CI must run them.
#pragma once

#include <libpq-fe.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "common/process.h"

namespace apprentice::testing {

struct ThrowawayPostgres {
  std::string socket_dir;
  std::string port;
  std::string password;
  // The superuser over the socket (no password) and over TCP (with it).
  std::string url(const std::string& database) const {
    return "postgresql://apprentice@/" + database + "?host=" + socket_dir + "&port=" + port;
  }
  std::string tcp_url(const std::string& database) const {
    return "postgresql://apprentice:" + password + "@127.0.0.1:" + port + "/" + database;
  }
};

inline std::string first_line_of(const std::filesystem::path& file) {
  std::string text = read_text(file);
  if (auto end = text.find('\n'); end != std::string::npos) text.resize(end);
  return text;
}

// The server, or nullopt with `why` set.
inline std::optional<ThrowawayPostgres> throwaway_postgres(std::string& why) {
  const char* state_env = std::getenv("APPRENTICE_PG_STATE");
  if (!state_env) {
    why = "APPRENTICE_PG_STATE is not set (run these tests through ctest, whose fixture postgres.start starts the server)";
    return std::nullopt;
  }
  const std::filesystem::path state(state_env);
  if (std::filesystem::exists(state / "missing")) {
    why = first_line_of(state / "missing");
    return std::nullopt;
  }
  if (!std::filesystem::exists(state / "server")) {
    why = "the throwaway PostgreSQL server was not started (" + state.string() + " has no server)";
    return std::nullopt;
  }
  return ThrowawayPostgres{first_line_of(state / "server"), first_line_of(state / "port"), first_line_of(state / "password")};
}

inline bool under_ci() {
  const char* ci = std::getenv("CI");
  return ci && std::string(ci) == "true";
}

// Runs one statement as the superuser on `database`; "" or libpq's error.
inline std::string run_sql(const std::string& url, const std::string& sql) {
  PGconn* c = PQconnectdb(url.c_str());
  std::string error;
  if (PQstatus(c) != CONNECTION_OK) {
    error = PQerrorMessage(c);
  } else {
    PGresult* r = PQexec(c, sql.c_str());
    const ExecStatusType s = PQresultStatus(r);
    if (s != PGRES_COMMAND_OK && s != PGRES_TUPLES_OK) error = PQresultErrorMessage(r);
    PQclear(r);
  }
  PQfinish(c);
  return error;
}

// A database of its own for one test, dropped by the destructor.
class TestDatabase {
 public:
  explicit TestDatabase(const ThrowawayPostgres& server) : server_(server) {
    static std::atomic<int> counter{0};
    std::random_device random;
    name_ = "t" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + "_" + std::to_string(random() % 100000);
    error_ = run_sql(server_.url("postgres"), "CREATE DATABASE " + name_ + " TEMPLATE template0");
  }
  ~TestDatabase() {
    if (error_.empty()) (void)run_sql(server_.url("postgres"), "DROP DATABASE " + name_ + " WITH (FORCE)");
  }
  TestDatabase(const TestDatabase&) = delete;
  TestDatabase& operator=(const TestDatabase&) = delete;
  const std::string& error() const { return error_; }
  const std::string& name() const { return name_; }
  std::string url() const { return server_.url(name_); }
  std::string tcp_url() const { return server_.tcp_url(name_); }
  std::string exec(const std::string& sql) const { return run_sql(url(), sql); }

 private:
  ThrowawayPostgres server_;
  std::string name_;
  std::string error_;
};

}  // namespace apprentice::testing

// In SetUp: the server into `server` (a std::optional<ThrowawayPostgres>),
// or skip (fail under CI=true) saying why.
#define APPRENTICE_REQUIRE_POSTGRES(server)                                                   \
  do {                                                                                        \
    std::string why_;                                                                         \
    server = ::apprentice::testing::throwaway_postgres(why_);                                 \
    if (!server) {                                                                            \
      if (::apprentice::testing::under_ci()) FAIL() << "CI=true, and no PostgreSQL: " << why_; \
      GTEST_SKIP() << "no PostgreSQL server for this test: " << why_;                         \
    }                                                                                         \
  } while (0)
