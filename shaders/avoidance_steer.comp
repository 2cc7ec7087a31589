#version 450
#extension GL_GOOGLE_include_directive : require
// Steering, one invocation per agent: the velocity that heads for the path-vector waypoint
// (goal), changed by the avoidance policy, written as heading (placement.w), velocity and
// speed (steer) and speed weight (motion.z = wTarget). Neighbours come from the grid's sorted
// copy, so reading them never races with the writes. CPU twin: crowd::steerCpu.
#include "crowd_types.h"
#include "avoidance_common.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Placement { vec4 placement[]; };
layout(std430, binding = 1) buffer Motion { vec4 motion[]; };
layout(std430, binding = 2) readonly buffer Goals { vec4 goals[]; };
layout(std430, binding = 3) buffer Steer { vec4 steer[]; };
layout(std430, binding = 4) readonly buffer Counts { uint counts[]; };
layout(std430, binding = 5) readonly buffer Starts { uint starts[]; };
layout(std430, binding = 6) readonly buffer SortedIndex { uint sortedIndex[]; };
layout(std430, binding = 7) readonly buffer Sorted { vec4 sorted[]; };
layout(push_constant) uniform Push { SteerPush push; };

// Karamouzas, Skinner & Guy 2014: E = k τ^-2 e^(-τ/τ0) over the time to collision τ of two
// discs; the force on agent i is −∇E = k e^(-τ/τ0) τ^-2 (2/τ + 1/τ0) (x + τ v) / √D, with x, v
// the relative position and velocity and D the discriminant. Overlapping discs are pushed apart.
// τ is floored at 0.1 s and √D at 0.05·|v|² (s/|v|²: half the time the discs would overlap):
// both forces are far above the cap there anyway, and without the floors the τ^-3 and 1/√D
// singularities turn float rounding into different steering on the GPU and the CPU twin.
vec2 ttcForce(vec2 x, vec2 v, float dist2) {
  float diameter = 2.0 * push.radius;
  float c = dist2 - diameter * diameter;
  if (c < 0.0) {
    float d = sqrt(dist2);
    return d > 1e-4 ? x * (push.ttcMaxForce * (diameter - d) / (diameter * d)) : vec2(0.0);
  }
  float a = dot(v, v);
  float b = dot(x, v);
  if (b >= 0.0 || a < 1e-6) return vec2(0.0);  // not approaching
  float disc = b * b - a * c;
  if (disc <= 0.0) return vec2(0.0);            // passing clear
  float s = sqrt(disc);
  float tau = c / (s - b);
  float t = max(tau, 0.1);
  float magnitude = push.ttcK * exp(-t / push.ttcTau0) / (t * t) * (2.0 / t + 1.0 / push.ttcTau0) / max(s, 0.05 * a);
  return (x + tau * v) * magnitude;
}

// Whether two agents come closer than `diameter2` (squared) within `horizon` seconds, from
// their relative position x and velocity v. Only while approaching: agents already too close
// may always move apart.
bool collides(vec2 x, vec2 v, float horizon, float diameter2) {
  float xv = dot(x, v);
  if (xv >= 0.0) return false;
  vec2 d = x + v * min(-xv / dot(v, v), horizon);
  return dot(d, d) < diameter2;
}

