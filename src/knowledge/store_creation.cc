#include "knowledge/store_creation.h"

#include <fcntl.h>
#include <stdio.h>  // renameat2
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <iterator>
#include <string>

#include <fmt/format.h>
#include <SQLiteCpp/SQLiteCpp.h>

#include "knowledge/store_engine.h"
#include "knowledge/store_sql.h"
#include "util/file.h"

namespace apprentice {

namespace {

constexpr const char* kCreatingInfix = ".creating-";
constexpr std::string_view kJournalSuffix = "-journal";

std::filesystem::path directory_of(const std::filesystem::path& path) {
  return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

// 16 hex digits that no other creation picks: getrandom, or else the clock.
std::string random_hex() {
  std::uint64_t bits = 0;
  if (::getrandom(&bits, sizeof bits, GRND_NONBLOCK) != static_cast<ssize_t>(sizeof bits))
    bits = static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) * 0x9E3779B97F4A7C15ull;
  return fmt::format("{:016x}", bits);
}

// The temporary file of one creation; removed (with any SQLite journal)
// when destroyed unless released.
struct TemporaryStore {
  std::filesystem::path path;
  FileDescriptor fd;

  TemporaryStore() = default;
  TemporaryStore(const TemporaryStore&) = delete;
  TemporaryStore& operator=(const TemporaryStore&) = delete;
  ~TemporaryStore() { remove(); }
  void remove() {
    fd = FileDescriptor();
    if (path.empty()) return;
    ::unlink(path.c_str());
    ::unlink((path.string() + std::string(kJournalSuffix)).c_str());
    path.clear();
  }
};

tl::unexpected<Error> cannot_create(const std::filesystem::path& path, const std::string& why) {
  return make_error(ErrorCode::kIo, path.string() + ": cannot open or create the knowledge store: " + why);
}

// Creates and locks a new temporary file next to `path`. A file an
// abandoned-creation sweep removed between the creation and the lock is
// given up for another name.
Status make_temporary(const std::filesystem::path& path, TemporaryStore& temp) {
  const std::string stem = "." + path.filename().string() + kCreatingInfix + std::to_string(::getpid()) + "-";
  for (int attempt = 0; attempt < 16; ++attempt) {
    std::filesystem::path candidate = directory_of(path) / (stem + random_hex());
    int fd = open_retrying(candidate, O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
      if (errno == EEXIST) continue;
      return cannot_create(path, std::strerror(errno));
    }
    temp.path = candidate;
    temp.fd = FileDescriptor(fd);
    if (flock_retrying(fd, LOCK_EX) != 0) return cannot_create(path, std::string("cannot lock ") + std::strerror(errno));
    struct stat info {};
    if (::fstat(fd, &info) != 0) return cannot_create(path, std::strerror(errno));
    if (info.st_nlink > 0) return {};
    // Swept away before it was locked: nothing of ours is there any more.
    temp.fd = FileDescriptor();
    temp.path.clear();
  }
  return cannot_create(path, "no free temporary name");
}

// Moves `from` to `to` unless something is at `to`: 0 if moved, else the
// errno (EEXIST: something is at `to`, and `from` is left as it was).
int move_without_replacing(const std::filesystem::path& from, const std::filesystem::path& to) {
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return 0;
  const int error = errno;
  if (error != EINVAL && error != ENOSYS && error != ENOTSUP) return error;
  // A file system without RENAME_NOREPLACE: link(2) never replaces
  // either; the caller then removes `from`.
  return ::link(from.c_str(), to.c_str()) == 0 ? 0 : errno;
}

}  // namespace

namespace {

// The tables of version 2 (migrate_1_to_2 makes them; the current schema
// is store_sql::schema).
constexpr const char* kGoalsTable =
    "CREATE TABLE goals(id INTEGER PRIMARY KEY AUTOINCREMENT, household TEXT NOT NULL, task TEXT NOT NULL, subtask TEXT NOT NULL, "
    "category TEXT NOT NULL, place TEXT NOT NULL, literals TEXT NOT NULL, object TEXT NOT NULL, "
    "source TEXT NOT NULL, UNIQUE(household, task, subtask, category, place))";
constexpr const char* kRulesTable =
    "CREATE TABLE rules(id INTEGER PRIMARY KEY AUTOINCREMENT, signature TEXT NOT NULL UNIQUE, body TEXT NOT NULL, "
    "object TEXT NOT NULL, source TEXT NOT NULL)";
constexpr const char* kTasksTable =
    "CREATE TABLE tasks(household TEXT NOT NULL, name TEXT NOT NULL, structure TEXT NOT NULL, PRIMARY KEY(household, name))";
// The SQL below names the default household as a literal.
static_assert(std::string_view(kDefaultHousehold) == "default");

// Version 1 to 2: goals and tasks gain a household, part of their keys
// (a new table each, as SQLite cannot change a table's keys); what there
// was is the default household's. Goals and rules keep their ids, so their
// order, and ids are never used again (AUTOINCREMENT: what another process
// saved is what comes after the last id seen, StoreEngine::news).
void migrate_1_to_2(SQLite::Database& db) {
  const std::string household = std::string("'") + kDefaultHousehold + "'";
  db.exec("ALTER TABLE goals RENAME TO goals_v1");
  db.exec(kGoalsTable);
  db.exec("INSERT INTO goals(id, household, task, subtask, category, place, literals, object, source) SELECT id, " +
          household + ", task, subtask, category, place, literals, object, source FROM goals_v1 ORDER BY id");
  db.exec("DROP TABLE goals_v1");
  db.exec("ALTER TABLE rules RENAME TO rules_v1");
  db.exec(kRulesTable);
  db.exec("INSERT INTO rules(id, signature, body, object, source) SELECT id, signature, body, object, source FROM rules_v1 "
          "ORDER BY id");
  db.exec("DROP TABLE rules_v1");
  db.exec("ALTER TABLE tasks RENAME TO tasks_v1");
  db.exec(kTasksTable);
  db.exec("INSERT INTO tasks(household, name, structure) SELECT " + household + ", name, structure FROM tasks_v1");
  db.exec("DROP TABLE tasks_v1");
}

// Version 2 to 3: each household's class rules with their evidence, and
// the rules it forgot (none yet).
void migrate_2_to_3(SQLite::Database& db) {
  for (const std::string& table : store_sql::class_rules_tables(store_sql::kSqliteId)) db.exec(table);
}

void migrate_3_to_4(SQLite::Database& db) {
  for (const char* step : store_sql::kMigration3To4) db.exec(step);
}

}  // namespace

void create_knowledge_schema(SQLite::Database& db) {
  for (const std::string& table : store_sql::schema(store_sql::kSqliteId)) db.exec(table);
  SQLite::Statement insert(db, store_sql::kInsertMeta);
  insert.bind(1, kKnowledgeFormatName);
  insert.bind(2, std::to_string(kKnowledgeSchemaVersion));
  insert.exec();
}

void migrate_knowledge_schema(SQLite::Database& db, int from_version) {
  // One entry per step, from version i + kOldestMigratedSchemaVersion.
  static constexpr void (*kSteps[])(SQLite::Database&) = {migrate_1_to_2, migrate_2_to_3, migrate_3_to_4};
  static_assert(std::size(kSteps) == kKnowledgeSchemaVersion - kOldestMigratedSchemaVersion);
  for (int v = from_version; v < kKnowledgeSchemaVersion; ++v) kSteps[v - kOldestMigratedSchemaVersion](db);
  SQLite::Statement version(db, store_sql::kSetVersion);
  version.bind(1, std::to_string(kKnowledgeSchemaVersion));
  version.exec();
}

bool is_creation_file_of(const std::string& file_name, const std::string& store_name) {
  const std::string prefix = "." + store_name + kCreatingInfix;
  return file_name.size() > prefix.size() && file_name.compare(0, prefix.size(), prefix) == 0;
}

Result<StoreCreation> create_store_file(const std::filesystem::path& path,
                                        const std::function<void(StoreCreationStep)>& after_step) {
  auto step = [&](StoreCreationStep s) {
    if (after_step) after_step(s);
  };
  // A temporary name swept away by another creator before the move is
  // made again (at most a few times).
  for (int attempt = 0; attempt < 4; ++attempt) {
    TemporaryStore temp;
    if (auto made = make_temporary(path, temp); !made) return tl::unexpected(made.error());
    step(StoreCreationStep::kTemporaryCreated);
    try {
      SQLite::Database db(temp.path.string(), SQLite::OPEN_READWRITE);
      db.exec("PRAGMA journal_mode = DELETE");
      db.exec("PRAGMA synchronous = FULL");
      SQLite::Transaction transaction(db, SQLite::TransactionBehavior::IMMEDIATE);
      create_knowledge_schema(db);
      transaction.commit();
    } catch (const std::exception& e) {
      return cannot_create(path, e.what());
    }
    step(StoreCreationStep::kSchemaWritten);
    if (::fsync(temp.fd.get()) != 0) return cannot_create(path, std::strerror(errno));
    step(StoreCreationStep::kSynced);
    // Unlocked before the move: the lock must not come along to the store,
    // where it would tell other processes the store is in use.
    flock_retrying(temp.fd.get(), LOCK_UN);
    temp.fd = FileDescriptor();
    const int moved = move_without_replacing(temp.path, path);
    if (moved == ENOENT && !std::filesystem::exists(temp.path)) continue;  // swept away: again
    if (moved != 0 && moved != EEXIST) return cannot_create(path, std::strerror(moved));
    if (moved == 0) {
      // The new name on disk too (best effort: some file systems cannot
      // sync a directory).
      if (int dir = open_retrying(directory_of(path), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
        ::fsync(dir);
        ::close(dir);
      }
    }
    // After link(2), or when a file was there already, the temporary name
    // is still there; after a rename nothing is.
    temp.remove();
    step(StoreCreationStep::kInPlace);
    return moved == 0 ? StoreCreation::kCreated : StoreCreation::kExisted;
  }
  return cannot_create(path, "its temporary file was removed by another process");
}

void remove_abandoned_creations(const std::filesystem::path& path) {
  const std::string store_name = path.filename().string();
  std::error_code ec;
  std::filesystem::directory_iterator it(directory_of(path), ec), end;
  std::vector<std::filesystem::path> files, journals;
  for (; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!is_creation_file_of(name, store_name)) continue;
    const bool journal = name.size() > kJournalSuffix.size() &&
                         name.compare(name.size() - kJournalSuffix.size(), kJournalSuffix.size(), kJournalSuffix) == 0;
    (journal ? journals : files).push_back(it->path());
  }
  for (const std::filesystem::path& file : files) {
    FileDescriptor fd(open_retrying(file, O_RDONLY | O_NOFOLLOW | O_CLOEXEC));
    if (fd.get() < 0 || flock_retrying(fd.get(), LOCK_EX | LOCK_NB) != 0) continue;  // a live creation
    struct stat held {}, named {};
    if (::fstat(fd.get(), &held) != 0 || ::lstat(file.c_str(), &named) != 0) continue;
    if (held.st_dev != named.st_dev || held.st_ino != named.st_ino) continue;
    ::unlink(file.c_str());
    ::unlink((file.string() + std::string(kJournalSuffix)).c_str());
  }
  // A journal whose file is gone belongs to nothing.
  for (const std::filesystem::path& journal : journals) {
    std::string file = journal.string();
    file.resize(file.size() - kJournalSuffix.size());
    struct stat info {};
    if (::lstat(file.c_str(), &info) != 0 && errno == ENOENT) ::unlink(journal.c_str());
  }
}

}  // namespace apprentice
