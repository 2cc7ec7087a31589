#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_shuffle : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// Steering, one invocation per agent in grid order: the velocity that heads for the path-vector
// waypoint (goal), changed by the avoidance policy, written as heading (placement.w), velocity
// and speed (steer) and speed weight (motion.z = wTarget). Neighbours come from the grid's
// sorted copy, so reading them never races with the writes. CPU twin: crowd::steerCpu.
//
// How the neighbour scan stays cheap on lavapipe, which runs the 8 lanes of a subgroup as one
// SIMD loop where a divergent branch costs both sides and a loop runs as often as its longest
// lane: the lanes share one candidate list. Lanes in one grid row (consecutive slots nearly
// always are) take the union of their neighbourhoods, which is one or two runs of slots per
// row; every lane loads one candidate at a time (one gather for kChunk candidates) and
// subgroupShuffle with a constant lane hands each candidate to all lanes in turn (lavapipe 22.3
// turns subgroupBroadcast into a search for the first active lane per component: a TTC step
// took 2.7 times as long with it). Every lane screens every candidate cheaply and marks those
// that can change its steering (scanRound); candidates outside a lane's own neighbourhood lie
// beyond the sensing distance and are never marked. Only marked ones are evaluated, handed
// from the lanes that fetched them by shuffles.
// Everything is read as uniform texel buffers: lavapipe fetches a texel for all lanes with one
// unrolled gather, where a storage-buffer load is a loop over the lanes with a branch per lane
// and component. Stores stay storage-buffer writes, as few and as wide as possible.
#include "crowd_types.h"
#include "shared_types.h"  // the motion vector's accessors
#include "crowd_bindings.h"
#include "avoidance_common.glsl"
#include "avoidance_walls.glsl"
#include "words64.glsl"

layout(local_size_x = 64) in;
layout(constant_id = kSteerConstantPolicy) const uint kPolicy = kSteerPolicyTtc;
layout(constant_id = kSteerConstantRange) const int kRange = 1;  // columns scanned each side: ceil(sensing / width)
layout(constant_id = kSteerConstantChunk) const uint kChunk = 8u;  // candidates per round: min(subgroup size, 32)
layout(constant_id = kSteerConstantRangeZ) const int kRangeZ = 1;  // rows scanned each side: ceil(sensing / depth)
layout(constant_id = kSteerConstantWalls) const uint kWalls = 0u;  // 1: static walls are read
const int kRows = 2 * kRangeZ + 1;
const int kRuns = 2 * kRows;                      // a row's columns may wrap around the table
const uint kStartValues = 4u * uint(kRows);       // grid table entries a round reads
const uint kStartLoads = (kStartValues + kChunk - 1u) / kChunk;

layout(std430, binding = kSteerBindingPlacement) buffer Placement { vec4 placement[]; };
layout(std430, binding = kSteerBindingMotion) writeonly buffer Motion { vec4 motion[]; };
layout(binding = kSteerBindingGoals) uniform samplerBuffer goalTexels;
layout(std430, binding = kSteerBindingSteer) writeonly buffer SteerWords { u64vec2 steerWords[]; };  // steer, stored in words
layout(binding = kSteerBindingStarts) uniform usamplerBuffer startTexels;
layout(binding = kSteerBindingSortedIndex) uniform usamplerBuffer sortedIndexTexels;
layout(binding = kSteerBindingSorted) uniform samplerBuffer sortedTexels;
// The rule's own heading and wait counter, read before this invocation writes them (texel reads
// of placement and steer; no other invocation writes agent i).
layout(binding = kSteerBindingPlacementTexels) uniform samplerBuffer placementTexels;
layout(binding = kSteerBindingSteerTexels) uniform samplerBuffer steerTexels;
// Static walls (bound but never read when kWalls is 0).
layout(std140, binding = kSteerBindingWallInfo) uniform WallInfo { WallGridInfo wallInfo; };
layout(binding = kSteerBindingWallEntries) uniform samplerBuffer wallEntries;
layout(binding = kSteerBindingWallStarts) uniform usamplerBuffer wallStarts;
layout(push_constant) uniform Push { SteerPush push; };

// This invocation's state, updated by every candidate it evaluates.
bool gMine;  // the lane takes part in the current round
vec2 gPos, gVCur, gVPref, gKeep;
vec2 gDraws[kRuleDraws];
float gSensing2, gDiameter2, gInvDiameter;
// The push constants, read once before any branch or loop: inside one, lavapipe reads a push
// constant as a gather from the constant buffer, lane by lane.
SteerPush gPush;
bool gBlocked, gKeepBlocked, gAgentBlocked;  // the course blocked (by anything, by an agent)
uint gDrawBlocked;
ivec2 gForce;
uint gDensity;  // kernel weights of the neighbours within the density radius (fixed point)

