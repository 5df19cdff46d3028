// The word vectors: converting the npm package's JSON, mapping the file,
// refusing a damaged one, saying once that it is missing, and (when the
// build converted the real GloVe vectors) what they know.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include "common/paths.h"
#include "common/process.h"
#include "common/scratch.h"
#include "util/cosine.h"
#include "vectors/convert.h"
#include "vectors/word_vectors.h"

namespace apprentice::vectors {
namespace {

using ::testing::HasSubstr;
using namespace apprentice::testing;

// The package's shape, three dimensions: each vector is followed by its
// norm and its index, which the converter ignores.
constexpr const char* kSmall = R"({"precision":8,"l2NormIndex":3,"wordIndex":4,"size":5,"dimensions":3,
  "words":["cat","dog","car","\"","\u00e9t\u00e9"],
  "vectors":{"cat":[1,0.1,0,1.005,0],"dog":[0.9,0.2,0.05,0.92,1],"car":[0,0.1,1,1.005,2],
             "\"":[0.5,0.5,0.5,0.87,3],"\u00e9t\u00e9":[-1,0,0,1,4]},
  "unkVector":[0,0,0,0,-1]})";

class WordVectorsTest : public ScratchTest {
 protected:
  std::ostringstream said_;
  std::filesystem::path convert(const std::string& json) {
    std::filesystem::path out = dir_ / "small.vectors";
    auto report = convert_wink_vectors_text(json, out);
    EXPECT_TRUE(report.has_value()) << (report ? "" : report.error().describe());
    return out;
  }
};

TEST_F(WordVectorsTest, ConvertedVectorsAreFoundByWordAndKeepTheirCosines) {
  auto vectors = WordVectors::open(convert(kSmall));
  ASSERT_TRUE(vectors.has_value()) << vectors.error().describe();
  EXPECT_EQ(vectors->dimensions(), 3u);
  EXPECT_EQ(vectors->size(), 5u);
  EXPECT_TRUE(vectors->contains("cat"));
  EXPECT_TRUE(vectors->contains("\""));
  EXPECT_TRUE(vectors->contains("\xC3\xA9t\xC3\xA9"));  // "été", from its \u escapes
  EXPECT_FALSE(vectors->contains("cow"));
  EXPECT_FALSE(vectors->contains("Cat"));
  EXPECT_TRUE(vectors->word("cow").empty());
  // Unit length after quantization, and the cosines within a few hundredths.
  std::vector<float> cat = vectors->word("cat");
  ASSERT_EQ(cat.size(), 3u);
  EXPECT_NEAR(cosine(cat, cat), 1.0, 1e-5);
  auto true_cosine = [](std::vector<double> a, std::vector<double> b) {
    double dot = 0, na = 0, nb = 0;
    for (int i = 0; i < 3; ++i) dot += a[i] * b[i], na += a[i] * a[i], nb += b[i] * b[i];
    return dot / std::sqrt(na * nb);
  };
  EXPECT_NEAR(*vectors->similarity("cat", "dog"), true_cosine({1, 0.1, 0}, {0.9, 0.2, 0.05}), 0.02);
  EXPECT_NEAR(*vectors->similarity("cat", "car"), true_cosine({1, 0.1, 0}, {0, 0.1, 1}), 0.02);
  EXPECT_GT(*vectors->similarity("cat", "dog"), *vectors->similarity("cat", "car"));
  EXPECT_FALSE(vectors->similarity("cat", "cow").has_value());
}

TEST_F(WordVectorsTest, APhraseIsTheWeightedSumOfItsWordsAndSkipsUnknownOnes) {
  auto vectors = WordVectors::open(convert(kSmall));
  ASSERT_TRUE(vectors.has_value());
  std::vector<std::string> words = {"cat", "cow", "car"};
  std::vector<float> even = vectors->phrase(words);
  std::vector<float> car_heavy = vectors->phrase(words, std::vector<double>{1, 1, 4});
  ASSERT_EQ(even.size(), 3u);
  EXPECT_NEAR(cosine(even, even), 1.0, 1e-5);
  EXPECT_GT(cosine(car_heavy, vectors->word("car")), cosine(even, vectors->word("car")));
  EXPECT_TRUE(vectors->phrase(std::vector<std::string>{"cow"}).empty());
}

