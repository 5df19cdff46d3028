#include "llm/wire_format.h"

#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "llm/chat_shapes.h"

namespace apprentice::llm {
namespace {

using nlohmann::json;

CompletionRequest goal_request() {
  CompletionRequest request;
  request.prompt = "(TASK) ... (RESULT)";
  request.temperature = 0.9;
  request.max_tokens = 64;
  request.stop = {"(END RESULT)"};
  request.top_logprobs = 0;
  return request;
}

TEST(WireFormatTest, OpenAiRequestBody) {
  json body = json::parse(build_request_body(WireFormat::kOpenAi, goal_request(), {"davinci", 7}));
  EXPECT_EQ(body["prompt"], "(TASK) ... (RESULT)");
  EXPECT_EQ(body["temperature"], 0.9);
  EXPECT_EQ(body["max_tokens"], 64);
  EXPECT_EQ(body["logprobs"], 1);  // at least one, for the chosen tokens
  EXPECT_EQ(body["stop"], json::array({"(END RESULT)"}));
  EXPECT_EQ(body["model"], "davinci");
  EXPECT_EQ(body["seed"], 7);
  EXPECT_EQ(body["stream"], false);
}

TEST(WireFormatTest, NativeRequestBodyOmitsUnsetFields) {
  CompletionRequest request = goal_request();
  request.top_logprobs = 5;
  request.stop.clear();
  json body = json::parse(build_request_body(WireFormat::kLlamaNative, request, {}));
  EXPECT_EQ(body["n_predict"], 64);
  EXPECT_EQ(body["n_probs"], 5);
  EXPECT_FALSE(body.contains("model"));
  EXPECT_FALSE(body.contains("seed"));
  EXPECT_FALSE(body.contains("stop"));
}

TEST(WireFormatTest, ChatRequestBodyIsTheSamePromptAsOneUserMessage) {
  CompletionRequest request = goal_request();
  request.top_logprobs = 5;
  json body = json::parse(build_request_body(WireFormat::kOpenAiChat, request, {"gpt-4o-mini", std::nullopt}));
  EXPECT_FALSE(body.contains("prompt"));
  ASSERT_EQ(body["messages"].size(), 1u);
  EXPECT_EQ(body["messages"][0]["role"], "user");
  EXPECT_EQ(body["messages"][0]["content"], "(TASK) ... (RESULT)");
  EXPECT_EQ(body["logprobs"], true);
  EXPECT_EQ(body["top_logprobs"], 5);
  EXPECT_EQ(body["max_tokens"], 64);
  EXPECT_EQ(body["temperature"], 0.9);
  EXPECT_EQ(body["stop"], json::array({"(END RESULT)"}));
  EXPECT_EQ(body["model"], "gpt-4o-mini");
  request.top_logprobs = 0;
  EXPECT_EQ(json::parse(build_request_body(WireFormat::kOpenAiChat, request, {}))["top_logprobs"], 1);
}

// Issue 13, item 5: the chat reply of each server, as its documentation has it.
TEST(WireFormatTest, ChatRepliesOfEveryServer) {
  for (const testing::ChatShape& shape : testing::chat_shapes()) {
    SCOPED_TRACE(shape.server);
    auto completion = parse_response_body(WireFormat::kOpenAiChat, shape.body);
    ASSERT_TRUE(completion.has_value()) << completion.error().describe();
    EXPECT_EQ(completion->text, " Open dishwasher");
    ASSERT_EQ(completion->tokens.size(), 3u);
    EXPECT_EQ(completion->tokens[0], (TokenLogprob{" Open", -0.02}));
    EXPECT_EQ(completion->tokens[1], (TokenLogprob{" dish", -0.3}));
    EXPECT_EQ(completion->tokens[2], (TokenLogprob{"washer", -0.001}));
    EXPECT_EQ(completion->finish_reason, "stop");
    EXPECT_EQ(completion->prompt_tokens, 310);
    EXPECT_EQ(completion->completion_tokens, 3);
    ASSERT_EQ(completion->top_logprobs.size(), 3u);
    ASSERT_GE(completion->top_logprobs[0].size(), 2u);
    EXPECT_EQ(completion->top_logprobs[0][0], (TokenLogprob{" Open", -0.02}));
    EXPECT_EQ(completion->top_logprobs[0][1], (TokenLogprob{" Pick", -4.1}));
    for (const TokenLogprob& alternative : completion->top_logprobs[0])
      EXPECT_GE(alternative.logprob, kFloorLogprob) << alternative.token;  // vLLM's -9999.0 is the floor
  }
}

TEST(WireFormatTest, ChatWithoutLogprobsKeepsTheText) {
  auto completion = parse_response_body(WireFormat::kOpenAiChat, testing::kChatWithoutLogprobs);
  ASSERT_TRUE(completion.has_value()) << completion.error().describe();
  EXPECT_EQ(completion->text, " Open");
  EXPECT_TRUE(completion->tokens.empty());
  EXPECT_EQ(completion->finish_reason, "length");
}

TEST(WireFormatTest, ChatTokensCutMidCharacterAreJoinedFromTheirBytes) {
  auto completion = parse_response_body(WireFormat::kOpenAiChat, testing::kChatCutCharacter);
  ASSERT_TRUE(completion.has_value()) << completion.error().describe();
  EXPECT_EQ(completion->text, " caf\xC3\xA9");
  ASSERT_EQ(completion->tokens.size(), 2u);
  EXPECT_EQ(completion->tokens[0], (TokenLogprob{" caf", -0.1}));
  EXPECT_EQ(completion->tokens[1].token, "\xC3\xA9");  // the é, whole
  EXPECT_DOUBLE_EQ(completion->tokens[1].logprob, -0.5);
  ASSERT_EQ(completion->top_logprobs.size(), 2u);
  ASSERT_EQ(completion->top_logprobs[1].size(), 1u);
  EXPECT_EQ(completion->top_logprobs[1][0].token, "\xEF\xBF\xBD");  // half a character cannot be shown
  std::string joined;
  for (const TokenLogprob& token : completion->tokens) joined += token.token;
  EXPECT_EQ(joined, completion->text);
}

TEST(WireFormatTest, OpenAiLegacyLogprobs) {
  const std::string body = R"({"id":"cmpl-1","object":"text_completion","choices":[{"text":" Open",
    "index":0,"finish_reason":"length","logprobs":{"tokens":[" Open"],"token_logprobs":[-0.6],
    "top_logprobs":[{" Pick":-1.58," Open":-0.6," Check":-2.7}],"text_offset":[10]}}],
    "usage":{"prompt_tokens":300,"completion_tokens":1,"total_tokens":301}})";
  auto completion = parse_response_body(WireFormat::kOpenAi, body);
  ASSERT_TRUE(completion.has_value()) << completion.error().describe();
  EXPECT_EQ(completion->text, " Open");
  ASSERT_EQ(completion->tokens.size(), 1u);
  EXPECT_EQ(completion->tokens[0], (TokenLogprob{" Open", -0.6}));
  ASSERT_EQ(completion->top_logprobs.size(), 1u);
  ASSERT_EQ(completion->top_logprobs[0].size(), 3u);
  EXPECT_EQ(completion->top_logprobs[0][0].token, " Open");  // most probable first
  EXPECT_EQ(completion->top_logprobs[0][1].token, " Pick");
  EXPECT_EQ(completion->top_logprobs[0][2].token, " Check");
  EXPECT_EQ(completion->finish_reason, "length");
  EXPECT_EQ(completion->prompt_tokens, 300);
  EXPECT_EQ(completion->completion_tokens, 1);
  EXPECT_EQ(completion->source, ResponseSource::kModel);
  EXPECT_EQ(completion->raw, body);
}