// Karamouzas, Skinner & Guy 2014: E = k τ^-2 e^(-τ/τ0) over the time to collision τ of two
// discs; the force on agent i is −∇E = k e^(-τ/τ0) τ^-2 (2/τ + 1/τ0) (x + τ v) / √D, with x, v
// the relative position and velocity and D the discriminant. Overlapping discs are pushed apart.
// τ is floored at 0.1 s and √D at 0.05·|v|² (s/|v|²: half the time the discs would overlap):
// both forces are far above the cap there anyway, and without the floors the τ^-3 and 1/√D
// singularities turn float rounding into different steering on the GPU and the CPU twin.
// Branch-free (every branch costs on lavapipe); the CPU twin's branches select the same values.
vec2 ttcForce(vec2 x, vec2 v, float dist2) {
  float c = dist2 - gDiameter2;
  vec2 apart = dist2 > 1e-8 ? x * (gPush.ttcMaxForce * (inversesqrt(dist2) - gInvDiameter)) : vec2(0.0);
  float a = dot(v, v);
  float b = dot(x, v);
  float disc = b * b - a * c;
  float s = sqrt(max(disc, 0.0));
  float tau = c / (s - b);
  float t = max(tau, 0.1);
  // τ^-2 (2/τ + 1/τ0) as (2 + τ/τ0) / τ³: one division where there were three.
  float magnitude = gPush.ttcK * exp(-t * gPush.ttcInvTau0) * (2.0 + t * gPush.ttcInvTau0) / (t * t * t * max(s, 0.05 * a));
  bool approaching = b < 0.0 && a >= 1e-6 && disc > 0.0;  // else: not approaching or passing clear
  return c < 0.0 ? apart : approaching ? (x + tau * v) * magnitude : vec2(0.0);
}

// The TTC term of the static walls (Karamouzas et al. 2014 treat static obstacles by the same
// energy over the time to collision with the obstacle): τ is when this agent's disc, moving at
// its current velocity, first touches any wall within sensing (a capsule of its radius around
// each segment: sides and end discs), and the force lies along that contact's normal n. Only
// the first contact counts: the walls are one static obstacle, and a corner's second segment,
// touched later, lies behind the first (counting it pushes agents back from convex corners).
// With vn = −v·n the approach speed along n, |∂τ/∂x| = 1/vn, which gives
// −∇E = k e^(-τ/τ0) (2 + τ/τ0) / (τ³ vn) n: the agents' formula, where √D is the approach speed
// times the diameter. Floors as for agents (vn ≥ 0.05 |v|² / 2r).
vec2 wallTtcForce(float tau, vec2 n) {
  if (tau >= kNoWallHit) return vec2(0.0);
  float t = max(tau, 0.1);
  float vn = max(-dot(gVCur, n), 0.025 * dot(gVCur, gVCur) / gPush.radius);
  return n * (gPush.ttcK * exp(-t * gPush.ttcInvTau0) * (2.0 + t * gPush.ttcInvTau0) / (t * t * t * vn));
}

ivec2 toFixed(vec2 f) { return ivec2(floor(clamp(f, -kForceTermCap, kForceTermCap) * kForceScale + 0.5)); }

// The slot of candidate t of the round's union (its runs concatenated), or 0xFFFFFFFF past the end.
uint slotOf(uint t, uint runBegin[kRuns], uint runLength[kRuns]) {
  uint slot = 0xFFFFFFFFu;
  uint before = 0u;
  for (int s = 0; s < kRuns; ++s) {
    if (t >= before && t - before < runLength[s]) slot = runBegin[s] + (t - before);
    before += runLength[s];
  }
  return slot;
}

