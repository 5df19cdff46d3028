// The layout of a word-vectors file, shared by the converter that writes it
// (convert_vectors.cc) and the reader that maps it (word_vectors.cc). See
// word_vectors.h for what each part holds. Little-endian, as the machines
// that build and run apprentice are.
#pragma once

#include <cstdint>
#include <string_view>

namespace apprentice::vectors {

inline constexpr std::uint32_t kMaxDimensions = 4096;

struct VectorsHeader {
  char magic[8];
  std::uint32_t dimensions;
  std::uint32_t reserved;
  std::uint64_t word_count;
  std::uint64_t slot_count;  // a power of two, at least 2 * word_count
  std::uint64_t entries_offset;
  std::uint64_t pool_offset;
  std::uint64_t pool_size;
  std::uint64_t slots_offset;
  std::uint64_t vectors_offset;  // word_count * dimensions int8
  std::uint64_t scales_offset;   // word_count float
  std::uint64_t file_size;
};
static_assert(sizeof(VectorsHeader) == 88);

struct WordEntry {
  std::uint32_t offset;  // into the pool
  std::uint32_t length;
};

// 64-bit FNV-1a: the hash of the slot table.
inline std::uint64_t fnv1a(std::string_view text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

}  // namespace apprentice::vectors
