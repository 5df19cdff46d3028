#include "knowledge/store_location.h"

#include <unistd.h>

#include <climits>

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

namespace {

constexpr std::size_t kLongestName = 64;

bool name_character(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
}

// "NAME" cannot name a WHAT: use 1 to 64 ALLOWED.
tl::unexpected<Error> bad_name(std::string_view name, const std::string& what, const std::string& allowed) {
  std::string shown(name.substr(0, kLongestName));
  for (char& c : shown)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return make_error(ErrorCode::kInvalidInput, "\"" + shown + (name.size() > kLongestName ? "...\"" : "\"") +
                                                  " cannot name a " + what + ": use 1 to 64 " + allowed + ".");
}

}  // namespace

Status check_household_name(std::string_view name) {
  bool ok = !name.empty() && name.size() <= kLongestName;
  for (char c : name) ok = ok && name_character(c);
  if (ok) return {};
  return bad_name(name, "household", "letters, digits, '-', '_' or '.'");
}

Status check_robot_name(std::string_view name) {
  bool ok = !name.empty() && name.size() <= kLongestName && name.front() != ' ' && name.back() != ' ';
  for (char c : name) ok = ok && (name_character(c) || c == ' ');
  if (ok) return {};
  return bad_name(name, "robot", "letters, digits, spaces, '-', '_' or '.', not starting or ending with a space");
}

std::string default_robot_name() {
  char host[HOST_NAME_MAX + 1] = {};
  std::string name;
  if (::gethostname(host, sizeof host - 1) == 0)
    for (const char* c = host; *c != '\0' && *c != '.' && name.size() < kLongestName; ++c)
      if (name_character(*c)) name += *c;
  return name.empty() ? "robot" : name;
}

}  // namespace apprentice
