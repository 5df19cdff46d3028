// The SQLite engine of the knowledge store (knowledge/store_engine.h): one
// file, the embedded default.
//
// Processes share a store through two kinds of lock. SQLite's own locks
// (with a busy timeout of 5 s) let several processes read and write it at
// once, each transaction whole. And each open store holds an flock(2) on
// its file: shared, except for StoreAccess::kFresh, which starts the store
// over and so holds it exclusively; an open that cannot get its lock is
// refused as "in use", so a store another process has open is never
// emptied, deleted or truncated.
//
// A new store is made whole under a temporary name and moved into place
// (knowledge/store_creation.h): killed at any point, a process leaves the
// path either absent or a complete store, never an empty file.
//
// The journal is a rollback journal (journal_mode = DELETE) with full syncs,
// so a transaction that returned is on disk and a killed writer leaves a
// journal SQLite rolls back the next time the store is opened.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "knowledge/store_engine.h"
#include "util/result.h"

namespace apprentice {

// Opens (or, unless kReadOnly, creates) the SQLite store at `path` for
// `household` (a name check_household_name accepts), saving `robot` with
// each goal and rule; a store of an older schema version is migrated unless
// kReadOnly. Errors as KnowledgeStore::open lists them, each naming the
// file.
Result<std::unique_ptr<StoreEngine>> open_sqlite_store(const std::filesystem::path& path, StoreAccess access,
                                                       const std::string& household, const std::string& robot);

}  // namespace apprentice
