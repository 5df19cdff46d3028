#include "world/sexpr.h"

#include <cctype>

#include "util/text.h"

namespace apprentice {

Error syntax_error(std::string_view source, SourcePosition position, std::string_view message) {
  return Error{ErrorCode::kInvalidInput, std::string(source) + ":" + std::to_string(position.line) +
                                            ":" + std::to_string(position.column) + ": " +
                                            std::string(message)};
}

namespace {

// Recursive descent over the text; depth is bounded so that hostile input
// cannot overflow the stack.
class Reader {
 public:
  Reader(std::string_view text, std::string_view source) : text_(text), source_(source) {}

  Result<SExpr> read_top() {
    skip_blanks();
    if (at_end()) return tl::unexpected(error("expected '(' but the file is empty"));
    auto expr = read(0);
    if (!expr) return expr;
    skip_blanks();
    if (!at_end()) return tl::unexpected(error("expected the end of the file after the closing ')'"));
    return expr;
  }

 private:
  static constexpr int kMaxDepth = 200;

  Result<SExpr> read(int depth) {
    if (depth > kMaxDepth) return tl::unexpected(error("expressions nest too deeply"));
    SExpr expr;
    expr.position = position_;
    if (peek() == ')') return tl::unexpected(error("expected an atom or '(' but found ')'"));
    if (peek() != '(') {
      std::string atom;
      while (!at_end() && !is_delimiter(peek())) atom.push_back(advance());
      expr.atom = to_lower(atom);
      return expr;
    }
    advance();  // '('
    expr.is_list = true;
    for (;;) {
      skip_blanks();
      if (at_end()) return tl::unexpected(error("expected ')' to close the list opened at line " +
                                                std::to_string(expr.position.line) + ":" +
                                                std::to_string(expr.position.column)));
      if (peek() == ')') {
        advance();
        return expr;
      }
      auto item = read(depth + 1);
      if (!item) return item;
      expr.items.push_back(std::move(*item));
    }
  }

  static bool is_delimiter(char c) {
    return c == '(' || c == ')' || c == ';' || std::isspace(static_cast<unsigned char>(c));
  }
  bool at_end() const { return offset_ >= text_.size(); }
  char peek() const { return text_[offset_]; }
  char advance() {
    char c = text_[offset_++];
    if (c == '\n') {
      ++position_.line;
      position_.column = 1;
    } else {
      ++position_.column;
    }
    return c;
  }
  void skip_blanks() {
    while (!at_end()) {
      if (peek() == ';') {
        while (!at_end() && peek() != '\n') advance();
      } else if (std::isspace(static_cast<unsigned char>(peek()))) {
        advance();
      } else {
        return;
      }
    }
  }
  Error error(std::string_view message) const { return syntax_error(source_, position_, message); }

  std::string_view text_;
  std::string_view source_;
  std::size_t offset_ = 0;
  SourcePosition position_;
};

}  // namespace

Result<SExpr> parse_sexpr(std::string_view text, std::string_view source) {
  return Reader(text, source).read_top();
}

}  // namespace apprentice