// Whether a candidate can change this lane's steering: within sensing distance, and for TTC
// either overlapping or on a collision course (ttcForce's own conditions but a ≥ 1e-6, which
// ttcForce tests itself). Candidates at x = 0, the lane itself included, change nothing (no
// TTC force there, and the rule's courses only collide while approaching). A few operations,
// against ttcForce's exp, sqrt and divisions or the rule's 2 + kRuleDraws course tests.
// Every candidate also adds its density weight here (the density radius is within sensing, so a
// lane's union holds all it needs; only for the lanes of the round).
bool screened(vec4 other) {
  vec2 x = gPos - other.xy;
  float dist2 = dot(x, x);
  gDensity += gMine ? densityWeight(x, dist2, gVPref, gPush.densityInvRadius2) : 0u;
  bool near = dist2 < gSensing2;
  if (kPolicy == kSteerPolicyRule) return near && dist2 > 0.0;
  vec2 v = gVCur - other.zw;
  float c = dist2 - gDiameter2;
  float b = dot(x, v);
  bool course = c < 0.0 || (b < 0.0 && b * b > dot(v, v) * c);
  return near && dist2 > 1e-8 && course;
}

// A screened candidate's effect on this lane.
void evaluate(vec4 other) {
  vec2 x = gPos - other.xy;
  if (kPolicy == kSteerPolicyRule) {
    vec2 theirs = other.zw;
    gAgentBlocked = gAgentBlocked || collides(x, gVPref - theirs, gPush.lookahead, gDiameter2);
    gBlocked = gBlocked || gAgentBlocked;
    gKeepBlocked = gKeepBlocked || collides(x, gKeep - theirs, gPush.lookahead, gDiameter2);
    for (uint d = 0u; d < kRuleDraws; ++d)
      if (collides(x, gDraws[d] - theirs, gPush.lookahead, gDiameter2)) gDrawBlocked |= 1u << d;
  } else if (kPolicy == kSteerPolicyTtc) {
    gForce += toFixed(ttcForce(x, gVCur - other.zw, dot(x, x)));
  }
}

// One round in two phases per block of kBlock union candidates: every lane screens every
// candidate (one bit each), then each lane evaluates its own marked ones only, in a loop that
// runs as often as the lane with the most. Of the ≈ 60 candidates of a union about 14 lie
// within a lane's sensing distance and only a few on a collision course with it, so the
// expensive part runs a few times per block instead of once per candidate (lavapipe skips
// work only in loops: every lane pays for both sides of a branch). The block's candidates stay
// in registers (`held`, one per lane and chunk) and reach the evaluating lanes by shuffles,
// which costs less than finding and fetching them again.
const uint kBlock = 32u;
const uint kHeld = kBlock / kChunk;  // chunks per block
void scanRound(uint total, uint runBegin[kRuns], uint runLength[kRuns]) {
  uint lane = gl_SubgroupInvocationID;
  // Do-whiles: lavapipe tests a loop's exit at its end, so a for loop would pay one more
  // (masked) round. Every lane of the round is in its own cell, so total >= 1. All lanes run
  // every loop here the same number of times, so the shuffles read active lanes only.
  uint base = 0u;
  do {
    uint bits = 0u;
    // Chunks past the end of the union are left unset: no lane marks a candidate there, so the
    // evaluation loop's selects never take them (setting them costs registers, ≈ 5% TTC).
    vec4 held[kHeld];
    uint chunk = 0u;
    do {
      uint offset = chunk * kChunk;
      uint t = lane < kChunk ? base + offset + lane : 0xFFFFFFFFu;
      uint slot = slotOf(t, runBegin, runLength);
      vec4 candidate = texelFetch(sortedTexels, int(min(slot, gPush.agentCount - 1u)));
      candidate = slot != 0xFFFFFFFFu ? candidate : vec4(1e18, 1e18, 0.0, 0.0);
      for (uint h = 0u; h < kHeld; ++h)  // constant indices: a dynamic one spills the array
        if (h == chunk) held[h] = candidate;
#define THRONG_SCREEN(n) \
  if (kChunk > n) bits |= screened(subgroupShuffle(candidate, n)) ? 1u << (offset + n) : 0u;
      THRONG_SCREEN(0u) THRONG_SCREEN(1u) THRONG_SCREEN(2u) THRONG_SCREEN(3u)
      THRONG_SCREEN(4u) THRONG_SCREEN(5u) THRONG_SCREEN(6u) THRONG_SCREEN(7u)
      THRONG_SCREEN(8u) THRONG_SCREEN(9u) THRONG_SCREEN(10u) THRONG_SCREEN(11u)
      THRONG_SCREEN(12u) THRONG_SCREEN(13u) THRONG_SCREEN(14u) THRONG_SCREEN(15u)
      THRONG_SCREEN(16u) THRONG_SCREEN(17u) THRONG_SCREEN(18u) THRONG_SCREEN(19u)
      THRONG_SCREEN(20u) THRONG_SCREEN(21u) THRONG_SCREEN(22u) THRONG_SCREEN(23u)
      THRONG_SCREEN(24u) THRONG_SCREEN(25u) THRONG_SCREEN(26u) THRONG_SCREEN(27u)
      THRONG_SCREEN(28u) THRONG_SCREEN(29u) THRONG_SCREEN(30u) THRONG_SCREEN(31u)
#undef THRONG_SCREEN
      ++chunk;
    } while (chunk < kHeld && base + chunk * kChunk < total);
    bits = gMine ? bits : 0u;
    // As many evaluations as the lane with the most marks (a butterfly of shuffles: subgroupMax
    // is a loop over the lanes on lavapipe).
    uint most = uint(bitCount(bits));
    for (uint m = 1u; m < gl_SubgroupSize; m <<= 1u) most = max(most, subgroupShuffleXor(most, m));
    for (uint k = 0u; k < most; ++k) {
      uint t = uint(findLSB(bits));  // 0xFFFFFFFF once this lane has none left
      bool has = bits != 0u;
      bits &= bits - 1u;
      uint from = t % kChunk, which = t / kChunk;
      vec4 other = subgroupShuffle(held[0], from);
      for (uint h = 1u; h < kHeld; ++h) {
        vec4 inChunk = subgroupShuffle(held[h], from);
        other = which == h ? inChunk : other;
      }
      if (has) evaluate(other);
    }
    base += kBlock;
  } while (base < total);
}

