// The PostgreSQL engine of the knowledge store (knowledge/store_engine.h):
// one database, shared by a fleet of robots. Chosen when --knowledge is a
// URL, postgresql://USER@HOST:PORT/DB (or postgres://...), through libpq.
//
// The same tables as the SQLite engine (meta, tasks, goals, rules) in the
// connection's current schema (public unless the URL sets search_path), so
// the promises read the same:
//   - each save and remove is one statement in its own transaction, with
//     synchronous_commit on: once it returns, the server has it on disk;
//   - meta's format and schema_version are checked at open; a database
//     holding other tables and no meta is another program's and is refused;
//     a store missing a table load() reads is damaged and refused;
//   - each open store holds an advisory lock on its schema: shared, except
//     StoreAccess::kFresh, which starts the store over and so holds it
//     exclusively; an open that cannot get its lock is refused "in use";
//   - load() reads one REPEATABLE READ snapshot while writers go on.
// A connection the server dropped (a restart) is made again and the write
// retried, for up to about 10 s; saves are idempotent, so a retried save
// whose first commit did land changes nothing.
//
// Credentials: a password comes from the URL, PGPASSWORD or PGPASSFILE, as
// libpq reads them. No message names it: stores are named by the URL
// without its password (scrub_store_location, knowledge/store_location.h).
#pragma once

#include <memory>
#include <string>

#include "knowledge/store_engine.h"
#include "util/result.h"

namespace apprentice {

// Opens (or, unless kReadOnly, creates the tables of) the store in the
// database at `url` for `household` (a name check_household_name accepts),
// saving `robot` with each goal and rule;
// a store of an older schema version is migrated unless kReadOnly. Errors as KnowledgeStore::open lists them; a server
// that cannot be reached (or refuses the login) is kIo, "HOST:PORT/DB:
// cannot connect to the PostgreSQL server ...", one line.
Result<std::unique_ptr<StoreEngine>> open_postgres_store(const std::string& url, StoreAccess access,
                                                         const std::string& household, const std::string& robot);

}  // namespace apprentice