TEST_F(WordVectorsTest, ADamagedOrForeignFileIsRefusedNeverMisread) {
  std::filesystem::path good = convert(kSmall);
  std::string bytes = read_text(good);
  ASSERT_GT(bytes.size(), 200u);
  auto refused = [&](const std::string& content) {
    std::filesystem::path bad = write("bad.vectors", content);
    auto opened = WordVectors::open(bad);
    EXPECT_FALSE(opened.has_value());
    return opened ? Error{} : opened.error();
  };
  EXPECT_EQ(refused(bytes.substr(0, bytes.size() - 1)).code, ErrorCode::kDataLoss);  // truncated
  EXPECT_THAT(refused(bytes.substr(0, bytes.size() - 1)).message, HasSubstr("truncated"));
  EXPECT_EQ(refused(bytes.substr(0, 40)).code, ErrorCode::kDataLoss);  // shorter than its header
  std::string foreign = bytes;
  foreign[0] = 'X';
  EXPECT_THAT(refused(foreign).message, HasSubstr("wrong magic"));
  std::string slots = bytes;
  slots[24] = 3;  // a slot count that is no power of two
  EXPECT_EQ(refused(slots).code, ErrorCode::kDataLoss);
  EXPECT_EQ(WordVectors::open(dir_ / "absent.vectors").error().code, ErrorCode::kNotFound);
  EXPECT_EQ(WordVectors::open(dir_).error().code, ErrorCode::kDataLoss);  // a directory
}

TEST_F(WordVectorsTest, JsonOfAnotherShapeIsRefusedWithWhereItWentWrong) {
  auto refused = [&](const std::string& json) {
    auto report = convert_wink_vectors_text(json, dir_ / "x.vectors");
    EXPECT_FALSE(report.has_value()) << json;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "x.vectors"));
    return report ? std::string() : report.error().message;
  };
  EXPECT_THAT(refused(R"({"dimensions":3})"), HasSubstr("no \"vectors\""));
  EXPECT_THAT(refused(R"({"vectors":{"a":[1,2,3]},"dimensions":3})"), HasSubstr("before \"dimensions\""));
  EXPECT_THAT(refused(R"({"dimensions":3,"vectors":{"a":[1,2]}})"), HasSubstr("fewer than the 3"));
  EXPECT_THAT(refused(R"({"dimensions":3,"vectors":{"a":[1,2,x]}})"), HasSubstr("at byte 36"));
  EXPECT_THAT(refused("[1,2,3]"), HasSubstr("expected '{'"));
  EXPECT_THAT(convert_wink_vectors(dir_ / "none.json", dir_ / "x.vectors").error().message, HasSubstr("none.json"));
}

TEST_F(WordVectorsTest, TheMissingFileIsSaidOnceInOneLineWithTheCommandThatInstallsIt) {
  const std::string message = missing_vectors_message(std::vector<std::filesystem::path>{dir_ / "none.vectors"});
  EXPECT_EQ(message.find('\n'), std::string::npos);
  EXPECT_THAT(message, HasSubstr("not installed"));
  EXPECT_THAT(message, HasSubstr((dir_ / "none.vectors").string()));
  EXPECT_THAT(message, HasSubstr("bash scripts/install-deps.sh && make"));
  // Said once per process, however often the vectors are wanted, and the
  // caller goes on without them.
  auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(said_);
  spdlog::default_logger()->sinks().push_back(sink);
  const auto level = spdlog::default_logger()->level();
  spdlog::default_logger()->set_level(spdlog::level::warn);
  ::setenv("APPRENTICE_VECTORS", (dir_ / "none.vectors").c_str(), 1);
  EXPECT_FALSE(open_default_vectors().has_value());
  EXPECT_FALSE(open_default_vectors().has_value());
  ::unsetenv("APPRENTICE_VECTORS");
  spdlog::default_logger()->sinks().pop_back();
  spdlog::default_logger()->set_level(level);
  const std::string logged = said_.str();
  EXPECT_EQ(std::count(logged.begin(), logged.end(), '\n'), 1) << logged;
  EXPECT_THAT(logged, HasSubstr("bash scripts/install-deps.sh && make"));
}

TEST(RealWordVectors, GloveKnowsWhatIsAlikeAndMapsAtOnce) {
  APPRENTICE_REQUIRE_VECTORS();
  auto vectors = WordVectors::open(built_vectors_path());
  ASSERT_TRUE(vectors.has_value()) << vectors.error().describe();
  EXPECT_EQ(vectors->dimensions(), 100u);
  EXPECT_EQ(vectors->size(), 341479u);
  EXPECT_GT(*vectors->similarity("banana", "apple"), *vectors->similarity("banana", "sofa"));
  EXPECT_GT(*vectors->similarity("skittles", "candy"), *vectors->similarity("skittles", "jacket"));
  EXPECT_GT(*vectors->similarity("gazette", "newspaper"), 0.5);
  EXPECT_TRUE(vectors->contains("t-shirt"));
}

}  // namespace
}  // namespace apprentice::vectors
