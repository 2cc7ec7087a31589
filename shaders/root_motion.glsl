// The body of root_motion.comp and root_motion_coverage.comp (the latter defines
// THRONG_ROOT_MOTION_COVERAGE). The includer enables GL_GOOGLE_include_directive,
// GL_EXT_control_flow_attributes and GL_EXT_shader_explicit_arithmetic_types_int64.
// Root motion (the paper's eq. 10, docs/design.md), one invocation per character: advance the phase, move the root by
// the blended displacement between the two phases (each clip's root lerped between its rows, so
// the step is continuous in the phase) rotated by the heading and scaled; w changes to wTarget
// only when the cycle ends. CPU twin: anim::stepCharacter.
#include "shared_types.h"
#include "synth_bindings.h"
#include "motion_common.glsl"
#include "speed_buckets.glsl"

layout(local_size_x = 64) in;
// The motion texels like the pose pass reads them (motion_texels.glsl): on lavapipe a texelFetch
// goes through the whole sampler path.
layout(constant_id = kRootMotionConstantJointCount) const int kJointCount = 1;
#include "motion_texels.glsl"
#include "words64.glsl"
// Read and written as 64-bit words (fromWords, toWords): lavapipe moves a storage-buffer vector one component per lane
// in a loop (docs/design.md, "Decisions for CPU devices"). Not through texel views: a pass that
// reads a buffer through one descriptor and writes it through another is a hazard.
layout(std430, binding = kRootMotionBindingPlacement) buffer Placement { u64vec2 placementWords[]; };
layout(std430, binding = kRootMotionBindingMotion) buffer Motion { u64vec2 motionWords[]; };
layout(std430, binding = kRootMotionBindingCacheRequested) writeonly buffer Requested { uint requested[]; };
#ifdef THRONG_ROOT_MOTION_COVERAGE
// The coverage LOD pass done here for the character just moved (no work between root motion
// and the pose pass moves it again): the level and mask of coverage.comp without the areas.
#include "coverage_types.h"
#include "coverage_common.glsl"
layout(std140, binding = kRootMotionBindingCoverageParts) uniform Parts { CoverageParts parts; };
layout(std430, binding = kRootMotionBindingMasks) buffer Masks { u64vec2 maskWords[]; };  // CoverageMask, in/out
layout(std140, binding = kRootMotionBindingCoverageView) uniform View { CoverageView camera; };
#include "coverage_mask.glsl"
#endif
layout(push_constant) uniform Push { RootMotionPush push; };

// Root position at row k ≥ 0 counted on from the cycle start (k ≥ F continues into the next
// cycle, moved on by the cycle's travel).
vec3 rootRow(bool fast, uint frames, vec3 cycleTravel, int k) {
  // k / frames by a float division: lavapipe has no vector integer division and would divide
  // lane by lane. GPUs may divide approximately (NVIDIA: within 2 ulp, so F / F can come out
  // just below 1); the half row keeps the quotient at least 0.5 / F away from every whole
  // number, far more than that error for the small whole numbers here (k, F far below 2^20).
  int cycles = int(floor((float(k) + 0.5) / float(frames)));
  int frame = k - cycles * int(frames);
  int texel = frame * 2 * kJointCount + 1;
  return (fast ? fastTexel(texel) : slowTexel(texel)).xyz + float(cycles) * cycleTravel;
}

// Root position at a continuous row u = phase · F ≥ 0: lerp of the rows on either side (row F is
// row 0 plus the cycle's travel, so the loop seam is smooth too). Mirrors anim's rootAt.
vec3 rootAt(bool fast, uint frames, vec3 cycleTravel, float u) {
  int k = int(u);
  float t = u - float(k);
  return rootRow(fast, frames, cycleTravel, k) * (1.0 - t) + rootRow(fast, frames, cycleTravel, k + 1) * t;
}

void main() {
  if (gl_GlobalInvocationID.x >= push.characterCount) return;
  uint i = push.firstCharacter + gl_GlobalInvocationID.x;
  vec4 place = fromWords(placementWords[i]);
  vec4 m = fromWords(motionWords[i]);
  float w = speedWeight(m);
  float duration = push.slowDuration * (1.0 - w) + push.fastDuration * w;
  float phase0 = cyclePhase(m);
  float phase1 = phase0 + push.dt / duration;
  vec3 dSlow = rootAt(false, push.slowFrames, push.slowCycleTravel.xyz, phase1 * float(push.slowFrames)) -
               rootAt(false, push.slowFrames, push.slowCycleTravel.xyz, phase0 * float(push.slowFrames));
  vec3 dFast = rootAt(true, push.fastFrames, push.fastCycleTravel.xyz, phase1 * float(push.fastFrames)) -
               rootAt(true, push.fastFrames, push.fastCycleTravel.xyz, phase0 * float(push.fastFrames));
  vec3 d = dSlow * (1.0 - w) + dFast * w;
  if (push.steering == 1u) place.w = atan(-place.z, place.x);
  float c = cos(place.w), s = sin(place.w);
  float scale = characterScale(m);
  place.x += scale * (d.x * c + d.z * s);
  place.z += scale * (-d.x * s + d.z * c);
  if (push.retargetEpoch > 0u) {
    float target = retargetSpeed(i, push.retargetEpoch, push.seed, push.minSpeedWeight, push.maxSpeedWeight);
    m = withTargetSpeedWeight(m, push.bucketWidth > 0.0 ? quantizeSpeed(target, push.bucketWidth) : target);
  }
  float wraps = floor(phase1);
  m = withCyclePhase(m, phase1 - wraps);
  if (wraps > 0.0) m = withSpeedWeight(m, targetSpeedWeight(m));
  placementWords[i] = toWords(place);
  motionWords[i] = toWords(m);
  // The motion cache's lookup: this frame needs the bucket of the speed weight it now has.
  if (push.cacheBucketWidth > 0.0)
    requested[speedBucket(speedWeight(m), push.cacheBucketWidth, push.cacheBucketCount)] = 1u;
#ifdef THRONG_ROOT_MOTION_COVERAGE
  maskWords[i] = frameMaskWords(camera.view, camera.viewport, camera.frustum, place, m, maskWords[i]);
#endif
}
