// The paper's LLM algorithms (appendix): retrieve_goals (Alg. 2),
// retrieve_actions (Alg. 3), get_unique_responses (Alg. 4) and
// finalize_choice (Alg. 5), with the paper's parameters as defaults.
//
// They need two things from the agent, passed in as seams so that this
// module depends on nothing but util: whether a word is an action the agent
// knows, and (for finalize_choice) whether a response grounds and an
// instructor to ask (Confirmer).
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "llm/llm_client.h"
#include "llm/prompts.h"
#include "util/result.h"

namespace apprentice::llm {

// One retrieved response.
struct Candidate {
  std::string text;                    // trimmed; for actions, word + completion
  std::optional<double> mean_logprob;  // over the completion's tokens
  double temperature = 0.0;            // of the query that produced it
  ResponseSource source = ResponseSource::kModel;
  std::string action_word;             // actions: the first word it continues
  double action_word_prob = 0.0;       // actions: that word's probability (NaN: not reported)

  friend bool operator==(const Candidate&, const Candidate&) = default;
};

// What a retrieval produced. A failing LLM is not fatal: `failure` says what
// went wrong and the retrieval stops there, keeping what it already had.
struct Retrieval {
  std::vector<Candidate> candidates;  // unique, in retrieval order
  int queries = 0;                    // calls made to the client
  std::optional<Error> failure;       // the error that stopped it, if any
  bool unanswered = false;            // the backend had nothing (corpus miss)
  std::vector<TokenLogprob> first_words;  // actions: the top-k words considered
};

// Algorithm 4. The first query is at low_temp; then, while fewer than
// `desired` unique responses and tries <= max_attempts, one more query at
// high_temp, or at max_temp once tries > max_attempts / 2 (tries counts the
// queries made, starting at 1 after the first). So at most 1 + max_attempts
// queries, as the pseudo-code has it (the prose says "up to 10 times"; we
// follow the pseudo-code). Responses are unique when they differ after
// trimming, collapsing spaces and ignoring case; empty responses are not
// kept. Stops early on an error or when the backend answers nothing.
struct UniqueResponsesParams {
  int desired = 3;
  int max_attempts = 10;
  double low_temp = 0.0;
  double high_temp = 0.9;
  double max_temp = 1.0;
};
Retrieval get_unique_responses(LlmClient& client, CompletionRequest request,
                               const UniqueResponsesParams& params);

// Algorithm 2: num_responses = 3, max_attempts = 10, temperatures 0, 0.9, 1.0.
struct GoalParams {
  UniqueResponsesParams unique{3, 10, 0.0, 0.9, 1.0};
  int max_tokens = 64;
  std::vector<std::string> stop = {"(END RESULT)"};
};
Retrieval retrieve_goals(LlmClient& client, const PromptTemplates& templates,
                         const TaskContext& context, const GoalParams& params = {});

// Called with a first word exactly as the model produced it, trimmed (e.g.
// "Open"); returns whether the agent knows it as an action verb.
using IsKnownActionWord = std::function<bool(std::string_view word)>;

// Algorithm 3: the top num_words = 5 first words at temperature 0; a word is
// kept if its probability is >= 0.09 when known, >= 0.5 otherwise; for each
// kept word (most probable first), the prompt plus " " + word is completed
// with get_unique_responses (2 unique in max_attempts = 5, temperatures 0
// then 0.9, never higher). Candidates are word + completion, unique across
// words. (The paper's pseudo-code overwrites its list for each word; its
// worked example keeps the actions of every word, as we do.)
struct ActionParams {
  int num_words = 5;
  double known_word_threshold = 0.09;
  double unknown_word_threshold = 0.5;
  UniqueResponsesParams unique{2, 5, 0.0, 0.9, 0.9};
  int max_tokens = 24;
  std::vector<std::string> stop = {"\n"};
};
Retrieval retrieve_actions(LlmClient& client, const PromptTemplates& templates,
                           const TaskContext& context, std::string_view goal,
                           std::span<const std::string> steps_so_far,
                           const IsKnownActionWord& is_known_action_word,
                           const ActionParams& params = {});

// "Open" + " dishwasher" -> "Open dishwasher"; "Pick" + "up plate" ->
// "Pick up plate" (a space is added when the completion starts with a letter
// or digit); the result is trimmed.
std::string join_action(std::string_view word, std::string_view completion);

// Sorts by mean log-probability, highest first; candidates without one go
// last. Stable: equal values keep retrieval order.
void sort_by_mean_logprob(std::vector<Candidate>& candidates);

// The instructor, as finalize_choice needs it. Implemented by the agent.
class Confirmer {
 public:
  virtual ~Confirmer() = default;
  // Puts one candidate to the instructor as a yes/no question (the agent
  // words it, e.g. "[LM] For a ceramic plate on the table, is the goal that
  // ...?", tagging corpus answers as such). Returns true for yes. An Error
  // (e.g. kCancelled at end of input) aborts finalize_choice.
  virtual Result<bool> confirm(QueryKind kind, const Candidate& candidate) = 0;
  // Every candidate was rejected, or none could be offered: asks for a
  // description ("What is the next goal or subtask of clear?"). Returns the
  // instructor's text, or nothing if they gave none (the default: a caller
  // that asks for descriptions itself passes ask_description = false).
  virtual Result<std::optional<std::string>> describe(QueryKind kind) {
    (void)kind;
    return std::optional<std::string>();
  }
};

// A Confirmer that asks through a function (the agent's dialogue).
class CallbackConfirmer : public Confirmer {
 public:
  using Ask = std::function<Result<bool>(QueryKind kind, const Candidate& candidate)>;
  explicit CallbackConfirmer(Ask ask) : ask_(std::move(ask)) {}
  Result<bool> confirm(QueryKind kind, const Candidate& candidate) override { return ask_(kind, candidate); }

