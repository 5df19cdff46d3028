// libFuzzer target for the PDDL reader: any bytes give a domain or an
// error with a message; a domain read back from what the writer makes of it
// is the same domain.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_support.h"
#include "world/pddl.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace apprentice;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  auto domain = parse_domain(text, "fuzz");
  if (!domain) {
    fuzz::require(!domain.error().message.empty());
    return 0;
  }
  const std::string written = write_domain(*domain);
  auto again = parse_domain(written, "written");
  fuzz::require(again.has_value());
  fuzz::require(write_domain(*again) == written);
  return 0;
}
