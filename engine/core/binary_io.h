#pragma once
// A small versioned chunked binary format shared by the secondary-motion files (.tsg explored
// graphs, .tsc compressed databases) and the MPI messages of the exploration.
//
// Layout (little endian, every chunk starts 8-byte aligned):
//   header   magic[8] | version u32 | chunkCount u32 | totalBytes u64 | reserved u64
//   chunk    tag[4] | ElementType u32 | elementBytes u32 | reserved u32 | count u64 | payload
//            (count × elementBytes bytes, zero-padded to a multiple of 8)
//   trailer  CRC-32 (IEEE, as zlib) of every byte before it, u32 | "TEND"
// A reader checks magic, version, size and checksum before it hands out any chunk, so a
// truncated or corrupted file is reported as such and never half-read.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <glm/glm.hpp>

namespace throng {

enum class ElementType : uint32_t {
  Bytes = 0,  // opaque records (elementBytes says how long)
  U8,
  I8,
  U16,
  I16,
  U32,
  I32,
  U64,
  I64,
  F32,
  F64,
  Utf8,  // a string: count bytes
};
const char* elementTypeName(ElementType type);

namespace detail {
template <typename T>
struct ScalarOf {
  using type = T;
};
template <glm::length_t L, typename T, glm::qualifier Q>
struct ScalarOf<glm::vec<L, T, Q>> {
  using type = T;
};
}  // namespace detail

// The element type recorded for T: its scalar type for arithmetic types and glm vectors
// (a vec3 is F32 with elementBytes 12), Bytes for any other trivially copyable record.
template <typename T>
constexpr ElementType elementTypeOf() {
  static_assert(std::is_trivially_copyable_v<T>, "chunks hold trivially copyable elements only");
  using S = typename detail::ScalarOf<T>::type;
  if constexpr (std::is_same_v<S, uint8_t>)
    return ElementType::U8;
  else if constexpr (std::is_same_v<S, int8_t>)
    return ElementType::I8;
  else if constexpr (std::is_same_v<S, uint16_t>)
    return ElementType::U16;
  else if constexpr (std::is_same_v<S, int16_t>)
    return ElementType::I16;
  else if constexpr (std::is_same_v<S, uint32_t>)
    return ElementType::U32;
  else if constexpr (std::is_same_v<S, int32_t>)
    return ElementType::I32;
  else if constexpr (std::is_same_v<S, uint64_t>)
    return ElementType::U64;
  else if constexpr (std::is_same_v<S, int64_t>)
    return ElementType::I64;
  else if constexpr (std::is_same_v<S, float>)
    return ElementType::F32;
  else if constexpr (std::is_same_v<S, double>)
    return ElementType::F64;
  else
    return ElementType::Bytes;
}

constexpr size_t kMagicBytes = 8;
constexpr size_t kFileHeaderBytes = 32;
constexpr size_t kChunkHeaderBytes = 24;
constexpr size_t kTrailerBytes = 8;

// CRC-32 (IEEE 802.3 polynomial, the value zlib.crc32 gives); `crc` continues a running one.
uint32_t crc32Ieee(std::span<const uint8_t> bytes, uint32_t crc = 0);

struct ChunkInfo {
  std::string tag;
  ElementType type = ElementType::Bytes;
  uint32_t elementBytes = 0;
  uint64_t count = 0;
  uint64_t offset = 0;  // of the payload, from the start of the file
  uint64_t payloadBytes() const { return count * elementBytes; }
};

// Collects chunks, then writes them in one pass. Tags are 4 characters and unique.
class ChunkWriter {
 public:
  ChunkWriter(std::string_view magic, uint32_t version);

  // Copies the data.
  template <typename T>
  void add(std::string_view tag, std::span<const T> values) {
    addRaw(tag, elementTypeOf<T>(), sizeof(T), values.size(), values.data(), true);
  }
  template <typename T>
  void add(std::string_view tag, const std::vector<T>& values) {
    add(tag, std::span<const T>(values));
  }
  template <typename T>
  void addScalar(std::string_view tag, const T& value) {
    add(tag, std::span<const T>(&value, 1));
  }
  void addString(std::string_view tag, std::string_view text);
  // Borrows the data (no copy, for the large frame arrays): it must outlive write*/bytes().
  template <typename T>
  void addView(std::string_view tag, std::span<const T> values) {
    addRaw(tag, elementTypeOf<T>(), sizeof(T), values.size(), values.data(), false);
  }