 private:
  Ask ask_;
};

// Whether the agent can interpret and ground a response in its world.
using Grounds = std::function<bool(const Candidate& candidate)>;

enum class ChoiceOrigin {
  kConfirmed,    // a candidate the instructor accepted
  kUnconfirmed,  // no instructor: the most probable candidate, taken as is
  kInstructor,   // the instructor's own description
  kNone,         // nothing: no candidates and no instructor, or no description
};

struct Choice {
  ChoiceOrigin origin = ChoiceOrigin::kNone;
  std::string text;
  std::optional<Candidate> candidate;  // kConfirmed, kUnconfirmed
  bool grounded = false;               // whether `candidate` grounds
  int offered = 0;                     // yes/no questions asked
  int skipped_ungrounded = 0;          // candidates not offered: they do not ground
  std::vector<Candidate> rejected;     // those the instructor said no to, in order
};

// What to take without an instructor: the paper takes the most probable
// response even when it does not ground (and records the failure);
// kFirstGrounded takes the most probable one that grounds.
enum class UnattendedPolicy { kFirst, kFirstGrounded };

struct ChoiceOptions {
  UnattendedPolicy unattended = UnattendedPolicy::kFirst;
  // The paper offers every response, also one the agent cannot ground (the
  // instructor can only say no to it); by default those are never offered.
  bool offer_ungrounded = false;
  // Ask for a description once every candidate is rejected (the last step
  // of Algorithm 5). Off for a caller that asks later itself, after
  // re-prompting the model with the rejected answers.
  bool ask_description = true;
  // Sort by mean log-probability first (Algorithm 5). Off for a caller
  // that has put the candidates in an order of its own (a score after
  // analysing them, see agent/goal_repair.h).
  bool sort_by_probability = true;
};

// Algorithm 5. Sorts `candidates` by mean log-probability (unless told
// not to). Without an instructor (confirmer == nullptr) returns the first
// one (see the unattended policy), with `grounded` set. With one, offers the
// candidates in that order until one is accepted (ungrounded ones only with
// offer_ungrounded), then asks for a description (unless told not to).
// `grounds` may be empty: everything grounds.
Result<Choice> finalize_choice(std::vector<Candidate> candidates, QueryKind kind, const Grounds& grounds,
                               Confirmer* confirmer, const ChoiceOptions& options);
// The same with the paper's defaults and an unattended policy.
Result<Choice> finalize_choice(std::vector<Candidate> candidates, QueryKind kind,
                               const Grounds& grounds, Confirmer* confirmer,
                               UnattendedPolicy policy = UnattendedPolicy::kFirst);

}  // namespace apprentice::llm
