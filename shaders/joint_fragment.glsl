// joints.frag and joints_over_splat.frag: a near joint's pixel. Ray-casts the joint's ellipsoid
// through this pixel, writes its true depth, and shades it. The includer defines
// THRONG_DEPTH_FROM_VISIBILITY when the depth attachment starts cleared instead of holding the
// splatted picture's depths: the pixel is then tested against the visibility buffer here.
#include "shared_types.h"
#include "render_bindings.h"
#include "joint_sprite.glsl"

layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
#ifdef THRONG_DEPTH_FROM_VISIBILITY
// The splat's words as (colour, depth bits).
layout(std430, binding = kRenderBindingVisibility) readonly buffer Visibility { uvec2 visibility[]; };
#endif
layout(location = 0) flat in vec3 tint;
layout(location = 1) flat in vec4 inverse0;
layout(location = 2) flat in vec4 inverse1;
layout(location = 3) flat in vec4 inverse2;
layout(location = 0) out vec4 color;

void main() {
  vec3 dir = pixelRay(gl_FragCoord.xy, frame);
  float t;
  vec3 n;
  if (!hitJoint(frame.eye.xyz, dir, inverse0, inverse1, inverse2, t, n)) discard;
  vec4 clip = frame.viewProjection * vec4(frame.eye.xyz + t * dir, 1.0);
  float depth = clip.z / clip.w;
#ifdef THRONG_DEPTH_FROM_VISIBILITY
  // The attachment's test (VK_COMPARE_OP_LESS_OR_EQUAL) against the depth the planes would have
  // copied in: the same comparison of the same 32-bit floats.
  uint pixel = uint(gl_FragCoord.y) * uint(frame.viewport.x) + uint(gl_FragCoord.x);
  if (!(depth <= uintBitsToFloat(visibility[pixel].y))) discard;
#endif
  gl_FragDepth = depth;
  color = vec4(shadeJoint(tint, n, dir, frame.lightDirection.xyz), 1.0);
}
