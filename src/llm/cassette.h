// Cassettes: JSONL files of recorded exchanges, so that an experiment run
// against a real LLM can be re-run offline and give the same run to the byte.
//
// One line per call to complete(), in call order:
//   {"request": {...}, "response": {...}}   the answer, complete (text,
//                                           tokens, alternatives, usage,
//                                           the server's raw body)
//   {"request": {...}, "error": {"code": "unavailable", "message": "..."}}
// A recorded error is replayed as the same error, so a run in which the LLM
// failed is reproduced too. The format is described in docs/llm.md.
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "llm/llm_client.h"
#include "util/result.h"

namespace apprentice::llm {

// One recorded exchange.
struct Exchange {
  CompletionRequest request;
  Result<Completion> response;
};

// The JSONL line for an exchange, without the newline; and back.
std::string exchange_to_line(const Exchange& exchange);
Result<Exchange> exchange_from_line(std::string_view line);

// Wraps any client and appends each exchange to a cassette file (created or
// truncated when opened; flushed after each line, so a crash loses nothing).
class RecordingClient : public LlmClient {
 public:
  static Result<std::unique_ptr<RecordingClient>> open(const std::filesystem::path& path,
                                                       std::unique_ptr<LlmClient> inner);
  std::string describe() const override;
  bool pools_sources() const override;

 protected:
  // The inner client's answer, or kIo when the cassette cannot be written
  // (a run whose record is incomplete could not be replayed).
  Result<Completion> do_complete(const CompletionRequest& request) override;

 private:
  RecordingClient(std::filesystem::path path, std::unique_ptr<LlmClient> inner, std::ofstream out)
      : path_(std::move(path)), inner_(std::move(inner)), out_(std::move(out)) {}

  std::filesystem::path path_;
  std::unique_ptr<LlmClient> inner_;
  std::ofstream out_;
};

// Answers from a cassette. A request is looked up
//  1. by the exact request (prompt, temperature, max_tokens, stop,
//     top_logprobs): the recorded answers to it, in recorded order;
//  2. else by meaning: the answers recorded for the same QueryAbout (fields
//     compared after normalize_label/normalize_place), in recorded order;
//  3. else kNotFound ("nothing recorded for ..."), and the agent asks the
//     instructor; but a re-prompt (a goal query listing rejected answers)
//     that was not recorded is answered "nothing" (answered = false), as a
//     corpus answers it, so that the run goes on as without re-prompting.
// When the answers to a key are used up they are given again from the first,
// so a longer run than the recorded one still gets answers (repeats).
class ReplayClient : public LlmClient {
 public:
  // Errors: kNotFound (no file), kDataLoss (a line that does not parse; the
  // message names the line).
  static Result<std::unique_ptr<ReplayClient>> open(const std::filesystem::path& path);
  std::string describe() const override;
  size_t size() const { return exchanges_.size(); }

 protected:
  Result<Completion> do_complete(const CompletionRequest& request) override;

 private:
  struct Cursor {
    std::vector<size_t> entries;  // indexes into exchanges_, recorded order
    size_t next = 0;
  };
  ReplayClient(std::filesystem::path path, std::vector<Exchange> exchanges);
  Result<Completion> take(Cursor& cursor);

  std::filesystem::path path_;
  std::vector<Exchange> exchanges_;
  std::map<std::string, Cursor> by_request_;
  std::map<std::string, Cursor> by_meaning_;
};

// The key under which ReplayClient finds an answer by meaning.
std::string meaning_key(const QueryAbout& about);

}  // namespace apprentice::llm
