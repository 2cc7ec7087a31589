#include "anim/reference_synth.h"

#include <cmath>
#include <vector>

#include "anim/speed_buckets.h"
#include "core/error.h"
#include "core/math.h"
#include "shaders/shared_types.h"

namespace throng::anim {
namespace {

glm::vec3 mixVec(glm::vec3 a, glm::vec3 b, float w) {
  return a * (1.0f - w) + b * w;
}

// Root position at row k ≥ 0 counted on from the cycle start (k ≥ F continues into the next
// cycle, moved on by the cycle's travel).
glm::vec3 rootRow(const MotionTexture& tex, int k) {
  int cycles = k / tex.frameCount;
  int frame = k - cycles * tex.frameCount;
  return tex.offset(frame, 0) + float(cycles) * tex.cycleTravel;
}

// Root position at a continuous row u = phase · F ≥ 0: lerp of the rows on either side, so the
// displacement between two phases has no step at row boundaries (and none at the loop seam,
// where row F is row 0 plus the cycle's travel).
glm::vec3 rootAt(const MotionTexture& tex, float u) {
  int k = static_cast<int>(u);
  return mixVec(rootRow(tex, k), rootRow(tex, k + 1), u - float(k));
}

// Both clips sampled at one phase, with the slerp weights of their row fractions and of w:
// what every joint of a character shares.
struct PhaseSampling {
  ClipSample slow, fast;
  SlerpWeights slowWeights, fastWeights, speedWeights;
  float w;
};

PhaseSampling samplePhase(const MotionPair& pair, float phase, float w) {
  ClipSample slow = clipSample(phase, pair.slow.frameCount),
             fast = clipSample(phase, pair.fast.frameCount);
  return {slow, fast, makeSlerpWeights(slow.t), makeSlerpWeights(fast.t), makeSlerpWeights(w), w};
}

// Joint j's local rotation and offset: each clip interpolated between its two rows, then slow
// and fast blended by w (the GPU pass does the same, operation for operation).
void blendJoint(const MotionPair& pair, const PhaseSampling& p, int j, glm::vec4& q, glm::vec3& o) {
  const MotionTexture &slow = pair.slow, &fast = pair.fast;
  glm::vec4 qSlow =
      slerpFast(slow.rotation(p.slow.row, j), slow.rotation(p.slow.next, j), p.slowWeights);
  glm::vec4 qFast =
      slerpFast(fast.rotation(p.fast.row, j), fast.rotation(p.fast.next, j), p.fastWeights);
  q = slerpFast(qSlow, qFast, p.speedWeights);
  glm::vec3 oSlow = mixVec(slow.offset(p.slow.row, j), slow.offset(p.slow.next, j), p.slow.t);
  glm::vec3 oFast = mixVec(fast.offset(p.fast.row, j), fast.offset(p.fast.next, j), p.fast.t);
  o = mixVec(oSlow, oFast, p.w);
}

}  // namespace

ClipSample clipSample(float phase, int frames) {
  float x = phase * float(frames);
  // A phase meant to land on a row (f / F in float, a few ulps off) lands on it exactly, so at
  // w = 0 or 1 it reproduces that row bit for bit; 1e-4 of a row is 3 µs of a 30 Hz clip.
  const float nearest = std::floor(x + 0.5f);
  if (std::abs(x - nearest) < kRowSnap) x = nearest;
  if (x >= float(frames)) x -= float(frames);  // a phase just below 1 is row 0 of the next cycle
  ClipSample s;
  s.row = std::min(static_cast<int>(x), frames - 1);
  s.next = s.row + 1 == frames ? 0 : s.row + 1;
  s.t = std::min(x - float(s.row), 1.0f);
  return s;
}

void stepCharacter(const MotionPair& pair, glm::vec4& placement, glm::vec4& motion, float dt,
                   Steering steering) {
  stepCharacter(pair, placement, motion, dt, steering, SpeedRetarget{}, 0);
}

void stepCharacter(const MotionPair& pair, glm::vec4& placement, glm::vec4& motion, float dt,
                   Steering steering, const SpeedRetarget& retarget, uint32_t character) {
  const MotionTexture& slow = pair.slow;
  const MotionTexture& fast = pair.fast;
  namespace m = gpu_types;
  float w = m::speedWeight(motion);
  float duration = slow.duration() * (1.0f - w) + fast.duration() * w;
  float phase0 = m::cyclePhase(motion);
  float phase1 = phase0 + dt / duration;
  glm::vec3 dSlow =
      rootAt(slow, phase1 * float(slow.frameCount)) - rootAt(slow, phase0 * float(slow.frameCount));
  glm::vec3 dFast =
      rootAt(fast, phase1 * float(fast.frameCount)) - rootAt(fast, phase0 * float(fast.frameCount));
  // A step of no time moves no one (as in root_motion.glsl, whose fused multiply-adds can leave
  // the difference of two equal roots just off zero).
  glm::vec3 d = dt > 0.0f ? mixVec(dSlow, dFast, w) : glm::vec3(0.0f);
  if (steering == Steering::Circle)
    placement.w = circleHeading(glm::vec2(placement.x, placement.z));
  float c = std::cos(placement.w), s = std::sin(placement.w);
  float scale = m::characterScale(motion);
  placement.x += scale * (d.x * c + d.z * s);
  placement.z += scale * (-d.x * s + d.z * c);
  applyRetarget(character, retarget, motion);
  float wraps = std::floor(phase1);
  motion = m::withCyclePhase(motion, phase1 - wraps);
  if (wraps > 0.0f) motion = m::withSpeedWeight(motion, m::targetSpeedWeight(motion));
}

void poseCharacterSpace(const MotionPair& pair, float phase, float w, std::span<PoseJoint> out) {
  const int joints = pair.jointCount();
  THRONG_CHECK(static_cast<int>(out.size()) >= joints, "pose output too small");
  const PhaseSampling sampling = samplePhase(pair, phase, w);
  for (int j = 0; j < joints; ++j) {
    glm::vec4 q;
    glm::vec3 o;
    blendJoint(pair, sampling, j, q, o);
    int p = pair.parents[j];
    if (p < 0) {
      out[j] = {glm::vec3(0.0f, o.y, 0.0f), q};
    } else {
      out[j] = {out[p].position + quatRotate(out[p].rotation, o), quatMul(out[p].rotation, q)};
    }
  }
}

void poseCharacterAt(const MotionPair& pair, float phase, float w, float heading, glm::vec3 origin,
                     float scale, std::span<glm::vec4> out) {
  const int joints = pair.jointCount();
  THRONG_CHECK(static_cast<int>(out.size()) >= joints, "joint point output too small");
  thread_local std::vector<PoseJoint> world;
  world.resize(joints);
  const glm::vec4 yaw = yawQuat(heading);
  const PhaseSampling sampling = samplePhase(pair, phase, w);
  // Composed directly in world space, like the GPU pass (root = M · root pose).
  for (int j = 0; j < joints; ++j) {
    glm::vec4 q;
    glm::vec3 o;
    blendJoint(pair, sampling, j, q, o);
    int p = pair.parents[j];
    float radius = pair.jointRadius[j];
    if (p < 0) {
      world[j].rotation = quatMul(yaw, q);
      world[j].position = origin + glm::vec3(0.0f, scale * o.y, 0.0f);
    } else {
      world[j].position = world[p].position + quatRotate(world[p].rotation, scale * o);
      world[j].rotation = quatMul(world[p].rotation, q);
      if (glm::length(o) <= 1e-6f) radius = 0.0f;  // zero-length bones are not drawn
    }
    out[j] = glm::vec4(world[j].position, scale * radius);
  }
}

void poseCharacter(const MotionPair& pair, const glm::vec4& placement, const glm::vec4& motion,
                   std::span<glm::vec4> out) {
  poseCharacterAt(pair, gpu_types::cyclePhase(motion), gpu_types::speedWeight(motion), placement.w,
                  glm::vec3(placement), gpu_types::characterScale(motion), out);
}

}  // namespace throng::anim