TEST(WireFormatTest, OpenAiNullLogprobEntriesAreUnreported) {
  const std::string body = R"({"choices":[{"text":"a b","logprobs":{"tokens":["a"," b"],
    "token_logprobs":[null,-0.5],"top_logprobs":[null,{" b":-0.5}]}}]})";
  auto completion = parse_response_body(WireFormat::kOpenAi, body);
  ASSERT_TRUE(completion.has_value()) << completion.error().describe();
  EXPECT_TRUE(std::isnan(completion->tokens[0].logprob));
  EXPECT_DOUBLE_EQ(*mean_logprob(completion->tokens), -0.5);
  EXPECT_EQ(completion->completion_tokens, 2);  // no usage: counted tokens
}

TEST(WireFormatTest, LlamaServerOpenAiCompatibleLogprobs) {
  const std::string body = R"({"choices":[{"text":" dishwasher","index":0,"finish_reason":"stop",
    "logprobs":{"content":[{"id":5,"token":" dish","bytes":[32],"logprob":-0.01,
    "top_logprobs":[{"id":5,"token":" dish","logprob":-0.01},{"id":6,"token":" cupboard","logprob":-5.0}]},
    {"id":7,"token":"washer","logprob":-0.001,"top_logprobs":[]}]}}],
    "usage":{"completion_tokens":2,"prompt_tokens":280,"total_tokens":282}})";
  auto completion = parse_response_body(WireFormat::kOpenAi, body);
  ASSERT_TRUE(completion.has_value()) << completion.error().describe();
  EXPECT_EQ(completion->text, " dishwasher");
  ASSERT_EQ(completion->tokens.size(), 2u);
  EXPECT_EQ(completion->tokens[1], (TokenLogprob{"washer", -0.001}));
  EXPECT_EQ(completion->top_logprobs[0][1], (TokenLogprob{" cupboard", -5.0}));
}

