// The body of root_motion.comp and root_motion_coverage.comp (the latter defines
// THRONG_ROOT_MOTION_COVERAGE), and of root_motion_groups.comp and _coverage (which define
// THRONG_ROOT_MOTION_GROUPS: every clip set of a crowd in one dispatch, each character's clips
// from its group's entry in the group table). The includer enables GL_GOOGLE_include_directive,
// GL_EXT_control_flow_attributes and GL_EXT_shader_explicit_arithmetic_types_int64.
// Root motion (the paper's eq. 10, docs/design.md), one invocation per character: advance the phase, move the root by
// the blended displacement between the two phases (each clip's root lerped between its rows, so
// the step is continuous in the phase) rotated by the heading and scaled; w changes to wTarget
// only when the cycle ends. Circle steering and new target speeds are root_motion_prep.comp's,
// run before this pass on the steps that need them: lavapipe runs every line of a pass for
// every character, so as branches here they cost 12% of every step (docs/performance.md).
// CPU twin: anim::stepCharacter.
#include "shared_types.h"
#include "synth_bindings.h"
#include "motion_common.glsl"
#include "speed_buckets.glsl"

layout(local_size_x = 64) in;
// The motion texels like the pose pass reads them (motion_texels.glsl): on lavapipe a texelFetch
// goes through the whole sampler path.
layout(constant_id = kRootMotionConstantJointCount) const int kJointCount = 1;
#ifndef THRONG_ROOT_MOTION_GROUPS
#include "motion_texels.glsl"
#endif
#include "words64.glsl"
// Read and written as 64-bit words (fromWords, toWords): lavapipe moves a storage-buffer vector one component per lane
// in a loop (docs/design.md, "Decisions for CPU devices"). Not through texel views: a pass that
// reads a buffer through one descriptor and writes it through another is a hazard.
layout(std430, binding = kRootMotionBindingPlacement) buffer Placement { u64vec2 placementWords[]; };
layout(std430, binding = kRootMotionBindingMotion) buffer Motion { u64vec2 motionWords[]; };
layout(std430, binding = kRootMotionBindingCacheRequested) writeonly buffer Requested { uint requested[]; };
#ifdef THRONG_ROOT_MOTION_GROUPS
layout(std140, binding = kRootMotionBindingGroups) uniform Groups { SynthGroupTable table; };
// Each clip's root position per frame (texel 1 of the frame's row), as 64-bit words.
layout(std430, binding = kRootMotionBindingRootRows) readonly buffer RootRows { u64vec2 rootRowWords[]; };
#endif
#ifdef THRONG_ROOT_MOTION_COVERAGE
// The coverage LOD pass done here for the character just moved (no work between root motion
// and the pose pass moves it again): the level and mask of coverage.comp without the areas.
#include "coverage_types.h"
#include "coverage_common.glsl"
#ifdef THRONG_ROOT_MOTION_GROUPS
// Every group's parts; coverage_mask.glsl reads `parts`, the moving character's group's.
layout(std140, binding = kRootMotionBindingCoverageParts) uniform Parts { CoverageParts groupParts[kSynthMaxGroups]; };
uint coverageGroup = 0u;
#define parts groupParts[coverageGroup]
#else
layout(std140, binding = kRootMotionBindingCoverageParts) uniform Parts { CoverageParts parts; };
#endif
layout(std430, binding = kRootMotionBindingMasks) buffer Masks { u64vec2 maskWords[]; };  // CoverageMask, in/out
layout(std140, binding = kRootMotionBindingCoverageView) uniform View { CoverageView camera; };
#include "coverage_mask.glsl"
#endif
#ifdef THRONG_ROOT_MOTION_SCHEDULED
// The update-rate LOD (update_rate.h): workgroup g moves the chunk of kUpdateChunkCharacters
// (the local size) that list entry g names, by the seconds since its last move, and raises the chunk's largest
// projected height for the next schedule: of the characters that may be on screen before the
// chunk's next move (the others count as 0 px tall, so a chunk of them waits the longest interval).
#include "update_rate.h"
layout(std430, binding = kRootMotionBindingChunkState) buffer ChunkState { uvec2 chunkState[]; };
layout(std430, binding = kRootMotionBindingChunkList) readonly buffer ChunkList { uvec2 chunkList[]; };
#endif
layout(push_constant) uniform Push { RootMotionPush push; };

// A character's clips: the dispatch's (push constants), or its group's in the group table.
struct Clips {
  uint slowFrames, fastFrames;
  uint slowRootBase, fastRootBase;  // groups: where each clip's root rows start
  float slowDuration, fastDuration;
  vec3 slowTravel, fastTravel;
  uint bucketBase;  // groups: the group cache's first bucket in `requested`
};

Clips clipsOf(uint i, out uint group) {
  group = 0u;
#ifdef THRONG_ROOT_MOTION_GROUPS
  [[unroll]] for (uint k = 1u; k < kSynthMaxGroups; ++k)
    if (k < table.counts.x && i >= table.groups[k].firstCharacter) group = k;
  SynthGroupInfo g = table.groups[group];
  return Clips(g.slowFrames, g.fastFrames, g.slowRootBase, g.fastRootBase, g.slowDuration,
               g.fastDuration, g.slowCycleTravel.xyz, g.fastCycleTravel.xyz, g.bucketBase);
#else
  return Clips(push.slowFrames, push.fastFrames, 0u, 0u, push.slowDuration, push.fastDuration,
               push.slowCycleTravel.xyz, push.fastCycleTravel.xyz, 0u);
#endif
}

