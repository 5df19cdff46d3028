#include "vectors/word_vectors.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <mutex>

#include <spdlog/spdlog.h>

#include "util/cosine.h"
#include "util/file.h"
#include "vectors/vectors_format.h"

#ifndef APPRENTICE_VECTORS_BUILD_DIR
#define APPRENTICE_VECTORS_BUILD_DIR "build/vectors"
#endif

namespace apprentice::vectors {

struct WordVectors::Mapping {
  std::filesystem::path path;
  const std::uint8_t* bytes = nullptr;
  std::size_t length = 0;
  VectorsHeader header{};
  const WordEntry* entries = nullptr;
  const char* pool = nullptr;
  const std::uint32_t* slots = nullptr;
  const std::int8_t* vectors = nullptr;
  const float* scales = nullptr;

  ~Mapping() {
    if (bytes != nullptr) ::munmap(const_cast<std::uint8_t*>(bytes), length);
  }
};

namespace {

tl::unexpected<Error> not_vectors(const std::filesystem::path& path, const std::string& why) {
  return make_error(ErrorCode::kDataLoss, path.string() + ": not a usable word-vectors file (" + why + ")");
}

// Whether [offset, offset + count * size) lies within `length`, without
// overflow.
bool within(std::uint64_t offset, std::uint64_t count, std::uint64_t size, std::uint64_t length) {
  if (offset > length) return false;
  if (size != 0 && count > (length - offset) / size) return false;
  return true;
}

}  // namespace

Result<WordVectors> WordVectors::open(const std::filesystem::path& path) {
  FileDescriptor fd(open_retrying(path, O_RDONLY | O_CLOEXEC));
  if (fd.get() < 0) {
    if (errno == ENOENT) return make_error(ErrorCode::kNotFound, path.string() + ": no such file");
    return make_error(ErrorCode::kIo, path.string() + ": cannot open: " + std::strerror(errno));
  }
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0) return make_error(ErrorCode::kIo, path.string() + ": " + std::strerror(errno));
  if (!S_ISREG(info.st_mode)) return not_vectors(path, "not a regular file");
  const std::size_t length = static_cast<std::size_t>(info.st_size);
  if (length < sizeof(VectorsHeader)) return not_vectors(path, "shorter than its header");
  void* mapped = ::mmap(nullptr, length, PROT_READ, MAP_PRIVATE, fd.get(), 0);
  if (mapped == MAP_FAILED) return make_error(ErrorCode::kIo, path.string() + ": cannot map: " + std::strerror(errno));
  auto m = std::make_unique<Mapping>();
  m->path = path;
  m->bytes = static_cast<const std::uint8_t*>(mapped);
  m->length = length;
  std::memcpy(&m->header, m->bytes, sizeof(VectorsHeader));
  const VectorsHeader& h = m->header;
  if (std::memcmp(h.magic, kVectorsMagic, sizeof h.magic) != 0) return not_vectors(path, "wrong magic number");
  if (h.file_size != length) return not_vectors(path, "truncated or extended: its header says " +
                                                          std::to_string(h.file_size) + " bytes, it has " +
                                                          std::to_string(length));
  const bool power_of_two = h.slot_count != 0 && (h.slot_count & (h.slot_count - 1)) == 0;
  if (h.dimensions == 0 || h.dimensions > kMaxDimensions || !power_of_two || h.slot_count < 2ull * h.word_count)
    return not_vectors(path, "an impossible header");
  const std::uint64_t vector_bytes = h.dimensions;
  if (!within(h.entries_offset, h.word_count, sizeof(WordEntry), length) || !within(h.pool_offset, h.pool_size, 1, length) ||
      !within(h.slots_offset, h.slot_count, sizeof(std::uint32_t), length) ||
      !within(h.vectors_offset, h.word_count, vector_bytes, length) ||
      !within(h.scales_offset, h.word_count, sizeof(float), length) || h.entries_offset % alignof(WordEntry) != 0 ||
      h.slots_offset % alignof(std::uint32_t) != 0 || h.scales_offset % alignof(float) != 0)
    return not_vectors(path, "a part lies outside the file");
  m->entries = reinterpret_cast<const WordEntry*>(m->bytes + h.entries_offset);
  m->pool = reinterpret_cast<const char*>(m->bytes + h.pool_offset);
  m->slots = reinterpret_cast<const std::uint32_t*>(m->bytes + h.slots_offset);
  m->vectors = reinterpret_cast<const std::int8_t*>(m->bytes + h.vectors_offset);
  m->scales = reinterpret_cast<const float*>(m->bytes + h.scales_offset);
  // Each entry's word must lie in the pool: checked once here, so that a
  // lookup never reads past it. (A pass over the entries, about a
  // millisecond for GloVe's 341k words.)
  for (std::uint64_t i = 0; i < h.word_count; ++i) {
    const WordEntry& e = m->entries[i];
    if (e.offset > h.pool_size || e.length > h.pool_size - e.offset) return not_vectors(path, "a word lies outside the pool");
  }
  return WordVectors(std::move(m));
}

