#include "gpu/spirv_reflect.h"

#include <algorithm>
#include <unordered_map>

#include "core/error.h"

namespace throng::gpu {
namespace {

// SPIR-V opcodes, decorations and storage classes used here (SPIR-V spec, section 3).
// clang-format off
enum Op : uint32_t {
  OpEntryPoint = 15, OpExecutionMode = 16, OpTypeInt = 21, OpTypeFloat = 22, OpTypeVector = 23,
  OpTypeMatrix = 24, OpTypeImage = 25, OpTypeSampler = 26, OpTypeSampledImage = 27,
  OpTypeArray = 28, OpTypeRuntimeArray = 29, OpTypeStruct = 30, OpTypePointer = 32,
  OpConstant = 43, OpVariable = 59, OpDecorate = 71, OpMemberDecorate = 72,
};
enum Decoration : uint32_t {
  DecBlock = 2, DecBufferBlock = 3, DecArrayStride = 6, DecMatrixStride = 7, DecBinding = 33,
  DecDescriptorSet = 34, DecOffset = 35,
};
enum StorageClass : uint32_t { UniformConstant = 0, Uniform = 2, PushConstant = 9, StorageBuffer = 12 };
// clang-format on
constexpr uint32_t kExecutionModeLocalSize = 17;
constexpr uint32_t kDimBuffer = 5;

struct Id {
  uint32_t opcode = 0;
  uint32_t typeId = 0;  // pointee for pointers, element for arrays/vectors/matrices
  uint32_t storageClass = 0;
  uint32_t width = 0;     // scalars: bits; vectors/matrices: component/column count
  uint32_t sampled = 0;   // images: 1 sampled, 2 storage
  uint32_t dim = 0;       // images: SPIR-V Dim (kDimBuffer for texel buffers)
  uint32_t constant = 0;  // OpConstant value
  uint32_t lengthId = 0;  // arrays
  uint32_t binding = UINT32_MAX, set = UINT32_MAX;
  uint32_t arrayStride = 0;
  bool block = false, bufferBlock = false;
  std::vector<uint32_t> members;
  std::vector<uint32_t> memberOffsets, memberMatrixStrides;
};

uint32_t typeSize(const std::unordered_map<uint32_t, Id>& ids, uint32_t typeId,
                  uint32_t matrixStride);

uint32_t structSize(const std::unordered_map<uint32_t, Id>& ids, const Id& s) {
  uint32_t size = 0;
  for (size_t m = 0; m < s.members.size(); ++m) {
    uint32_t offset = m < s.memberOffsets.size() ? s.memberOffsets[m] : 0;
    uint32_t stride = m < s.memberMatrixStrides.size() ? s.memberMatrixStrides[m] : 0;
    size = std::max(size, offset + typeSize(ids, s.members[m], stride));
  }
  return size;
}

uint32_t typeSize(const std::unordered_map<uint32_t, Id>& ids, uint32_t typeId,
                  uint32_t matrixStride) {
  auto it = ids.find(typeId);
  if (it == ids.end()) return 0;
  const Id& t = it->second;
  switch (t.opcode) {
    case OpTypeInt:
    case OpTypeFloat:
      return t.width / 8;
    case OpTypeVector:
      return t.width * typeSize(ids, t.typeId, 0);
    case OpTypeMatrix:
      return t.width * (matrixStride ? matrixStride : typeSize(ids, t.typeId, 0));
    case OpTypeArray: {
      auto len = ids.find(t.lengthId);
      uint32_t count = len == ids.end() ? 0 : len->second.constant;
      return count * (t.arrayStride ? t.arrayStride : typeSize(ids, t.typeId, 0));
    }
    case OpTypeStruct:
      return structSize(ids, t);
    default:
      return 0;
  }
}

VkDescriptorType descriptorType(const std::unordered_map<uint32_t, Id>& ids, const Id& pointee,
                                uint32_t storageClass) {
  if (storageClass == StorageBuffer) return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  if (storageClass == Uniform) {
    return pointee.bufferBlock ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER
                               : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  }
  const Id* t = &pointee;
  if (t->opcode == OpTypeArray || t->opcode == OpTypeRuntimeArray) t = &ids.at(t->typeId);
  switch (t->opcode) {
    case OpTypeSampledImage:
      return ids.at(t->typeId).dim == kDimBuffer ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
                                                 : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    case OpTypeSampler:
      return VK_DESCRIPTOR_TYPE_SAMPLER;
    case OpTypeImage:
      if (t->dim == kDimBuffer)
        return t->sampled == 2 ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER
                               : VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
      return t->sampled == 2 ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    default:
      return VK_DESCRIPTOR_TYPE_MAX_ENUM;
  }
}

// A type declaration (result id in word 1): the fields the layout needs.
void recordType(Id& t, uint32_t opcode, const uint32_t* w, uint32_t count) {
  t.opcode = opcode;
  switch (opcode) {
    case OpTypeInt:
    case OpTypeFloat:
      t.width = w[2];
      break;
    case OpTypeVector:
    case OpTypeMatrix:
      t.typeId = w[2];
      t.width = w[3];
      break;
    case OpTypeImage:
      t.dim = w[3];
      t.sampled = w[7];
      break;
    case OpTypeSampledImage:
    case OpTypeRuntimeArray:
      t.typeId = w[2];
      break;
    case OpTypeArray:
      t.typeId = w[2];
      t.lengthId = w[3];
      break;
    case OpTypeStruct:
      t.members.assign(w + 2, w + count);
      break;
    case OpTypePointer:
      t.storageClass = w[2];
      t.typeId = w[3];
      break;
    default:
      break;
  }
}

}  // namespace

ShaderReflection reflectSpirv(std::span<const uint32_t> words, const std::string& shaderName) {
  if (words.size() < 5 || words[0] != 0x07230203u)
    fail(shaderName, ": not SPIR-V (bad magic number)");
  ShaderReflection out;
  std::unordered_map<uint32_t, Id> ids;
  std::vector<uint32_t> variables;
  size_t i = 5;
  while (i < words.size()) {
    uint32_t opcode = words[i] & 0xFFFFu;
    uint32_t count = words[i] >> 16;
    if (count == 0 || i + count > words.size()) fail(shaderName, ": truncated SPIR-V at word ", i);
    const uint32_t* w = &words[i];
    switch (opcode) {
      case OpEntryPoint:
        out.stage = w[1] == 0   ? VK_SHADER_STAGE_VERTEX_BIT
                    : w[1] == 4 ? VK_SHADER_STAGE_FRAGMENT_BIT
                                : VK_SHADER_STAGE_COMPUTE_BIT;
        break;
      case OpExecutionMode:
        if (w[2] == kExecutionModeLocalSize && count >= 6) {
          out.localSize[0] = w[3];
          out.localSize[1] = w[4];
          out.localSize[2] = w[5];
        }
        break;
      case OpDecorate: {
        Id& id = ids[w[1]];
        if (w[2] == DecBinding) id.binding = w[3];
        if (w[2] == DecDescriptorSet) id.set = w[3];
        if (w[2] == DecBlock) id.block = true;
        if (w[2] == DecBufferBlock) id.bufferBlock = true;
        if (w[2] == DecArrayStride) id.arrayStride = w[3];
        break;
      }
      case OpMemberDecorate: {
        Id& id = ids[w[1]];
        uint32_t member = w[2];
        if (w[3] == DecOffset) {
          if (id.memberOffsets.size() <= member) id.memberOffsets.resize(member + 1, 0);
          id.memberOffsets[member] = w[4];
        }
        if (w[3] == DecMatrixStride) {
          if (id.memberMatrixStrides.size() <= member) id.memberMatrixStrides.resize(member + 1, 0);
          id.memberMatrixStrides[member] = w[4];
        }
        break;
      }
      case OpTypeInt:
      case OpTypeFloat:
      case OpTypeVector:
      case OpTypeMatrix:
      case OpTypeImage:
      case OpTypeSampler:
      case OpTypeSampledImage:
      case OpTypeArray:
      case OpTypeRuntimeArray:
      case OpTypeStruct:
      case OpTypePointer:
        recordType(ids[w[1]], opcode, w, count);
        break;
      case OpConstant:
        ids[w[2]].opcode = opcode;
        ids[w[2]].constant = count > 3 ? w[3] : 0;
        break;
      case OpVariable:
        ids[w[2]].opcode = opcode;
        ids[w[2]].typeId = w[1];
        ids[w[2]].storageClass = w[3];
        variables.push_back(w[2]);
        break;
      default:
        break;
    }
    i += count;
  }
  for (uint32_t v : variables) {
    const Id& var = ids[v];
    const Id& pointer = ids[var.typeId];
    const Id& pointee = ids[pointer.typeId];
    if (var.storageClass == PushConstant) {
      out.pushConstantSize = std::max(out.pushConstantSize, structSize(ids, pointee));
    } else if (var.storageClass == UniformConstant || var.storageClass == Uniform ||
               var.storageClass == StorageBuffer) {
      if (var.binding == UINT32_MAX) continue;
      VkDescriptorType type = descriptorType(ids, pointee, var.storageClass);
      if (type == VK_DESCRIPTOR_TYPE_MAX_ENUM)
        fail(shaderName, ": binding ", var.binding,
             " has a resource type this engine does not handle");
      out.bindings.push_back({var.set == UINT32_MAX ? 0 : var.set, var.binding, type});
    }
  }
  std::sort(
      out.bindings.begin(), out.bindings.end(),
      [](const ReflectedBinding& a, const ReflectedBinding& b) { return a.binding < b.binding; });
  for (const ReflectedBinding& b : out.bindings) {
    if (b.set != 0)
      fail(shaderName, ": binding ", b.binding, " uses set ", b.set, "; only set 0 is supported");
  }
  return out;
}

}  // namespace throng::gpu
