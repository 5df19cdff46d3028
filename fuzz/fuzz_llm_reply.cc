// libFuzzer target for the LLM reply parser: any bytes, read as the body of
// a 200 reply in both dialects (OpenAI-compatible and llama-server's own),
// give a completion or an error with a message; never an exception, a
// crash or a sanitizer report.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_support.h"
#include "llm/wire_format.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace apprentice;
  using llm::WireFormat;
  std::string_view body(reinterpret_cast<const char*>(data), size);
  for (WireFormat format : {WireFormat::kOpenAi, WireFormat::kLlamaNative}) {
    auto completion = llm::parse_response_body(format, body);
    if (!completion) {
      fuzz::require(!completion.error().message.empty());
      continue;
    }
    // A completion's text comes from the reply, so it is valid UTF-8.
    fuzz::require(!llm::find_invalid_utf8(completion->text).has_value());
  }
  return 0;
}
