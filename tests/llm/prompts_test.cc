#include "llm/prompts.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "common/paths.h"

namespace apprentice::llm {
namespace {

const std::filesystem::path kPromptDir = std::filesystem::path(APPRENTICE_SOURCE_DIR) / "data/prompts";
const std::filesystem::path kPaper =
    std::filesystem::path(APPRENTICE_SHARED_DIR) / "seed/000_d09e4a28d1113fc6.txt";

const char* const kExamples =
    "(EXAMPLES)(TASK)Task name: store object. Task context: I am in mailroom. Aware of package of "
    "office supplies, package is in mailroom.\n"
    "(RESULT)The goal is that the package is in the closet and the closet is closed(END RESULT)\n"
    "Steps:\n"
    "1. Open closet\n"
    "2. Pick up package of office supplies\n"
    "3. Put package into closet\n"
    "4. Close closet\n"
    "(END TASK)\n"
    "(TASK)Task name: deliver package. Task context: I am in mailroom. Aware of package addressed "
    "to Gary, package is in mailroom.\n"
    "(RESULT)The goal is that the package is in Gary's office(END RESULT)\n"
    "Steps:\n"
    "1. Pick up package addressed to Gary\n"
    "2. Go to Gary's office\n"
    "3. Put package onto desk in Gary's office\n"
    "(END TASK)\n"
    "(END EXAMPLES)\n";

const char* const kTaskLine =
    "(TASK) Task name: tidy kitchen. Task context: I am in kitchen. Aware of ceramic-plate on table.\n";

const char* const kGoal =
    "If the object is a ceramic-plate then the goal is that the object is in the dishwasher and "
    "the dishwasher is closed";

TaskContext plate() { return TaskContext{"tidy kitchen", "clear", "kitchen", "ceramic-plate", "on table"}; }

PromptTemplates load() {
  auto templates = PromptTemplates::load(kPromptDir);
  EXPECT_TRUE(templates.has_value()) << templates.error().describe();
  return std::move(*templates);
}

// The paper prints its prompts wrapped at the page width. Compare modulo
// that: whitespace runs become one space, and the space a wrap leaves before
// "(END" goes.
std::string unwrap(std::string_view text) {
  std::string out;
  for (char c : text) {
    const bool space = c == ' ' || c == '\n' || c == '\t';
    if (space) {
      if (!out.empty() && out.back() != ' ') out.push_back(' ');
    } else {
      out.push_back(c);
    }
  }
  if (!out.empty() && out.back() == ' ') out.pop_back();
  for (size_t at; (at = out.find(" (END")) != std::string::npos;) out.erase(at, 1);
  return out;
}

// The verbatim block that follows `title` in the paper's source.
std::string paper_block(const std::string& paper, const std::string& title) {
  size_t at = paper.find(title);
  if (at == std::string::npos) return {};
  const std::string begin = "\\begin{verbatim}\n";
  size_t start = paper.find(begin, at);
  size_t end = paper.find("\\end{verbatim}", start);
  if (start == std::string::npos || end == std::string::npos) return {};
  start += begin.size();
  return paper.substr(start, end - start);
}

// The parts one after another. (Not `std::string(a) + b + c`: at -O2 GCC
// 12 warns falsely about such chains, -Warray-bounds.)
std::string concatenated(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view part : parts) out.append(part);
  return out;
}

TEST(PromptsTest, GoalPromptForTheCeramicPlateIsThePapers) {
  PromptTemplates templates = load();
  EXPECT_EQ(templates.goal_prompt(plate()), concatenated({kExamples, kTaskLine, "(RESULT)"}));
}

// Issue 13, item 2: the failure context of a re-prompt, one "Not:" line per
// rejected answer just before (RESULT); the first prompt is unchanged.
TEST(PromptsTest, AGoalRepromptListsTheRejectedAnswers) {
  PromptTemplates templates = load();
  TaskContext context = plate();
  context.rejected = {"the goal is that the ceramic-plate is in the cupboard",
                      "The goal is that the ceramic-plate is in the sink."};
  EXPECT_EQ(templates.goal_prompt(context),
            concatenated({kExamples, kTaskLine, "Not: the ceramic-plate is in the cupboard.\n",
                          "Not: the ceramic-plate is in the sink.\n(RESULT)"}));
  QueryAbout about = about_for(context, QueryKind::kGoal);
  EXPECT_EQ(about.rejected, context.rejected);
  EXPECT_TRUE(about_for(context, QueryKind::kActionWord).rejected.empty());
}

TEST(PromptsTest, ActionPromptNumbersTheStepsSoFar) {
  PromptTemplates templates = load();
  const std::string head = concatenated({kExamples, kTaskLine, "(RESULT)", kGoal, "(END RESULT)\nSteps:\n"});
  EXPECT_EQ(templates.action_prompt(plate(), kGoal, {}), head + "1.");
  const std::vector<std::string> steps = {"Open dishwasher", "Pick up ceramic-plate "};
  EXPECT_EQ(templates.action_prompt(plate(), kGoal, steps),
            head + "1. Open dishwasher\n2. Pick up ceramic-plate\n3.");
}

TEST(PromptsTest, MatchesEveryPromptPrintedInThePaper) {
  APPRENTICE_REQUIRE_SHARED(kPaper);
  std::ifstream in(kPaper);
  ASSERT_TRUE(in) << "cannot read " << kPaper;
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string paper = buffer.str();
  PromptTemplates templates = load();
  const std::string goal_dot = concatenated({kGoal, "."});
  const std::vector<std::string> opened = {"Open dishwasher"};
  struct Case {
    std::string title;
    std::string ours;
  };
  const std::vector<Case> cases = {
      {"Agent-created prompt: Goal to tidy ceramic-plate?", templates.goal_prompt(plate())},
      {"Agent-created prompt: What actions can satisfy ceramic-plate goal?",
       templates.action_prompt(plate(), kGoal, {})},
      {"Agent-created action completion prompt with ``open''",
       templates.action_prompt(plate(), goal_dot, {}) + " Open"},
      {"Agent-created action completion prompt with ``pick''",
       templates.action_prompt(plate(), goal_dot, {}) + " Pick"},
      {"Prompt for initial term after ``open dishwasher''",
       templates.action_prompt(plate(), goal_dot, opened)},
      {"Prompt for action completion with ``pick''",
       templates.action_prompt(plate(), goal_dot, opened) + " Pick"},
  };
  for (const Case& c : cases) {
    const std::string printed = paper_block(paper, c.title);
    ASSERT_FALSE(printed.empty()) << c.title;
    EXPECT_EQ(unwrap(c.ours), unwrap(printed)) << c.title;
  }
}

TEST(PromptsTest, ValuesAreNotExpandedAgain) {
  PromptTemplates templates = load();
  TaskContext odd = plate();
  odd.object = "{goal}";
  EXPECT_NE(templates.goal_prompt(odd).find("Aware of {goal} on table."), std::string::npos);
}

TEST(PromptsTest, AboutCarriesTheContext) {
  QueryAbout about = about_for(plate(), QueryKind::kGoal);
  EXPECT_EQ(about.task, "tidy kitchen");
  EXPECT_EQ(about.subtask, "clear");
  EXPECT_EQ(about.object_category, "ceramic-plate");
  EXPECT_EQ(about.place, "table");
}

class BadTemplatesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("apprentice_prompts_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    write("examples.txt", "(EXAMPLES)(END EXAMPLES)\n");
    write("action.txt", "{examples}{task}{location}{object}{object_location}{goal}{steps}\n");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  std::filesystem::path dir_;
};

TEST_F(BadTemplatesTest, MissingFileIsNotFound) {
  auto templates = PromptTemplates::load(dir_);
  ASSERT_FALSE(templates.has_value());
  EXPECT_EQ(templates.error().code, ErrorCode::kNotFound);
  EXPECT_NE(templates.error().message.find("goal.txt"), std::string::npos);
}

TEST_F(BadTemplatesTest, UnknownPlaceholderIsInvalid) {
  write("goal.txt", "{examples}{task}{location}{object}{object_location}{colour}\n");
  auto templates = PromptTemplates::load(dir_);
  ASSERT_FALSE(templates.has_value());
  EXPECT_EQ(templates.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(templates.error().message.find("{colour}"), std::string::npos);
}

TEST_F(BadTemplatesTest, MissingPlaceholderIsInvalid) {
  write("goal.txt", "{examples}{task}{object}{object_location}\n");
  auto templates = PromptTemplates::load(dir_);
  ASSERT_FALSE(templates.has_value());
  EXPECT_NE(templates.error().message.find("{location}"), std::string::npos);
}

TEST(PromptsTest, DefaultDirHasTheTemplates) {
  EXPECT_TRUE(PromptTemplates::load(apprentice::testing::source_path("data/prompts")).has_value());
}

}  // namespace
}  // namespace apprentice::llm
