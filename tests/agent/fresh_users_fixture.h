// The fixture of the fresh users' tests (teach_fresh_users_cli_test.cc,
// teach_fresh_users5_cli_test.cc): their worlds, and teaching one in the
// real binary with replies typed in turn.
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/paths.h"
#include "common/scratch.h"
#include "process.h"

namespace apprentice::testing {

// A world a fresh user wrote: tests/agent/data/fresh-users/`file`.
inline std::string fresh_user_world(const char* file) {
  return source_path(std::string("tests/agent/data/fresh-users/") + file);
}

class FreshUserTeaching : public ScratchTest {
 protected:
  // Teaches `file` with `replies` typed in turn, keeping what was taught in
  // `store` (here); the whole transcript.
  std::string teach(const char* file, std::vector<std::string> replies, const char* store = "store.sqlite") {
    Process run({APPRENTICE_BINARY, "teach", "--scenario", fresh_user_world(file), "--knowledge", (dir_ / store).string()});
    EXPECT_TRUE(run.write(typed_lines(replies)));
    run.wait();
    return run.out();
  }
};

}  // namespace apprentice::testing
