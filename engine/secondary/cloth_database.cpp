#include "secondary/cloth_database.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include "core/binary_io.h"
#include "core/error.h"
#include "core/file_io.h"
#include "secondary/cloth_entropy.h"
#include "synth/motion_cache.h"

namespace throng::secondary {

namespace {
constexpr std::string_view kKind = "compressed cloth (.tsc)";

// Index arrays take the narrowest unsigned type holding their largest value.
void addIndices(ChunkWriter& w, std::string_view tag, const std::vector<uint32_t>& values) {
  uint32_t largest = values.empty() ? 0u : *std::max_element(values.begin(), values.end());
  if (largest < 256u) {
    w.add(tag, std::vector<uint8_t>(values.begin(), values.end()));
  } else if (largest < 65536u) {
    w.add(tag, std::vector<uint16_t>(values.begin(), values.end()));
  } else {
    w.add(tag, values);
  }
}

template <typename T>
std::vector<uint32_t> widened(const ChunkReader& r, std::string_view tag) {
  std::vector<T> narrow = r.vector<T>(tag);
  return {narrow.begin(), narrow.end()};
}

std::vector<uint32_t> readIndices(const ChunkReader& r, std::string_view tag) {
  switch (r.require(tag).type) {
    case ElementType::U8:
      return widened<uint8_t>(r, tag);
    case ElementType::U16:
      return widened<uint16_t>(r, tag);
    default:
      return r.vector<uint32_t>(tag);
  }
}

// One bit per merge flag.
std::vector<uint8_t> packBits(const std::vector<uint8_t>& flags) {
  std::vector<uint8_t> bytes((flags.size() + 7) / 8, 0);
  for (size_t i = 0; i < flags.size(); ++i)
    if (flags[i]) bytes[i / 8] |= uint8_t(1u << (i % 8));
  return bytes;
}

struct BasisHeader {
  uint32_t bits;
  float scale, offset, step;
};
static_assert(sizeof(BasisHeader) == 16);

struct ReportRecord {
  float targetError, quantum, maxErrorBeforeQuantization, maxError, meanError, coefficientQuantum;
};
static_assert(sizeof(ReportRecord) == 24);

// rows × columns of a decoded table; a product past 64 bits is refused, not wrapped.
size_t checkedProduct(size_t rows, size_t columns, const std::string& name) {
  if (columns && rows > std::numeric_limits<size_t>::max() / columns)
    fail(name, ": ", rows, " × ", columns, " values do not fit in memory");
  return rows * columns;
}

uint32_t coefficientStep(const ClothDatabase& db, uint32_t basis) {
  return db.coefficientSteps.empty() ? 1u : db.coefficientSteps[basis];
}

// Bases: each value minus the same axis of the previous vertex (the garment's vertices are in
// grid order and bases are smooth over it, so the differences are small), one model per basis.
std::vector<uint8_t> encodeBases(const ClothDatabase& db) {
  const size_t rows = size_t(db.vertexCount) * 3;
  std::vector<int32_t> deltas;
  deltas.reserve(rows * db.bases.size());
  for (const QuantizedBasis& b : db.bases)
    for (size_t r = 0; r < rows; ++r)
      deltas.push_back(int32_t(b.values[r]) - (r >= 3 ? int32_t(b.values[r - 3]) : 0));
  return encodeIntegerBlocks(deltas, rows);
}

// Coefficients basis by basis (one model each: their spreads differ by orders of magnitude), as
// multiples of the basis' step. Predicting them from the previous frame was measured on the
// 25,252-frame cape and gained nothing past the first few bases (the fine motion is not smooth
// from frame to frame), so they are coded as they are.
std::vector<uint8_t> encodeCoefficients(const ClothDatabase& db) {
  const uint32_t S = db.stateCount(), B = db.basisCount();
  std::vector<int32_t> values;
  values.reserve(size_t(S) * B);
  for (uint32_t i = 0; i < B; ++i)
    for (uint32_t s = 0; s < S; ++s)
      values.push_back(db.coefficients[size_t(s) * B + i] / int32_t(coefficientStep(db, i)));
  return encodeIntegerBlocks(values, S);
}

ChunkWriter writer(const ClothDatabase& db) {
  validateDatabase(db, "cloth database");
  ChunkWriter w(kClothDatabaseMagic, kClothDatabaseVersion);
  w.addScalar("VERT", db.vertexCount);
  addIndices(w, "TRIS", db.triangles);
  const PlaybackPrimary& p = db.primary;
  w.add("NODE", p.nodes);
  addIndices(w, "PSUO", p.firstSuccessor);
  addIndices(w, "PSUC", p.successors);
  w.addScalar("BWID", p.run.bucketWidth);
  addIndices(w, "FPBK", p.run.framesPerBucket);
  // firstEdge follows from the states' nodes; merge flags are one bit each.
  addIndices(w, "SNOD", db.graph.stateNode);
  addIndices(w, "ETGT", db.graph.edgeTarget);
  w.add("EMRG", packBits(db.graph.edgeIsMerge));
  w.add("MEAN", db.mean);
  std::vector<BasisHeader> headers;
  std::vector<uint16_t> steps;
  for (uint32_t i = 0; i < db.basisCount(); ++i) {
    const QuantizedBasis& b = db.bases[i];
    headers.push_back({b.bits, b.scale, b.offset, b.step});
    steps.push_back(uint16_t(coefficientStep(db, i)));
  }
  w.add("BASH", headers);
  w.add("BENC", encodeBases(db));
  w.add("CSTP", steps);
  w.add("CENC", encodeCoefficients(db));
  const CompressionReport& r = db.report;
  w.addScalar("REPT", ReportRecord{r.targetError, r.quantum, r.maxErrorBeforeQuantization,
                                   r.maxError, r.meanError, r.coefficientQuantum});
  w.add("SVAL", r.singularValues);
  if (db.clips.recorded()) addClipIdentityChunks(w, db.clips);
  return w;
}

ClothDatabase read(const ChunkReader& r) {
  ClothDatabase db;
  const std::string& name = r.name();
  // Version 1 stored plain bases and coefficients; nothing reads it any more (recompressing the
  // .tsg takes a minute), so it is refused by name rather than half-read.
  if (r.version() < 2)
    fail(name, ": ", kKind, " version ", r.version(), " unsupported (this build reads versions 2 ",
         "to ", kClothDatabaseVersion, "): recompress it with `throng cloth compress`");
  if (r.has("CLPI")) db.clips = readClipIdentityChunks(r);
  db.vertexCount = r.scalar<uint32_t>("VERT");
  // Every count is checked against a chunk whose bytes are in the file before anything of that
  // size is allocated: the mean holds 3 floats a vertex, so VERT cannot claim more than the file.
  const size_t rows = size_t(db.vertexCount) * 3;
  if (rows == 0) fail(name, ": the garment has no vertices");
  r.expectCount(r.require("MEAN"), rows);
  db.triangles = readIndices(r, "TRIS");
  PlaybackPrimary& p = db.primary;
  p.nodes = r.vector<PrimaryNode>("NODE");
  p.firstSuccessor = readIndices(r, "PSUO");
  p.successors = readIndices(r, "PSUC");
  p.run.bucketWidth = r.scalar<float>("BWID");
  p.run.framesPerBucket = readIndices(r, "FPBK");
  db.graph.stateNode = readIndices(r, "SNOD");
  db.graph.edgeTarget = readIndices(r, "ETGT");
  if (p.firstSuccessor.size() != p.nodes.size() + 1)
    fail(name, ": primary successor offsets do not match the nodes");
  db.graph.firstEdge.assign(1, 0u);
  for (uint32_t node : db.graph.stateNode) {
    if (node >= p.nodes.size() || p.firstSuccessor[node] > p.firstSuccessor[node + 1])
      fail(name, ": a state sits at node ", node, ", out of range (", p.nodes.size(), " nodes)");
    db.graph.firstEdge.push_back(db.graph.firstEdge.back() + p.firstSuccessor[node + 1] -
                                 p.firstSuccessor[node]);
  }
  r.expectCount(r.require("EMRG"), (db.graph.edgeTarget.size() + 7) / 8);
  std::vector<uint8_t> bits = r.vector<uint8_t>("EMRG");
  db.graph.edgeIsMerge.resize(db.graph.edgeTarget.size());
  for (size_t i = 0; i < db.graph.edgeIsMerge.size(); ++i)
    db.graph.edgeIsMerge[i] = (bits[i / 8] >> (i % 8)) & 1u;
  db.mean = r.vector<float>("MEAN");
  std::vector<BasisHeader> headers = r.vector<BasisHeader>("BASH");
  for (const BasisHeader& h : headers)
    if (h.bits != 8 && h.bits != 16)
      fail(name, ": a basis has ", h.bits, " bits, expected 8 or 16");
  r.expectCount(r.require("CSTP"), headers.size());
  std::vector<int32_t> deltas = decodeIntegerBlocks(
      r.vector<uint8_t>("BENC"), checkedProduct(rows, headers.size(), name), rows, name);
  for (size_t i = 0; i < headers.size(); ++i) {
    QuantizedBasis b;
    b.bits = uint8_t(headers[i].bits);
    b.scale = headers[i].scale;
    b.offset = headers[i].offset;
    b.step = headers[i].step;
    const int32_t largest = b.bits == 8 ? 255 : 65535;
    b.values.resize(rows);
    for (size_t k = 0; k < rows; ++k) {
      int64_t v = int64_t(deltas[i * rows + k]) + (k >= 3 ? int64_t(b.values[k - 3]) : 0);
      if (v < 0 || v > largest)
        fail(name, ": basis ", i, " decodes to ", v, ", outside its ", int(b.bits), " bits");
      b.values[k] = uint16_t(v);
    }
    db.bases.push_back(std::move(b));
  }
  const size_t S = db.graph.stateNode.size();
  db.coefficientSteps = r.vector<uint16_t>("CSTP");
  std::vector<int32_t> multiples = decodeIntegerBlocks(
      r.vector<uint8_t>("CENC"), checkedProduct(S, headers.size(), name), S, name);
  db.coefficients.resize(S * headers.size());
  for (size_t i = 0; i < headers.size(); ++i)
    for (size_t s = 0; s < S; ++s) {
      int64_t q = int64_t(multiples[i * S + s]) * db.coefficientSteps[i];
      if (q < -32767 || q > 32767)
        fail(name, ": coefficient ", i, " of state ", s, " decodes to ", q, ", outside 16 bits");
      db.coefficients[s * headers.size() + i] = int16_t(q);
    }
  ReportRecord rec = r.scalar<ReportRecord>("REPT");
  CompressionReport& rep = db.report;
  rep.targetError = rec.targetError;
  rep.quantum = rec.quantum;
  rep.maxErrorBeforeQuantization = rec.maxErrorBeforeQuantization;
  rep.maxError = rec.maxError;
  rep.meanError = rec.meanError;
  rep.coefficientQuantum = rec.coefficientQuantum;
  rep.singularValues = r.vector<float>("SVAL");
  validateDatabase(db, name);
  rep.states = db.stateCount();
  rep.vertices = db.vertexCount;
  rep.bases = db.basisCount();
  rep.bases8 = uint32_t(std::count_if(db.bases.begin(), db.bases.end(),
                                      [](const QuantizedBasis& b) { return b.bits == 8; }));
  rep.bases16 = rep.bases - rep.bases8;
  rep.rawBytes = uint64_t(rep.states) * rep.vertices * 12;
  rep.storedBytes = r.totalBytes();
  return db;
}
}  // namespace

PlaybackPrimary playbackPrimary(const PrimaryGraph& graph, float bucketWidth) {
  if (!(bucketWidth > 0.0f && bucketWidth <= 1.0f))
    fail("bucket width ", bucketWidth, ": expected (0, 1]");
  PlaybackPrimary p;
  p.nodes = graph.nodes;
  p.firstSuccessor.push_back(0);
  for (const std::vector<uint32_t>& s : graph.successors) {
    p.successors.insert(p.successors.end(), s.begin(), s.end());
    p.firstSuccessor.push_back(uint32_t(p.successors.size()));
  }
  p.run.bucketWidth = bucketWidth;
  p.run.framesPerBucket.assign(synth::speedBucketCount(bucketWidth), 0u);
  for (const PrimaryNode& n : graph.nodes) {
    if (n.clip != 0) continue;
    if (n.bucket >= p.run.framesPerBucket.size())
      fail("primary node of bucket ", n.bucket, " but a bucket width of ", bucketWidth, " gives ",
           p.run.framesPerBucket.size(), " buckets");
    p.run.framesPerBucket[n.bucket] = std::max(p.run.framesPerBucket[n.bucket], n.frame + 1);
  }
  return p;
}

void validateDatabase(const ClothDatabase& db, const std::string& name) {
  const uint32_t V = db.vertexCount, S = db.stateCount(), N = db.primary.nodeCount(),
                 B = db.basisCount();
  auto bad = [&](const auto&... what) { fail(name, ": ", what...); };
  if (V == 0) bad("the garment has no vertices");
  if (db.triangles.size() % 3 != 0)
    bad("triangle indices (", db.triangles.size(), ") are not a multiple of 3");
  for (uint32_t i : db.triangles)
    if (i >= V) bad("triangle index ", i, " out of range (", V, " vertices)");
  const PlaybackPrimary& p = db.primary;
  if (p.firstSuccessor.size() != size_t(N) + 1 || p.firstSuccessor.front() != 0 ||
      p.firstSuccessor.back() != p.successors.size())
    bad("primary successor offsets are inconsistent");
  for (size_t n = 0; n < N; ++n)
    if (p.firstSuccessor[n] > p.firstSuccessor[n + 1])
      bad("primary successor offsets decrease at node ", n);
  for (uint32_t s : p.successors)
    if (s >= N) bad("primary successor ", s, " out of range (", N, " nodes)");
  if (!(p.run.bucketWidth > 0.0f && p.run.bucketWidth <= 1.0f))
    bad("bucket width ", p.run.bucketWidth);
  if (p.run.framesPerBucket.size() != synth::speedBucketCount(p.run.bucketWidth))
    bad("frames per bucket has ", p.run.framesPerBucket.size(), " entries, the bucket width gives ",
        synth::speedBucketCount(p.run.bucketWidth));
  // Playback allocates a table of Σ F_b entries: each F_b must be what the run nodes give.
  std::vector<uint32_t> frames(p.run.framesPerBucket.size(), 0u);
  for (const PrimaryNode& n : p.nodes)
    if (n.clip == 0 && n.bucket < frames.size())
      frames[n.bucket] = std::max(frames[n.bucket], n.frame + 1);
  for (size_t b = 0; b < frames.size(); ++b)
    if (p.run.framesPerBucket[b] != frames[b])
      bad("bucket ", b, " claims ", p.run.framesPerBucket[b], " run frames, its nodes give ",
          frames[b]);
  const PlaybackGraph& g = db.graph;
  if (S == 0) bad("no cloth states");
  if (g.firstEdge.size() != size_t(S) + 1 || g.firstEdge.front() != 0 ||
      g.firstEdge.back() != g.edgeTarget.size() || g.edgeIsMerge.size() != g.edgeTarget.size())
    bad("secondary edge offsets are inconsistent");
  for (uint32_t s = 0; s < S; ++s) {
    uint32_t node = g.stateNode[s];
    if (node >= N) bad("state ", s, " sits at node ", node, ", out of range (", N, " nodes)");
    uint32_t edges = g.firstEdge[s + 1] - g.firstEdge[s];
    uint32_t successors = p.firstSuccessor[node + 1] - p.firstSuccessor[node];
    if (g.firstEdge[s] > g.firstEdge[s + 1] || edges != successors)
      bad("state ", s, " has ", edges, " edges, its primary node ", node, " has ", successors,
          " successors");
    for (uint32_t k = 0; k < edges; ++k) {
      uint32_t t = g.edgeTarget[g.firstEdge[s] + k];
      if (t >= S)
        bad("edge of state ", s, " leads to state ", t, ", out of range (", S, " states)");
      if (g.stateNode[t] != p.successors[p.firstSuccessor[node] + k])
        bad("edge ", k, " of state ", s, " leads to a state at node ", g.stateNode[t],
            ", not at successor node ", p.successors[p.firstSuccessor[node] + k]);
    }
  }
  if (db.mean.size() != size_t(V) * 3)
    bad("mean has ", db.mean.size(), " values, expected ", size_t(V) * 3);
  if (B == 0) bad("no bases");
  for (uint32_t i = 0; i < B; ++i) {
    const QuantizedBasis& b = db.bases[i];
    if (b.bits != 8 && b.bits != 16)
      bad("basis ", i, " has ", int(b.bits), " bits, expected 8 or 16");
    if (b.values.size() != size_t(V) * 3)
      bad("basis ", i, " has ", b.values.size(), " values, expected ", size_t(V) * 3);
    if (b.bits == 8 && *std::max_element(b.values.begin(), b.values.end()) > 255)
      bad("8-bit basis ", i, " exceeds 255");
  }
  if (db.coefficients.size() != size_t(S) * B)
    bad("coefficients: ", db.coefficients.size(), " values, expected ", size_t(S) * B);
  if (!db.coefficientSteps.empty()) {
    if (db.coefficientSteps.size() != B)
      bad("coefficient steps: ", db.coefficientSteps.size(), " values, expected ", B);
    for (uint32_t i = 0; i < B; ++i) {
      const int32_t step = db.coefficientSteps[i];
      if (step < 1 || step > 32767) bad("basis ", i, " has a coefficient step of ", step);
      for (uint32_t s = 0; s < S; ++s)
        if (db.coefficients[size_t(s) * B + i] % step != 0)
          bad("coefficient ", i, " of state ", s, " is not a multiple of its step ", step);
    }
  }
  for (int16_t c : db.coefficients)
    if (c < -32767) bad("a coefficient is -32768, outside [-32767, 32767]");
}

void checkClothClips(const ClothDatabase& db, const std::string& file,
                     const anim::ClipPair& crowdClips) {
  checkClipsMatch(db.clips, file, crowdClips);
}

std::vector<uint8_t> encodeClothDatabase(const ClothDatabase& db) {
  return writer(db).bytes();
}

bool isClothDatabase(std::span<const uint8_t> bytes) {
  return bytes.size() >= kMagicBytes &&
         std::memcmp(bytes.data(), kClothDatabaseMagic.data(), kMagicBytes) == 0;
}

ClothDatabase decodeClothDatabase(std::span<const uint8_t> bytes, const std::string& name) {
  return read(ChunkReader::fromBytes(std::vector<uint8_t>(bytes.begin(), bytes.end()), name,
                                     kClothDatabaseMagic, kClothDatabaseVersion, kKind));
}

void writeClothDatabase(const std::filesystem::path& path, const ClothDatabase& db) {
  writer(db).writeFileAtomic(path);
}

ClothDatabase readClothDatabase(const std::filesystem::path& path) {
  return read(ChunkReader::openFile(path, kClothDatabaseMagic, kClothDatabaseVersion, kKind));
}

}  // namespace throng::secondary
