#include "core/binary_io.h"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <bit>
#include <cerrno>
#include <cstring>
#include <iomanip>
#include <limits>

#include "core/error.h"
#include "core/file_io.h"

namespace throng {
static_assert(std::endian::native == std::endian::little,
              "the chunk format is written little endian");

namespace {
constexpr char kTrailerTag[4] = {'T', 'E', 'N', 'D'};
constexpr size_t kIoBlock = 1 << 20;

uint64_t padded(uint64_t bytes) {
  return (bytes + 7) & ~uint64_t(7);
}

std::array<std::array<uint32_t, 256>, 8> makeCrcTables() {
  std::array<std::array<uint32_t, 256>, 8> t{};
  for (uint32_t i = 0; i < 256; ++i) {
    uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    t[0][i] = c;
  }
  for (uint32_t i = 0; i < 256; ++i)
    for (size_t s = 1; s < 8; ++s) t[s][i] = (t[s - 1][i] >> 8) ^ t[0][t[s - 1][i] & 0xFF];
  return t;
}

template <typename T>
void put(uint8_t* at, T value) {
  std::memcpy(at, &value, sizeof(T));
}
template <typename T>
T get(const uint8_t* at) {
  T value;
  std::memcpy(&value, at, sizeof(T));
  return value;
}

std::string printableTag(const char* bytes, size_t n) {
  std::string out;
  for (size_t i = 0; i < n; ++i) {
    unsigned char c = static_cast<unsigned char>(bytes[i]);
    if (c >= 32 && c < 127)
      out += char(c);
    else
      out += concat("\\x", std::hex, std::setw(2), std::setfill('0'), unsigned(c));
  }
  return out;
}

std::string hex32(uint32_t v) {
  return concat("0x", std::hex, std::setw(8), std::setfill('0'), v);
}

void checkTag(std::string_view tag) {
  if (tag.size() != 4) fail("chunk tag '", tag, "': expected exactly 4 characters");
}
}  // namespace

const char* elementTypeName(ElementType type) {
  switch (type) {
    case ElementType::Bytes:
      return "bytes";
    case ElementType::U8:
      return "u8";
    case ElementType::I8:
      return "i8";
    case ElementType::U16:
      return "u16";
    case ElementType::I16:
      return "i16";
    case ElementType::U32:
      return "u32";
    case ElementType::I32:
      return "i32";
    case ElementType::U64:
      return "u64";
    case ElementType::I64:
      return "i64";
    case ElementType::F32:
      return "f32";
    case ElementType::F64:
      return "f64";
    case ElementType::Utf8:
      return "utf8";
  }
  return "unknown";
}

uint32_t crc32Ieee(std::span<const uint8_t> bytes, uint32_t crc) {
  static const auto t = makeCrcTables();
  crc = ~crc;
  const uint8_t* p = bytes.data();
  size_t n = bytes.size();
  while (n >= 8) {
    uint32_t lo = get<uint32_t>(p) ^ crc;
    uint32_t hi = get<uint32_t>(p + 4);
    crc = t[7][lo & 0xFF] ^ t[6][(lo >> 8) & 0xFF] ^ t[5][(lo >> 16) & 0xFF] ^ t[4][lo >> 24] ^
          t[3][hi & 0xFF] ^ t[2][(hi >> 8) & 0xFF] ^ t[1][(hi >> 16) & 0xFF] ^ t[0][hi >> 24];
    p += 8;
    n -= 8;
  }
  while (n--) crc = t[0][(crc ^ *p++) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

// ---- writer ----------------------------------------------------------------------------

ChunkWriter::ChunkWriter(std::string_view magic, uint32_t version) : version_(version) {
  if (magic.size() != kMagicBytes) fail("file magic '", magic, "': expected exactly 8 characters");
  std::memcpy(magic_, magic.data(), kMagicBytes);
}

void ChunkWriter::addRaw(std::string_view tag, ElementType type, size_t elementBytes, size_t count,
                         const void* data, bool copy) {
  checkTag(tag);
  for (const Chunk& c : chunks_)
    if (c.tag == tag) fail("chunk '", tag, "' added twice");
  Chunk chunk{std::string(tag), type, uint32_t(elementBytes), uint64_t(count), {}, nullptr};
  const size_t bytes = elementBytes * count;
  if (copy) {
    chunk.owned.resize(bytes);
    if (bytes) std::memcpy(chunk.owned.data(), data, bytes);
  } else {
    chunk.borrowed = bytes ? data : nullptr;
  }
  chunks_.push_back(std::move(chunk));
}

void ChunkWriter::addString(std::string_view tag, std::string_view text) {
  addRaw(tag, ElementType::Utf8, 1, text.size(), text.data(), true);
}

uint64_t ChunkWriter::totalBytes() const {
  uint64_t total = kFileHeaderBytes + kTrailerBytes;
  for (const Chunk& c : chunks_) total += kChunkHeaderBytes + padded(c.count * c.elementBytes);
  return total;
}

// Feeds the file to sink(bytes) in order, the trailer's checksum computed on the way.
template <typename Sink>
void ChunkWriter::emit(Sink&& sink) const {
  uint32_t crc = 0;
  auto out = [&](const uint8_t* p, size_t n) {
    crc = crc32Ieee({p, n}, crc);
    sink(p, n);
  };
  uint8_t header[kFileHeaderBytes] = {};
  std::memcpy(header, magic_, kMagicBytes);
  put(header + 8, version_);
  put(header + 12, uint32_t(chunks_.size()));
  put(header + 16, totalBytes());
  out(header, sizeof header);
  static const uint8_t zeros[8] = {};
  for (const Chunk& c : chunks_) {
    uint8_t h[kChunkHeaderBytes] = {};
    std::memcpy(h, c.tag.data(), 4);
    put(h + 4, uint32_t(c.type));
    put(h + 8, c.elementBytes);
    put(h + 16, c.count);
    out(h, sizeof h);
    const uint64_t bytes = c.count * c.elementBytes;
    for (uint64_t at = 0; at < bytes; at += kIoBlock)
      out(c.data() + at, size_t(std::min<uint64_t>(kIoBlock, bytes - at)));
    if (padded(bytes) != bytes) out(zeros, size_t(padded(bytes) - bytes));
  }
  uint8_t trailer[kTrailerBytes];
  put(trailer, crc);
  std::memcpy(trailer + 4, kTrailerTag, 4);
  sink(trailer, sizeof trailer);
}

std::vector<uint8_t> ChunkWriter::bytes() const {
  std::vector<uint8_t> all;
  all.reserve(totalBytes());
  emit([&](const uint8_t* p, size_t n) { all.insert(all.end(), p, p + n); });
  return all;
}

void ChunkWriter::writeFileAtomic(const std::filesystem::path& path) const {
  throng::writeFileAtomic(path, [this](const ByteSink& sink) { emit(sink); });
}

// ---- reader ----------------------------------------------------------------------------

ChunkReader::ChunkReader(ChunkReader&& o) noexcept {
  *this = std::move(o);
}

ChunkReader& ChunkReader::operator=(ChunkReader&& o) noexcept {
  if (this != &o) {
    if (file_) std::fclose(file_);
    name_ = std::move(o.name_);
    memory_ = std::move(o.memory_);
    file_ = o.file_;
    o.file_ = nullptr;
    sourceBytes_ = o.sourceBytes_;
    version_ = o.version_;
    totalBytes_ = o.totalBytes_;
    chunks_ = std::move(o.chunks_);
  }
  return *this;
}

ChunkReader::~ChunkReader() {
  if (file_) std::fclose(file_);
}

ChunkReader ChunkReader::openFile(const std::filesystem::path& path, std::string_view magic,
                                  uint32_t maxVersion, std::string_view kind) {
  ChunkReader r;
  r.name_ = path.string();
  r.file_ = std::fopen(path.c_str(), "rb");
  if (!r.file_) fail(r.name_, ": cannot open for reading (", std::strerror(errno), ")");
  if (std::fseek(r.file_, 0, SEEK_END) != 0)
    fail(r.name_, ": cannot seek (", std::strerror(errno), ")");
  const long size = std::ftell(r.file_);
  if (size < 0) fail(r.name_, ": cannot tell its size (", std::strerror(errno), ")");
  r.sourceBytes_ = uint64_t(size);
  r.parse(magic, maxVersion, kind);
  return r;
}

ChunkReader ChunkReader::fromBytes(std::vector<uint8_t> bytes, std::string name,
                                   std::string_view magic, uint32_t maxVersion,
                                   std::string_view kind) {
  ChunkReader r;
  r.name_ = std::move(name);
  r.memory_ = std::move(bytes);
  r.sourceBytes_ = r.memory_.size();
  r.parse(magic, maxVersion, kind);
  return r;
}

void ChunkReader::readAt(uint64_t offset, size_t bytes, void* out) const {
  if (offset + bytes > sourceBytes_)
    fail(name_, ": truncated at byte ", sourceBytes_, ", expected ", offset + bytes, " bytes");
  if (!file_) {
    if (bytes) std::memcpy(out, memory_.data() + offset, bytes);
    return;
  }
  size_t done = 0;
  while (done < bytes) {
    const ssize_t n = ::pread(fileno(file_), static_cast<uint8_t*>(out) + done, bytes - done,
                              off_t(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      fail(name_, ": read failed at byte ", offset + done, " (",
           n < 0 ? std::strerror(errno) : "end of file", ")");
    done += size_t(n);
  }
}

void ChunkReader::parse(std::string_view magic, uint32_t maxVersion, std::string_view kind) {
  if (sourceBytes_ < kMagicBytes)
    fail(name_, ": truncated at byte ", sourceBytes_, ", expected a ", kind, " header of ",
         kFileHeaderBytes, " bytes");
  uint8_t header[kFileHeaderBytes] = {};
  readAt(0, kMagicBytes, header);
  if (std::memcmp(header, magic.data(), kMagicBytes) != 0)
    fail(name_, ": not a ", kind, " file (magic '",
         printableTag(reinterpret_cast<const char*>(header), kMagicBytes), "', expected '", magic,
         "')");
  if (sourceBytes_ < kFileHeaderBytes)
    fail(name_, ": truncated at byte ", sourceBytes_, ", expected a ", kind, " header of ",
         kFileHeaderBytes, " bytes");
  readAt(0, kFileHeaderBytes, header);
  version_ = get<uint32_t>(header + 8);
  if (version_ == 0 || version_ > maxVersion)
    fail(name_, ": ", kind, " version ", version_, " unsupported (this build reads versions 1 to ",
         maxVersion, ")");
  const uint32_t chunkCount = get<uint32_t>(header + 12);
  totalBytes_ = get<uint64_t>(header + 16);
  if (sourceBytes_ < totalBytes_)
    fail(name_, ": truncated at byte ", sourceBytes_, ", expected ", totalBytes_, " bytes");
  if (sourceBytes_ > totalBytes_)
    fail(name_, ": ", sourceBytes_ - totalBytes_, " unexpected bytes after the end at byte ",
         totalBytes_);
  if (totalBytes_ < kFileHeaderBytes + kTrailerBytes)
    fail(name_, ": header says ", totalBytes_, " bytes, less than a header and trailer");

  uint32_t crc = 0;
  std::vector<uint8_t> block(std::min<uint64_t>(kIoBlock, totalBytes_));
  const uint64_t body = totalBytes_ - kTrailerBytes;
  for (uint64_t at = 0; at < body; at += kIoBlock) {
    const size_t n = size_t(std::min<uint64_t>(kIoBlock, body - at));
    readAt(at, n, block.data());
    crc = crc32Ieee({block.data(), n}, crc);
  }
  uint8_t trailer[kTrailerBytes];
  readAt(body, kTrailerBytes, trailer);
  if (std::memcmp(trailer + 4, kTrailerTag, 4) != 0)
    fail(name_, ": no end marker at byte ", body + 4, " (the file is corrupted or was cut)");
  const uint32_t stored = get<uint32_t>(trailer);
  if (stored != crc)
    fail(name_, ": checksum mismatch (stored ", hex32(stored), ", computed ", hex32(crc),
         "): the file is corrupted");

  uint64_t at = kFileHeaderBytes;
  for (uint32_t i = 0; i < chunkCount; ++i) {
    if (at + kChunkHeaderBytes > body)
      fail(name_, ": truncated at byte ", body, ", expected chunk ", i, " of ", chunkCount,
           " at byte ", at);
    uint8_t h[kChunkHeaderBytes];
    readAt(at, kChunkHeaderBytes, h);
    ChunkInfo c;
    c.tag = printableTag(reinterpret_cast<const char*>(h), 4);
    c.type = ElementType(get<uint32_t>(h + 4));
    c.elementBytes = get<uint32_t>(h + 8);
    c.count = get<uint64_t>(h + 16);
    c.offset = at + kChunkHeaderBytes;
    if (c.elementBytes == 0 && c.count)
      fail(name_, ": chunk '", c.tag, "' at byte ", at, " has 0-byte elements");
    if (c.elementBytes && c.count > (body - c.offset) / c.elementBytes)
      fail(name_, ": chunk '", c.tag, "' at byte ", at, ": truncated at byte ", body, ", expected ",
           c.count, " × ", c.elementBytes, " bytes of payload");
    at = c.offset + padded(c.payloadBytes());
    if (at > body) fail(name_, ": chunk '", c.tag, "' padding runs past byte ", body);
    chunks_.push_back(std::move(c));
  }
  if (at != body) fail(name_, ": ", body - at, " stray bytes after the last chunk at byte ", at);
}

const ChunkInfo* ChunkReader::find(std::string_view tag) const {
  for (const ChunkInfo& c : chunks_)
    if (c.tag == tag) return &c;
  return nullptr;
}

const ChunkInfo& ChunkReader::require(std::string_view tag) const {
  const ChunkInfo* c = find(tag);
  if (!c) fail(name_, ": missing chunk '", tag, "'");
  return *c;
}

const ChunkInfo& ChunkReader::checked(std::string_view tag, ElementType type,
                                      size_t elementBytes) const {
  const ChunkInfo& c = require(tag);
  if (c.type != type || c.elementBytes != elementBytes)
    fail(name_, ": chunk '", tag, "': expected ", elementTypeName(type), " elements of ",
         elementBytes, " bytes, found ", elementTypeName(c.type), " elements of ", c.elementBytes,
         " bytes");
  return c;
}

void ChunkReader::readPayload(const ChunkInfo& c, void* out) const {
  readAt(c.offset, size_t(c.payloadBytes()), out);
}

std::string ChunkReader::string(std::string_view tag) const {
  const ChunkInfo& c = checked(tag, ElementType::Utf8, 1);
  std::string s(c.count, '\0');
  readPayload(c, s.data());
  return s;
}

void ChunkReader::expectCount(const ChunkInfo& c, uint64_t count) const {
  if (c.count != count)
    fail(name_, ": chunk '", c.tag, "' holds ", c.count, " elements, expected ", count);
}

namespace {
// The pid of "<name>.tmp-<pid>" when `file` is a temporary of `name`, else -1.
long temporaryPid(const std::string& file, const std::string& name) {
  const std::string prefix = name + ".tmp-";
  if (file.size() <= prefix.size() || file.size() > prefix.size() + 10 ||
      file.compare(0, prefix.size(), prefix) != 0)
    return -1;
  long pid = 0;
  for (size_t i = prefix.size(); i < file.size(); ++i) {
    if (file[i] < '0' || file[i] > '9') return -1;
    pid = pid * 10 + (file[i] - '0');
  }
  return pid > 0 ? pid : -1;
}

bool processRuns(long pid) {
  if (pid == long(::getpid())) return false;  // this process is not writing it yet
  if (pid > long(std::numeric_limits<pid_t>::max())) return false;
  return ::kill(pid_t(pid), 0) == 0 || errno != ESRCH;
}
}  // namespace

std::vector<std::filesystem::path> removeStaleTemporaries(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  const std::string name = path.filename().string();
  std::vector<fs::path> removed;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const long pid = temporaryPid(it->path().filename().string(), name);
    if (pid < 0 || processRuns(pid) || !it->is_regular_file(ec)) continue;
    std::error_code removeError;
    if (fs::remove(it->path(), removeError)) removed.push_back(it->path());
  }
  return removed;
}

std::vector<std::filesystem::path> prepareOutputFile(const std::filesystem::path& path,
                                                     std::string_view option) {
  namespace fs = std::filesystem;
  if (path.empty()) fail(option, ": expected a file path");
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::is_directory(status))
    fail(option, " ", path.string(), ": is a directory, expected a file to write");
  if (fs::exists(status) && !fs::is_regular_file(status))
    fail(option, " ", path.string(), ": not a regular file");
  ensureWritableDirectory(path.has_parent_path() ? path.parent_path() : fs::path("."));
  return removeStaleTemporaries(path);
}

std::string readMagic(const std::filesystem::path& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) fail(path.string(), ": cannot open for reading (", std::strerror(errno), ")");
  char magic[kMagicBytes];
  const size_t n = std::fread(magic, 1, kMagicBytes, f);
  std::fclose(f);
  return n == kMagicBytes ? std::string(magic, kMagicBytes) : std::string();
}

}  // namespace throng
