#pragma once
// Compression of explored cloth states (Kim et al. 2013, §6): the data matrix D (3V rows ×
// S states, character-space positions, the mean of each row subtracted) is factored D ≈ B C by
// a randomized SVD that streams the states (memory stays bounded), b bases are kept (given, or
// the fewest whose largest vertex error is at most a target), each basis is rescaled by
// m_i = max_j |C_ij| so coefficients lie in [−1, 1], bases are quantized to 8 or 16 bits at a
// length quantum and coefficients to 16 bits, in steps of the basis' coefficient step (so one
// step moves no vertex more than the coefficient quantum); the file entropy-codes both.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "secondary/cloth_database.h"

namespace throng::secondary {

// The cloth states to compress, read by index; `positions` must be deterministic and safe to
// call from several threads at once (the SVD reads blocks in parallel, several times).
struct ClothFrames {
  uint32_t stateCount = 0;
  uint32_t vertexCount = 0;
  std::function<void(uint32_t state, std::span<glm::vec3> positions)> positions;
};

struct CompressOptions {
  uint32_t bases = 0;          // 0: the fewest meeting targetError, at most maxBases
  float targetError = 0.002f;  // metres, largest vertex error before quantization
  uint32_t maxBases = 96;
  float quantum = 300e-6f;  // metres: a basis goes to 8 bits when its range × m_i / 255 ≤ quantum
  // Metres: the coefficient step of basis i is the largest multiple of 1/32767 that moves no
  // vertex more than this; 0 keeps every coefficient at full 16-bit precision (so the round trip
  // stays within the quantum; `cloth compress` passes 1 mm).
  float coefficientQuantum = 0.0f;
  // > 0 and bases == 0: at most the bases that keep raw / stored bytes at least this (the file's
  // bytes, as reported); the error target still picks fewer when it can.
  double minRatio = 0.0;
  // When the bases miss targetError: passes of reweighting towards the worst states
  // (reweightedSvd in cloth_compress.cpp; `cloth compress` passes 1).
  uint32_t reweightPasses = 0;
  // > 0: states still above targetError after quantization get up to this many coefficient steps
  // chosen for their largest error (cloth_refine.h; `cloth compress` passes 4096).
  uint32_t refineSteps = 0;
  uint32_t oversampling = 10;
  uint32_t powerIterations = 1;
  uint64_t seed = 1;
  unsigned threads = 0;    // 0: all cores
  ClipPairIdentity clips;  // recorded in the database (what the frames were simulated on)
  std::function<void(const char* stage)> progress;  // optional: called as each stage starts
};

// The whole pipeline: mean, SVD, basis count, rescaling, quantization, and the report (raw vs
// stored bytes, largest error before and after quantization). Throws Error on bad options or an
// inconsistent graph (validateDatabase).
ClothDatabase compressCloth(const ClothFrames& frames, std::vector<uint32_t> triangles,
                            PlaybackPrimary primary, PlaybackGraph graph,
                            const CompressOptions& options);

// Basis i rescaled by m_i and quantized: 8 bits when range(basis × m_i) / 255 ≤ quantum, else 16.
QuantizedBasis quantizeBasis(std::span<const float> unitBasis, float scale, float quantum);
// The coefficient step of a quantized basis: the largest k (1 … 32767) such that k / 32767 times
// the basis' largest vertex displacement is at most `coefficientQuantum` (1 when that is 0).
uint16_t coefficientStepFor(const QuantizedBasis& basis, float coefficientQuantum);
// C_ij / m_i on 16 bits as a multiple of `step` (the nearest one inside [−32767, 32767]).
int16_t quantizeCoefficientInSteps(float unitCoefficient, uint16_t step);

// Largest and mean per-vertex distance between the frames and their decoded states.
struct ReconstructionError {
  float max = 0.0f;
  float mean = 0.0f;
};
ReconstructionError reconstructionError(const ClothFrames& frames, const ClothDatabase& db,
                                        unsigned threads = 0);

// `throng cloth info` for a .tsc file: states, primary nodes, bases (8/16 bits), raw and stored
// bytes, ratio, errors in metres. Throws Error naming the file when it is not a valid .tsc.
nlohmann::json clothCompressedInfo(const std::filesystem::path& path);
nlohmann::json compressionReportJson(const ClothDatabase& db);

// Every number in `j` that is exactly a float (the reports' metres are floats) rewritten as that
// float's shortest decimal, 0.05 rather than 0.05000000074505806; other numbers are kept.
void writeFloatsShort(nlohmann::json& j);

}  // namespace throng::secondary
