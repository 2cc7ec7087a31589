#include "synth/coverage.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/math.h"
#include "gpu/job_check.h"
#include "shaders/synth_bindings.h"
#include "synth/synth_jobs.h"

namespace throng::synth {

using namespace gpu_types;

CoverageCamera coverageCamera(const glm::mat4& view, float fovYDegrees, uint32_t width,
                              uint32_t height, float nearPlane) {
  if (!(fovYDegrees > 0.0f && fovYDegrees < 180.0f))
    fail("coverage camera: fovy must be in (0, 180) degrees, got ", fovYDegrees);
  CoverageCamera camera;
  camera.view = view;
  camera.width = width;
  camera.height = height;
  camera.focalPixels = 0.5f * float(height) / std::tan(0.5f * glm::radians(fovYDegrees));
  camera.nearPlane = nearPlane;
  return camera;
}

namespace {

void setLevelTables(CoverageParts& out, const BodyParts& parts,
                    const CoverageThresholds& thresholds) {
  const std::array<LevelJoints, 3> levels = levelJoints(parts);
  const float enter[3] = {0.0f, thresholds.midHeight, thresholds.nearHeight};
  for (uint32_t l = 0; l < kLevelCount; ++l) {
    CoverageLevel& level = out.levels[l];
    level.synthLo = uint32_t(levels[l].synth);
    level.synthHi = uint32_t(levels[l].synth >> 32);
    level.drawLo = uint32_t(levels[l].draw);
    level.drawHi = uint32_t(levels[l].draw >> 32);
    level.enterHeight = enter[l];
    level.leaveHeight = enter[l] * (1.0f - thresholds.hysteresis);
    for (uint32_t j = 0; j < 64; ++j) {
      const uint32_t at = l * 64 + j;
      out.boneFrom[at / 16][(at / 4) % 4] |= uint32_t(levels[l].boneFrom[j]) << (8 * (at % 4));
      out.boneRadius[at / 4][at % 4] = levels[l].boneRadius[j];
    }
  }
}

}  // namespace

CoverageParts makeCoverageParts(const BodyParts& parts, const CoverageThresholds& thresholds) {
  if (parts.jointCount < 1 || parts.jointCount > 64)
    fail("coverage: body parts describe ", parts.jointCount, " joints, expected 1..64");
  if (!(thresholds.midHeight >= 0.0f) || !(thresholds.nearHeight >= 0.0f))
    fail("coverage: the mid and near heights must be >= 0 pixels, got ", thresholds.midHeight,
         " and ", thresholds.nearHeight);
  if (!(thresholds.hysteresis >= 0.0f && thresholds.hysteresis < 1.0f))
    fail("coverage: the hysteresis must be in [0, 1), got ", thresholds.hysteresis);
  if (!(thresholds.minChangeSeconds >= 0.0f))
    fail("coverage: the least time between level changes must be >= 0 s");
  CoverageParts out{};
  // Off screen nothing is posed or drawn (capes and the next frame's coverage need no joint of
  // it); near at any height (threshold 0) means every joint everywhere, off screen too.
  const uint64_t offScreen = thresholds.nearHeight <= 0.0f ? parts.allMask : 0u;
  out.offScreenLo = uint32_t(offScreen);
  out.offScreenHi = uint32_t(offScreen >> 32);
  out.allLo = uint32_t(parts.allMask);
  out.allHi = uint32_t(parts.allMask >> 32);
  out.body = glm::vec4(parts.height, thresholds.minChangeSeconds, parts.slowCycleSeconds,
                       parts.fastCycleSeconds);
  if (parts.parents.size() != size_t(parts.jointCount))
    fail("coverage: the body parts give ", parts.parents.size(), " parents for ", parts.jointCount,
         " joints");
  for (int k = 0; k < kBodyPartCount; ++k) {
    const BodyPart& part = parts.parts[size_t(k)];
    if (part.centreJoint < 0 || part.centreJoint >= parts.jointCount)
      fail("coverage: the ", bodyPartName(k), " has centre joint ", part.centreJoint, " of ",
           parts.jointCount);
    CoveragePart& p = out.parts[k];
    p.centre = glm::vec4(part.meanCentre, part.radius);
    p.joint = uint32_t(part.centreJoint);
    p.parent = parts.parents[size_t(part.centreJoint)];
    // The root's bone is vertical, 2r long and centred on it (gpu_types::bonePoint).
    p.bonePoint = p.parent < 0 ? 0.5f : 1.0f;
  }
  setLevelTables(out, parts, thresholds);
  return out;
}

CoverageView coverageView(const CoverageCamera& camera) {
  CoverageView push{};
  push.view = camera.view;
  const float f = camera.focalPixels, halfW = 0.5f * float(camera.width),
              halfH = 0.5f * float(camera.height);
  push.viewport = glm::vec4(float(camera.width), float(camera.height), f, camera.nearPlane);
  const float nx = std::sqrt(f * f + halfW * halfW), ny = std::sqrt(f * f + halfH * halfH);
  push.frustum = glm::vec4(f / nx, halfW / nx, f / ny, halfH / ny);
  return push;
}

CoveragePush makeCoveragePush(const CoverageCamera& camera, uint32_t jointCount,
                              uint32_t firstCharacter, uint32_t characterCount, uint32_t flags) {
  const CoverageView view = coverageView(camera);
  CoveragePush push{};
  push.view = view.view;
  push.viewport = view.viewport;
  push.frustum = view.frustum;
  push.characterCount = characterCount;
  push.firstCharacter = firstCharacter;
  push.jointCount = jointCount;
  push.flags = flags;
  return push;
}

// Mirrored operation for operation by sphereCoverage in coverage.comp.
float sphereCoveragePixels(const CoveragePush& push, glm::vec3 worldCentre, float radius) {
  const glm::vec4 v = push.view * glm::vec4(worldCentre, 1.0f);
  const glm::vec3 o(v.x, v.y, -v.z);  // camera space looking down +z
  const float f = push.viewport.z, nearPlane = push.viewport.w;
  const float screen = push.viewport.x * push.viewport.y;
  const float l2 = glm::dot(o, o), r2 = radius * radius;
  if (l2 <= r2) return screen;
  if (o.z + radius <= nearPlane) return 0.0f;
  // Signed distances to the side planes |x|·f − z·W/2 = 0 (normalized): beyond r is outside.
  if (std::abs(o.x) * push.frustum.x - o.z * push.frustum.y > radius) return 0.0f;
  if (std::abs(o.y) * push.frustum.z - o.z * push.frustum.w > radius) return 0.0f;
  if (o.z <= radius) return screen;
  const float d = o.z * o.z - r2;
  const float area = kPi * f * f * r2 * std::sqrt(l2 - r2) / (d * std::sqrt(d));
  return std::min(area, screen);
}

glm::vec3 cameraSpace(const CoveragePush& push, glm::vec3 world) {
  const glm::vec4 v = push.view * glm::vec4(world, 1.0f);
  return {v.x, v.y, -v.z};
}

bool sphereInFrustum(const CoveragePush& push, glm::vec3 o, float radius) {
  if (glm::dot(o, o) <= radius * radius) return true;
  if (o.z + radius <= push.viewport.w) return false;
  if (std::abs(o.x) * push.frustum.x - o.z * push.frustum.y > radius) return false;
  if (std::abs(o.y) * push.frustum.z - o.z * push.frustum.w > radius) return false;
  return true;
}

float projectedHeight(const CoveragePush& push, glm::vec3 middle, float height) {
  return middle.z > 0.5f * height ? push.viewport.z * height / middle.z : 1.0e9f;
}

namespace {

// The camera-space middle of a character `height` tall standing at `placement`.
glm::vec3 bodyMiddle(const CoveragePush& push, glm::vec4 placement, float height) {
  return cameraSpace(push, glm::vec3(placement) + glm::vec3(0.0f, 0.5f * height, 0.0f));
}

}  // namespace

float characterHeightPixels(const CoveragePush& push, const CoverageParts& parts,
                            glm::vec4 placement, glm::vec4 motion) {
  const float height = parts.body.x * gpu_types::characterScale(motion);
  return projectedHeight(push, bodyMiddle(push, placement, height), height);
}

bool bodyWithinReach(const CoveragePush& push, const CoverageParts& parts, glm::vec4 placement,
                     glm::vec4 motion, float reach) {
  const float height = parts.body.x * gpu_types::characterScale(motion);
  return sphereInFrustum(push, bodyMiddle(push, placement, height), (0.8f + reach) * height);
}

namespace {

// Mirrors levelForHeight and nextLevel in coverage_common.glsl.
static_assert(kLevelCount == 3, "coverage_common.glsl writes the three levels out");
uint32_t levelForHeight(const CoverageParts& parts, uint32_t level, float h) {
  if (level == 0u && h >= parts.levels[1].enterHeight) level = 1u;
  if (level == 1u && h >= parts.levels[2].enterHeight) level = 2u;
  if (level == 2u && h < parts.levels[2].leaveHeight) level = 1u;
  if (level == 1u && h < parts.levels[1].leaveHeight) level = 0u;
  return level;
}

std::pair<uint32_t, uint32_t> nextLevel(const CoverageParts& parts, const CoverageMask& previous,
                                        glm::vec4 motion, float h, bool visible) {
  const uint32_t state = previous.state;
  const bool initialized = (state & kStateInitialized) != 0u;
  const float previousPhase = float(state >> kStatePhaseShift) / 65535.0f;
  float advance = gpu_types::cyclePhase(motion) - previousPhase;
  const bool wrapped = advance < 0.0f;
  if (wrapped) advance = advance + 1.0f;
  const float cycleSeconds = parts.body.z * (1.0f - gpu_types::speedWeight(motion)) +
                             parts.body.w * gpu_types::speedWeight(motion);
  uint32_t timer = std::min(((state >> kStateTimerShift) & kStateTimerMax) +
                                uint32_t(advance * cycleSeconds * kStateTimerUnits),
                            kStateTimerMax);
  uint32_t level = initialized ? std::min(previous.level, kLevelCount - 1u) : kLevelFar;
  const uint32_t target = levelForHeight(parts, level, h);
  if (!initialized) {
    level = target;
    timer = 0u;
  } else if (target != level && float(timer) >= parts.body.y * kStateTimerUnits &&
             (wrapped || !visible)) {
    level = target;
    timer = 0u;
  }
  const uint32_t phaseBits = std::min(uint32_t(gpu_types::cyclePhase(motion) * 65535.0f), 65535u);
  return {level, kStateInitialized | (timer << kStateTimerShift) | (phaseBits << kStatePhaseShift)};
}

}  // namespace

namespace {

// The five part spheres' areas and on-screen bits; mirrors measureParts in coverage.comp.
uint32_t measureParts(const CoveragePush& push, const CoverageParts& parts, glm::vec4 placement,
                      float scale, const JointPoint* joints, uint64_t previousMask, float* areas) {
  const bool readJoints = (push.flags & kCoverageReadJoints) != 0u && joints != nullptr;
  const float c = std::cos(placement.w), s = std::sin(placement.w);
  uint32_t onScreen = 0;
  for (uint32_t k = 0; k < kCoveragePartCount; ++k) {
    const CoveragePart& part = parts.parts[k];
    glm::vec3 centre;
    if (readJoints && ((previousMask >> part.joint) & 1u) != 0u) {
      // The pose pass wrote this joint (and its parent) last frame: the centre is
      // A·(0, bonePoint, 0, 1) of its bone.
      const glm::vec4 point = joints[part.joint].positionRadius;
      const glm::vec4 parent = joints[gpu_types::partBoneStart(part)].positionRadius;
      centre = gpu_types::bonePoint(parent, point, part.parent < 0, part.bonePoint);
    } else {
      // Not synthesized: the centre joint's mean character-space position, placed like the root.
      const glm::vec3 m = glm::vec3(part.centre) * scale;
      centre = glm::vec3(placement) + glm::vec3(m.x * c + m.z * s, m.y, -m.x * s + m.z * c);
    }
    const float area = sphereCoveragePixels(push, centre, part.centre.w * scale);
    if (areas) areas[k] = area;
    if (area > 0.0f) onScreen |= 1u << k;
  }
  return onScreen;
}

}  // namespace

CoverageMask coverageCharacter(const CoveragePush& push, const CoverageParts& parts,
                               glm::vec4 placement, glm::vec4 motion, const JointPoint* joints,
                               const CoverageMask& previous, float* areas) {
  const float scale = gpu_types::characterScale(motion);
  const float height = parts.body.x * scale;
  const glm::vec3 middle = bodyMiddle(push, placement, height);
  const float h = projectedHeight(push, middle, height);
  // Mirrors bodyOnScreen in coverage_common.glsl.
  const bool visible = sphereInFrustum(push, middle, 0.8f * height);
  const uint32_t onScreen =
      (push.flags & kCoverageWriteAreas) != 0u
          ? measureParts(push, parts, placement, scale, joints, maskBits(previous), areas)
          : 0u;
  const auto [level, state] = nextLevel(parts, previous, motion, h, visible);
  const CoverageLevel& chosen = parts.levels[level];
  CoverageMask out{};
  out.lo = visible ? chosen.synthLo : parts.offScreenLo;
  out.hi = visible ? chosen.synthHi : parts.offScreenHi;
  out.level = level;
  out.state = state | onScreen;
  return out;
}

void coverageCpu(const CoverageCamera& camera, const CoverageParts& parts, uint32_t jointCount,
                 const crowd::Crowd& crowd, std::span<const JointPoint> joints,
                 std::span<CoverageMask> masks, std::span<float> areas) {
  const size_t n = crowd.size();
  if (masks.size() != n) fail("coverageCpu: ", masks.size(), " masks for ", n, " characters");
  if (!joints.empty() && joints.size() != n * jointCount)
    fail("coverageCpu: ", joints.size(), " joint points, expected ", n, " × ", jointCount);
  if (!areas.empty() && areas.size() != n * kCoveragePartCount)
    fail("coverageCpu: ", areas.size(), " areas, expected 5 × ", n);
  uint32_t flags =
      (joints.empty() ? 0u : kCoverageReadJoints) | (areas.empty() ? 0u : kCoverageWriteAreas);
  const CoveragePush push = makeCoveragePush(camera, jointCount, 0, uint32_t(n), flags);
  for (size_t i = 0; i < n; ++i) {
    masks[i] = coverageCharacter(push, parts, crowd.placement[i], crowd.motion[i],
                                 joints.empty() ? nullptr : &joints[i * jointCount], masks[i],
                                 areas.empty() ? nullptr : &areas[i * kCoveragePartCount]);
  }
}

bool parentsBeforeChildren(uint64_t mask, std::span<const int32_t> parents) {
  for (size_t j = 0; j < parents.size() && j < 64; ++j)
    if (((mask >> j) & 1u) && parents[j] >= 0 && !((mask >> parents[j]) & 1u)) return false;
  return true;
}

std::vector<std::string> CoverageJob::validate() const {
  std::vector<std::string> problems;
  if (!crowd) problems.push_back("input 'crowd' buffers are missing");
  if (crowd && (!crowd->placement || !crowd->motion))
    problems.push_back("crowd buffers are not allocated");
  if (crowd && (!crowd->placementTexels || !crowd->motionTexels))
    problems.push_back(
        "texel views of placement and motion are missing (make the buffers with "
        "uploadCrowd)");
  if (!parts || !*parts) problems.push_back("input 'parts' (uniform CoverageParts) is missing");
  if (!masks || !*masks) problems.push_back("input/output 'masks' buffer is missing");
  if (jointCount < 1 || jointCount > 64)
    problems.push_back(concat("jointCount must be 1..64, got ", jointCount));
  if (camera.width == 0 || camera.height == 0) problems.push_back("camera viewport is empty");
  if (!(camera.focalPixels > 0.0f))
    problems.push_back(concat("camera focal length must be > 0 pixels, got ", camera.focalPixels));
  if (!(camera.nearPlane >= 0.0f))
    problems.push_back(concat("camera near plane must be >= 0, got ", camera.nearPlane));
  if (parts && *parts && parts->size() < sizeof(CoverageParts))
    problems.push_back(concat("input 'parts' holds ", parts->size(), " bytes, CoverageParts needs ",
                              sizeof(CoverageParts)));
  if (!crowd || !problems.empty()) return problems;
  if (firstCharacter > crowd->count)
    problems.push_back("firstCharacter is past the end of the crowd");
  const uint32_t count =
      characterCount ? characterCount : crowd->count - std::min(firstCharacter, crowd->count);
  const VkDeviceSize end = VkDeviceSize(firstCharacter) + count;
  if (end > crowd->count) problems.push_back("chunk runs past the end of the crowd");
  if (masks->size() < end * sizeof(CoverageMask))
    problems.push_back(concat("input/output 'masks' holds ", masks->size(),
                              " bytes, characters up to ", end, " need ",
                              end * sizeof(CoverageMask)));
  if (joints && *joints) {
    VkDeviceSize need = VkDeviceSize(count) * jointCount * sizeof(JointPoint);
    if (jointsOffset + need > joints->size())
      problems.push_back(concat("input 'joints' holds ", joints->size(), " bytes, the chunk needs ",
                                need, " at offset ", jointsOffset));
  }
  if (areas && *areas && areas->size() < end * kCoveragePartCount * sizeof(float))
    problems.push_back(concat("output 'areas' holds ", areas->size(), " bytes, characters up to ",
                              end, " need ", end * kCoveragePartCount * sizeof(float)));
  return problems;
}

void CoverageJob::record(VkCommandBuffer cmd, const gpu::ComputeProgram& program) const {
  gpu::throwIfInvalid("CoverageJob", validate());
  const uint32_t count = characterCount ? characterCount : crowd->count - firstCharacter;
  if (count == 0) return;
  const bool readJoints = joints && *joints, writeAreas = areas && *areas;
  const CoveragePush push = makeCoveragePush(
      camera, jointCount, firstCharacter, count,
      (readJoints ? kCoverageReadJoints : 0u) | (writeAreas ? kCoverageWriteAreas : 0u));
  // Unused optional bindings get a stand-in buffer the shader never touches (flags say so).
  gpu::Binding bindings[] = {
      gpu::uniformBinding(gpu_types::kCoverageBindingParts, *parts, 0, sizeof(CoverageParts)),
      gpu::uniformTexelBinding(gpu_types::kCoverageBindingPlacement, crowd->placementTexels.get()),
      gpu::uniformTexelBinding(gpu_types::kCoverageBindingMotion, crowd->motionTexels.get()),
      readJoints ? gpu::storageBinding(gpu_types::kCoverageBindingJoints, *joints, jointsOffset,
                                       VkDeviceSize(count) * jointCount * sizeof(JointPoint))
                 : gpu::storageBinding(gpu_types::kCoverageBindingJoints, crowd->placement),
      gpu::storageBinding(gpu_types::kCoverageBindingMasks, *masks),
      writeAreas ? gpu::storageBinding(gpu_types::kCoverageBindingAreas, *areas)
                 : gpu::storageBinding(gpu_types::kCoverageBindingAreas, *masks),
  };
  gpu::dispatch(cmd, program, bindings, push, count);
}

gpu::ComputeProgram makeCoverageProgram(const gpu::Context& context) {
  return gpu::ComputeProgram(context, "coverage.comp");
}

}  // namespace throng::synth
