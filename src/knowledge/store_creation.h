// Creating a knowledge store file atomically (KnowledgeStore::open uses
// this; it is a header of its own so that tests can stop a creation at each
// step).
//
// A new store is written whole under a temporary name in the same
// directory, ".NAME.creating-PID-RANDOM", synced, and then moved to NAME
// without replacing anything there (renameat2 RENAME_NOREPLACE, or link(2)
// and unlink where the file system lacks it). So NAME is either absent or a
// complete store, whenever the process is killed. A temporary file is never
// taken for a store (no reader opens such a name), is removed on every
// error, and one a killed process left is removed by the next writer that
// opens a store of that name: each creator holds an flock(2) on its
// temporary file, and a file nobody holds a lock on is abandoned.
#pragma once

#include <filesystem>
#include <functional>

#include "util/result.h"

namespace SQLite {
class Database;
}

namespace apprentice {

// The value of the `format` row of a store's meta table.
inline constexpr const char* kKnowledgeFormatName = "apprentice-knowledge";

// Creates the store's tables and meta rows in `db` (an empty database),
// in the caller's transaction. Throws SQLite::Exception.
void create_knowledge_schema(SQLite::Database& db);

// Migrates the store in `db`, of schema version `from_version` (at least
// kOldestMigratedSchemaVersion), to kKnowledgeSchemaVersion, one step per
// version, in the caller's transaction; meta's schema_version is set last.
// Throws SQLite::Exception.
void migrate_knowledge_schema(SQLite::Database& db, int from_version);

// The steps of create_store_file, in order, for tests that kill a creation
// part way.
enum class StoreCreationStep {
  kTemporaryCreated,  // the temporary file exists, empty, and is locked
  kSchemaWritten,     // it holds a whole store, committed
  kSynced,            // and is on disk
  kInPlace,           // it is the store at `path` (or another process's was found there)
};

enum class StoreCreation {
  kCreated,  // this call made the store at `path`
  kExisted,  // something was at `path` already (or appeared meanwhile): it was left as it was
};

// Makes `path` a new, empty knowledge store unless a file is there already.
// Calls `after_step` (if set) after each step. Errors (kIo) name `path` and
// give the system's reason; no temporary file is left behind by an error.
Result<StoreCreation> create_store_file(const std::filesystem::path& path,
                                        const std::function<void(StoreCreationStep)>& after_step = {});

// Removes the temporary files of creations of `path` that a killed process
// left behind (those whose creator no longer holds their lock), and their
// SQLite journals. Best effort: a file that cannot be removed is left.
void remove_abandoned_creations(const std::filesystem::path& path);

// Whether `file_name` is the name of a temporary file of a creation of a
// store named `store_name`.
bool is_creation_file_of(const std::string& file_name, const std::string& store_name);

}  // namespace apprentice
