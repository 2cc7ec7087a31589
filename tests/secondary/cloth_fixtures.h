#pragma once
// Synthetic inputs for the compression and playback suites, independent of the simulator and the
// exploration: a small run graph (buckets × frames, cycle ends joining every bucket), a secondary
// graph with a few states per node and some merge edges, a cape-like grid mesh, and low-rank cloth
// frames or a database with random bases.
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "core/rng.h"
#include "secondary/cloth_database.h"
#include "secondary/offline/cloth_compress.h"

namespace throng::test {

// Nodes (0, b, f) for f < framesPerBucket[b]; edges (b, f) → (b, f + 1) and (b, F_b − 1) → (b', 0)
// for every b' (increasing), like buildRunGraph.
inline secondary::PlaybackPrimary syntheticPrimary(float bucketWidth,
                                                   const std::vector<uint32_t>& framesPerBucket) {
  secondary::PlaybackPrimary p;
  p.run.bucketWidth = bucketWidth;
  p.run.framesPerBucket = framesPerBucket;
  std::vector<uint32_t> first;
  for (uint32_t b = 0; b < framesPerBucket.size(); ++b) {
    first.push_back(uint32_t(p.nodes.size()));
    for (uint32_t f = 0; f < framesPerBucket[b]; ++f) p.nodes.push_back({0u, b, f});
  }
  p.firstSuccessor.push_back(0);
  for (const secondary::PrimaryNode& n : p.nodes) {
    if (n.frame + 1 < framesPerBucket[n.bucket]) {
      p.successors.push_back(first[n.bucket] + n.frame + 1);
    } else {
      for (uint32_t b = 0; b < framesPerBucket.size(); ++b) p.successors.push_back(first[b]);
    }
    p.firstSuccessor.push_back(uint32_t(p.successors.size()));
  }
  return p;
}

// `copies` states per node (state = node · copies + copy); along successor k a state goes to copy
// (copy + k) % copies of the successor node, and that edge is a merge when the copy changes.
inline secondary::PlaybackGraph syntheticGraph(const secondary::PlaybackPrimary& p,
                                               uint32_t copies) {
  secondary::PlaybackGraph g;
  g.firstEdge.push_back(0);
  for (uint32_t n = 0; n < p.nodeCount(); ++n) {
    for (uint32_t c = 0; c < copies; ++c) {
      g.stateNode.push_back(n);
      for (uint32_t e = p.firstSuccessor[n]; e < p.firstSuccessor[n + 1]; ++e) {
        uint32_t k = e - p.firstSuccessor[n];
        uint32_t target = (c + k) % copies;
        g.edgeTarget.push_back(p.successors[e] * copies + target);
        g.edgeIsMerge.push_back(target != c ? 1 : 0);
      }
      g.firstEdge.push_back(uint32_t(g.edgeTarget.size()));
    }
  }
  return g;
}

// A cols × rows grid hanging in the x/y plane behind the character (character space), two
// triangles per cell.
struct GridMesh {
  uint32_t cols = 0, rows = 0;
  std::vector<glm::vec3> rest;
  std::vector<uint32_t> triangles;
};
inline GridMesh gridMesh(uint32_t cols, uint32_t rows, float width = 0.5f, float height = 0.8f) {
  GridMesh m{cols, rows, {}, {}};
  for (uint32_t r = 0; r < rows; ++r)
    for (uint32_t c = 0; c < cols; ++c)
      m.rest.push_back({width * (float(c) / float(cols - 1) - 0.5f),
                        1.5f - height * float(r) / float(rows - 1), -0.15f});
  for (uint32_t r = 0; r + 1 < rows; ++r)
    for (uint32_t c = 0; c + 1 < cols; ++c) {
      uint32_t i = r * cols + c;
      m.triangles.insert(m.triangles.end(), {i, i + cols, i + 1, i + 1, i + cols, i + cols + 1});
    }
  return m;
}

// Smooth low-rank motion: rest + Σ_k amplitude_k · sin(frequency_k · s + k) · mode_k(v), with
// smooth modes of unit maximum; exactly rank `amplitudes.size()` about the mean.
struct LowRankFrames {
  GridMesh mesh;
  std::vector<float> amplitudes;
  std::vector<glm::vec3> mode(uint32_t k) const {
    std::vector<glm::vec3> m(mesh.rest.size());
    for (size_t v = 0; v < m.size(); ++v) {
      float u = float(v % mesh.cols) / float(mesh.cols - 1),
            t = float(v / mesh.cols) / float(mesh.rows - 1);
      float a = std::sin(3.1f * (k + 1) * u + 0.7f * k) * t, b = std::cos(2.3f * (k + 1) * t) * t;
      m[v] = glm::vec3(a, 0.5f * b * a, b) * (1.0f / 1.2f);
    }
    return m;
  }
  secondary::ClothFrames frames(uint32_t states) const {
    std::vector<std::vector<glm::vec3>> modes;
    for (uint32_t k = 0; k < amplitudes.size(); ++k) modes.push_back(mode(k));
    secondary::ClothFrames f;
    f.stateCount = states;
    f.vertexCount = uint32_t(mesh.rest.size());
    f.positions = [rest = mesh.rest, modes, amps = amplitudes](uint32_t s,
                                                               std::span<glm::vec3> out) {
      for (size_t v = 0; v < out.size(); ++v) out[v] = rest[v];
      for (size_t k = 0; k < modes.size(); ++k) {
        float a = amps[k] * std::sin(0.37f * float(k + 1) * float(s) + float(k));
        for (size_t v = 0; v < out.size(); ++v) out[v] += a * modes[k][v];
      }
    };
    return f;
  }
};

// A database with random quantized bases and coefficients (for playback tests: no compression).
inline secondary::ClothDatabase randomDatabase(const secondary::PlaybackPrimary& p,
                                               const secondary::PlaybackGraph& g,
                                               const GridMesh& mesh, uint32_t bases,
                                               uint64_t seed) {
  Rng rng(seed);
  secondary::ClothDatabase db;
  db.vertexCount = uint32_t(mesh.rest.size());
  db.triangles = mesh.triangles;
  db.primary = p;
  db.graph = g;
  for (const glm::vec3& r : mesh.rest) db.mean.insert(db.mean.end(), {r.x, r.y, r.z});
  for (uint32_t i = 0; i < bases; ++i) {
    secondary::QuantizedBasis b;
    b.bits = i % 3 == 2 ? 8 : 16;
    b.scale = 0.2f / float(i + 1);
    b.offset = -b.scale;
    b.step = 2.0f * b.scale / (b.bits == 8 ? 255.0f : 65535.0f);
    for (uint32_t r = 0; r < db.vertexCount * 3; ++r)
      b.values.push_back(uint16_t(rng.next() % (b.bits == 8 ? 256u : 65536u)));
    db.bases.push_back(std::move(b));
  }
  for (uint32_t s = 0; s < g.stateCount() * bases; ++s)
    db.coefficients.push_back(int16_t(int(rng.next() % 65535u) - 32767));
  return db;
}

}  // namespace throng::test
