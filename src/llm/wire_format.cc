#include "llm/wire_format.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "llm/json_fields.h"

namespace apprentice::llm {
namespace {

using nlohmann::json;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

Error bad_body(std::string what) {
  return Error{ErrorCode::kUnavailable, "unusable response from the LLM server: " + std::move(what)};
}

double prob_to_logprob(double prob) {
  if (!(prob > 0.0)) return kFloorLogprob;
  return std::max(std::log(std::min(prob, 1.0)), kFloorLogprob);
}

// A number field, or NaN when absent, null or not finite.
double number_or_nan(const json& object, const char* key) {
  auto it = object.find(key);
  if (it == object.end()) return kNan;
  return json_fields::finite_number(*it).value_or(kNan);
}

// A log-probability as reported, kept within [kFloorLogprob, 0]; NaN when
// it is not a finite number.
double clamp_logprob(const json& value) {
  auto number = json_fields::finite_number(value);
  if (!number) return kNan;
  return std::clamp(*number, kFloorLogprob, 0.0);
}

std::string string_field(const json& object, std::initializer_list<const char*> keys) {
  for (const char* key : keys) {
    auto it = object.find(key);
    if (it != object.end() && it->is_string()) return it->get<std::string>();
  }
  return {};
}

// An entry's log-probability, from "logprob" or else "prob".
double entry_logprob(const json& entry) {
  double logprob = number_or_nan(entry, "logprob");
  if (!std::isnan(logprob)) return std::clamp(logprob, kFloorLogprob, 0.0);
  double prob = number_or_nan(entry, "prob");
  if (!std::isnan(prob)) return prob_to_logprob(prob);
  return kNan;
}

// The token's bytes ("bytes": [226, 128]) as a string, when the entry has
// them: servers send them because a token may be cut in the middle of a
// UTF-8 character, and its "token" string is then mangled ("\\xe2\\x80",
// or U+FFFD). Nothing when absent, null or not a list of bytes.
std::optional<std::string> bytes_field(const json& entry) {
  auto it = entry.find("bytes");
  if (it == entry.end() || !it->is_array()) return std::nullopt;
  std::string out;
  for (const json& byte : *it) {
    auto value = json_fields::integer_in(byte, 0, 255);
    if (!value) return std::nullopt;
    out.push_back(static_cast<char>(*value));
  }
  return out;
}

// The token is its string, unless its bytes cut a UTF-8 character: then
// the string cannot say what it is, and the bytes are kept (to be joined
// with the tokens that complete the character, see join_cut_characters).
TokenLogprob read_entry(const json& entry) {
  auto bytes = bytes_field(entry);
  if (bytes && find_invalid_utf8(*bytes)) return TokenLogprob{std::move(*bytes), entry_logprob(entry)};
  return TokenLogprob{string_field(entry, {"token", "tok_str", "content"}), entry_logprob(entry)};
}

// `text` with every byte that is not part of well-formed UTF-8 replaced by
// U+FFFD, so that every token we keep is valid UTF-8.
std::string valid_utf8(std::string text) {
  while (auto bad = find_invalid_utf8(text)) text.replace(*bad, 1, "\xEF\xBF\xBD");
  return text;
}

// Tokens cut in the middle of a UTF-8 character are joined with the ones
// that complete it: one token of their bytes, with the summed
// log-probability (the probability of the sequence) and the alternatives
// of the first. Whatever cannot be completed is replaced by U+FFFD.
void join_cut_characters(Completion& out) {
  std::vector<TokenLogprob> tokens;
  std::vector<std::vector<TokenLogprob>> top;
  for (size_t i = 0; i < out.tokens.size();) {
    TokenLogprob joined = out.tokens[i];
    size_t next = i + 1;
    // A UTF-8 character has at most 4 bytes, so at most 3 more tokens complete it.
    while (find_invalid_utf8(joined.token) && next < out.tokens.size() && next < i + 4) {
      joined.token += out.tokens[next].token;
      joined.logprob += out.tokens[next].logprob;  // NaN if either is unreported
      ++next;
    }
    joined.logprob = std::max(joined.logprob, kFloorLogprob);  // keeps NaN
    joined.token = valid_utf8(std::move(joined.token));
    std::vector<TokenLogprob> alternatives = i < out.top_logprobs.size() ? out.top_logprobs[i] : std::vector<TokenLogprob>{};
    for (TokenLogprob& alternative : alternatives) alternative.token = valid_utf8(std::move(alternative.token));
    tokens.push_back(std::move(joined));
    top.push_back(std::move(alternatives));
    i = next;
  }
  out.tokens = std::move(tokens);
  out.top_logprobs = std::move(top);
}

void sort_alternatives(std::vector<TokenLogprob>& alternatives) {
  std::stable_sort(alternatives.begin(), alternatives.end(),
                   [](const TokenLogprob& a, const TokenLogprob& b) {
                     if (std::isnan(b.logprob)) return !std::isnan(a.logprob);
                     return a.logprob > b.logprob;
                   });
}

// Whether an entry's log-probability is only that of the last byte of its
// character: llama-server sends no entry for the byte tokens that begin a
// character (its text is incomplete then) and gives the character to the
// token that completes it, with that token's own log-probability; its
// alternatives are then bytes that cannot stand alone (a continuation byte
// such as [169]). The character's true log-probability, the sum over its
// bytes, is not in the reply.
bool carries_only_the_last_byte(const json& entry, const TokenLogprob& chosen) {
  auto bytes = bytes_field(entry);
  if (!bytes || bytes->size() < 2 || find_invalid_utf8(*bytes)) return false;
  for (const char* key : {"top_logprobs", "top_probs"}) {
    auto it = entry.find(key);
    if (it == entry.end() || !it->is_array()) continue;
    for (const json& alternative : *it) {
      if (!alternative.is_object()) continue;
      auto alternative_bytes = bytes_field(alternative);
      if (!alternative_bytes || alternative_bytes->empty() || !find_invalid_utf8(*alternative_bytes)) continue;
      const auto first = static_cast<unsigned char>(alternative_bytes->front());
      if (first >= 0x80 && first <= 0xBF && chosen.token.size() > 1) return true;  // a continuation byte
    }
  }
  return false;
}

// One position of llama-server's per-token layouts (current, post-sampling
// and legacy); see wire_format.h.
void read_position(const json& entry, Completion& out) {
  if (!entry.is_object()) throw std::runtime_error("a token entry is not an object");
  TokenLogprob chosen = read_entry(entry);
  std::vector<TokenLogprob> alternatives;
  for (const char* key : {"top_logprobs", "top_probs", "probs"}) {
    auto it = entry.find(key);
    if (it == entry.end() || !it->is_array()) continue;
    for (const json& alternative : *it) {
      if (alternative.is_object()) alternatives.push_back(read_entry(alternative));
    }
    break;
  }
  if (std::isnan(chosen.logprob)) {
    // Legacy layout: the chosen token's probability is among the alternatives.
    for (const TokenLogprob& alternative : alternatives) {
      if (alternative.token == chosen.token) chosen.logprob = alternative.logprob;
    }
  }
  if (carries_only_the_last_byte(entry, chosen)) {
    // Unreported rather than wrong; the alternatives are of the last byte.
    chosen.logprob = kNan;
    alternatives.clear();
  }
  sort_alternatives(alternatives);
  out.tokens.push_back(std::move(chosen));
  out.top_logprobs.push_back(std::move(alternatives));
}

// llama-server's entries as its text really is:
//  - an entry with no text is a token whose text came with the next entry
//    (held back while it might begin a stop string): its log-probability
//    joins the next one's, the probability of the two; at the end it is
//    the end of the sequence (or the stop string), which is not text and
//    is not counted (NaN), its alternatives kept for the next-token query;
//  - at a stop string the server leaves out the entries of as many tokens
//    as the stop string has on its own, which may be the last tokens of the
//    text: text the entries do not cover becomes one token without a
//    log-probability, so that the tokens spell the text.
void reconcile_with_text(Completion& out) {
  std::vector<TokenLogprob> tokens;
  std::vector<std::vector<TokenLogprob>> top;
  std::optional<TokenLogprob> held;
  std::vector<TokenLogprob> held_alternatives;
  for (size_t i = 0; i < out.tokens.size(); ++i) {
    TokenLogprob token = out.tokens[i];
    std::vector<TokenLogprob> alternatives = i < out.top_logprobs.size() ? out.top_logprobs[i] : std::vector<TokenLogprob>{};
    if (held) {
      token.logprob = std::max(token.logprob + held->logprob, kFloorLogprob);  // NaN if either is
      alternatives = std::move(held_alternatives);
      held.reset();
    }
    if (token.token.empty()) {
      held = token;
      held_alternatives = std::move(alternatives);
      continue;
    }
    tokens.push_back(std::move(token));
    top.push_back(std::move(alternatives));
  }
  if (held) {
    tokens.push_back(TokenLogprob{"", kNan});
    top.push_back(std::move(held_alternatives));
  }
  std::string spelled;
  for (const TokenLogprob& token : tokens) spelled += token.token;
  if (spelled.size() < out.text.size() && out.text.compare(0, spelled.size(), spelled) == 0 && !tokens.empty()) {
    // Before a trailing end-of-sequence entry, if there is one.
    const bool ends_empty = tokens.back().token.empty();
    const auto at = static_cast<std::ptrdiff_t>(tokens.size() - (ends_empty ? 1 : 0));
    tokens.insert(tokens.begin() + at, TokenLogprob{out.text.substr(spelled.size()), kNan});
    top.insert(top.begin() + at, std::vector<TokenLogprob>{});
  }
  out.tokens = std::move(tokens);
  out.top_logprobs = std::move(top);
}

void read_openai_logprobs(const json& logprobs, Completion& out) {
  if (!logprobs.is_object()) return;  // null: the server gave none
  if (auto content = logprobs.find("content"); content != logprobs.end() && content->is_array()) {
    for (const json& entry : *content) read_position(entry, out);
    join_cut_characters(out);
    reconcile_with_text(out);
    return;
  }
  const json& tokens = logprobs.at("tokens");
  const json& token_logprobs = logprobs.at("token_logprobs");
  auto top = logprobs.find("top_logprobs");
  for (size_t i = 0; i < tokens.size(); ++i) {
    TokenLogprob token{tokens.at(i).get<std::string>(), kNan};
    if (i < token_logprobs.size()) token.logprob = clamp_logprob(token_logprobs.at(i));
    std::vector<TokenLogprob> alternatives;
    if (top != logprobs.end() && top->is_array() && i < top->size() && top->at(i).is_object()) {
      for (const auto& [text, value] : top->at(i).items()) {
        alternatives.push_back(TokenLogprob{text, clamp_logprob(value)});
      }
    }
    sort_alternatives(alternatives);
    out.tokens.push_back(std::move(token));
    out.top_logprobs.push_back(std::move(alternatives));
  }
}

void read_openai(const json& body, Completion& out, bool chat) {
  const json& choices = body.at("choices");
  if (!choices.is_array() || choices.empty()) throw std::runtime_error("no choices");
  const json& choice = choices.at(0);
  if (chat) {
    // choices[0].message.content; null only with a refusal or tool calls.
    const json& content = choice.at("message").at("content");
    if (!content.is_string()) throw std::runtime_error("the message has no text content");
    out.text = content.get<std::string>();
  } else {
    out.text = choice.at("text").get<std::string>();
  }
  if (auto reason = choice.find("finish_reason"); reason != choice.end() && reason->is_string()) {
    out.finish_reason = reason->get<std::string>();
  }
  if (auto logprobs = choice.find("logprobs"); logprobs != choice.end()) {
    read_openai_logprobs(*logprobs, out);
  }
  out.completion_tokens = static_cast<int64_t>(out.tokens.size());
  if (auto usage = body.find("usage"); usage != body.end()) {
    // Counts that are not counts (negative, fractional, absurd) are ignored.
    out.prompt_tokens = json_fields::integer_field(*usage, "prompt_tokens", 0, json_fields::kMaxTokenCount, 0);
    out.completion_tokens = json_fields::integer_field(*usage, "completion_tokens", 0, json_fields::kMaxTokenCount,
                                                       out.completion_tokens);
  }
}

void read_native(const json& body, Completion& out) {
  out.text = body.at("content").get<std::string>();
  if (auto probs = body.find("completion_probabilities"); probs != body.end() && probs->is_array()) {
    for (const json& entry : *probs) read_position(entry, out);
    join_cut_characters(out);
    reconcile_with_text(out);
  }
  std::string stop_type = string_field(body, {"stop_type"});
  if (stop_type == "eos" || stop_type == "word") {
    out.finish_reason = "stop";
  } else if (stop_type == "limit") {
    out.finish_reason = "length";
  } else if (body.value("stopped_limit", false)) {
    out.finish_reason = "length";
  } else if (body.value("stopped_eos", false) || body.value("stopped_word", false)) {
    out.finish_reason = "stop";
  }
  out.prompt_tokens = json_fields::integer_field(body, "tokens_evaluated", 0, json_fields::kMaxTokenCount, 0);
  out.completion_tokens = json_fields::integer_field(body, "tokens_predicted", 0, json_fields::kMaxTokenCount,
                                                     static_cast<int64_t>(out.tokens.size()));
}

std::string server_error_message(const json& error) {
  if (error.is_string()) return error.get<std::string>();
  if (error.is_object()) {
    std::string message = string_field(error, {"message"});
    if (!message.empty()) return message;
  }
  return error.dump(-1, ' ', false, json::error_handler_t::replace);
}

}  // namespace

std::string build_request_body(WireFormat format, const CompletionRequest& request,
                               const WireOptions& options) {
  json body;
  body["prompt"] = request.prompt;
  body["temperature"] = request.temperature;
  body["stream"] = false;
  // At least one, so that the chosen tokens come with their log-probabilities.
  const int alternatives = std::max(1, request.top_logprobs);
  if (format == WireFormat::kOpenAiChat) {
    // The same prompt, as the one user message.
    body.erase("prompt");
    body["messages"] = json::array({json{{"role", "user"}, {"content", request.prompt}}});
    body["max_tokens"] = request.max_tokens;
    body["logprobs"] = true;
    body["top_logprobs"] = alternatives;
    body["n"] = 1;
  } else if (format == WireFormat::kOpenAi) {
    body["max_tokens"] = request.max_tokens;
    body["logprobs"] = alternatives;
    body["n"] = 1;
  } else {
    body["n_predict"] = request.max_tokens;
    body["n_probs"] = alternatives;
    body["cache_prompt"] = true;
  }
  if (!request.stop.empty()) body["stop"] = request.stop;
  if (!options.model.empty()) body["model"] = options.model;
  if (options.seed) body["seed"] = *options.seed;
  return body.dump(-1, ' ', false, json::error_handler_t::replace);
}

Result<Completion> parse_response_body(WireFormat format, std::string_view body) {
  if (auto bad = find_invalid_utf8(body)) {
    return tl::unexpected(
        bad_body("the body is not valid UTF-8 (byte " + std::to_string(*bad) + ")"));
  }
  json parsed;
  try {
    parsed = json::parse(body);
  } catch (const json::parse_error& e) {
    if (e.byte >= body.size()) {
      return tl::unexpected(bad_body("the JSON body is cut short after " +
                                     std::to_string(body.size()) + " bytes"));
    }
    return tl::unexpected(bad_body("the body is not JSON (" + std::string(e.what()) + ")"));
  } catch (const json::exception& e) {
    // out_of_range for a number such as 1e400, and any other of nlohmann's.
    return tl::unexpected(bad_body("the body is not usable JSON (" + std::string(e.what()) + ")"));
  }
  if (!parsed.is_object()) return tl::unexpected(bad_body("the body is not a JSON object"));
  if (auto error = parsed.find("error"); error != parsed.end() && !error->is_null()) {
    return tl::unexpected(Error{ErrorCode::kUnavailable,
                                "the LLM server reported an error: " +
                                    excerpt_for_message(server_error_message(*error))});
  }
  Completion out;
  out.source = ResponseSource::kModel;
  try {
    if (format == WireFormat::kLlamaNative) {
      read_native(parsed, out);
    } else {
      read_openai(parsed, out, format == WireFormat::kOpenAiChat);
    }
  } catch (const std::exception& e) {
    // nlohmann's out_of_range / type_error for missing or mistyped fields.
    const char* layout = format == WireFormat::kOpenAi       ? "OpenAI completions"
                         : format == WireFormat::kOpenAiChat ? "OpenAI chat completions"
                                                             : "llama-server";
    return tl::unexpected(bad_body(std::string("not in the ") + layout +
                                   " layout: " + e.what()));
  }
  out.raw = std::string(body);
  return out;
}

std::optional<size_t> find_invalid_utf8(std::string_view text) {
  size_t i = 0;
  const size_t n = text.size();
  while (i < n) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte < 0x80) {
      ++i;
      continue;
    }
    size_t length = 0;
    uint32_t code = 0;
    if (byte >= 0xC2 && byte <= 0xDF) {
      length = 2, code = byte & 0x1F;
    } else if (byte >= 0xE0 && byte <= 0xEF) {
      length = 3, code = byte & 0x0F;
    } else if (byte >= 0xF0 && byte <= 0xF4) {
      length = 4, code = byte & 0x07;
    } else {
      return i;
    }
    if (i + length > n) return i;
    for (size_t k = 1; k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      if ((next & 0xC0) != 0x80) return i;
      code = (code << 6) | (next & 0x3F);
    }
    const bool overlong = (length == 3 && code < 0x800) || (length == 4 && code < 0x10000);
    const bool surrogate = code >= 0xD800 && code <= 0xDFFF;
    if (overlong || surrogate || code > 0x10FFFF) return i;
    i += length;
  }
  return std::nullopt;
}

std::string excerpt_for_message(std::string_view body, size_t limit) {
  std::string out;
  size_t i = 0;
  while (i < body.size() && out.size() < limit) {
    const auto byte = static_cast<unsigned char>(body[i]);
    if (byte < 0x20 || byte == 0x7F) {
      out.push_back(byte == '\n' || byte == '\t' ? ' ' : '?');
      ++i;
      continue;
    }
    if (byte < 0x80) {
      out.push_back(static_cast<char>(byte));
      ++i;
      continue;
    }
    // Copy one well-formed multi-byte character, or a '?' for a bad byte.
    size_t length = byte >= 0xF0 ? 4 : byte >= 0xE0 ? 3 : 2;
    std::string_view piece = body.substr(i, length);
    if (piece.size() == length && !find_invalid_utf8(piece)) {
      out.append(piece);
      i += length;
    } else {
      out.push_back('?');
      ++i;
    }
  }
  if (i < body.size()) out += "...";
  return out;
}

}  // namespace apprentice::llm
