// The utterance corpus (tests/language/golden/replies.test): every reply
// read with read_reply at its question in the paper's kitchen, against the
// meaning written down by hand. Reports the share read correctly per kind
// of question and fails below 95% overall; the expectations are never
// regenerated from the code.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "language/reply.h"
#include "golden_blocks.h"
#include "language_fixtures.h"
#include "util/text.h"

namespace apprentice::language {
namespace {

using testing::grounder;
using testing::kitchen30;
using testing::source_path;

struct Case {
  std::size_t line = 0;
  std::string scenario = "tidy-kitchen";  // data/scenarios/<scenario>.yaml
  std::string asked;
  std::string object;
  std::string recent;
  std::string choices;
  std::string reply;
  std::string meaning;
};

std::vector<Case> read_corpus(const std::filesystem::path& path) {
  std::vector<Case> cases;
  for (const testing::GoldenBlock& block : testing::read_golden_blocks(path)) {
    Case c;
    c.line = block.line;
    for (const auto& [key, value] : block.fields) {
      if (key == "scenario") c.scenario = value;
      else if (key == "asked") c.asked = value;
      else if (key == "object") c.object = value;
      else if (key == "recent") c.recent = value;
      else if (key == "choices") c.choices = value;
      else if (key == "reply") c.reply = value;
      else if (key == "meaning") c.meaning = value;
      else ADD_FAILURE() << path.filename() << ":" << block.line << ": unknown key '" << key << "'";
    }
    if (!c.reply.empty()) cases.push_back(std::move(c));
  }
  return cases;
}

std::optional<Asked> asked_from(std::string_view text) {
  for (Asked a : {Asked::kTask, Asked::kTaskStep, Asked::kSubtaskEnd, Asked::kGoal, Asked::kAction, Asked::kYesNo,
                  Asked::kWhich})
    if (to_string(a) == text) return a;
  return std::nullopt;
}

ObjectId object_id(const World& world, const std::string& name) {
  auto id = world.universe->find(name);
  EXPECT_TRUE(id.has_value()) << "no object " << name;
  return id.value_or(0);
}

// The world a case is read in: the paper's kitchen unless it names another
// shipped scenario; each is loaded once.
const World& world_of(const Case& c) {
  static std::map<std::string, Scenario> loaded;
  if (c.scenario == "tidy-kitchen") return kitchen30().world;
  auto found = loaded.find(c.scenario);
  if (found == loaded.end())
    found = loaded.emplace(c.scenario, apprentice::testing::shipped_scenario(c.scenario)).first;
  return found->second.world;
}

// Reads every case of one file; prints the shares per kind and what was
// read otherwise; returns the overall share.
double run_corpus(const std::string& file) {
  std::vector<Case> cases = read_corpus(source_path("tests/language/golden/" + file));
  if (cases.empty()) {
    ADD_FAILURE() << "no cases in " << file;
    return 0;
  }
  std::map<std::string, std::pair<int, int>> per_kind;  // kind -> (right, total)
  int right = 0;
  std::ostringstream misses;
  for (const Case& c : cases) {
    auto asked = asked_from(c.asked);
    if (!asked) {
      ADD_FAILURE() << file << ":" << c.line << ": unknown question '" << c.asked << "'";
      continue;
    }
    const World& world = world_of(c);
    ReplyContext context;
    context.asked = *asked;
    if (!c.object.empty()) context.object = object_id(world, c.object);
    if (!c.recent.empty()) context.recent_place = object_id(world, c.recent);
    for (const std::string& id : split_words(c.choices)) context.choices.push_back(object_id(world, id));
    std::string meaning = format_reply(world, read_reply(grounder(), world, context, c.reply));
    auto& [kind_right, kind_total] = per_kind[c.asked];
    ++kind_total;
    if (meaning == c.meaning) {
      ++kind_right;
      ++right;
    } else {
      misses << "  " << file << ":" << c.line << " [" << c.asked << "] \"" << c.reply << "\"\n      expected: "
             << c.meaning << "\n      got:      " << meaning << "\n";
    }
  }
  std::printf("%s, %zu replies:\n", file.c_str(), cases.size());
  for (const auto& [kind, counts] : per_kind)
    std::printf("  %-12s %3d / %3d  %5.1f%%\n", kind.c_str(), counts.first, counts.second,
                100.0 * counts.first / counts.second);
  double share = 100.0 * right / static_cast<double>(cases.size());
  std::printf("  %-12s %3d / %3zu  %5.1f%%\n", "overall", right, cases.size(), share);
  if (!misses.str().empty()) std::printf("Read otherwise:\n%s", misses.str().c_str());
  return share;
}

TEST(ReplyCorpus, ReadsAtLeast95PercentCorrectly) {
  EXPECT_GE(read_corpus(source_path("tests/language/golden/replies.test")).size(), 200u);
  EXPECT_GE(run_corpus("replies.test"), 95.0);
}

// Written after the reader, on phrasings it was not developed on.
TEST(ReplyCorpus, HeldOutReadsAtLeast95PercentCorrectly) { EXPECT_GE(run_corpus("replies-heldout.test"), 95.0); }

// Written in round 2 before the reader was run on them; docs/language.md
// gives the first run's share beside this one.
TEST(ReplyCorpus, SecondHeldOutReadsAtLeast95PercentCorrectly) {
  EXPECT_GE(run_corpus("replies-heldout-2.test"), 95.0);
}

// The worlds beyond the kitchen: properties, kinds of place, surfaces.
TEST(ReplyCorpus, OtherWorldsReadAtLeast95PercentCorrectly) { EXPECT_GE(run_corpus("replies-worlds.test"), 95.0); }

}  // namespace
}  // namespace apprentice::language

