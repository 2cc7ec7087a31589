#version 450
#extension GL_GOOGLE_include_directive : require
// The frame's visibility buffer into the colour and depth planes the target is copied from. The
// buffer started as the ground (ground.comp's words, copied in) and every splat kept each pixel's
// nearest hit in it by atomicMin, so it holds the whole picture: a pixel's word is its colour
// (low 32 bits) and its depth (high 32). Four pixels per invocation: the words are read as
// texels of two pixels (a texel view: lavapipe gathers a texel fetch's lanes in vector loads) and
// the planes written as 16-byte stores (lavapipe runs each storage access as a loop over the
// lanes; its image stores to a texel view cost more still).
#include "shared_types.h"
#include "render_bindings.h"

layout(local_size_x = 64) in;
layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
// The visibility words as texels of two pixels' (colour, depth) pairs (R32G32B32A32_UINT).
layout(binding = kRenderBindingVisibility) uniform usamplerBuffer visibilityPairs;
// The colour plane, then the depth plane from word visibilityDepthPlane(pixels) (a multiple of
// four, so that both planes hold whole uvec4s).
layout(std430, binding = kRenderBindingFramePlanes) writeonly buffer Planes { uint planes[]; };
layout(std430, binding = kRenderBindingFramePlanes) writeonly buffer PlaneQuads { uvec4 planeQuads[]; };
layout(push_constant) uniform Push { uint planes; } push;  // kPlanesWithDepth or 0

void main() {
  uint pixels = uint(frame.viewport.x) * uint(frame.viewport.y);
  uint depthQuads = visibilityDepthPlane(pixels) / 4u;
  uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  // Read here, before the loop: lavapipe reads a push constant inside a loop lane by lane.
  bool withDepth = push.planes == kPlanesWithDepth;
  for (uint i = gl_GlobalInvocationID.x; i < pixels / 4u; i += stride) {
    uvec4 a = texelFetch(visibilityPairs, int(2u * i)), b = texelFetch(visibilityPairs, int(2u * i + 1u));
    planeQuads[i] = uvec4(a.xz, b.xz);
    if (withDepth) planeQuads[depthQuads + i] = uvec4(a.yw, b.yw);
  }
  uint rest = pixels & 3u;
  if (gl_GlobalInvocationID.x < rest) {
    uint p = pixels - rest + gl_GlobalInvocationID.x;
    uvec4 pair = texelFetch(visibilityPairs, int(p / 2u));
    uvec2 last = (p & 1u) != 0u ? pair.zw : pair.xy;
    planes[p] = last.x;
    if (withDepth) planes[visibilityDepthPlane(pixels) + p] = last.y;
  }
}