// Every pending lane's neighbourhood, one grid row of lanes per round of the outer loop
// (nearly always a single round).
void scanNeighbours(bool pending, ivec2 cell) {
  uint width = 1u << gPush.widthShift;
  uint lane = gl_SubgroupInvocationID;
  do {
    int row = subgroupMin(pending ? cell.y : 0x7fffffff);
    gMine = pending && cell.y == row;
    pending = pending && !gMine;
    int xlo = subgroupMin(gMine ? cell.x : 0x7fffffff) - kRange;
    int xhi = subgroupMax(gMine ? cell.x : -0x7fffffff) + kRange;
    // The union's columns xlo..xhi in rows row-kRangeZ..row+kRangeZ: per row one run of slots,
    // or two when the columns wrap around the table, or the whole row when they span it.
    uint runBegin[kRuns], runLength[kRuns];
    uint total = 0u;
    bool whole = uint(xhi - xlo) + 1u >= width;
    uint lo = uint(xlo) & (width - 1u), hi = uint(xhi) & (width - 1u);
    bool wraps = !whole && lo > hi;
    // The 4 table entries per row are fetched one per lane and handed round by shuffles: on
    // lavapipe every load is a loop over the lanes, and these are the same for all of them.
    uint fetched[kStartLoads];
    for (uint k = 0u; k < kStartLoads; ++k) {
      uint j = k * kChunk + lane;
      uint rowBase = (uint(row + int(j / 4u) - kRangeZ) & gPush.rowMask) << gPush.widthShift;
      uint kind = j % 4u;
      uint column = kind == 0u ? (whole ? 0u : lo) : kind == 1u ? (whole || wraps ? width : hi + 1u) : kind == 2u ? 0u : (wraps ? hi + 1u : 0u);
      fetched[k] = j < kStartValues && lane < kChunk ? texelFetch(startTexels, int(rowBase + column)).x : 0u;
    }
    for (int r = 0; r < kRows; ++r) {
#define THRONG_FETCHED(kind) subgroupShuffle(fetched[(4u * uint(r) + kind) / kChunk], (4u * uint(r) + kind) % kChunk)
      uint a = THRONG_FETCHED(0u);
      uint b = THRONG_FETCHED(1u);
      uint c = THRONG_FETCHED(2u);
      uint d = THRONG_FETCHED(3u);
#undef THRONG_FETCHED
      runBegin[2 * r] = a;
      runLength[2 * r] = b - a;
      runBegin[2 * r + 1] = c;
      runLength[2 * r + 1] = d - c;
      total += (b - a) + (d - c);
    }
    scanRound(total, runBegin, runLength);
  } while (subgroupAny(pending));
  gMine = false;
}

