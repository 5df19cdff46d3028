// JSON from outside never throws out of parse_json, whatever it holds, and
// dump_json never throws on invalid UTF-8 (it writes U+FFFD instead).
#include "util/json.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace apprentice {
namespace {

using ::testing::HasSubstr;

TEST(ParseJson, AnOutOfRangeNumberIsAnErrorNotAnAbort) {
  auto parsed = parse_json(R"({"usage":{"prompt_tokens":1e400}})", "reply");
  ASSERT_FALSE(parsed.has_value());
  EXPECT_EQ(parsed.error().code, ErrorCode::kInvalidInput);
  EXPECT_THAT(parsed.error().message, HasSubstr("reply: "));
}

TEST(ParseJson, SyntaxAndEncodingErrorsAreErrors) {
  for (const char* text : {"", "{", "[1,]", "\"\xff\"", "nul", "{\"a\":1}}"}) {
    auto parsed = parse_json(text, "x");
    EXPECT_FALSE(parsed.has_value()) << text;
  }
  auto good = parse_json(R"({"a":[1,2.5,"b"]})", "x");
  ASSERT_TRUE(good.has_value());
  EXPECT_EQ((*good)["a"][2], "b");
}

TEST(DumpJson, InvalidUtf8IsReplacedNotThrown) {
  nlohmann::json value{{"name", std::string("kitchen\xff")}};
  EXPECT_THROW((void)value.dump(), nlohmann::json::type_error);  // what nlohmann does by itself
  EXPECT_EQ(dump_json(value), "{\"name\":\"kitchen\xef\xbf\xbd\"}");
  EXPECT_EQ(dump_json(value, 2), "{\n  \"name\": \"kitchen\xef\xbf\xbd\"\n}");
  nlohmann::ordered_json ordered{{"b", std::string("\xc3")}, {"a", "ok"}};
  EXPECT_EQ(dump_json(ordered), "{\"b\":\"\xef\xbf\xbd\",\"a\":\"ok\"}");
}

}  // namespace
}  // namespace apprentice
