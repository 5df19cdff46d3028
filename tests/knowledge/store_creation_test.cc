// Creating a knowledge store is atomic (issue 11): a process killed at any
// step of a creation leaves the store's path absent or a complete store,
// never an empty file or a database without tables; the temporary file it
// leaves is never taken for a store and is removed by the next writer; a
// store that appears while another is being created is opened, never
// replaced; and errors leave no temporary file behind.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <random>
#include <set>
#include <thread>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "knowledge/store.h"
#include "knowledge/store_creation.h"
#include "knowledge_fixtures.h"

namespace apprentice {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::SizeIs;
using namespace apprentice::testing;

class StoreCreationTest : public KitchenStoreTest {
 protected:
  std::set<std::string> files() const {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_.path())) names.insert(entry.path().filename().string());
    return names;
  }
  std::set<std::string> creation_files(const fs::path& store) const {
    std::set<std::string> names;
    for (const std::string& name : files())
      if (is_creation_file_of(name, store.filename().string())) names.insert(name);
    return names;
  }
  // The store at `store` opens read-only and loads, holding nothing.
  void expect_complete_empty_store(const fs::path& store) {
    auto opened = KnowledgeStore::open(store, StoreAccess::kReadOnly);
    ASSERT_TRUE(opened.has_value()) << opened.error().describe();
    auto loaded = opened->load(domain_);
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    EXPECT_TRUE(loaded->tasks.empty());
  }
};

const char* step_name(StoreCreationStep step) {
  switch (step) {
    case StoreCreationStep::kTemporaryCreated: return "temporary file created";
    case StoreCreationStep::kSchemaWritten: return "schema written";
    case StoreCreationStep::kSynced: return "synced";
    case StoreCreationStep::kInPlace: return "in place";
  }
  return "?";
}

TEST_F(StoreCreationTest, KilledAtEachStepLeavesNoStoreOrACompleteOne) {
  for (StoreCreationStep step : {StoreCreationStep::kTemporaryCreated, StoreCreationStep::kSchemaWritten,
                                 StoreCreationStep::kSynced, StoreCreationStep::kInPlace}) {
    SCOPED_TRACE(step_name(step));
    const fs::path store = dir_ / ("store-" + std::to_string(static_cast<int>(step)) + ".sqlite");
    pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      (void)create_store_file(store, [step](StoreCreationStep s) {
        if (s == step) ::raise(SIGKILL);
      });
      ::_exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "the child was not killed at the step";

    if (step == StoreCreationStep::kInPlace) {
      expect_complete_empty_store(store);
      EXPECT_THAT(creation_files(store), SizeIs(0));
    } else {
      EXPECT_FALSE(fs::exists(store)) << "a store killed while being created is at its path";
      EXPECT_THAT(creation_files(store), SizeIs(1)) << "the killed creation left no temporary file to test with";
      // The temporary file is not a store to a reader...
      auto read = KnowledgeStore::open(store, StoreAccess::kReadOnly);
      ASSERT_FALSE(read.has_value());
      EXPECT_EQ(read.error().code, ErrorCode::kNotFound);
    }
    // ...and the next writer creates the store and removes it.
    {
      auto written = KnowledgeStore::open(store, StoreAccess::kReadWrite);
      ASSERT_TRUE(written.has_value()) << written.error().describe();
      EXPECT_THAT(creation_files(store), SizeIs(0));
    }
    expect_complete_empty_store(store);
  }
  EXPECT_THAT(files(), SizeIs(4)) << ::testing::PrintToString(files());
}

TEST_F(StoreCreationTest, AStoreThatAppearsMeanwhileIsKeptAndNotReplaced) {
  auto outcome = create_store_file(path_, [this](StoreCreationStep s) {
    if (s != StoreCreationStep::kSynced) return;
    // Another process creates the store and saves a task in it.
    auto other = KnowledgeStore::open(path_, StoreAccess::kReadWrite);
    ASSERT_TRUE(other.has_value()) << other.error().describe();
    ASSERT_TRUE(other->save_task(TaskKnowledge{"tidy kitchen", {{"clear", "on", "table"}}}));
  });
  ASSERT_TRUE(outcome.has_value()) << outcome.error().describe();
  EXPECT_EQ(*outcome, StoreCreation::kExisted);
  auto knowledge = load_knowledge_read_only(path_, domain_);
  ASSERT_TRUE(knowledge.has_value()) << knowledge.error().describe();
  ASSERT_THAT(knowledge->tasks, SizeIs(1));
  EXPECT_EQ(knowledge->tasks[0].name, "tidy kitchen");
  EXPECT_THAT(files(), ElementsAre(path_.filename().string()));
}