TEST(WireFormatTest, NativeCurrentLayout) {
  const std::string body = R"({"content":" Open","stop":true,"stop_type":"limit",
    "tokens_predicted":1,"tokens_evaluated":301,
    "completion_probabilities":[{"id":1,"token":" Open","bytes":[32,79],"logprob":-0.6,
      "top_logprobs":[{"id":2,"token":" Pick","logprob":-1.58},{"id":1,"token":" Open","logprob":-0.6}]}]})";
  auto completion = parse_response_body(WireFormat::kLlamaNative, body);
  ASSERT_TRUE(completion.has_value()) << completion.error().describe();
  EXPECT_EQ(completion->text, " Open");
  EXPECT_EQ(completion->tokens[0], (TokenLogprob{" Open", -0.6}));
  EXPECT_EQ(completion->top_logprobs[0][0].token, " Open");
  EXPECT_EQ(completion->finish_reason, "length");
  EXPECT_EQ(completion->prompt_tokens, 301);
  EXPECT_EQ(completion->completion_tokens, 1);
}

TEST(WireFormatTest, NativePostSamplingLayout) {
  const std::string body = R"({"content":" Open","stop_type":"word","tokens_predicted":1,
    "completion_probabilities":[{"id":1,"token":" Open","prob":0.5,
      "top_probs":[{"id":1,"token":" Open","prob":0.5},{"id":2,"token":" Pick","prob":0.0}]}]})";
  auto completion = parse_response_body(WireFormat::kLlamaNative, body);
  ASSERT_TRUE(completion.has_value()) << completion.error().describe();
  EXPECT_DOUBLE_EQ(completion->tokens[0].logprob, std::log(0.5));
  EXPECT_EQ(completion->top_logprobs[0][1], (TokenLogprob{" Pick", kFloorLogprob}));
  EXPECT_EQ(completion->finish_reason, "stop");
}