  uint64_t totalBytes() const;
  std::vector<uint8_t> bytes() const;
  // Streams to "<path>.tmp-<pid>" and renames it over `path`: a reader sees the old file or
  // the complete new one, never a partial write.
  void writeFileAtomic(const std::filesystem::path& path) const;

 private:
  struct Chunk {
    std::string tag;
    ElementType type;
    uint32_t elementBytes;
    uint64_t count;
    std::vector<uint8_t> owned;
    const void* borrowed = nullptr;
    const uint8_t* data() const {
      return borrowed ? static_cast<const uint8_t*>(borrowed) : owned.data();
    }
  };
  void addRaw(std::string_view tag, ElementType type, size_t elementBytes, size_t count,
              const void* data, bool copy);
  template <typename Sink>
  void emit(Sink&& sink) const;

  char magic_[kMagicBytes];
  uint32_t version_;
  std::vector<Chunk> chunks_;
};

// Validates a whole file (or message) on open, then reads chunks by tag with type checks.
// Errors name the source: "<name>: truncated at byte N, expected M bytes", "checksum mismatch",
// "version X unsupported", "missing chunk 'TAG'", element type mismatches.
class ChunkReader {
 public:
  // Reads from a file; payloads are read on demand, so memory stays at one chunk.
  static ChunkReader openFile(const std::filesystem::path& path, std::string_view magic,
                              uint32_t maxVersion, std::string_view kind);
  static ChunkReader fromBytes(std::vector<uint8_t> bytes, std::string name, std::string_view magic,
                               uint32_t maxVersion, std::string_view kind);

  ChunkReader(ChunkReader&&) noexcept;
  ChunkReader& operator=(ChunkReader&&) noexcept;
  ~ChunkReader();

  const std::string& name() const { return name_; }
  uint32_t version() const { return version_; }
  uint64_t totalBytes() const { return totalBytes_; }
  const std::vector<ChunkInfo>& chunks() const { return chunks_; }
  bool has(std::string_view tag) const { return find(tag) != nullptr; }
  const ChunkInfo* find(std::string_view tag) const;
  const ChunkInfo& require(std::string_view tag) const;

  template <typename T>
  std::vector<T> vector(std::string_view tag) const {
    const ChunkInfo& c = checked(tag, elementTypeOf<T>(), sizeof(T));
    std::vector<T> out(c.count);
    readPayload(c, out.data());
    return out;
  }
  template <typename T>
  T scalar(std::string_view tag) const {
    const ChunkInfo& c = checked(tag, elementTypeOf<T>(), sizeof(T));
    expectCount(c, 1);
    T value{};
    readPayload(c, &value);
    return value;
  }
  std::string string(std::string_view tag) const;
  // Fails unless the chunk holds exactly `count` elements (cross-chunk consistency checks).
  void expectCount(const ChunkInfo& chunk, uint64_t count) const;

 private:
  ChunkReader() = default;
  void parse(std::string_view magic, uint32_t maxVersion, std::string_view kind);
  void readAt(uint64_t offset, size_t bytes, void* out) const;
  const ChunkInfo& checked(std::string_view tag, ElementType type, size_t elementBytes) const;
  void readPayload(const ChunkInfo& chunk, void* out) const;

  std::string name_;
  std::vector<uint8_t> memory_;
  std::FILE* file_ = nullptr;
  uint64_t sourceBytes_ = 0;
  uint32_t version_ = 0;
  uint64_t totalBytes_ = 0;
  std::vector<ChunkInfo> chunks_;
};

// Before a long run that ends by writing `path` (option names it in messages, e.g. "--out"):
// refuses a path that is a directory or another non-file, makes sure its directory exists and
// accepts a new file, and removes the stale temporaries of earlier writers of this path
// (removeStaleTemporaries). Returns the temporaries removed.
std::vector<std::filesystem::path> prepareOutputFile(const std::filesystem::path& path,
                                                     std::string_view option);
// "<path>.tmp-<pid>" files that writeFileAtomic left when its process was killed mid-write
// (they can be hundreds of MB): removes those whose process no longer runs, and this process's
// own; a live writer's file is left alone. Returns the paths removed.
std::vector<std::filesystem::path> removeStaleTemporaries(const std::filesystem::path& path);

// The first 8 bytes of a file ("" when it is shorter), to dispatch on the file kind.
std::string readMagic(const std::filesystem::path& path);

}  // namespace throng
