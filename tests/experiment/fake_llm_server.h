// A local stand-in for an OpenAI-compatible completion server, for the
// experiment's LLM tests: on 127.0.0.1, an ephemeral port, in-process.
//
// When it behaves, it plays a small language model that reads the paper's
// prompts: for a goal prompt ("... Aware of ketchup on table.\n(RESULT)") it
// answers the statements the test gave for that category, the first at
// temperature 0 and the next ones at higher temperatures; a prompt that
// lists rejected statements ("Not: ...") gets the category's second
// thoughts instead, if the test gave any; for an action prompt it proposes
// the next step of the usual open / pick up / put / close sequence. Every
// answer carries log-probabilities. It speaks three dialects: OpenAI's
// /v1/completions, OpenAI's /v1/chat/completions and llama-server's
// /completion.
//
// When it misbehaves, it fails every request in one of the ways a real
// server does (after the first `healthy_for` requests, if set). A listener
// that never accepts stands in for a hung connection.
//
// Like a real server it can refuse a configuration: a wrong API key (401),
// a model it does not serve (404, as vLLM words it), a path it does not
// serve (404). And it can answer in llama-server's own shape, with the four
// ways llama-server's log-probabilities differ from OpenAI's (LlamaQuirks).
#pragma once

#include <httplib.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace apprentice::testing {

enum class ServerMode {
  kModel,             // answers as described above
  kStatus500,         // 500 Internal Server Error, always
  kRateLimited,       // 429 with Retry-After: 1, always
  kRateLimitedOnce,   // every other request 429 with Retry-After: 1, the next one answered
  kSlow,              // answers only after a second (past the client's timeout)
  kMalformedJson,     // 200 with a body cut short
  kWrongJson,         // 200 with JSON that is not a completion
};

// How llama-server (tools/server) really reports log-probabilities, in all
// three dialects, where they differ from OpenAI's:
//  - at a stop string it leaves out as many entries as the stop string has
//    tokens on its own, which may be the text's last token: here, goal
//    answers above temperature 0 and step completions end at a stop string
//    and lack their last token's entry;
//  - when the stop string comes first, the answer is empty and has no
//    log-probabilities at all (no "logprobs" key in chat, null in
//    completions, no completion_probabilities): here, the one-token check
//    ("Hello");
//  - a character made of several byte tokens gets one entry, of the last
//    byte's log-probability (-6 here), with the last byte as alternative;
//  - an answer that ends at the end of the sequence has one more entry,
//    with no text (-9 here): here, goal answers at temperature 0.
struct LlamaQuirks {
  bool on = false;
};

class FakeLlmServer {
 public:
  // Goal statements by object category, most probable first. A category
  // not listed gets `fallback` (with "X" replaced by the category).
  using Goals = std::map<std::string, std::vector<std::string>>;

  explicit FakeLlmServer(ServerMode mode, Goals goals = {},
                         std::vector<std::string> fallback = {"The goal is that the X is on the moon",
                                                              "The goal is that the X is clean",
                                                              "The goal is that the X is in the attic"},
                         Goals second_thoughts = {});
  ~FakeLlmServer();
  FakeLlmServer(const FakeLlmServer&) = delete;
  FakeLlmServer& operator=(const FakeLlmServer&) = delete;

  // The API base for the openai: and openai-chat: backends.
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_) + "/v1"; }
  // The server root, for the llama: backend.
  std::string root() const { return "http://127.0.0.1:" + std::to_string(port_); }
  int requests() const { return requests_.load(); }

  // Set before the first request.
  void healthy_for(int requests) { healthy_for_ = requests; }
  // Fails (in its mode) only up to request `last`, then answers again.
  void broken_until(int last) { broken_until_ = last; }
  void require_key(std::string key) { required_key_ = std::move(key); }
  void serve_only(std::string model) { served_model_ = std::move(model); }
  void llama_server_shape() { llama_quirks_.on = true; }
  // A chat model opens its first word with a quote: '"' at p = 0.72, the
  // step's word after it.
  void open_with_a_quote() { quote_first_ = true; }
  // Every request body received, in order (as JSON text).
  std::vector<std::string> bodies();
  // Every goal prompt received, in order.
  std::vector<std::string> goal_prompts();

  struct Answer;  // the model's answer, before it is put in a dialect

 private:
  enum class Dialect { kCompletions, kChat, kLlama };
  void handle(Dialect dialect, const httplib::Request& request, httplib::Response& response);
  Answer model_answer(const std::string& prompt, double temperature, int max_tokens, int logprobs);
  // Sleeps up to `limit`, less if the server is being torn down.
  void pause(std::chrono::milliseconds limit);

  ServerMode mode_;
  Goals goals_;
  std::vector<std::string> fallback_;
  Goals second_thoughts_;
  httplib::Server server_;
  int port_ = 0;
  std::thread thread_;
  std::atomic<int> requests_{0};
  std::mutex mutex_;
  std::condition_variable released_;
  bool stopping_ = false;
  std::map<std::string, int> asked_;  // prompt -> times asked (guarded by mutex_)
  std::vector<std::string> goal_prompts_;  // guarded by mutex_
  std::vector<std::string> bodies_;        // guarded by mutex_
  int healthy_for_ = 0;
  int broken_until_ = 0;  // 0: for ever
  std::string required_key_;
  std::string served_model_;
  LlamaQuirks llama_quirks_;
  bool quote_first_ = false;
};

// A port that accepts connections into its backlog and never answers: a
// client connects, sends its request, and waits.
class HungServer {
 public:
  HungServer();
  ~HungServer();
  HungServer(const HungServer&) = delete;
  HungServer& operator=(const HungServer&) = delete;
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_) + "/v1"; }

 private:
  int fd_ = -1;
  int port_ = 0;
};

// A port nobody listens on.
int closed_port();

}  // namespace apprentice::testing