TEST_F(StoreCreationTest, ADirectoryThatAppearsMeanwhileIsReportedAndNoTemporaryFileIsLeft) {
  auto outcome = create_store_file(path_, [this](StoreCreationStep s) {
    if (s == StoreCreationStep::kSynced) fs::create_directory(path_);
  });
  ASSERT_TRUE(outcome.has_value()) << outcome.error().describe();
  EXPECT_EQ(*outcome, StoreCreation::kExisted);
  EXPECT_TRUE(fs::is_directory(path_));
  EXPECT_THAT(files(), ElementsAre(path_.filename().string()));
  auto store = KnowledgeStore::open(path_, StoreAccess::kReadWrite);
  ASSERT_FALSE(store.has_value());
  EXPECT_EQ(store.error().code, ErrorCode::kInvalidInput);
  EXPECT_THAT(store.error().message, HasSubstr("is a directory"));
  EXPECT_THAT(files(), ElementsAre(path_.filename().string()));
}

TEST_F(StoreCreationTest, AMissingDirectoryIsAnIoErrorWithItsReasonAndCreatesNothing) {
  const fs::path store = dir_ / "missing" / "knowledge.sqlite";
  auto opened = KnowledgeStore::open(store, StoreAccess::kReadWrite);
  ASSERT_FALSE(opened.has_value());
  EXPECT_EQ(opened.error().code, ErrorCode::kIo);
  EXPECT_THAT(opened.error().message, HasSubstr("No such file or directory"));
  EXPECT_THAT(files(), SizeIs(0));
}

TEST_F(StoreCreationTest, ACreationUnderWayIsNotSweptAway) {
  auto outcome = create_store_file(path_, [this](StoreCreationStep s) {
    if (s != StoreCreationStep::kSchemaWritten) return;
    // Another writer sweeps abandoned creations while this one is live.
    remove_abandoned_creations(path_);
    EXPECT_THAT(creation_files(path_), SizeIs(1));
  });
  ASSERT_TRUE(outcome.has_value()) << outcome.error().describe();
  EXPECT_EQ(*outcome, StoreCreation::kCreated);
  expect_complete_empty_store(path_);
  EXPECT_THAT(files(), ElementsAre(path_.filename().string()));
}

TEST_F(StoreCreationTest, OnlyTheStoresOwnTemporaryNamesAreCreationFiles) {
  EXPECT_TRUE(is_creation_file_of(".k.sqlite.creating-12-00ff", "k.sqlite"));
  EXPECT_TRUE(is_creation_file_of(".k.sqlite.creating-12-00ff-journal", "k.sqlite"));
  EXPECT_FALSE(is_creation_file_of("k.sqlite", "k.sqlite"));
  EXPECT_FALSE(is_creation_file_of(".k.sqlite.creating-", "k.sqlite"));
  EXPECT_FALSE(is_creation_file_of(".other.sqlite.creating-12-00ff", "k.sqlite"));
}

// KnowledgeStore::open itself, killed at random moments while it creates
// store after store: every path is absent or a complete store.
TEST_F(StoreCreationTest, KilledAtRandomWhileCreatingStoresLeavesOnlyCompleteOnes) {
  // The kills are spread over about three creations, as long as one takes
  // on this machine (its syncs dominate).
  const auto start = std::chrono::steady_clock::now();
  ASSERT_TRUE(KnowledgeStore::open(dir_ / "timed.sqlite", StoreAccess::kReadWrite).has_value());
  const auto creation_us = std::max<long>(
      1000, std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start).count());
  std::mt19937 random(11);
  std::size_t stores_checked = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const fs::path trial_dir = dir_ / ("trial-" + std::to_string(trial));
    fs::create_directory(trial_dir);
    // The child says when its first store is whole, so that on a loaded
    // machine the kill does not come before it has run at all.
    int first_done[2];
    ASSERT_EQ(::pipe(first_done), 0);
    pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ::close(first_done[0]);
      for (int i = 0;; ++i) {
        (void)KnowledgeStore::open(trial_dir / ("store-" + std::to_string(i) + ".sqlite"), StoreAccess::kReadWrite);
        if (i == 0) {
          (void)!::write(first_done[1], "1", 1);
          ::close(first_done[1]);
        }
      }
    }
    ::close(first_done[1]);
    char byte = 0;
    while (::read(first_done[0], &byte, 1) < 0 && errno == EINTR) {
    }
    ::close(first_done[0]);
    std::this_thread::sleep_for(std::chrono::microseconds(std::uniform_int_distribution<long>(0, 3 * creation_us)(random)));
    ::kill(child, SIGKILL);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    for (const auto& entry : fs::directory_iterator(trial_dir)) {
      const std::string name = entry.path().filename().string();
      if (name.front() == '.') continue;  // a creation's temporary file
      if (name.ends_with("-journal")) continue;
      SCOPED_TRACE(entry.path().string());
      expect_complete_empty_store(entry.path());
      ++stores_checked;
    }
  }
  EXPECT_GT(stores_checked, 0u) << "no store was created before a kill";
}

}  // namespace
}  // namespace apprentice