// The segments of this agent's wall cell, each a neighbour that never moves: under TTC the
// first contact with any of them (wallTtcForce); under the rule its closest point, of no size, blocks the courses that come
// within the radius of it (the rule's own test, with the wall's zero velocity). Per lane, no
// subgroup sharing: a cell lists a handful of segments. (A two-phase form like the neighbour
// scan's, screening every segment and then testing only the marked ones in a second loop, cost
// 50% more here on lavapipe, 2026-11-26: the lists are too short for the second loop to pay.)
void scanWalls() {
  WallGridInfo info = wallInfo;
  uint cell = wallCell(gPos, info);
  bool inGrid = cell != 0xFFFFFFFFu;
  uint begin = inGrid ? texelFetch(wallStarts, int(cell)).x : 0u;
  uint end = inGrid ? texelFetch(wallStarts, int(cell + 1u)).x : 0u;
  float r2 = gPush.radius * gPush.radius;
  float firstTau = kNoWallHit;
  vec2 firstNormal = vec2(0.0);
  float ruleReach = gPush.radius + length(gVPref) * gPush.lookahead;
  for (uint k = begin; k < end; ++k) {
    vec4 s = texelFetch(wallEntries, int(k));
    if (kPolicy == kSteerPolicyRule) {
      vec2 x = gPos - closestOnSegment(gPos, s.xy, s.zw);
      // Every course runs at the preferred speed: none comes within r of a point farther than
      // r + speed · lookahead (the same screen as the twin's, so both decide alike).
      if (dot(x, x) >= gSensing2 || dot(x, x) > ruleReach * ruleReach) continue;
      gBlocked = gBlocked || collides(x, gVPref, gPush.lookahead, r2);
      gKeepBlocked = gKeepBlocked || collides(x, gKeep, gPush.lookahead, r2);
      for (uint d = 0u; d < kRuleDraws; ++d)
        if (collides(x, gDraws[d], gPush.lookahead, r2)) gDrawBlocked |= 1u << d;
    } else {
      // Closer than the radius (only before the wall constraint first ran): pushed straight
      // out, like overlapping agents; else a candidate for the first contact.
      vec2 off = gPos - closestOnSegment(gPos, s.xy, s.zw);
      float d2 = dot(off, off);
      if (d2 >= gSensing2) continue;
      if (d2 < r2) {
        if (d2 > 1e-8) gForce += toFixed(off * (gPush.ttcMaxForce * (inversesqrt(d2) - 1.0 / gPush.radius)));
        continue;
      }
      // Moving along or away from the closest point never touches the segment: the distance
      // to a segment is convex along a line (an exact screen; the twin's too).
      if (!(dot(gVCur, off) < 0.0)) continue;
      vec2 n;
      float tau = segmentHit(gPos, gVCur, s.xy, s.zw, gPush.radius, n);
      if (tau < firstTau) {
        firstTau = tau;
        firstNormal = n;
      }
    }
  }
  if (kPolicy == kSteerPolicyTtc) gForce += toFixed(wallTtcForce(firstTau, firstNormal));
}