TEST(WireFormatTest, NativeLegacyLayout) {
  const std::string body = R"({"content":" Open","stopped_limit":true,"tokens_predicted":1,
    "tokens_evaluated":12,"completion_probabilities":[{"content":" Open",
      "probs":[{"tok_str":" Pick","prob":0.25},{"tok_str":" Open","prob":0.5}]}]})";
  auto completion = parse_response_body(WireFormat::kLlamaNative, body);
  ASSERT_TRUE(completion.has_value()) << completion.error().describe();
  EXPECT_EQ(completion->tokens[0].token, " Open");
  EXPECT_DOUBLE_EQ(completion->tokens[0].logprob, std::log(0.5));  // found among the probs
  EXPECT_EQ(completion->top_logprobs[0][0].token, " Open");
  EXPECT_EQ(completion->finish_reason, "length");
}

void expect_unusable(WireFormat format, const std::string& body, const std::string& says) {
  auto completion = parse_response_body(format, body);
  ASSERT_FALSE(completion.has_value()) << body;
  EXPECT_EQ(completion.error().code, ErrorCode::kUnavailable);
  EXPECT_NE(completion.error().message.find(says), std::string::npos) << completion.error().message;
}

TEST(WireFormatTest, BadBodiesAreClearErrors) {
  expect_unusable(WireFormat::kOpenAi, R"({"choices":[{"text":" The goal)", "cut short");
  expect_unusable(WireFormat::kOpenAi, R"({"choices":[{"text": nope}]})", "not JSON");
  expect_unusable(WireFormat::kOpenAi, "", "cut short");
  expect_unusable(WireFormat::kOpenAi, "<html>busy</html>", "not JSON");
  expect_unusable(WireFormat::kOpenAi, "[1,2]", "not a JSON object");
  expect_unusable(WireFormat::kOpenAi, R"({"choices":[]})", "OpenAI completions layout");
  expect_unusable(WireFormat::kOpenAi, R"({"choices":[{"text":5}]})", "OpenAI completions layout");
  expect_unusable(WireFormat::kLlamaNative, R"({"text":"x"})", "llama-server layout");
  expect_unusable(WireFormat::kOpenAi, "{\"choices\":[{\"text\":\"caf\xC3\"}]}", "not valid UTF-8");
  expect_unusable(WireFormat::kOpenAi, R"({"error":{"message":"model not loaded","code":503}})",
                  "model not loaded");
}

// Issue 11, defect 1: nlohmann throws out_of_range (not parse_error) for a
// number beyond a double, and that used to escape parse_response_body and
// abort the run (exit 134).
TEST(WireFormatTest, ANumberBeyondADoubleIsAClearErrorNotAnException) {
  expect_unusable(WireFormat::kOpenAi,
                  R"({"choices":[{"text":" Open","index":0}],"usage":{"prompt_tokens":1e400}})",
                  "not usable JSON");
  expect_unusable(WireFormat::kOpenAi,
                  R"({"choices":[{"text":" Open","logprobs":{"tokens":[" Open"],"token_logprobs":[-1e999]}}]})",
                  "not usable JSON");
  expect_unusable(WireFormat::kLlamaNative, R"({"content":" Open","tokens_evaluated":1e400})", "not usable JSON");
}

