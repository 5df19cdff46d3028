// The JSON spoken with completion servers, kept apart from the transport so
// that it can be tested without a network (and fuzzed: the functions here are
// pure). Three dialects:
//
//  - kOpenAi: POST {base}/completions, the OpenAI legacy completions API,
//    also served by llama-server, vLLM and Ollama under /v1/completions.
//    Log-probabilities come either in OpenAI's layout (logprobs.tokens,
//    .token_logprobs, .top_logprobs as a list of {token: logprob} maps) or in
//    llama-server's (logprobs.content: [{token, logprob, top_logprobs: [...]}]).
//  - kOpenAiChat: POST {base}/chat/completions, the chat endpoint that
//    current servers and OpenAI's models are built around, with the same
//    prompt as the one user message, "logprobs": true and "top_logprobs".
//    The reply's choices[0].message.content is the text and
//    choices[0].logprobs.content the tokens ({token, logprob, bytes,
//    top_logprobs: [{token, logprob, bytes}]}), as OpenAI, llama-server,
//    vLLM (-9999.0 for an impossible token, bytes may be null) and Ollama
//    (no bytes; top_logprobs left out when empty) send them.
//  - kLlamaNative: POST {base}/completion, llama-server's own endpoint with
//    n_probs. Its completion_probabilities come in three layouts, all read:
//    current ({token, logprob, top_logprobs: [{token, logprob}]}), with
//    post_sampling_probs ({token, prob, top_probs: [{token, prob}]}) and the
//    legacy one ({content, probs: [{tok_str, prob}]}).
//
// Wherever an entry has "bytes", the token is read from them; tokens cut in
// the middle of a UTF-8 character are joined with the ones that complete it
// (their log-probabilities summed), so that every token kept is valid UTF-8.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "llm/llm_client.h"
#include "util/result.h"

namespace apprentice::llm {

enum class WireFormat { kOpenAi, kOpenAiChat, kLlamaNative };

struct WireOptions {
  std::string model;          // omitted from the body when empty
  std::optional<int> seed;    // omitted when not set
};

// The JSON body for `request`.
std::string build_request_body(WireFormat format, const CompletionRequest& request,
                               const WireOptions& options);

// Reads a 200 response body. The completion's `raw` is the body. Errors
// (kUnavailable) name what is wrong: not UTF-8, not JSON, JSON cut short,
// missing fields, an "error" object from the server.
Result<Completion> parse_response_body(WireFormat format, std::string_view body);

// The offset of the first byte that is not part of well-formed UTF-8
// (no overlongs, no surrogates, nothing above U+10FFFF), or nothing.
std::optional<size_t> find_invalid_utf8(std::string_view text);

// A short, printable excerpt of a server's error body for messages: at most
// `limit` bytes, invalid UTF-8 and control characters replaced by '?'.
std::string excerpt_for_message(std::string_view body, size_t limit = 200);

}  // namespace apprentice::llm
