// Reply bodies of the OpenAI-compatible chat endpoint (/v1/chat/completions
// with "logprobs": true), one per server, written for these tests from each
// server's documentation of its reply: the fields each one sends, in its
// order, with its own extras. All say " Open dishwasher", with " Open" at
// -0.02 and " Pick" as the runner-up where the server gives alternatives.
#pragma once

#include <string>
#include <vector>

namespace apprentice::llm::testing {

struct ChatShape {
  const char* server;
  std::string body;
  bool alternatives;  // whether the body carries a runner-up for the first token
};

inline std::vector<ChatShape> chat_shapes() {
  return {
      // OpenAI: bytes on every token and alternative; "refusal": null.
      {"openai", R"({"id":"chatcmpl-A1","object":"chat.completion","created":1730000000,"model":"gpt-4o-mini-2024-07-18",
"choices":[{"index":0,"message":{"role":"assistant","content":" Open dishwasher","refusal":null},
"logprobs":{"content":[
{"token":" Open","logprob":-0.02,"bytes":[32,79,112,101,110],"top_logprobs":[
  {"token":" Open","logprob":-0.02,"bytes":[32,79,112,101,110]},{"token":" Pick","logprob":-4.1,"bytes":[32,80,105,99,107]}]},
{"token":" dish","logprob":-0.3,"bytes":[32,100,105,115,104],"top_logprobs":[{"token":" dish","logprob":-0.3,"bytes":[32,100,105,115,104]}]},
{"token":"washer","logprob":-0.001,"bytes":[119,97,115,104,101,114],"top_logprobs":[{"token":"washer","logprob":-0.001,"bytes":[119,97,115,104,101,114]}]}],
"refusal":null},"finish_reason":"stop"}],
"usage":{"prompt_tokens":310,"completion_tokens":3,"total_tokens":313,"completion_tokens_details":{"reasoning_tokens":0}},
"system_fingerprint":"fp_0123456789"})",
       true},
      // llama-server: token ids beside the tokens, and its timings.
      {"llama-server", R"({"choices":[{"finish_reason":"stop","index":0,"message":{"role":"assistant","content":" Open dishwasher"},
"logprobs":{"content":[
{"id":5614,"token":" Open","bytes":[32,79,112,101,110],"logprob":-0.02,"top_logprobs":[
  {"id":5614,"token":" Open","bytes":[32,79,112,101,110],"logprob":-0.02},{"id":14687,"token":" Pick","bytes":[32,80,105,99,107],"logprob":-4.1}]},
{"id":23087,"token":" dish","bytes":[32,100,105,115,104],"logprob":-0.3,"top_logprobs":[]},
{"id":50088,"token":"washer","bytes":[119,97,115,104,101,114],"logprob":-0.001,"top_logprobs":[]}]}}],
"created":1730000000,"model":"gpt-3.5-turbo","system_fingerprint":"b4500-0a1b2c3d","object":"chat.completion",
"usage":{"completion_tokens":3,"prompt_tokens":310,"total_tokens":313},"id":"chatcmpl-xyz",
"timings":{"prompt_n":310,"prompt_ms":80.5,"predicted_n":3,"predicted_ms":12.1}})",
       true},
      // vLLM: -9999.0 for an impossible token, bytes may be null, extra
      // message and choice fields.
      {"vllm", R"({"id":"chatcmpl-9f8e","object":"chat.completion","created":1730000000,"model":"meta-llama/Llama-3.1-8B-Instruct",
"choices":[{"index":0,"message":{"role":"assistant","reasoning_content":null,"content":" Open dishwasher","tool_calls":[]},
"logprobs":{"content":[
{"token":" Open","logprob":-0.02,"bytes":[32,79,112,101,110],"top_logprobs":[
  {"token":" Open","logprob":-0.02,"bytes":[32,79,112,101,110]},{"token":" Pick","logprob":-4.1,"bytes":[32,80,105,99,107]},
  {"token":"<|eot_id|>","logprob":-9999.0,"bytes":null}]},
{"token":" dish","logprob":-0.3,"bytes":[32,100,105,115,104],"top_logprobs":[]},
{"token":"washer","logprob":-0.001,"bytes":[119,97,115,104,101,114],"top_logprobs":[]}]},
"finish_reason":"stop","stop_reason":null}],
"usage":{"prompt_tokens":310,"total_tokens":313,"completion_tokens":3,"prompt_tokens_details":null},"prompt_logprobs":null})",
       true},
      // Ollama's OpenAI compatibility: no bytes, top_logprobs left out when
      // empty, its own fingerprint.
      {"ollama", R"({"id":"chatcmpl-512","object":"chat.completion","created":1730000000,"model":"llama3.2","system_fingerprint":"fp_ollama",
"choices":[{"index":0,"message":{"role":"assistant","content":" Open dishwasher"},"finish_reason":"stop",
"logprobs":{"content":[
{"token":" Open","logprob":-0.02,"top_logprobs":[{"token":" Open","logprob":-0.02},{"token":" Pick","logprob":-4.1}]},
{"token":" dish","logprob":-0.3},{"token":"washer","logprob":-0.001}]}}],
"usage":{"prompt_tokens":310,"completion_tokens":3,"total_tokens":313}})",
       true},
  };
}

// A server that ignores "logprobs" (or cannot give them): "logprobs": null.
inline const char* const kChatWithoutLogprobs =
    R"({"id":"chatcmpl-0","object":"chat.completion","created":1730000000,"model":"m",
"choices":[{"index":0,"message":{"role":"assistant","content":" Open"},"logprobs":null,"finish_reason":"length"}],
"usage":{"prompt_tokens":310,"completion_tokens":1,"total_tokens":311}})";

// "café" with the é (C3 A9) cut between two tokens, whose strings cannot
// show half a character: OpenAI's escape and the replacement character.
inline const char* const kChatCutCharacter =
    R"({"choices":[{"index":0,"message":{"role":"assistant","content":" café"},"finish_reason":"stop",
"logprobs":{"content":[
{"token":" caf","logprob":-0.1,"bytes":[32,99,97,102],"top_logprobs":[]},
{"token":"bytes:\\xc3","logprob":-0.2,"bytes":[195],"top_logprobs":[{"token":"\ufffd","logprob":-0.2,"bytes":[195]}]},
{"token":"\ufffd","logprob":-0.3,"bytes":[169],"top_logprobs":[]}]}}]})";

}  // namespace apprentice::llm::testing