TEST(WireFormatTest, NumbersThatAreNotCountsOrLogprobsAreIgnoredOrClamped) {
  // Finite but absurd: token counts that are not counts are ignored (never
  // cast out of range), log-probabilities are kept within [floor, 0].
  auto completion = parse_response_body(WireFormat::kOpenAi,
                                        R"({"choices":[{"text":" Open","logprobs":{"tokens":[" Open"," x"],
      "token_logprobs":[1e300,-1e300],"top_logprobs":[{" Open":5.0},{}]}}],
      "usage":{"prompt_tokens":1e300,"completion_tokens":-4}})");
  ASSERT_TRUE(completion.has_value()) << completion.error().describe();
  EXPECT_EQ(completion->prompt_tokens, 0);
  EXPECT_EQ(completion->completion_tokens, 2);  // counted, since the server's is not a count
  EXPECT_EQ(completion->tokens[0].logprob, 0.0);
  EXPECT_EQ(completion->tokens[1].logprob, kFloorLogprob);
  EXPECT_EQ(completion->top_logprobs[0][0].logprob, 0.0);
  auto native = parse_response_body(WireFormat::kLlamaNative,
                                    R"({"content":" Open","tokens_evaluated":2.5,"tokens_predicted":18446744073709551615})");
  ASSERT_TRUE(native.has_value()) << native.error().describe();
  EXPECT_EQ(native->prompt_tokens, 0);
  EXPECT_EQ(native->completion_tokens, 0);
}

TEST(WireFormatTest, ChatBadBodiesAreClearErrors) {
  expect_unusable(WireFormat::kOpenAiChat,
                  R"({"choices":[{"index":0,"message":{"role":"assistant","content":null,"refusal":"I cannot"}}]})",
                  "OpenAI chat completions layout");
  expect_unusable(WireFormat::kOpenAiChat, R"({"choices":[{"text":" Open"}]})", "OpenAI chat completions layout");
  expect_unusable(WireFormat::kOpenAiChat, R"({"error":{"message":"logprobs are not supported"}})",
                  "logprobs are not supported");
}

// Issue 25, item 4: llama-server's entries as it really sends them, in its
// native reply (tools/server: the stop string's tokens are cut off by count,
// byte tokens that begin a character get no entry, the end of the sequence
// gets one with no text). Each was read before as if it were OpenAI's.
TEST(WireFormatTest, LlamaServersStopDropsTheLastEntry) {
  // " cupboard\n" was generated as " cup", "board\n(" ... ; the stop
  // string's count of entries took "board\n(" along.
  auto native = parse_response_body(WireFormat::kLlamaNative, R"({"content":" the cupboard\n","stop_type":"word",
    "completion_probabilities":[{"token":" the","bytes":[32,116,104,101],"logprob":-0.5,"top_logprobs":[]},
    {"token":" cup","bytes":[32,99,117,112],"logprob":-1.5,"top_logprobs":[]}]})");
  ASSERT_TRUE(native.has_value()) << native.error().describe();
  ASSERT_EQ(native->tokens.size(), 3u);
  EXPECT_EQ(native->tokens[2].token, "board\n");  // the tokens spell the text
  EXPECT_TRUE(std::isnan(native->tokens[2].logprob));
  EXPECT_DOUBLE_EQ(*mean_logprob(native->tokens), -1.0);
}

TEST(WireFormatTest, LlamaServersEmptyAnswerHasNoLogprobsKey) {
  auto chat = parse_response_body(WireFormat::kOpenAiChat,
                                  R"({"choices":[{"finish_reason":"stop","index":0,"message":{"role":"assistant","content":""}}]})");
  ASSERT_TRUE(chat.has_value()) << chat.error().describe();
  EXPECT_EQ(logprobs_arrived(*chat), LogprobsArrived::kNoText);
  auto text = parse_response_body(WireFormat::kOpenAi, R"({"choices":[{"text":" Open","logprobs":null}]})");
  ASSERT_TRUE(text.has_value());
  EXPECT_EQ(logprobs_arrived(*text), LogprobsArrived::kNo);  // a server without them
}

