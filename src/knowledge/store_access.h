// How a command uses a knowledge store: its own header, so that the public
// face (face/apprentice.h) can name it without the store's engine.
#pragma once

namespace apprentice {

// The household a store is opened for when none is named (--household).
// Goal preferences and task structures belong to a household; policy
// rules are shared by every household of the store (the fleet).
inline constexpr const char* kDefaultHousehold = "default";

// How a command uses a store.
enum class StoreAccess {
  // Read and write (teach): a missing or empty store becomes a new one.
  kReadWrite,
  // Read only (knowledge, run): the store must already exist; nothing is
  // written to it, except that SQLite completes the rollback of a
  // transaction a killed writer left unfinished.
  kReadOnly,
  // Start over (experiment --knowledge-out): a missing store becomes a new
  // one, an existing store is emptied; refused ("in use") while another
  // process has the store open, and held exclusively until closed.
  kFresh,
};

}  // namespace apprentice
