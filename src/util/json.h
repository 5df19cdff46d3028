// JSON from and to the outside world, through nlohmann/json, with its
// exceptions kept inside: every parse of outside JSON catches all of them
// (a syntax error, a number out of range such as 1e400, a type mismatch),
// and every dump replaces invalid UTF-8 (U+FFFD) instead of throwing.
//
// The UTF-8 policy (docs/cli.md): apprentice accepts any bytes in its
// input; text output passes them through, and JSON output (--json, the
// JSON inside knowledge stores) replaces each invalid sequence with U+FFFD.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include "util/result.h"

namespace apprentice {

// Parses `text`; kInvalidInput "<what>: <reason>" on any failure.
Result<nlohmann::json> parse_json(std::string_view text, std::string_view what);

// `value` as text (indent < 0: one line), never throwing on invalid UTF-8.
std::string dump_json(const nlohmann::json& value, int indent = -1);
std::string dump_json(const nlohmann::ordered_json& value, int indent = -1);

}  // namespace apprentice
