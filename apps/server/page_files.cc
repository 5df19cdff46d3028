#include "page_files.h"

#include <cstdint>
#include <memory>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "util/file.h"
#include "util/json.h"

namespace apprentice::serve {

namespace {

// 16 hex digits of FNV-1a over the text: which version of a file a page
// names.
std::string content_digest(std::string_view text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
  static const char* kHex = "0123456789abcdef";
  std::string out(16, '0');
  for (int i = 15; i >= 0; --i, hash >>= 4) out[static_cast<std::size_t>(i)] = kHex[hash & 0xf];
  return out;
}

}  // namespace

Result<std::map<std::string, StaticFile>> load_page(const std::filesystem::path& web_dir) {
  static const std::map<std::string, std::string> kTypes{{".html", "text/html; charset=utf-8"},
                                                         {".js", "text/javascript; charset=utf-8"},
                                                         {".css", "text/css; charset=utf-8"},
                                                         {".svg", "image/svg+xml"},
                                                         {".png", "image/png"}};
  std::map<std::string, StaticFile> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(web_dir, ec)) {
    auto type = kTypes.find(entry.path().extension().string());
    if (!entry.is_regular_file() || type == kTypes.end()) continue;
    auto body = read_input_file(entry.path());
    if (!body) return tl::unexpected(body.error());
    files["/" + entry.path().filename().string()] = StaticFile{std::move(*body), type->second, ""};
  }
  if (!files.contains("/index.html"))
    return make_error(ErrorCode::kNotFound, (web_dir / "index.html").string() + ": the page is missing (is the data installed?)");
  std::string& html = files["/index.html"].body;
  for (auto& [name, file] : files) {
    if (name == "/index.html") continue;
    file.version = content_digest(file.body);
    for (const std::string attribute : {"src=\"", "href=\""}) {
      const std::string reference = attribute + name + "\"";
      for (std::size_t at = html.find(reference); at != std::string::npos; at = html.find(reference, at + 1))
        html.replace(at, reference.size(), attribute + name + "?v=" + file.version + "\"");
    }
  }
  return files;
}

std::string page_with_options(std::string html, std::string_view options_json) {
  std::string data;
  for (char c : options_json) data += c == '<' ? std::string("\\u003c") : std::string(1, c);
  const std::string block = "<script type=\"application/json\" id=\"server-options\">" + data + "</script>\n";
  const std::size_t head_end = html.find("</head>");
  html.insert(head_end == std::string::npos ? 0 : head_end, block);
  return html;
}

void send_body(httplib::Response& res, std::string body, const std::string& type) {
  // httplib compresses only a body it holds itself; a body given by a
  // provider of known length goes out as it is. An empty body has nothing
  // to compress (and a provider must have a length).
  if (body.empty()) return res.set_content(body, type);
  auto shared = std::make_shared<const std::string>(std::move(body));
  res.set_content_provider(shared->size(), type,
                           [shared](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                             return sink.write(shared->data() + offset, length);
                           });
}

void send_error(httplib::Response& res, int status, const std::string& message) {
  res.status = status;
  send_body(res, dump_json(nlohmann::json{{"error", message}}), "application/json");
}

}  // namespace apprentice::serve
