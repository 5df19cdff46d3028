// Reading fields of JSON that came from outside (a server's reply, a
// cassette, a corpus line) without exceptions or undefined behaviour.
// Internal to src/llm: only its .cc files include it.
//
// nlohmann's get<int64_t>() of a float such as 1e300 is a float-to-integer
// conversion out of range (undefined behaviour), and json::parse throws
// out_of_range, not parse_error, for a number such as 1e400. Callers parse
// inside a try block that catches nlohmann::json::exception (the base of
// all of nlohmann's exceptions) and read numbers through these functions.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>

#include <nlohmann/json.hpp>

namespace apprentice::llm::json_fields {

// The value as an integer in [low, high], or nothing: not a number, a
// fraction, or out of range. A float with an integral value (3.0) is read.
inline std::optional<int64_t> integer_in(const nlohmann::json& value, int64_t low, int64_t high) {
  if (value.is_number_integer()) {
    if (value.is_number_unsigned()) {
      const uint64_t u = value.get<uint64_t>();
      if (u > static_cast<uint64_t>(INT64_MAX)) return std::nullopt;
      const auto i = static_cast<int64_t>(u);
      return i >= low && i <= high ? std::optional<int64_t>(i) : std::nullopt;
    }
    const int64_t i = value.get<int64_t>();
    return i >= low && i <= high ? std::optional<int64_t>(i) : std::nullopt;
  }
  if (!value.is_number_float()) return std::nullopt;
  const double d = value.get<double>();
  if (!std::isfinite(d) || d != std::floor(d)) return std::nullopt;
  if (d < static_cast<double>(low) || d > static_cast<double>(high)) return std::nullopt;
  return static_cast<int64_t>(d);
}

// The field `key` of an object as an integer in [low, high], else `fallback`.
inline int64_t integer_field(const nlohmann::json& object, const char* key, int64_t low, int64_t high,
                             int64_t fallback) {
  if (!object.is_object()) return fallback;
  auto it = object.find(key);
  if (it == object.end()) return fallback;
  return integer_in(*it, low, high).value_or(fallback);
}

// A finite number, or nothing.
inline std::optional<double> finite_number(const nlohmann::json& value) {
  if (!value.is_number()) return std::nullopt;
  const double d = value.get<double>();
  if (!std::isfinite(d)) return std::nullopt;
  return d;
}

// The largest token count we believe from a server (usage fields).
inline constexpr int64_t kMaxTokenCount = int64_t{1} << 40;

}  // namespace apprentice::llm::json_fields