void main() {
  gPush = push;
  uint slot = gl_GlobalInvocationID.x;
  bool valid = slot < gPush.agentCount;
  uint i = texelFetch(sortedIndexTexels, int(min(slot, gPush.agentCount - 1u))).x;
  vec4 goal = texelFetch(goalTexels, int(i));
  // Position and velocity from the grid's copy (read in slot order, so nearly contiguous);
  // heading and wait counter only where the rule needs them (each load costs on lavapipe).
  vec4 own = texelFetch(sortedTexels, int(min(slot, gPush.agentCount - 1u)));
  vec4 place = kPolicy == kSteerPolicyRule ? texelFetch(placementTexels, int(i)) : vec4(0.0);
  vec4 state = kPolicy == kSteerPolicyRule ? texelFetch(steerTexels, int(i)) : vec4(0.0);
  bool isActive = valid && goal.w != 0.0;
  gPos = own.xy;
  gVPref = (goal.xy - gPos) * gPush.invSecondsLeft;
  float prefSpeed = length(gVPref);
  if (prefSpeed > goal.z) {
    gVPref *= goal.z / prefSpeed;
    prefSpeed = goal.z;
  }
  gVCur = own.zw;
  gSensing2 = gPush.sensing * gPush.sensing;
  gDiameter2 = 4.0 * gPush.radius * gPush.radius;
  gInvDiameter = 0.5 / gPush.radius;
  gBlocked = false;
  gKeepBlocked = false;
  gAgentBlocked = false;
  gDrawBlocked = 0u;
  gForce = ivec2(0);
  gDensity = 0u;

  // The rule tests courses: towards the waypoint, on along the current heading, and
  // kRuleDraws random headings within the gaze around the waypoint's direction.
  float goalHeading = prefSpeed > 1e-4 ? atan(gVPref.x, gVPref.y) : place.w;
  gKeep = prefSpeed * vec2(sin(place.w), cos(place.w));
  for (uint d = 0u; d < kRuleDraws; ++d) {
    gDraws[d] = vec2(0.0);
    if (kPolicy == kSteerPolicyRule) {
      float heading = goalHeading + (steerRandom(i, gPush.step * kRuleDraws + d, gPush.seed) - 0.5) * gPush.gazeAngle;
      gDraws[d] = prefSpeed * vec2(sin(heading), cos(heading));
    }
  }
  if (kPolicy != kSteerPolicyNone) scanNeighbours(isActive, cellCoord(gPos, vec2(gPush.invCellX, gPush.invCellZ)));
  if (kPolicy != kSteerPolicyNone && kWalls != 0u && isActive) scanWalls();
  if (!isActive) {
    if (valid) steerWords[i] = u64vec2(0ul);
    return;
  }

  // The speed the local density allows (Weidmann); the policies' courses keep their directions.
  float cap = goal.z * densitySpeedFactor(gDensity, gPush.densityNorm);
  vec2 v = gVPref;
  uint flags = 0u;
  if (kPolicy == kSteerPolicyRule && gBlocked) {
    // Keep an earlier turn while its course is free and still within the gaze around the
    // waypoint; else take the first free random heading; else wait, but for at most
    // kRuleMaxWait seconds before taking the first draw anyway (a dense crossing would
    // otherwise wait for ever).
    bool inGaze = prefSpeed > 1e-4 && dot(gKeep, gVPref) >= gPush.cosHalfGaze * prefSpeed * prefSpeed;
    float waited = max(-state.w, 0.0) * gPush.dt;
    if (!gKeepBlocked && inGaze) {
      v = gKeep;
      flags = kSteerFlagKept;
    } else {
      v = waited < kRuleMaxWait ? vec2(0.0) : gDraws[0];
      flags = waited < kRuleMaxWait ? kSteerFlagWaiting : kSteerFlagForced;
      for (uint d = kRuleDraws; d > 0u; --d) {  // the first free draw wins
        if ((gDrawBlocked & (1u << (d - 1u))) == 0u) {
          v = gDraws[d - 1u];
          flags = kSteerFlagTurned;
        }
      }
      // Blocked by walls alone: the course, which the wall constraint slides along them.
      if (flags != kSteerFlagTurned && !gAgentBlocked) {
        v = gVPref;
        flags = 0u;
      }
    }
  } else if (kPolicy == kSteerPolicyTtc) {
    vec2 avoid = vec2(gForce) * (1.0 / kForceScale);
    float avoidLength = length(avoid);
    if (avoidLength > gPush.ttcMaxForce) avoid *= gPush.ttcMaxForce / avoidLength;
    vec2 pref = prefSpeed > cap ? gVPref * (cap / prefSpeed) : gVPref;
    v = gVCur + ((pref - gVCur) / gPush.ttcXi + avoid) * gPush.dt;
    float speed = length(v);
    if (speed > goal.z) v *= goal.z / speed;  // avoidance may still use the full speed
  }
  // The rule's courses all run at the preferred speed (or stand): scaled down together, and
  // left alone where the density allows it (no rounding of a free agent's course).
  if (kPolicy == kSteerPolicyRule && prefSpeed > cap) v *= cap / prefSpeed;

  float speed = length(v);
  if (speed > 1e-3) placement[i].w = atan(v.x, v.y);
  // steer.w: the flags, or while waiting minus the steps waited so far.
  float stateOut = flags == kSteerFlagWaiting ? min(state.w, 0.0) - 1.0 : float(flags);
  steerWords[i] = toWords(vec4(v, speed, stateOut));
  // The clip pair of the agent's range maps its speed to the speed weight.
  float slow = i < gPush.setEnd.x ? gPush.setSlow.x : i < gPush.setEnd.y ? gPush.setSlow.y : i < gPush.setEnd.z ? gPush.setSlow.z : gPush.setSlow.w;
  float fast = i < gPush.setEnd.x ? gPush.setFast.x : i < gPush.setEnd.y ? gPush.setFast.y : i < gPush.setEnd.z ? gPush.setFast.z : gPush.setFast.w;
  if (fast > slow) motion[i] = withTargetSpeedWeight(motion[i], clamp((speed - slow) / (fast - slow), 0.0, 1.0));
}