// Root position at row k ≥ 0 counted on from the cycle start (k ≥ F continues into the next
// cycle, moved on by the cycle's travel).
vec3 rootRow(bool fast, uint frames, uint rootBase, vec3 cycleTravel, int k) {
  // k / frames by a float division: lavapipe has no vector integer division and would divide
  // lane by lane. GPUs may divide approximately (NVIDIA: within 2 ulp, so F / F can come out
  // just below 1); the half row keeps the quotient at least 0.5 / F away from every whole
  // number, far more than that error for the small whole numbers here (k, F far below 2^20).
  int cycles = int(floor((float(k) + 0.5) / float(frames)));
  int frame = k - cycles * int(frames);
#ifdef THRONG_ROOT_MOTION_GROUPS
  vec3 root = fromWords(rootRowWords[rootBase + uint(frame)]).xyz;
#else
  int texel = frame * 2 * kJointCount + 1;
  vec3 root = (fast ? fastTexel(texel) : slowTexel(texel)).xyz;
#endif
  return root + float(cycles) * cycleTravel;
}

// Root position at a continuous row u = phase · F ≥ 0: lerp of the rows on either side (row F is
// row 0 plus the cycle's travel, so the loop seam is smooth too). Mirrors anim's rootAt.
vec3 rootAt(bool fast, uint frames, uint rootBase, vec3 cycleTravel, float u) {
  int k = int(u);
  float t = u - float(k);
  return rootRow(fast, frames, rootBase, cycleTravel, k) * (1.0 - t) +
         rootRow(fast, frames, rootBase, cycleTravel, k + 1) * t;
}

void main() {
#ifdef THRONG_ROOT_MOTION_SCHEDULED
  uvec2 entry = chunkList[gl_WorkGroupID.x];
  uint local = entry.x * kUpdateChunkCharacters + gl_LocalInvocationID.x;
  float dt = uintBitsToFloat(entry.y);
#else
  uint local = gl_GlobalInvocationID.x;
  float dt = push.dt;
#endif
  if (local >= push.characterCount) return;
  uint i = push.firstCharacter + local;
  uint group;
  Clips clips = clipsOf(i, group);
  vec4 place = fromWords(placementWords[i]);
  vec4 m = fromWords(motionWords[i]);
  float w = speedWeight(m);
  float duration = clips.slowDuration * (1.0 - w) + clips.fastDuration * w;
  float phase0 = cyclePhase(m);
  float phase1 = phase0 + dt / duration;
  float slowFrames = float(clips.slowFrames), fastFrames = float(clips.fastFrames);
  vec3 dSlow = rootAt(false, clips.slowFrames, clips.slowRootBase, clips.slowTravel, phase1 * slowFrames) -
               rootAt(false, clips.slowFrames, clips.slowRootBase, clips.slowTravel, phase0 * slowFrames);
  vec3 dFast = rootAt(true, clips.fastFrames, clips.fastRootBase, clips.fastTravel, phase1 * fastFrames) -
               rootAt(true, clips.fastFrames, clips.fastRootBase, clips.fastTravel, phase0 * fastFrames);
  // A step of no time moves no one: the two rootAt calls agree, but contracted into fused
  // multiply-adds their difference need not be exactly zero.
  vec3 d = dt > 0.0 ? dSlow * (1.0 - w) + dFast * w : vec3(0.0);
  float c = cos(place.w), s = sin(place.w);
  float scale = characterScale(m);
  place.x += scale * (d.x * c + d.z * s);
  place.z += scale * (-d.x * s + d.z * c);
  float wraps = floor(phase1);
  m = withCyclePhase(m, phase1 - wraps);
  if (wraps > 0.0) m = withSpeedWeight(m, targetSpeedWeight(m));
  placementWords[i] = toWords(place);
  motionWords[i] = toWords(m);
  // The motion cache's lookup: this frame needs the bucket of the speed weight it now has.
  if (push.cacheBucketWidth > 0.0)
    requested[clips.bucketBase + speedBucket(speedWeight(m), push.cacheBucketWidth, push.cacheBucketCount)] = 1u;
#ifdef THRONG_ROOT_MOTION_COVERAGE
#ifdef THRONG_ROOT_MOTION_GROUPS
  coverageGroup = group;
#endif
#ifdef THRONG_ROOT_MOTION_SCHEDULED
  // A character that cannot reach the view before its chunk's next move may not be drawn
  // before it moves again.
  float h;
  bool withinReach;
  maskWords[i] = frameMaskWords(camera.view, camera.viewport, camera.frustum, place, m, maskWords[i],
                                push.reachPerHeight, h, withinReach);
  if (!withinReach) h = 0.0;
  // Heights are positive, so their bits order like the floats.
  float chunkHeight = subgroupMax(h);
  if (subgroupElect()) atomicMax(chunkState[entry.x].x, floatBitsToUint(chunkHeight));
#else
  maskWords[i] = frameMaskWords(camera.view, camera.viewport, camera.frustum, place, m, maskWords[i]);
#endif
#endif
}