TEST(WireFormatTest, LlamaServersByteTokensCarryOnlyTheLastBytesLogprob) {
  // "é" from two byte tokens: one entry, the second byte's -6, with the
  // byte 169 as its alternative.
  auto native = parse_response_body(WireFormat::kLlamaNative, R"({"content":" caf\u00e9","stop_type":"limit",
    "completion_probabilities":[{"token":" caf","bytes":[32,99,97,102],"logprob":-0.25,"top_logprobs":[]},
    {"token":"\u00e9","bytes":[195,169],"logprob":-6.0,"top_logprobs":[{"token":"","bytes":[169],"logprob":-6.0}]}]})");
  ASSERT_TRUE(native.has_value()) << native.error().describe();
  ASSERT_EQ(native->tokens.size(), 2u);
  EXPECT_EQ(native->tokens[1].token, "\xC3\xA9");
  EXPECT_TRUE(std::isnan(native->tokens[1].logprob));
  EXPECT_TRUE(native->top_logprobs[1].empty());
  EXPECT_DOUBLE_EQ(*mean_logprob(native->tokens), -0.25);
  // A character that is one token of the vocabulary keeps its own.
  auto whole = parse_response_body(WireFormat::kLlamaNative, R"({"content":"\u00e9","completion_probabilities":[
    {"token":"\u00e9","bytes":[195,169],"logprob":-0.5,"top_logprobs":[{"token":"\u00e9","bytes":[195,169],"logprob":-0.5}]}]})");
  ASSERT_TRUE(whole.has_value());
  EXPECT_DOUBLE_EQ(whole->tokens[0].logprob, -0.5);
}

TEST(WireFormatTest, LlamaServersEndOfSequenceEntryIsNotCounted) {
  auto chat = parse_response_body(WireFormat::kOpenAiChat, R"({"choices":[{"finish_reason":"stop","index":0,
    "message":{"role":"assistant","content":" Open it"},"logprobs":{"content":[
    {"token":" Open","bytes":[32,79,112,101,110],"logprob":-0.2,"top_logprobs":[]},
    {"token":"","bytes":[],"logprob":-1.0,"top_logprobs":[]},
    {"token":" it","bytes":[32,105,116],"logprob":-0.3,"top_logprobs":[]},
    {"token":"","bytes":[],"logprob":-9.0,"top_logprobs":[{"token":"","bytes":[],"logprob":-9.0},{"token":" now","logprob":-9.5}]}]}}]})");
  ASSERT_TRUE(chat.has_value()) << chat.error().describe();
  ASSERT_EQ(chat->tokens.size(), 3u);
  EXPECT_DOUBLE_EQ(chat->tokens[1].logprob, -1.3);  // the held-back token joins the next
  EXPECT_EQ(chat->tokens[2].token, "");
  EXPECT_TRUE(std::isnan(chat->tokens[2].logprob));  // the end of the sequence: not text
  EXPECT_EQ(chat->top_logprobs[2].size(), 2u);        // its alternatives kept
  EXPECT_DOUBLE_EQ(*mean_logprob(chat->tokens), -0.75);
}

TEST(WireFormatTest, Utf8Validation) {
  EXPECT_FALSE(find_invalid_utf8("plain ascii").has_value());
  EXPECT_FALSE(find_invalid_utf8("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x8D\xBD").has_value());
  EXPECT_EQ(find_invalid_utf8("ab\xC3"), 2u);                 // cut short
  EXPECT_EQ(find_invalid_utf8("\xC0\xAF"), 0u);               // overlong
  EXPECT_EQ(find_invalid_utf8("x\xED\xA0\x80"), 1u);          // surrogate
  EXPECT_EQ(find_invalid_utf8("\xF4\x90\x80\x80"), 0u);       // above U+10FFFF
  EXPECT_EQ(find_invalid_utf8("\xFF"), 0u);
}

TEST(WireFormatTest, ExcerptIsPrintableAndBounded) {
  EXPECT_EQ(excerpt_for_message("a\nb\x01\xFF" "c", 100), "a b??c");
  EXPECT_EQ(excerpt_for_message(std::string(300, 'x'), 10), std::string(10, 'x') + "...");
  EXPECT_EQ(excerpt_for_message("caf\xC3\xA9"), "caf\xC3\xA9");
}

}  // namespace
}  // namespace apprentice::llm
