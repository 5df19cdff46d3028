// Input files are read within documented limits (64 MiB a file, 1 MiB a
// line): hostile input (/dev/zero, a directory, a huge file, a huge line)
// gets a clear error naming the file, never a read until memory runs out.
#include "util/file.h"

#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/scratch.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;

class InputFile : public testing::ScratchTest {};

TEST_F(InputFile, ReadsAFileAsItIs) {
  auto path = write("a.txt", "one\r\ntwo\n\nthree");
  auto text = read_input_file(path);
  ASSERT_TRUE(text.has_value()) << text.error().describe();
  EXPECT_EQ(*text, "one\r\ntwo\n\nthree");
  auto lines = read_input_lines(path);
  ASSERT_TRUE(lines.has_value());
  EXPECT_EQ(*lines, (std::vector<std::string>{"one", "two", "", "three"}));
}

TEST_F(InputFile, AMissingFileIsNotFound) {
  auto text = read_input_file(dir_ / "absent.yaml");
  ASSERT_FALSE(text.has_value());
  EXPECT_EQ(text.error().code, ErrorCode::kNotFound);
  EXPECT_THAT(text.error().message, HasSubstr("absent.yaml: no such file"));
}

TEST_F(InputFile, ADirectoryIsSaidToBeOne) {
  auto text = read_input_file(dir_);
  ASSERT_FALSE(text.has_value());
  EXPECT_EQ(text.error().code, ErrorCode::kInvalidInput);
  EXPECT_THAT(text.error().message, HasSubstr("is a directory"));
}

TEST_F(InputFile, DevZeroStopsAtTheLineLimit) {
  auto text = read_input_file("/dev/zero");
  ASSERT_FALSE(text.has_value());
  EXPECT_EQ(text.error().code, ErrorCode::kInvalidInput);
  EXPECT_THAT(text.error().message, HasSubstr("/dev/zero:1: the line is longer than 1 MiB"));
}

TEST_F(InputFile, AFileOverTheLimitIsRefusedBeforeItIsRead) {
  auto path = write("big.txt", std::string(4096, '\n'));
  auto text = read_input_file(path, InputLimits{1024, 100});
  ASSERT_FALSE(text.has_value());
  EXPECT_EQ(text.error().code, ErrorCode::kInvalidInput);
  EXPECT_THAT(text.error().message, HasSubstr("larger than 1 KiB, the limit for an input file"));
}

TEST_F(InputFile, AStreamOverTheLimitIsRefused) {
  // A character device has no size to check first: the limit stops the read.
  auto text = read_input_file("/dev/zero", InputLimits{100000, 200000});
  ASSERT_FALSE(text.has_value());
  EXPECT_THAT(text.error().message, HasSubstr("larger than 100000 bytes"));
}

TEST_F(InputFile, ALongLineIsRefusedWithItsNumber) {
  auto path = write("lines.jsonl", "{}\n{}\n" + std::string(300, 'x') + "\n{}\n");
  auto lines = read_input_lines(path, InputLimits{1 << 20, 256});
  ASSERT_FALSE(lines.has_value());
  EXPECT_EQ(lines.error().code, ErrorCode::kInvalidInput);
  EXPECT_THAT(lines.error().message, HasSubstr("lines.jsonl:3: the line is longer than 256 bytes"));
  // At the limit exactly is fine.
  auto fits = read_input_lines(write("fits.jsonl", std::string(256, 'x')), InputLimits{1 << 20, 256});
  EXPECT_TRUE(fits.has_value());
}

TEST_F(InputFile, TheDefaultLimitsAreTheDocumentedOnes) {
  EXPECT_EQ(describe_size(kMaxInputFileBytes), "64 MiB");
  EXPECT_EQ(describe_size(kMaxInputLineBytes), "1 MiB");
}

}  // namespace
}  // namespace apprentice
