#include "knowledge/store_location.h"

namespace apprentice {

bool is_postgres_location(std::string_view location) {
  return location.starts_with("postgresql://") || location.starts_with("postgres://");
}

std::string scrub_store_location(std::string_view location) {
  if (!is_postgres_location(location)) return std::string(location);
  const std::size_t start = location.find("://") + 3;
  std::size_t end = location.find_first_of("/?#", start);
  if (end == std::string_view::npos) end = location.size();
  std::string authority(location.substr(start, end - start));
  // user:password@host: the userinfo is everything before the last '@'.
  if (auto at = authority.rfind('@'); at != std::string::npos) {
    std::string user = authority.substr(0, at);
    if (auto colon = user.find(':'); colon != std::string::npos) user.resize(colon);
    authority = user + authority.substr(at);
  }
  std::string rest(location.substr(end));
  std::string out = std::string(location.substr(0, start)) + authority;
  // Query parameters: every one but password=.
  const std::size_t query = rest.find('?');
  out += rest.substr(0, query);
  if (query == std::string::npos) return out;
  std::string kept;
  std::string_view parameters = std::string_view(rest).substr(query + 1);
  while (!parameters.empty()) {
    const std::size_t amp = parameters.find('&');
    std::string_view parameter = parameters.substr(0, amp);
    if (!parameter.starts_with("password=") && parameter != "password" && !parameter.empty())
      kept += (kept.empty() ? "?" : "&") + std::string(parameter);
    if (amp == std::string_view::npos) break;
    parameters.remove_prefix(amp + 1);
  }
  return out + kept;
}

Status check_household_name(std::string_view name) {
  constexpr std::size_t kLongest = 64;
  auto allowed = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
  };
  bool ok = !name.empty() && name.size() <= kLongest;
  for (char c : name) ok = ok && allowed(c);
  if (ok) return {};
  std::string shown(name.substr(0, kLongest));
  for (char& c : shown)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return make_error(ErrorCode::kInvalidInput,
                    "\"" + shown + (name.size() > kLongest ? "...\"" : "\"") +
                        " cannot name a household: use 1 to 64 letters, digits, '-', '_' or '.'.");
}

}  // namespace apprentice
