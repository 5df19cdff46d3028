// libFuzzer target for opening a knowledge store from arbitrary bytes: the
// bytes become a file, which is opened read-only and then read-write and
// loaded against the kitchen domain. Each open and load gives a store and
// its knowledge or an error with a message; never a crash, a sanitizer
// report or a hang. A file that opens read-only must load or be refused as
// damaged, foreign or of another domain, with one of the documented codes.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <optional>
#include <string>

#include "fuzz_support.h"
#include "knowledge/store.h"
#include "util/log.h"
#include "world/pddl.h"

namespace {

std::optional<apprentice::Domain> kitchen;
std::filesystem::path scratch;

// The file and whatever SQLite left beside it (a fuzzed header can ask for
// write-ahead logging).
void remove_scratch() {
  std::error_code ignored;
  for (const char* suffix : {"", "-journal", "-wal", "-shm"})
    std::filesystem::remove(scratch.string() + suffix, ignored);
}

bool documented(apprentice::ErrorCode code) {
  using apprentice::ErrorCode;
  return code == ErrorCode::kFailedPrecondition || code == ErrorCode::kDataLoss || code == ErrorCode::kIo ||
         code == ErrorCode::kNotFound || code == ErrorCode::kInvalidInput;
}

void open_and_load(apprentice::StoreAccess access) {
  auto store = apprentice::KnowledgeStore::open(scratch, access);
  if (!store) {
    apprentice::fuzz::require(!store.error().message.empty() && documented(store.error().code));
    return;
  }
  auto knowledge = store->load(*kitchen);
  if (!knowledge)
    apprentice::fuzz::require(!knowledge.error().message.empty() && documented(knowledge.error().code));
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  apprentice::configure_logging(apprentice::LogLevel::kQuiet);
  auto domain = apprentice::read_domain_file(apprentice::fuzz::source_dir() / "data/domains/kitchen.pddl");
  apprentice::fuzz::require(domain.has_value());
  kitchen = std::move(*domain);
  scratch = std::filesystem::temp_directory_path() / ("apprentice-fuzz-store-" + std::to_string(getpid()) + ".sqlite");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using apprentice::StoreAccess;
  for (StoreAccess access : {StoreAccess::kReadOnly, StoreAccess::kReadWrite}) {
    remove_scratch();
    {
      std::ofstream out(scratch, std::ios::binary | std::ios::trunc);
      out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
      apprentice::fuzz::require(static_cast<bool>(out));
    }
    open_and_load(access);
  }
  remove_scratch();
  return 0;
}
