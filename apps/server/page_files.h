// The page's own files (data/web), read once when the server starts, and
// the bodies the server sends. Only these files are ever served: a request
// names one of them, never a path.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "util/result.h"

namespace httplib {
struct Response;
}

namespace apprentice::serve {

struct StaticFile {
  std::string body;
  std::string type;
  std::string version;  // a digest of the body, for the page's references
};

// The files of `web_dir` ("/index.html", "/app.js", ...). The page names
// its script and style with their contents' digest ("/app.js?v=..."), so
// that the browser may keep them and a changed file is still fetched anew.
// kNotFound when index.html is missing.
Result<std::map<std::string, StaticFile>> load_page(const std::filesystem::path& web_dir);

// The page with the server's options (the JSON of GET /api/options) in it,
// as a JSON data block before </head>, so that its start screen needs no
// second request. '<' is escaped, so that no text in it can end the block.
std::string page_with_options(std::string html, std::string_view options_json);

// Sends `body` as it is, never compressed. cpp-httplib, built with brotli
// as Debian builds it, compresses every body whose client accepts "br"
// (every browser does) at brotli's slowest quality, on each request: 60 to
// 150 ms for the page's script on a busy two-core machine, which was most
// of a first page load (docs/benchmarks.md). On the machine itself or a
// study's local network the bytes saved are worth nothing.
void send_body(httplib::Response& res, std::string body, const std::string& type);
// {"error": message} with `status`, sent as send_body sends.
void send_error(httplib::Response& res, int status, const std::string& message);

}  // namespace apprentice::serve