WordVectors::WordVectors(std::unique_ptr<Mapping> mapping) : mapping_(std::move(mapping)) {}
WordVectors::WordVectors(WordVectors&&) noexcept = default;
WordVectors& WordVectors::operator=(WordVectors&&) noexcept = default;
WordVectors::~WordVectors() = default;

std::size_t WordVectors::dimensions() const { return mapping_->header.dimensions; }
std::size_t WordVectors::size() const { return mapping_->header.word_count; }
const std::filesystem::path& WordVectors::path() const { return mapping_->path; }

std::optional<std::uint32_t> WordVectors::find(std::string_view word) const {
  const Mapping& m = *mapping_;
  const std::uint64_t mask = m.header.slot_count - 1;
  for (std::uint64_t slot = fnv1a(word) & mask, probes = 0; probes <= mask; slot = (slot + 1) & mask, ++probes) {
    const std::uint32_t value = m.slots[slot];
    if (value == 0) return std::nullopt;
    const std::uint32_t index = value - 1;
    if (index >= m.header.word_count) return std::nullopt;  // a damaged table answers nothing
    const WordEntry& e = m.entries[index];
    if (std::string_view(m.pool + e.offset, e.length) == word) return index;
  }
  return std::nullopt;
}

bool WordVectors::contains(std::string_view word) const { return find(word).has_value(); }

void WordVectors::add(std::uint32_t index, double weight, std::vector<double>& sum) const {
  const Mapping& m = *mapping_;
  const std::int8_t* v = m.vectors + static_cast<std::size_t>(index) * m.header.dimensions;
  const double scale = m.scales[index] * weight;
  for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += scale * v[i];
}

namespace {

std::vector<float> unit(const std::vector<double>& sum) {
  double norm = 0;
  for (double x : sum) norm += x * x;
  if (norm <= 0) return {};
  norm = std::sqrt(norm);
  std::vector<float> out(sum.size());
  for (std::size_t i = 0; i < sum.size(); ++i) out[i] = static_cast<float>(sum[i] / norm);
  return out;
}

}  // namespace

std::vector<float> WordVectors::word(std::string_view word) const {
  auto index = find(word);
  if (!index) return {};
  std::vector<double> sum(dimensions(), 0.0);
  add(*index, 1.0, sum);
  return unit(sum);
}

std::vector<float> WordVectors::phrase(std::span<const std::string> words, std::span<const double> weights) const {
  std::vector<double> sum(dimensions(), 0.0);
  bool any = false;
  for (std::size_t i = 0; i < words.size(); ++i) {
    auto index = find(words[i]);
    const double weight = weights.empty() ? 1.0 : (i < weights.size() ? weights[i] : 0.0);
    if (!index || weight == 0) continue;
    add(*index, weight, sum);
    any = true;
  }
  return any ? unit(sum) : std::vector<float>{};
}

std::optional<double> WordVectors::similarity(std::string_view a, std::string_view b) const {
  std::vector<float> va = word(a), vb = word(b);
  if (va.empty() || vb.empty()) return std::nullopt;
  return cosine(va, vb);
}

std::vector<std::filesystem::path> vectors_search_path() {
  std::vector<std::filesystem::path> out;
  if (const char* env = std::getenv("APPRENTICE_VECTORS"); env != nullptr && *env != '\0') {
    out.emplace_back(env);
    return out;
  }
  std::error_code ec;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path dir = exe.parent_path();
    out.push_back(dir / "vectors" / kVectorsFileName);
    out.push_back(dir.parent_path() / "vectors" / kVectorsFileName);  // build/python, build/tests/x
    out.push_back(dir.parent_path() / "share" / "apprentice" / "vectors" / kVectorsFileName);
  }
  out.push_back(std::filesystem::path(APPRENTICE_VECTORS_BUILD_DIR) / kVectorsFileName);
  return out;
}

std::string missing_vectors_message(std::span<const std::filesystem::path> searched) {
  std::string where = searched.empty() ? std::string("anywhere") : searched.front().string();
  if (searched.size() > 1) where += " (nor in " + std::to_string(searched.size() - 1) + " other places)";
  return "The word vectors are not installed, so names WordNet does not know are placed by WordNet alone: no " +
         std::string(kVectorsFileName) + " at " + where +
         ". To install them, run `bash scripts/install-deps.sh && make` in the apprentice source tree.";
}

std::optional<WordVectors> open_default_vectors() {
  static std::once_flag said;
  std::vector<std::filesystem::path> searched = vectors_search_path();
  std::string problem;
  for (const std::filesystem::path& path : searched) {
    auto opened = WordVectors::open(path);
    if (opened) {
      spdlog::debug("vectors: {} words of {} dimensions from {}", opened->size(), opened->dimensions(), path.string());
      return std::move(*opened);
    }
    if (opened.error().code != ErrorCode::kNotFound && problem.empty()) problem = opened.error().message;
  }
  std::call_once(said, [&] {
    if (problem.empty()) spdlog::warn("{}", missing_vectors_message(searched));
    else
      spdlog::warn("The word vectors cannot be used ({}), so names WordNet does not know are placed by WordNet alone. "
                   "To rebuild them, run `bash scripts/install-deps.sh && make` in the apprentice source tree.",
                   problem);
  });
  return std::nullopt;
}

}  // namespace apprentice::vectors
