#pragma once
// The compressed secondary-motion database (.tsc): what playback needs and nothing more — the
// garment's triangles, the primary graph's nodes and edges with the run-graph parameters that map
// a character's (speed weight, phase) to a node, the secondary graph's edges, and the cloth
// states as mean + quantized bases × quantized coefficients (Kim et al. 2013, §6). In the file
// (version 2) bases and coefficients are entropy-coded (cloth_entropy.h); in memory they are the
// plain 8/16-bit values and 16-bit coefficients playback reads.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "secondary/clip_identity.h"
#include "secondary/secondary_types.h"

namespace throng::secondary {

constexpr uint32_t kNoNode = 0xFFFFFFFFu;

// How the crowd's run cycle maps onto primary nodes: node (clip 0, bucket b, frame f) with
// b = synth::speedBucket(w, bucketWidth) and f = min(floor(phase · F_b), F_b − 1).
struct RunGraphParams {
  float bucketWidth = 0.05f;
  std::vector<uint32_t> framesPerBucket;  // F_b; 0 where the graph has no node of that bucket
};

// The primary graph without poses: nodes and successor lists (CSR, same order as
// PrimaryGraph::successors, so successor k of a node is edge k of each of its cloth states).
struct PlaybackPrimary {
  std::vector<PrimaryNode> nodes;
  std::vector<uint32_t> firstSuccessor;  // nodes + 1
  std::vector<uint32_t> successors;
  RunGraphParams run;
  uint32_t nodeCount() const { return uint32_t(nodes.size()); }
};
PlaybackPrimary playbackPrimary(const PrimaryGraph& graph, float bucketWidth);

// Basis i after rescaling by m_i = max_j |C_ij|: value r = offset + q_r · step, q_r on `bits` bits.
struct QuantizedBasis {
  uint8_t bits = 16;
  float scale = 1.0f;  // m_i (kept for reports: the basis' unit vector is values / m_i)
  float offset = 0.0f;
  float step = 0.0f;
  std::vector<uint16_t> values;  // 3V, row 3v + axis; < 256 when bits == 8
  float value(size_t row) const { return offset + float(values[row]) * step; }
};

// Coefficients are C_ij / m_i ∈ [−1, 1] on 16 bits.
constexpr float kCoefficientScale = 32767.0f;
inline int16_t quantizeCoefficient(float c) {
  float q = c * kCoefficientScale;
  q = q < -kCoefficientScale ? -kCoefficientScale : (q > kCoefficientScale ? kCoefficientScale : q);
  return int16_t(q < 0.0f ? q - 0.5f : q + 0.5f);
}
inline float dequantizeCoefficient(int16_t q) {
  return float(q) / kCoefficientScale;
}

struct CompressionReport {
  uint32_t states = 0, vertices = 0, bases = 0;
  uint32_t bases8 = 0, bases16 = 0;
  uint64_t rawBytes = 0;                    // states × vertices × 3 × 4 (float32 positions)
  uint64_t storedBytes = 0;                 // the whole .tsc file
  float targetError = 0.0f;                 // metres, before quantization (0: bases were given)
  float quantum = 0.0f;                     // metres
  float coefficientQuantum = 0.0f;          // metres: largest vertex move of one coefficient step
  float maxErrorBeforeQuantization = 0.0f;  // metres, L∞ over states and vertices
  float maxError = 0.0f;                    // metres, after quantization
  float meanError = 0.0f;                   // metres, mean per-vertex distance after quantization
  std::vector<float> singularValues;        // of the first bases (decreasing)
  // Coefficient refinement (compression only, not stored): states above the target after
  // quantization, states changed, steps taken.
  uint32_t statesAboveTarget = 0, statesRefined = 0;
  uint64_t refineSteps = 0;
  double ratio() const { return storedBytes ? double(rawBytes) / double(storedBytes) : 0.0; }
};

struct ClothDatabase {
  uint32_t vertexCount = 0;
  std::vector<uint32_t> triangles;  // 3 per triangle
  PlaybackPrimary primary;
  PlaybackGraph graph;
  std::vector<float> mean;  // 3V
  std::vector<QuantizedBasis> bases;
  std::vector<int16_t> coefficients;  // states × bases, state-major
  // Per basis: its coefficients are multiples of this step (a coarser coefficient quantum for
  // bases whose motion is small: the multiples entropy-code to fewer bits). Empty: all 1.
  std::vector<uint16_t> coefficientSteps;
  // The skeleton and clip pair the capes were simulated on; not recorded: the built-in run.
  ClipPairIdentity clips;
  CompressionReport report;
  uint32_t stateCount() const { return graph.stateCount(); }
  uint32_t basisCount() const { return uint32_t(bases.size()); }
};

// Throws Error naming `sourceName` and the first inconsistency (sizes, indices, edge counts that
// do not match the successor counts, bits not 8 or 16, quantized values out of range).
void validateDatabase(const ClothDatabase& db, const std::string& sourceName);

// A versioned chunked binary file (binary_io.h, magic kClothDatabaseMagic) with a checksum;
// decode throws Error naming the source on a bad magic, version (version 1 files, with plain
// bases and coefficients, are refused: recompress them), truncation, checksum or content.
// Version 3 adds the clip identity (clip_identity.h); version 2 files are read as made for the
// built-in run. write is atomic.
constexpr std::string_view kClothDatabaseMagic = "THRNGTSC";
constexpr uint32_t kClothDatabaseVersion = 3;
// Throws Error naming `file` and both pairs when the database was made for another skeleton or
// other clips than `crowdClips` (what playback would show as a floating cape).
void checkClothClips(const ClothDatabase& db, const std::string& file,
                     const anim::ClipPair& crowdClips);
std::vector<uint8_t> encodeClothDatabase(const ClothDatabase& db);
ClothDatabase decodeClothDatabase(std::span<const uint8_t> bytes, const std::string& sourceName);
void writeClothDatabase(const std::filesystem::path& path, const ClothDatabase& db);
ClothDatabase readClothDatabase(const std::filesystem::path& path);
// True when the bytes start with the .tsc magic (for `cloth info`'s dispatch).
bool isClothDatabase(std::span<const uint8_t> bytes);

}  // namespace throng::secondary
