#version 450
#extension GL_GOOGLE_include_directive : require
// Kinematic integration of the steering output: position += velocity · dt for active agents.
// CPU twin: crowd::advanceCpu. (The render path moves characters by root motion instead.)
#include "crowd_types.h"
#include "crowd_bindings.h"

layout(local_size_x = 64) in;
layout(std430, binding = kAdvanceBindingPlacement) buffer Placement { vec4 placement[]; };
layout(std430, binding = kAdvanceBindingSteer) readonly buffer Steer { vec4 steer[]; };
layout(std430, binding = kAdvanceBindingGoals) readonly buffer Goals { vec4 goals[]; };
layout(push_constant) uniform Push { AdvancePush push; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.agentCount || goals[i].w == 0.0) return;
  vec4 p = placement[i];
  vec2 v = steer[i].xy;
  p.x += v.x * push.dt;
  p.z += v.y * push.dt;
  placement[i] = p;
}
