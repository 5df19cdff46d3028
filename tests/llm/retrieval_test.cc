#include "common/paths.h"
#include "llm/retrieval.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <deque>

#include "llm/fake_llm.h"
#include "llm/wire_format.h"

namespace apprentice::llm {
namespace {

using testing::answer;
using testing::FakeClient;
using ::testing::ElementsAre;

const TaskContext kPlate{"tidy kitchen", "clear", "kitchen", "ceramic-plate", "on table"};
const char* const kGoal =
    "If the object is a ceramic-plate then the goal is that the object is in the dishwasher and "
    "the dishwasher is closed";

PromptTemplates templates() {
  auto loaded = PromptTemplates::load(apprentice::testing::source_path("data/prompts"));
  EXPECT_TRUE(loaded.has_value());
  return std::move(*loaded);
}

// Always the same answer: the worst case for uniqueness.
FakeClient parrot(const std::string& text) {
  return FakeClient([text](const CompletionRequest&, size_t) -> Result<Completion> { return answer(text); });
}

TEST(GetUniqueResponsesTest, GoalScheduleIsOneAtZeroFiveAtPointNineFiveAtOne) {
  FakeClient client = parrot("the goal is that the plate is in the sink");
  auto prompts = templates();
  Retrieval goals = retrieve_goals(client, prompts, kPlate);
  EXPECT_EQ(goals.candidates.size(), 1u);
  EXPECT_EQ(goals.queries, 11);
  EXPECT_THAT(client.temperatures(),
              ElementsAre(0.0, 0.9, 0.9, 0.9, 0.9, 0.9, 1.0, 1.0, 1.0, 1.0, 1.0));
  const CompletionRequest& first = client.requests.front();
  EXPECT_EQ(first.prompt, prompts.goal_prompt(kPlate));
  EXPECT_THAT(first.stop, ElementsAre("(END RESULT)"));
  EXPECT_EQ(first.about.kind, QueryKind::kGoal);
  EXPECT_EQ(first.about.object_category, "ceramic-plate");
  EXPECT_EQ(first.about.place, "table");
  EXPECT_EQ(first.about.subtask, "clear");
}

TEST(GetUniqueResponsesTest, StopsAtTheDesiredNumber) {
  const std::vector<std::string> texts = {"a", "a", "b", "A ", "c", "d"};
  FakeClient client([&](const CompletionRequest&, size_t call) -> Result<Completion> {
    return answer(texts[call]);
  });
  Retrieval goals = retrieve_goals(client, templates(), kPlate);
  ASSERT_EQ(goals.candidates.size(), 3u);
  EXPECT_EQ(goals.candidates[0].text, "a");
  EXPECT_EQ(goals.candidates[1].text, "b");
  EXPECT_EQ(goals.candidates[2].text, "c");  // "A " was the same as "a"
  EXPECT_EQ(goals.candidates[0].temperature, 0.0);
  EXPECT_EQ(goals.candidates[2].temperature, 0.9);
  EXPECT_EQ(goals.queries, 5);
}

TEST(GetUniqueResponsesTest, ErrorStopsTheRetrievalAndKeepsWhatItHad) {
  FakeClient client([](const CompletionRequest&, size_t call) -> Result<Completion> {
    if (call == 2) return make_error(ErrorCode::kUnavailable, "server down");
    return answer(call == 0 ? "a" : "b");
  });
  Retrieval goals = retrieve_goals(client, templates(), kPlate);
  EXPECT_EQ(goals.candidates.size(), 2u);
  ASSERT_TRUE(goals.failure.has_value());
  EXPECT_EQ(goals.failure->message, "server down");
  EXPECT_EQ(goals.queries, 3);
}

TEST(GetUniqueResponsesTest, CutsAtStopSequencesTheServerIgnored) {
  FakeClient client = parrot("the goal is that the plate is in the sink(END RESULT)\nSteps:");
  Retrieval goals = retrieve_goals(client, templates(), kPlate);
  ASSERT_EQ(goals.candidates.size(), 1u);
  EXPECT_EQ(goals.candidates[0].text, "the goal is that the plate is in the sink");
}

// The paper's step-by-step example: first words Open .549, Pick .206,
// Check .067, Go .065, If .027; Open and Pick are known actions.
FakeClient paper_model(std::vector<std::string>* pick_answers = nullptr) {
  return FakeClient([pick_answers](const CompletionRequest& request, size_t) -> Result<Completion> {
    if (request.max_tokens == 1) {
      Completion completion = answer("Open", std::log(0.549));
      completion.top_logprobs = {{{" Open", std::log(0.549)},
                                  {" Pick", std::log(0.206)},
                                  {" Check", std::log(0.067)},
                                  {" Go", std::log(0.065)},
                                  {" If", std::log(0.027)}}};
      return completion;
    }
    if (request.prompt.ends_with(" Open")) return answer("dishwasher", std::log(0.999));
    if (pick_answers != nullptr && !pick_answers->empty()) {
      std::string text = pick_answers->front();
      pick_answers->erase(pick_answers->begin());
      return answer(text, std::log(0.944));
    }
    return answer("up ceramic-plate from table.", std::log(0.944));
  });
}

bool paper_knows(std::string_view word) { return word == "Open" || word == "Pick" || word == "Go"; }

TEST(RetrieveActionsTest, PaperExample) {
  FakeClient client = paper_model();
  auto prompts = templates();
  Retrieval actions = retrieve_actions(client, prompts, kPlate, kGoal, {}, paper_knows);
  ASSERT_EQ(actions.candidates.size(), 2u);
  EXPECT_EQ(actions.candidates[0].text, "Open dishwasher");
  EXPECT_EQ(actions.candidates[1].text, "Pick up ceramic-plate from table.");
  EXPECT_NEAR(std::exp(*actions.candidates[0].mean_logprob), 0.999, 1e-9);
  EXPECT_EQ(actions.candidates[0].action_word, "Open");
  EXPECT_NEAR(actions.candidates[1].action_word_prob, 0.206, 1e-9);
  EXPECT_EQ(actions.first_words.size(), 5u);

  // 1 word query (top 5 at temperature 0), then per kept word 1 at 0 + 5 at 0.9.
  ASSERT_EQ(client.requests.size(), 13u);
  EXPECT_EQ(actions.queries, 13);
  const CompletionRequest& words = client.requests[0];
  EXPECT_EQ(words.max_tokens, 1);
  EXPECT_EQ(words.top_logprobs, 5);
  EXPECT_EQ(words.temperature, 0.0);
  EXPECT_EQ(words.about.kind, QueryKind::kActionWord);
  EXPECT_EQ(words.about.goal, kGoal);
  const std::string base = prompts.action_prompt(kPlate, kGoal, {});
  EXPECT_EQ(words.prompt, base);
  EXPECT_EQ(client.requests[1].prompt, base + " Open");
  EXPECT_EQ(client.requests[1].about.kind, QueryKind::kAction);
  EXPECT_EQ(client.requests[1].about.action_word, "Open");
  EXPECT_THAT(client.requests[1].stop, ElementsAre("\n"));
  EXPECT_EQ(client.requests[7].prompt, base + " Pick");
  std::vector<double> temperatures = client.temperatures();
  EXPECT_THAT(std::vector<double>(temperatures.begin() + 1, temperatures.begin() + 7),
              ElementsAre(0.0, 0.9, 0.9, 0.9, 0.9, 0.9));  // never above 0.9 for actions
}

TEST(RetrieveActionsTest, UnknownWordsNeedHalf) {
  FakeClient client = paper_model();
  // Nothing known: no word reaches 0.5 except Open (.549).
  Retrieval actions = retrieve_actions(client, templates(), kPlate, kGoal, {},
                                       [](std::string_view) { return false; });
  ASSERT_EQ(actions.candidates.size(), 1u);
  EXPECT_EQ(actions.candidates[0].text, "Open dishwasher");
  // Go is known but .065 < .09.
}

TEST(RetrieveActionsTest, TwoUniqueCompletionsPerWordAtMost) {
  std::vector<std::string> picks = {"up ceramic-plate", "up ceramic-plate", "up plate", "up the plate"};
  FakeClient client = paper_model(&picks);
  Retrieval actions = retrieve_actions(client, templates(), kPlate, kGoal, {}, paper_knows);
  ASSERT_EQ(actions.candidates.size(), 3u);
  EXPECT_EQ(actions.candidates[1].text, "Pick up ceramic-plate");
  EXPECT_EQ(actions.candidates[2].text, "Pick up plate");
  EXPECT_EQ(actions.queries, 1 + 6 + 3);
}

TEST(RetrieveActionsTest, StepsSoFarGoIntoThePromptAndAbout) {
  FakeClient client = paper_model();
  const std::vector<std::string> steps = {"Open dishwasher"};
  auto prompts = templates();
  retrieve_actions(client, prompts, kPlate, kGoal, steps, paper_knows);
  EXPECT_EQ(client.requests[0].prompt, prompts.action_prompt(kPlate, kGoal, steps));
  EXPECT_THAT(client.requests[0].about.steps_so_far, ElementsAre("Open dishwasher"));
}

TEST(RetrieveActionsTest, FailureOfTheWordQueryIsReported) {
  FakeClient client([](const CompletionRequest&, size_t) -> Result<Completion> {
    return make_error(ErrorCode::kDeadlineExceeded, "too slow");
  });
  Retrieval actions = retrieve_actions(client, templates(), kPlate, kGoal, {}, paper_knows);
  EXPECT_TRUE(actions.candidates.empty());
  ASSERT_TRUE(actions.failure.has_value());
  EXPECT_EQ(actions.failure->code, ErrorCode::kDeadlineExceeded);
  EXPECT_EQ(actions.queries, 1);
}

// Issue 13, item 7: a server that sends "logprobs": null gave no first word
// at all, so no action candidate. The chosen token is the text; it is kept.
TEST(RetrieveActionsTest, AServerWithoutLogprobsStillGivesItsChosenWord) {
  FakeClient client([](const CompletionRequest& request, size_t) -> Result<Completion> {
    const std::string text = request.max_tokens == 1 ? " Open" : " dishwasher";
    return parse_response_body(WireFormat::kOpenAi,
                               R"({"choices":[{"text":")" + text + R"(","index":0,"logprobs":null,"finish_reason":"length"}]})");
  });
  Retrieval actions = retrieve_actions(client, templates(), kPlate, kGoal, {}, paper_knows);
  ASSERT_EQ(actions.first_words.size(), 1u);
  EXPECT_EQ(actions.first_words[0].token, " Open");
  EXPECT_TRUE(std::isnan(actions.first_words[0].logprob));
  ASSERT_EQ(actions.candidates.size(), 1u);
  EXPECT_EQ(actions.candidates[0].text, "Open dishwasher");
  EXPECT_FALSE(actions.candidates[0].mean_logprob.has_value());  // kept, in retrieval order
}

TEST(JoinActionTest, AddsASpaceOnlyBeforeAWord) {
  EXPECT_EQ(join_action("Open", " dishwasher"), "Open dishwasher");
  EXPECT_EQ(join_action("Pick", "up plate"), "Pick up plate");
  EXPECT_EQ(join_action("Open", "."), "Open.");
  EXPECT_EQ(join_action(" Go ", ""), "Go");
}

// ---- finalize_choice ----

Candidate candidate(const std::string& text, double prob) {
  Candidate c;
  c.text = text;
  c.mean_logprob = std::log(prob);
  return c;
}

// The paper's goal candidates, in retrieval order.
std::vector<Candidate> plate_goals() {
  return {candidate("in the sink", 0.866), candidate("in the cupboard", 0.915),
          candidate("in the dishwasher and turned on", 0.901)};
}

class ScriptedInstructor : public Confirmer {
 public:
  std::deque<bool> answers;
  std::optional<std::string> description;
  std::vector<std::string> asked;
  int descriptions_asked = 0;

