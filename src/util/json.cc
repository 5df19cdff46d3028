#include "util/json.h"

#include <nlohmann/json.hpp>

namespace apprentice {

Result<nlohmann::json> parse_json(std::string_view text, std::string_view what) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    return make_error(ErrorCode::kInvalidInput, std::string(what) + ": " + e.what());
  } catch (const std::exception& e) {
    return make_error(ErrorCode::kInvalidInput, std::string(what) + ": " + e.what());
  }
}

std::string dump_json(const nlohmann::json& value, int indent) {
  return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string dump_json(const nlohmann::ordered_json& value, int indent) {
  return value.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace apprentice
