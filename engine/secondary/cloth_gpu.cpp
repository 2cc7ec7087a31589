#include "secondary/cloth_gpu.h"

#include <algorithm>
#include <cstring>

#include "core/error.h"
#include "secondary/cloth_gpu_types.h"
#include "shaders/cloth_bindings.h"

namespace throng::secondary {

using gpu_types::ClothLevel;

std::vector<uint32_t> clothGraphTable(const ClothDatabase& db, const PlaybackTables& t) {
  std::vector<uint32_t> merges(db.graph.edgeIsMerge.begin(), db.graph.edgeIsMerge.end());
  const std::vector<uint32_t>* tables[kClothGraphTables] = {&t.runFirst,
                                                            &t.runNodes,
                                                            &db.primary.firstSuccessor,
                                                            &db.primary.successors,
                                                            &db.graph.firstEdge,
                                                            &db.graph.edgeTarget,
                                                            &merges,
                                                            &t.firstStateAtNode,
                                                            &t.naturalSuccessor};
  std::vector<uint32_t> words(kClothGraphTables, 0u);
  for (uint32_t i = 0; i < kClothGraphTables; ++i) {
    words[i] = uint32_t(words.size());
    words.insert(words.end(), tables[i]->begin(), tables[i]->end());
  }
  return words;
}

DecodedBases permutedBases(const DecodedBases& d, const ClothLod& lod) {
  DecodedBases p = d;
  const size_t rows = size_t(d.vertexCount) * 3;
  for (uint32_t k = 0; k < d.vertexCount; ++k)
    for (uint32_t a = 0; a < 3; ++a) {
      const size_t from = size_t(lod.order[k]) * 3 + a, to = size_t(k) * 3 + a;
      p.mean[to] = d.mean[from];
      for (uint32_t i = 0; i < d.basisCount; ++i) p.bases[i * rows + to] = d.bases[i * rows + from];
    }
  return p;
}

namespace {
// Rows as vec4s: `rows` floats per block, `blocks` blocks, each zero padded to whole vec4s.
std::vector<float> vec4Rows(const std::vector<float>& values, size_t rows, size_t blocks,
                            uint32_t rowVectors) {
  std::vector<float> out(size_t(rowVectors) * 4 * blocks, 0.0f);
  for (size_t b = 0; b < blocks; ++b)
    std::copy(values.begin() + long(b * rows), values.begin() + long((b + 1) * rows),
              out.begin() + long(b * rowVectors * 4));
  return out;
}
}  // namespace

ClothGpuData uploadCloth(const gpu::Context& context, const ClothDatabase& db) {
  validateDatabase(db, "cloth database");
  ClothGpuData g;
  g.vertexCount = db.vertexCount;
  g.basisCount = db.basisCount();
  g.stateCount = db.stateCount();
  g.bucketWidth = db.primary.run.bucketWidth;
  g.rowVectors = (3 * g.vertexCount + 3) / 4;
  g.tables = makePlaybackTables(db);
  g.bucketCount = g.tables.bucketCount;
  g.lod = buildClothLod(db);
  DecodedBases decoded = permutedBases(dequantize(db), g.lod);
  const size_t rows = size_t(g.vertexCount) * 3;
  // The decode pass reads whole blocks of kClothDecodeRows rows: pad the ends.
  std::vector<float> mean = vec4Rows(decoded.mean, rows, 1, g.rowVectors);
  std::vector<float> bases = vec4Rows(decoded.bases, rows, g.basisCount, g.rowVectors);
  mean.resize(mean.size() + 4 * gpu_types::kClothDecodeRows, 0.0f);
  bases.resize(bases.size() + 4 * gpu_types::kClothDecodeRows, 0.0f);
  g.mean = gpu::makeStorageBuffer<float>(context, mean);
  g.bases = gpu::makeStorageBuffer<float>(context, bases);
  g.coefficients = gpu::makeStorageBuffer<float>(context, decoded.coefficients);
  std::vector<ClothLevel> levels;
  for (uint32_t L = 0; L < kClothLevels; ++L)
    levels.push_back(
        {g.lod.levelVertices[L], g.lod.levelBases[L], g.lod.firstIndex[L], g.lod.indexCount[L]});
  g.levels = gpu::makeStorageBuffer<ClothLevel>(context, levels);
  g.graph = gpu::makeStorageBuffer<uint32_t>(context, clothGraphTable(db, g.tables));
  g.indices = gpu::makeStorageBuffer<uint32_t>(context, g.lod.indices, gpu::MemoryUse::DeviceLocal,
                                               VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  g.remap = gpu::makeStorageBuffer<uint32_t>(context, g.lod.remap);
  // The splat bakes the splat level's mesh in: vertex count, triangle count, then the indices.
  const uint32_t splatLevel = gpu_types::kClothSplatLevel;
  const uint32_t splatTriangles = g.lod.indexCount[splatLevel] / 3;
  if (context.info().int64Atomics &&
      g.lod.levelVertices[splatLevel] <= gpu_types::kClothSplatMaxVertices && splatTriangles > 0 &&
      splatTriangles <= gpu_types::kClothSplatMaxTriangles) {
    std::vector<uint32_t> constants(
        gpu_types::kClothSplatConstantIndices + 3 * gpu_types::kClothSplatMaxTriangles, 0u);
    constants[gpu_types::kClothSplatConstantVertices] = g.lod.levelVertices[splatLevel];
    constants[gpu_types::kClothSplatConstantTriangles] = splatTriangles;
    for (uint32_t i = 0; i < 3 * splatTriangles; ++i)
      constants[gpu_types::kClothSplatConstantIndices + i] =
          g.lod.indices[g.lod.firstIndex[splatLevel] + i];
    g.splat = gpu::ComputeProgram(context, "cloth_splat.comp", constants);
  }
  const VkDeviceSize largest = std::max({g.bases.size(), g.coefficients.size(), g.graph.size()});
  if (largest > context.info().maxStorageBufferRange)
    fail("cloth database: a buffer of ", largest,
         " bytes exceeds the device's storage-binding limit of ",
         context.info().maxStorageBufferRange, " bytes");
  return g;
}

ClothCrowdBuffers makeClothCrowdBuffers(const gpu::Context& context, const ClothGpuData& cloth,
                                        uint32_t characterCount, uint64_t fineBudgetBytes) {
  ClothCrowdBuffers b;
  b.characterCount = characterCount;
  const uint64_t limitVertices = context.info().maxStorageBufferRange / 12;
  const uint32_t coarse = std::max(4u, slotVertices(cloth.lod, kClothLevels - 1));
  // A state and a blend source per character at most; beyond what one pool binding holds at the
  // coarsest level, further states are not decoded (their characters show a stale slot).
  uint64_t maxUsed = std::min<uint64_t>(cloth.stateCount, 2ull * std::max(1u, characterCount));
  maxUsed = std::min<uint64_t>(maxUsed, limitVertices / 2 / coarse);
  b.maxUsedStates = uint32_t(std::max<uint64_t>(1, maxUsed));
  b.reservedVertices = b.maxUsedStates * coarse;
  b.fineBudget =
      uint32_t(std::min<uint64_t>(fineBudgetBytes / 12, limitVertices - b.reservedVertices)) & ~3u;
  auto device = [&](VkDeviceSize bytes, VkBufferUsageFlags extra = 0) {
    return gpu::Buffer(context, std::max<VkDeviceSize>(bytes, 16), gpu::kStorageUsage | extra,
                       gpu::MemoryUse::DeviceLocal);
  };
  std::vector<ClothCharacter> none(std::max(1u, characterCount), noClothCharacter());
  b.characters = gpu::makeStorageBuffer<ClothCharacter>(context, none);
  b.counters = gpu::Buffer(context, sizeof(gpu_types::ClothCounters), gpu::kStorageUsage,
                           gpu::MemoryUse::HostVisible);
  std::memset(b.counters.mapped(), 0, sizeof(gpu_types::ClothCounters));
  b.stateLevel = device(VkDeviceSize(cloth.stateCount) * 4);
  b.usedStates = device(VkDeviceSize(b.maxUsedStates) * 4);
  b.levelLists = device(VkDeviceSize(kClothLevels) * b.maxUsedStates * 4);
  // Slots start at (0, coarsest): a state never decoded reads valid pool memory.
  std::vector<glm::uvec2> slots(cloth.stateCount, glm::uvec2(0u, kClothLevels - 1));
  b.slots = gpu::makeStorageBuffer<glm::uvec2>(context, slots);
  b.pool = device(VkDeviceSize(b.reservedVertices + uint64_t(b.fineBudget)) * 12);
  b.draws = gpu::Buffer(context, kClothLevels * 20,
                        gpu::kStorageUsage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                        gpu::MemoryUse::HostVisible);
  std::memset(b.draws.mapped(), 0, kClothLevels * 20);
  b.drawList = device(VkDeviceSize(kClothLevels) * characterCount * 4);
  b.dispatchArgs = device(12 * (2 + kClothLevels), VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
  return b;
}

ClothStats readClothStats(const ClothCrowdBuffers& buffers) {
  gpu_types::ClothCounters c;
  std::memcpy(&c, buffers.counters.mapped(), sizeof(c));
  ClothStats stats{std::min(c.usedStates, buffers.maxUsedStates),
                   c.demoted,
                   std::min(c.fineCursor, buffers.fineBudget),
                   {}};
  const uint32_t* draws = static_cast<const uint32_t*>(buffers.draws.mapped());
  for (uint32_t L = 0; L < kClothLevels; ++L) stats.capes[L] = draws[5 * L + 1];
  return stats;
}

namespace {
// Rows the decode pass shares across a subgroup per round: min(subgroup size, kClothDecodeRows).
std::vector<uint32_t> decodeSpecialization(const gpu::Context& context) {
  const gpu::DeviceInfo& info = context.info();
  const VkSubgroupFeatureFlags needed =
      VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_SHUFFLE_BIT;
  if ((info.computeSubgroupOperations & needed) != needed || info.subgroupSize < 1)
    fail("the cloth decode pass needs compute subgroups with shuffle; ", info.name, " has ",
         info.subgroupSize, " lanes, compute operations 0x", std::hex,
         info.computeSubgroupOperations);
  std::vector<uint32_t> constants(gpu_types::kClothDecodeConstantLanes + 1);
  constants[gpu_types::kClothDecodeConstantLanes] =
      std::min(info.subgroupSize, gpu_types::kClothDecodeRows);
  return constants;
}
}  // namespace

ClothPrograms::ClothPrograms(const gpu::Context& context, VkFormat colorFormat,
                             VkFormat depthFormat)
    : advance(context, "cloth_advance.comp"),
      mark(context, "cloth_mark.comp"),
      args(context, "cloth_args.comp"),
      classify(context, "cloth_classify.comp"),
      decode(context, "cloth_decode.comp", decodeSpecialization(context)) {
  gpu::GraphicsPipelineDesc desc;
  desc.vertexShader = "cloth.vert";
  desc.fragmentShader = "cloth.frag";
  desc.colorFormat = colorFormat;
  desc.depthFormat = depthFormat;
  desc.cullMode = VK_CULL_MODE_NONE;  // two-sided
  desc.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  draw = gpu::GraphicsProgram(context, desc);
}

}  // namespace throng::secondary