void main() {
  // Invocations walk the agents in grid order, so neighbouring lanes scan the same cells
  // (coherent loops and caches; on lavapipe about twice as fast as agent order).
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= push.agentCount) return;
  uint i = sortedIndex[slot];
  vec4 goal = goals[i];
  if (goal.w == 0.0) {
    steer[i] = vec4(0.0);
    return;
  }
  vec4 place = placement[i];
  vec2 pos = place.xz;
  vec2 vPref = (goal.xy - pos) * push.invSecondsLeft;
  float prefSpeed = length(vPref);
  if (prefSpeed > goal.z) {
    vPref *= goal.z / prefSpeed;
    prefSpeed = goal.z;
  }
  vec2 vCur = steer[i].xy;

  // The rule tests courses: towards the waypoint, on along the current heading, and
  // kRuleDraws random headings within the gaze around the waypoint's direction.
  float goalHeading = prefSpeed > 1e-4 ? atan(vPref.x, vPref.y) : place.w;
  vec2 keep = prefSpeed * vec2(sin(place.w), cos(place.w));
  vec2 draws[kRuleDraws];
  for (uint d = 0u; d < kRuleDraws; ++d) draws[d] = vec2(0.0);
  if (push.policy == kSteerPolicyRule) {
    for (uint d = 0u; d < kRuleDraws; ++d) {
      float heading = goalHeading + (steerRandom(i, push.step * kRuleDraws + d, push.seed) - 0.5) * push.gazeAngle;
      draws[d] = prefSpeed * vec2(sin(heading), cos(heading));
    }
  }
  bool blocked = false, keepBlocked = false;
  uint drawBlocked = 0u;
  vec2 avoid = vec2(0.0);
  if (push.policy != kSteerPolicyNone) {
    float diameter2 = 4.0 * push.radius * push.radius;
    float sensing2 = push.sensing * push.sensing;
    ivec2 home = cellCoord(pos, push.invCellSize);
    for (int dz = -push.cellRange; dz <= push.cellRange; ++dz) {
      for (int dx = -push.cellRange; dx <= push.cellRange; ++dx) {
        ivec2 cell = home + ivec2(dx, dz);
        uint h = cellHash(cell, push.cellCount);
        uint first = starts[h];
        uint end = first + counts[h];
        for (uint k = first; k < end; ++k) {
          vec4 other = sorted[k];
          if (k == slot || cellCoord(other.xy, push.invCellSize) != cell) continue;
          vec2 x = pos - other.xy;
          float dist2 = dot(x, x);
          if (dist2 >= sensing2) continue;
          if (push.policy == kSteerPolicyRule) {
            vec2 theirs = other.zw;
            if (collides(x, vPref - theirs, push.lookahead, diameter2)) blocked = true;
            if (collides(x, keep - theirs, push.lookahead, diameter2)) keepBlocked = true;
            for (uint d = 0u; d < kRuleDraws; ++d)
              if (collides(x, draws[d] - theirs, push.lookahead, diameter2)) drawBlocked |= 1u << d;
          } else {
            avoid += ttcForce(x, vCur - other.zw, dist2);
          }
        }
      }
    }
  }

  vec2 v = vPref;
  uint flags = 0u;
  if (push.policy == kSteerPolicyRule && blocked) {
    // Keep an earlier turn while its course is free and still within the gaze around the
    // waypoint; else take the first free random heading; else wait, but for at most
    // kRuleMaxWait seconds before taking the first draw anyway (a dense crossing would
    // otherwise wait for ever).
    bool inGaze = prefSpeed > 1e-4 && dot(keep, vPref) >= push.cosHalfGaze * prefSpeed * prefSpeed;
    float waited = max(-steer[i].w, 0.0) * push.dt;
    if (!keepBlocked && inGaze) {
      v = keep;
      flags = kSteerFlagKept;
    } else {
      v = waited < kRuleMaxWait ? vec2(0.0) : draws[0];
      flags = waited < kRuleMaxWait ? kSteerFlagWaiting : kSteerFlagForced;
      for (uint d = 0u; d < kRuleDraws; ++d) {
        if ((drawBlocked & (1u << d)) == 0u) {
          v = draws[d];
          flags = kSteerFlagTurned;
          break;
        }
      }
    }
  } else if (push.policy == kSteerPolicyTtc) {
    float avoidLength = length(avoid);
    if (avoidLength > push.ttcMaxForce) avoid *= push.ttcMaxForce / avoidLength;
    v = vCur + ((vPref - vCur) / push.ttcXi + avoid) * push.dt;
    float speed = length(v);
    if (speed > goal.z) v *= goal.z / speed;
  }

  float speed = length(v);
  if (speed > 1e-3) place.w = atan(v.x, v.y);
  placement[i] = place;
  // steer.w: the flags, or while waiting minus the steps waited so far.
  float state = flags == kSteerFlagWaiting ? min(steer[i].w, 0.0) - 1.0 : float(flags);
  steer[i] = vec4(v, speed, state);
  if (push.fastSpeed > push.slowSpeed)
    motion[i].z = clamp((speed - push.slowSpeed) / (push.fastSpeed - push.slowSpeed), 0.0, 1.0);
}
