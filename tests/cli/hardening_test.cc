// Hostile input to the apprentice binary (issue 11): invalid UTF-8 never
// aborts --json; input files are read within documented limits
// (/dev/zero included); a directory, an unreadable file and YAML nested too
// deeply get a message that says so; the same kind of bad input gets the
// same exit code whichever flag it came through.
#include <algorithm>
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/paths.h"
#include "common/process.h"
#include "common/scratch.h"

namespace apprentice {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;
using testing::Invocation;

namespace fs = std::filesystem;

class Hostile : public testing::ScratchTest {
 protected:
  Invocation run(const std::vector<std::string>& args) const { return testing::run_cli(args, dir_, fs::path()); }
  // The tidy kitchen with its domain given by absolute path, and `edit`
  // applied to the text.
  fs::path kitchen_with(const std::string& name, const std::string& from, const std::string& to) const {
    std::string text = testing::read_text(testing::scenario_path("tidy-kitchen"));
    text.replace(text.find("domain: ../domains/kitchen.pddl"), 31,
                 "domain: " + testing::source_path("data/domains/kitchen.pddl").string());
    if (!from.empty()) {
      auto at = text.find(from);
      EXPECT_NE(at, std::string::npos) << from;
      if (at != std::string::npos) text.replace(at, from.size(), to);
    }
    return write(name, text);
  }
};

TEST_F(Hostile, WorldJsonWithABadByteInTheScenarioDoesNotAbort) {
  fs::path path = kitchen_with("bad-byte.yaml", "name: tidy-kitchen", "name: tidy-kitchen\xff");
  Invocation r = run({"world", "--scenario", path.string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;  // was 134, nlohmann's type_error 316
  auto json = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(json.is_discarded());
  EXPECT_EQ(json["scenario"], "tidy-kitchen\xef\xbf\xbd");
  // Text output passes the byte through as it is.
  Invocation text = run({"world", "--scenario", path.string()});
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_THAT(text.out, HasSubstr("tidy-kitchen\xff"));
}

TEST_F(Hostile, DevZeroAsAnyInputFileIsRefusedAtTheLimit) {
  Invocation scenario = run({"world", "--scenario", "/dev/zero"});
  EXPECT_EQ(scenario.exit_code, 2);
  EXPECT_THAT(scenario.err, AllOf(HasSubstr("/dev/zero"), HasSubstr("the limit")));

  fs::path path = kitchen_with("zero-domain.yaml", "", "");
  std::string text = testing::read_text(path);
  text.replace(text.find("domain: "), text.find('\n', text.find("domain: ")) - text.find("domain: "), "domain: /dev/zero");
  path = write("zero-domain.yaml", text);
  Invocation domain = run({"world", "--scenario", path.string()});
  EXPECT_EQ(domain.exit_code, 2);
  EXPECT_THAT(domain.err, AllOf(HasSubstr("/dev/zero"), HasSubstr("the limit")));

  Invocation corpus = run({"interpret", "--scenario", testing::scenario_path("tidy-kitchen").string(), "--corpus",
                           "/dev/zero"});
  EXPECT_EQ(corpus.exit_code, 2);
  EXPECT_THAT(corpus.err, AllOf(HasSubstr("/dev/zero"), HasSubstr("the limit")));

  Invocation llm_corpus = run({"experiment", "--scenario", testing::scenario_path("tidy-kitchen").string(),
                               "--conditions", "inst+llm", "--llm", "corpus:/dev/zero"});
  EXPECT_EQ(llm_corpus.exit_code, 2);
  EXPECT_THAT(llm_corpus.err, AllOf(HasSubstr("/dev/zero"), HasSubstr("the limit")));

  Invocation cassette = run({"experiment", "--scenario", testing::scenario_path("tidy-kitchen").string(),
                             "--conditions", "inst+llm", "--llm", "replay:/dev/zero"});
  EXPECT_EQ(cassette.exit_code, 2);
  EXPECT_THAT(cassette.err, AllOf(HasSubstr("/dev/zero"), HasSubstr("the limit")));
}

TEST_F(Hostile, ADirectoryIsSaidToBeOneWhereverItIsGiven) {
  fs::create_directories(dir_ / "a-directory");
  const std::string directory = (dir_ / "a-directory").string();
  Invocation scenario = run({"world", "--scenario", directory});
  EXPECT_EQ(scenario.exit_code, 2);
  EXPECT_THAT(scenario.err, HasSubstr(directory + ": is a directory"));

  fs::path path = kitchen_with("dir-domain.yaml", "", "");
  std::string text = testing::read_text(path);
  text.replace(text.find("domain: "), text.find('\n', text.find("domain: ")) - text.find("domain: "),
               "domain: " + directory);
  path = write("dir-domain.yaml", text);
  Invocation domain = run({"world", "--scenario", path.string()});
  EXPECT_EQ(domain.exit_code, 2);
  EXPECT_THAT(domain.err, HasSubstr(directory + ": is a directory"));
  EXPECT_THAT(domain.err, Not(HasSubstr("empty")));

  // --corpus <dir> exited 3 where --scenario <dir> exits 2.
  Invocation corpus = run({"interpret", "--scenario", testing::scenario_path("tidy-kitchen").string(), "--corpus",
                           directory});
  EXPECT_EQ(corpus.exit_code, 2) << corpus.err;
  EXPECT_THAT(corpus.err, HasSubstr("is a directory"));

  Invocation knowledge = run({"knowledge", "--knowledge", directory});
  EXPECT_EQ(knowledge.exit_code, 2) << knowledge.err;
  EXPECT_THAT(knowledge.err, HasSubstr("is a directory"));
}

TEST_F(Hostile, AFileThatCannotBeReadSaysWhy) {
  // /proc/self/mem opens but cannot be read at offset 0 (EIO), even as root.
  Invocation r = run({"world", "--scenario", "/proc/self/mem"});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_THAT(r.err, HasSubstr("/proc/self/mem: cannot be read: Input/output error"));
}

TEST_F(Hostile, YamlNestedTooDeeplySaysSo) {
  std::string deep = "name: x\ndomain: d.pddl\nplaces: " + std::string(3000, '[') + std::string(3000, ']') + "\n";
  fs::path path = write("deep.yaml", deep);
  Invocation r = run({"world", "--scenario", path.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, AllOf(HasSubstr(path.string() + ":3:"), HasSubstr("nested too deeply")));
  EXPECT_THAT(r.err, Not(HasSubstr("bad file")));
}

}  // namespace
}  // namespace apprentice
