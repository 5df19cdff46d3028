// The LLM client interface: one completion request in, the text with its
// per-token log-probabilities and the top alternatives at each position out.
//
// Every request also says what it is about (QueryAbout): the kind of query
// (goal, action word, action) and the task context it was built from. The
// backends that do not run a model (replay, corpus) answer by that meaning
// rather than by the exact prompt text.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"

namespace apprentice::llm {

// What a query asks for: the three query types of the paper's appendix,
// and the two of a person's preferences (llm/preference_prompts.h).
enum class QueryKind {
  kGoal,        // a goal statement for an object (goal template)
  kActionWord,  // the top-k first words of the next step (action template)
  kAction,      // the rest of a step after a chosen first word
  kSummary,     // the rule a person's placements follow, in one sentence
  kPlacement,   // where each of several things goes, by a rule or by examples
};

std::string_view to_string(QueryKind kind);
// Parses "goal", "action_word", "action".
std::optional<QueryKind> query_kind_from_string(std::string_view text);

// The task context a query was built from. Empty strings mean "not given".
struct QueryAbout {
  QueryKind kind = QueryKind::kGoal;
  std::string task;             // "tidy kitchen"
  std::string subtask;          // "clear"
  std::string object_category;  // "ceramic-plate"
  std::string place;            // where the object is: "table"
  std::string goal;             // kActionWord, kAction: the goal the steps are for
  std::vector<std::string> steps_so_far;  // kActionWord, kAction: steps done
  std::string action_word;      // kAction: the first word being continued
  // kGoal: answers already rejected for this object (a "no" from the
  // instructor, or unusable), which the prompt lists so that the model
  // proposes something else. Empty for a first query.
  std::vector<std::string> rejected;
  // kSummary, kPlacement: the places things go, in the world's words
  // ("left storage box"); the [thing, place] examples the person gave
  // (kSummary, and kPlacement by examples); the rule to place by
  // (kPlacement; empty: by the examples, or with neither by common sense);
  // the things to place (kPlacement).
  std::vector<std::string> receptacles = {};
  std::vector<std::pair<std::string, std::string>> examples = {};
  std::string summary = {};
  std::vector<std::string> objects = {};

  friend bool operator==(const QueryAbout&, const QueryAbout&) = default;
};

struct CompletionRequest {
  std::string prompt;
  double temperature = 0.0;          // in [0, 2]
  int max_tokens = 64;               // >= 1
  std::vector<std::string> stop;     // stop sequences (the server cuts before them)
  // How many alternatives to report at each position, 0..20. Backends that
  // speak HTTP always ask for at least 1, so that the chosen tokens carry
  // their log-probabilities.
  int top_logprobs = 1;
  QueryAbout about;

  friend bool operator==(const CompletionRequest&, const CompletionRequest&) = default;
};

// A token and its natural-log probability. A log-probability the server did
// not report is NaN; a probability of 0 is stored as kFloorLogprob so that
// every stored value survives a JSON round trip unchanged.
struct TokenLogprob {
  std::string token;
  double logprob = 0.0;

  friend bool operator==(const TokenLogprob& a, const TokenLogprob& b);
};

inline constexpr double kFloorLogprob = -100.0;

// Where an answer came from. The agent tags what it shows the instructor
// accordingly ("[LM]" for a model, "[corpus]" for a corpus).
enum class ResponseSource { kModel, kCorpus };
std::string_view to_string(ResponseSource source);

struct Completion {
  // False when the backend has nothing for this query (a corpus without
  // that object, say). That is not an error: the caller asks the instructor.
  bool answered = true;
  ResponseSource source = ResponseSource::kModel;
  std::string text;                    // valid UTF-8
  std::vector<TokenLogprob> tokens;    // the generated tokens, in order
  // top_logprobs[i]: the alternatives at position i, most probable first.
  std::vector<std::vector<TokenLogprob>> top_logprobs;
  std::string finish_reason;           // "stop", "length" or "" if unknown
  int64_t prompt_tokens = 0;           // as reported by the server (corpus: words)
  int64_t completion_tokens = 0;
  // The server's response body, verbatim (empty for corpus answers). Kept for
  // cassettes and debugging; never parsed again.
  std::string raw;

  friend bool operator==(const Completion&, const Completion&) = default;
};

// The mean of the finite token log-probabilities, or nothing when there are
// none. exp() of it is what the paper reports as "prob".
std::optional<double> mean_logprob(const std::vector<TokenLogprob>& tokens);

// Whether an answer's log-probabilities arrived: kNoText for an answer with
// no text (the stop came first), which has none to report whatever the
// server, so that it is not taken for a server without them.
enum class LogprobsArrived { kYes, kNo, kNoText };
LogprobsArrived logprobs_arrived(const Completion& completion);

// An answer in one line, for -v: its text quoted with newlines escaped, and
// what came with it: "\" Open the fridge\" (mean log-probability -0.41
// over 4 tokens)", "(no log-probabilities)", or "(no text)".
std::string describe_answer(const Completion& completion);

// Running totals kept by every client (see LlmClient::complete).
struct LlmUsage {
  int64_t queries = 0;            // calls to complete()
  int64_t failures = 0;           // calls that returned an Error
  int64_t unanswered = 0;         // calls answered "nothing" (corpus miss)
  int64_t prompt_tokens = 0;
  int64_t completion_tokens = 0;
};

// The interface the agent talks to. Implementations are not thread-safe: one
// client per thread.
class LlmClient {
 public:
  virtual ~LlmClient() = default;
  LlmClient() = default;
  LlmClient(const LlmClient&) = delete;
  LlmClient& operator=(const LlmClient&) = delete;

  // Checks the request (a malformed request is a bug and aborts), forwards
  // it to the backend and keeps the usage totals. Never throws. Errors are
  // kUnavailable (server down or answering garbage), kDeadlineExceeded,
  // kFailedPrecondition (refused credentials), kInvalidInput (the server
  // rejected the request), kNotFound (nothing recorded in a cassette).
  Result<Completion> complete(const CompletionRequest& request);

  const LlmUsage& usage() const { return usage_; }

  // A one-line description for logs and transcripts: the backend and where it
  // points. Never contains a credential.
  virtual std::string describe() const = 0;

  // Whether the answers pool several sources (a corpus read as an ensemble
  // of runs), so that tables can say so rather than set them beside a
  // single model's figures.
  virtual bool pools_sources() const { return false; }

 protected:
  virtual Result<Completion> do_complete(const CompletionRequest& request) = 0;

 private:
  LlmUsage usage_;
};

// The paper's single next-token top-k query: one token at temperature 0 with
// k alternatives. Returns the alternatives at the first position, most
// probable first (the chosen token alone when the backend gave no
// alternatives; the text with a NaN log-probability when it gave no
// log-probabilities at all; empty when it answered nothing).
Result<std::vector<TokenLogprob>> next_token_alternatives(LlmClient& client,
                                                          std::string prompt, int k,
                                                          QueryAbout about);

// Normal forms used to match QueryAbout fields by meaning: lower case,
// '-' and '_' read as spaces, runs of spaces collapsed, trimmed.
std::string normalize_label(std::string_view text);
// normalize_label, then a leading "on the ", "in the ", "on ", "in ", "at ",
// "the " dropped: "on the dish-rack" -> "dish rack".
std::string normalize_place(std::string_view text);

}  // namespace apprentice::llm
