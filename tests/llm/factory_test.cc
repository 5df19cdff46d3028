#include "llm/factory.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>

namespace apprentice::llm {
namespace {

const std::string kFixture = std::string(APPRENTICE_SOURCE_DIR) + "/tests/llm/data/goal_corpus.jsonl";

// Sets an environment variable for one test and restores it afterwards.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value == nullptr) {
      ::unsetenv(name);
    } else {
      ::setenv(name, value, 1);
    }
  }
  ~ScopedEnv() {
    if (old_) {
      ::setenv(name_, old_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(FactoryTest, EachConditionGetsItsOwnCassettesHoweverNested) {
  EXPECT_EQ(spec_for_condition("replay:dir/run.jsonl", "inst+llm"), "replay:dir/run.inst+llm.jsonl");
  EXPECT_EQ(spec_for_condition("record:run.jsonl,openai:http://h:1/v1", "search4+llm"),
            "record:run.search4+llm.jsonl,openai:http://h:1/v1");
  // Issue 13, item 7: the inner replay's file was not renamed, so a
  // re-recording of several conditions could not find its cassettes.
  EXPECT_EQ(spec_for_condition("record:new.jsonl,replay:old.jsonl", "inst+llm"),
            "record:new.inst+llm.jsonl,replay:old.inst+llm.jsonl");
  EXPECT_EQ(spec_for_condition("record:a.jsonl,record:b.jsonl,corpus:c.jsonl", "x"),
            "record:a.x.jsonl,record:b.x.jsonl,corpus:c.jsonl");
  EXPECT_EQ(spec_for_condition("corpus:c.jsonl,condition=TBP", "x"), "corpus:c.jsonl,condition=TBP");
  EXPECT_EQ(spec_for_condition("openai:http://h:1/v1", "x"), "openai:http://h:1/v1");
}

TEST(FactoryTest, Endpoints) {
  EXPECT_EQ(openai_endpoint("http://127.0.0.1:8080"), "http://127.0.0.1:8080/v1/completions");
  EXPECT_EQ(openai_endpoint("http://127.0.0.1:8080/v1/"), "http://127.0.0.1:8080/v1/completions");
  EXPECT_EQ(openai_endpoint("https://api.openai.com/v1"), "https://api.openai.com/v1/completions");
  EXPECT_EQ(openai_endpoint("http://h/v1/completions"), "http://h/v1/completions");
  EXPECT_EQ(llama_endpoint("http://127.0.0.1:8080/"), "http://127.0.0.1:8080/completion");
  EXPECT_EQ(llama_endpoint("http://h/completion"), "http://h/completion");
}

TEST(FactoryTest, OpenAiFromTheEnvironment) {
  ScopedEnv base("OPENAI_BASE_URL", "http://127.0.0.1:9/v1");
  ScopedEnv key("OPENAI_API_KEY", "sk-from-env-123");
  ScopedEnv model("OPENAI_MODEL", "env-model");
  auto client = make_llm_client("openai", LlmOptions{});
  ASSERT_TRUE(client.has_value()) << client.error().describe();
  EXPECT_EQ((*client)->describe(), "openai http://127.0.0.1:9/v1/completions model=env-model");
  EXPECT_EQ((*client)->describe().find("sk-from-env"), std::string::npos);
}

TEST(FactoryTest, OpenAiWithoutUrlIsAClearError) {
  ScopedEnv base("OPENAI_BASE_URL", nullptr);
  auto client = make_llm_client("openai", LlmOptions{});
  ASSERT_FALSE(client.has_value());
  EXPECT_EQ(client.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(client.error().message.find("OPENAI_BASE_URL"), std::string::npos);
}

TEST(FactoryTest, CredentialsInTheUrlAreNotShown) {
  auto client = make_llm_client("llama:http://user:pw@127.0.0.1:9", LlmOptions{});
  ASSERT_TRUE(client.has_value());
  EXPECT_EQ((*client)->describe(), "llama http://[redacted]@127.0.0.1:9/completion");
}

TEST(FactoryTest, BadSpecs) {
  for (const char* spec : {"", "gpt", "openai:localhost:8080", "llama:", "replay:", "record:x.jsonl",
                           "record:,openai:http://h", "corpus:", "corpus:,condition=TBP"}) {
    auto client = make_llm_client(spec, LlmOptions{});
    ASSERT_FALSE(client.has_value()) << spec;
    EXPECT_EQ(client.error().code, ErrorCode::kInvalidInput) << spec << ": " << client.error().message;
  }
  EXPECT_EQ(make_llm_client("replay:/nonexistent/x.jsonl", LlmOptions{}).error().code, ErrorCode::kNotFound);
  EXPECT_EQ(make_llm_client("corpus:/nonexistent/x.jsonl", LlmOptions{}).error().code, ErrorCode::kNotFound);
}

TEST(FactoryTest, RecordWrapsAnyBackend) {
  const auto cassette = std::filesystem::temp_directory_path() / "apprentice_factory_record.jsonl";
  auto client = make_llm_client("record:" + cassette.string() + ",corpus:" + kFixture, LlmOptions{});
  ASSERT_TRUE(client.has_value()) << client.error().describe();
  EXPECT_NE((*client)->describe().find("<- corpus"), std::string::npos);
  client->reset();
  EXPECT_TRUE(std::filesystem::exists(cassette));
  std::filesystem::remove(cassette);
}

TEST(FactoryTest, SpecFromFlagOrEnvironment) {
  ScopedEnv spec("APPRENTICE_LLM", "corpus:x.jsonl");
  EXPECT_EQ(resolve_llm_spec("replay:y.jsonl"), "replay:y.jsonl");
  EXPECT_EQ(resolve_llm_spec(""), "corpus:x.jsonl");
  ScopedEnv none("APPRENTICE_LLM", nullptr);
  EXPECT_FALSE(resolve_llm_spec("").has_value());
}

}  // namespace
}  // namespace apprentice::llm
