#include "secondary/cloth_lod.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "core/error.h"

namespace throng::secondary {

namespace {
// Cluster cell per level in mean edge lengths. The splat level jumps to 16: it serves capes under
// ~24 pixels, where a dozen flat triangles show the shape and each triangle costs the splat.
constexpr float kLevelCells[kClothLevels] = {1.0f, 2.0f, 4.0f, 16.0f};

std::vector<glm::vec3> meanShape(const ClothDatabase& db) {
  std::vector<glm::vec3> p(db.vertexCount);
  for (uint32_t v = 0; v < db.vertexCount; ++v)
    p[v] = {db.mean[3 * v], db.mean[3 * v + 1], db.mean[3 * v + 2]};
  return p;
}

float meanEdgeLength(const std::vector<glm::vec3>& p, const std::vector<uint32_t>& triangles) {
  double sum = 0.0;
  size_t edges = 0;
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      sum += glm::length(p[triangles[t + e]] - p[triangles[t + (e + 1) % 3]]);
      ++edges;
    }
  return edges && sum > 0.0 ? float(sum / double(edges)) : 0.01f;
}

// One coarsening step: representatives of the finer level grouped by grid cell; each group keeps
// the member nearest its centroid (lowest index on ties). Returns member → representative.
std::vector<uint32_t> clusterStep(const std::vector<glm::vec3>& p,
                                  const std::vector<uint32_t>& reps, float cell) {
  std::map<std::tuple<int, int, int>, std::vector<uint32_t>> groups;
  for (uint32_t v : reps) {
    glm::vec3 q = glm::floor(p[v] / cell);
    groups[{int(q.x), int(q.y), int(q.z)}].push_back(v);
  }
  std::vector<uint32_t> up(p.size(), 0xFFFFFFFFu);
  for (const auto& [key, members] : groups) {
    glm::vec3 centroid(0.0f);
    for (uint32_t v : members) centroid += p[v];
    centroid /= float(members.size());
    uint32_t best = members.front();
    for (uint32_t v : members)
      if (glm::length(p[v] - centroid) < glm::length(p[best] - centroid)) best = v;
    for (uint32_t v : members) up[v] = best;
  }
  return up;
}

float basisExtent(const QuantizedBasis& b) {
  const float top = b.offset + b.step * (b.bits == 8 ? 255.0f : 65535.0f);
  return std::max(std::abs(b.offset), std::abs(top));
}
}  // namespace

ClothLod buildClothLod(const ClothDatabase& db) {
  const uint32_t V = db.vertexCount;
  THRONG_CHECK(V > 0 && db.mean.size() == size_t(V) * 3, "database without a mean shape");
  const std::vector<glm::vec3> p = meanShape(db);
  const float h0 = meanEdgeLength(p, db.triangles);

  // rep[L][v]: the level-L representative of vertex v.
  std::array<std::vector<uint32_t>, kClothLevels> rep;
  rep[0].resize(V);
  for (uint32_t v = 0; v < V; ++v) rep[0][v] = v;
  std::vector<uint32_t> reps = rep[0];
  std::vector<uint32_t> coarsest(V, 0);  // coarsest level each vertex represents
  for (uint32_t L = 1; L < kClothLevels; ++L) {
    std::vector<uint32_t> up = clusterStep(p, reps, h0 * kLevelCells[L]);
    rep[L].resize(V);
    for (uint32_t v = 0; v < V; ++v) rep[L][v] = up[rep[L - 1][v]];
    std::vector<uint32_t> next;
    for (uint32_t v : reps)
      if (up[v] == v) {
        next.push_back(v);
        coarsest[v] = L;
      }
    reps = std::move(next);
  }

  ClothLod lod;
  lod.vertexCount = V;
  lod.order.resize(V);
  for (uint32_t v = 0; v < V; ++v) lod.order[v] = v;
  std::stable_sort(lod.order.begin(), lod.order.end(),
                   [&](uint32_t a, uint32_t b) { return coarsest[a] > coarsest[b]; });
  std::vector<uint32_t> position(V);
  for (uint32_t k = 0; k < V; ++k) position[lod.order[k]] = k;
  const uint32_t b = db.basisCount();
  for (uint32_t L = 0; L < kClothLevels; ++L) {
    lod.levelVertices.push_back(uint32_t(
        std::count_if(coarsest.begin(), coarsest.end(), [&](uint32_t c) { return c >= L; })));
    uint32_t bases = L == 0 ? b : std::max(std::min(b, 32u >> L), (b + (1u << L) - 1) >> L);
    lod.levelBases.push_back(bases);
    lod.firstIndex.push_back(uint32_t(lod.indices.size()));
    std::set<std::array<uint32_t, 3>> seen;
    for (size_t t = 0; t + 2 < db.triangles.size(); t += 3) {
      std::array<uint32_t, 3> tri{position[rep[L][db.triangles[t]]],
                                  position[rep[L][db.triangles[t + 1]]],
                                  position[rep[L][db.triangles[t + 2]]]};
      if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
      std::array<uint32_t, 3> key = tri;
      std::sort(key.begin(), key.end());
      if (!seen.insert(key).second) continue;
      lod.indices.insert(lod.indices.end(), tri.begin(), tri.end());
    }
    lod.indexCount.push_back(uint32_t(lod.indices.size()) - lod.firstIndex.back());
  }
  lod.remap.resize(size_t(kClothLevels) * V);
  for (uint32_t d = 0; d < kClothLevels; ++d)
    for (uint32_t k = 0; k < V; ++k) lod.remap[size_t(d) * V + k] = position[rep[d][lod.order[k]]];

  for (const glm::vec3& q : p) lod.center += q;
  lod.center /= float(V);
  for (const glm::vec3& q : p)
    lod.shapeRadius = std::max(lod.shapeRadius, glm::length(q - lod.center));
  // Largest displacement from the mean: max over states of Σ_i |c'_si| · max_r |B'_ir| (per axis).
  std::vector<float> extent(b);
  for (uint32_t i = 0; i < b; ++i) extent[i] = basisExtent(db.bases[i]);
  float displacement = 0.0f;
  for (uint32_t s = 0; s < db.stateCount(); ++s) {
    float sum = 0.0f;
    for (uint32_t i = 0; i < b; ++i)
      sum += std::abs(dequantizeCoefficient(db.coefficients[size_t(s) * b + i])) * extent[i];
    displacement = std::max(displacement, sum);
  }
  lod.radius = lod.shapeRadius + std::sqrt(3.0f) * displacement;
  return lod;
}

}  // namespace throng::secondary