  Result<bool> confirm(QueryKind, const Candidate& c) override {
    asked.push_back(c.text);
    if (answers.empty()) return make_error(ErrorCode::kCancelled, "end of input");
    bool yes = answers.front();
    answers.pop_front();
    return yes;
  }
  Result<std::optional<std::string>> describe(QueryKind) override {
    ++descriptions_asked;
    return description;
  }
};

TEST(FinalizeChoiceTest, AsksInOrderOfProbabilityThenForADescription) {
  ScriptedInstructor instructor;
  instructor.answers = {false, false, false};
  instructor.description = "If the object is a ceramic-plate then the goal is that ...";
  auto choice = finalize_choice(plate_goals(), QueryKind::kGoal, {}, &instructor);
  ASSERT_TRUE(choice.has_value());
  EXPECT_THAT(instructor.asked,
              ElementsAre("in the cupboard", "in the dishwasher and turned on", "in the sink"));
  EXPECT_EQ(choice->origin, ChoiceOrigin::kInstructor);
  EXPECT_EQ(choice->text, *instructor.description);
  EXPECT_EQ(choice->offered, 3);
}

TEST(FinalizeChoiceTest, TakesTheFirstAccepted) {
  ScriptedInstructor instructor;
  instructor.answers = {false, true};
  auto choice = finalize_choice(plate_goals(), QueryKind::kGoal, {}, &instructor);
  ASSERT_TRUE(choice.has_value());
  EXPECT_EQ(choice->origin, ChoiceOrigin::kConfirmed);
  EXPECT_EQ(choice->text, "in the dishwasher and turned on");
  EXPECT_EQ(instructor.descriptions_asked, 0);
}

TEST(FinalizeChoiceTest, NeverOffersWhatDoesNotGround) {
  ScriptedInstructor instructor;
  instructor.answers = {false};
  instructor.description = std::nullopt;
  auto grounds = [](const Candidate& c) { return c.text == "in the sink"; };
  auto choice = finalize_choice(plate_goals(), QueryKind::kGoal, grounds, &instructor);
  ASSERT_TRUE(choice.has_value());
  EXPECT_THAT(instructor.asked, ElementsAre("in the sink"));
  EXPECT_EQ(choice->skipped_ungrounded, 2);
  EXPECT_EQ(choice->origin, ChoiceOrigin::kNone);
  EXPECT_EQ(instructor.descriptions_asked, 1);
}

TEST(FinalizeChoiceTest, WithoutAnInstructorTakesTheMostProbable) {
  auto grounds = [](const Candidate& c) { return c.text != "in the cupboard"; };
  auto first = finalize_choice(plate_goals(), QueryKind::kGoal, grounds, nullptr);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->origin, ChoiceOrigin::kUnconfirmed);
  EXPECT_EQ(first->text, "in the cupboard");
  EXPECT_FALSE(first->grounded);
  auto grounded = finalize_choice(plate_goals(), QueryKind::kGoal, grounds, nullptr,
                                  UnattendedPolicy::kFirstGrounded);
  ASSERT_TRUE(grounded.has_value());
  EXPECT_EQ(grounded->text, "in the dishwasher and turned on");
  EXPECT_TRUE(grounded->grounded);
  auto none = finalize_choice({}, QueryKind::kGoal, grounds, nullptr);
  ASSERT_TRUE(none.has_value());
  EXPECT_EQ(none->origin, ChoiceOrigin::kNone);
}

TEST(FinalizeChoiceTest, OfferingUngroundedResponsesAsThePaperDid) {
  ScriptedInstructor instructor;
  instructor.answers = {false, false, true};
  auto grounds = [](const Candidate& c) { return c.text == "in the sink"; };
  ChoiceOptions options;
  options.offer_ungrounded = true;
  auto choice = finalize_choice(plate_goals(), QueryKind::kGoal, grounds, &instructor, options);
  ASSERT_TRUE(choice.has_value());
  EXPECT_THAT(instructor.asked, ElementsAre("in the cupboard", "in the dishwasher and turned on", "in the sink"));
  EXPECT_EQ(choice->skipped_ungrounded, 0);
  EXPECT_EQ(choice->offered, 3);
  EXPECT_TRUE(choice->grounded);
  ASSERT_EQ(choice->rejected.size(), 2u);
  EXPECT_EQ(choice->rejected[1].text, "in the dishwasher and turned on");
}

TEST(FinalizeChoiceTest, ACallerMayKeepItsOrderAndAskForTheDescriptionItself) {
  ScriptedInstructor instructor;
  instructor.answers = {false, false, false};
  instructor.description = "never asked";
  ChoiceOptions options;
  options.sort_by_probability = false;
  options.ask_description = false;
  auto choice = finalize_choice(plate_goals(), QueryKind::kGoal, {}, &instructor, options);
  ASSERT_TRUE(choice.has_value());
  EXPECT_THAT(instructor.asked, ElementsAre("in the sink", "in the cupboard", "in the dishwasher and turned on"));
  EXPECT_EQ(instructor.descriptions_asked, 0);
  EXPECT_EQ(choice->origin, ChoiceOrigin::kNone);
  EXPECT_EQ(choice->rejected.size(), 3u);
}

TEST(FinalizeChoiceTest, InstructorErrorsPropagate) {
  ScriptedInstructor instructor;  // no answers: end of input
  auto choice = finalize_choice(plate_goals(), QueryKind::kAction, {}, &instructor);
  ASSERT_FALSE(choice.has_value());
  EXPECT_EQ(choice.error().code, ErrorCode::kCancelled);
}

TEST(SortTest, StableAndUnknownLast) {
  Candidate unknown;
  unknown.text = "b";
  std::vector<Candidate> candidates = {candidate("a", 0.5), unknown, candidate("c", 0.9),
                                       candidate("d", 0.5)};
  sort_by_mean_logprob(candidates);
  EXPECT_EQ(candidates[0].text, "c");
  EXPECT_EQ(candidates[1].text, "a");
  EXPECT_EQ(candidates[2].text, "d");
  EXPECT_EQ(candidates[3].text, "b");
}

}  // namespace
}  // namespace apprentice::llm
