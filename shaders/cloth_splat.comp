#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_EXT_control_flow_attributes : require
// Cloth playback, far capes: one invocation per cape at the splat level projects its vertices,
// then rasterizes its triangles over the pixels whose centres they cover and keeps the nearest hit
// per pixel in the joint renderer's visibility buffer, a 64-bit atomicMin of
// (depth bits << 32 | colour) like joint_splat.comp; the renderer's resolve pass writes it with
// depth. Flat two-sided shading per triangle. The level's mesh is baked in (specialization
// constants) and the loops unrolled, so the vertices stay in registers and no index is loaded.
// Twin: secondary::splatCapesCpu.
#include "cloth_types.h"

layout(local_size_x = 64) in;
layout(constant_id = 0) const uint kVertices = 0u;   // of the splat level (<= kClothSplatMaxVertices)
layout(constant_id = 1) const uint kTriangles = 0u;  // (<= kClothSplatMaxTriangles)
layout(constant_id = 2) const uint kIndex0 = 0u;
layout(constant_id = 3) const uint kIndex1 = 0u;
layout(constant_id = 4) const uint kIndex2 = 0u;
layout(constant_id = 5) const uint kIndex3 = 0u;
layout(constant_id = 6) const uint kIndex4 = 0u;
layout(constant_id = 7) const uint kIndex5 = 0u;
layout(constant_id = 8) const uint kIndex6 = 0u;
layout(constant_id = 9) const uint kIndex7 = 0u;
layout(constant_id = 10) const uint kIndex8 = 0u;
layout(constant_id = 11) const uint kIndex9 = 0u;
layout(constant_id = 12) const uint kIndex10 = 0u;
layout(constant_id = 13) const uint kIndex11 = 0u;
layout(constant_id = 14) const uint kIndex12 = 0u;
layout(constant_id = 15) const uint kIndex13 = 0u;
layout(constant_id = 16) const uint kIndex14 = 0u;
layout(constant_id = 17) const uint kIndex15 = 0u;
layout(constant_id = 18) const uint kIndex16 = 0u;
layout(constant_id = 19) const uint kIndex17 = 0u;
layout(constant_id = 20) const uint kIndex18 = 0u;
layout(constant_id = 21) const uint kIndex19 = 0u;
layout(constant_id = 22) const uint kIndex20 = 0u;
layout(constant_id = 23) const uint kIndex21 = 0u;
layout(constant_id = 24) const uint kIndex22 = 0u;
layout(constant_id = 25) const uint kIndex23 = 0u;
layout(constant_id = 26) const uint kIndex24 = 0u;
layout(constant_id = 27) const uint kIndex25 = 0u;
layout(constant_id = 28) const uint kIndex26 = 0u;
layout(constant_id = 29) const uint kIndex27 = 0u;
layout(constant_id = 30) const uint kIndex28 = 0u;
layout(constant_id = 31) const uint kIndex29 = 0u;
layout(constant_id = 32) const uint kIndex30 = 0u;
layout(constant_id = 33) const uint kIndex31 = 0u;
layout(constant_id = 34) const uint kIndex32 = 0u;
layout(constant_id = 35) const uint kIndex33 = 0u;
layout(constant_id = 36) const uint kIndex34 = 0u;
layout(constant_id = 37) const uint kIndex35 = 0u;
layout(constant_id = 38) const uint kIndex36 = 0u;
layout(constant_id = 39) const uint kIndex37 = 0u;
layout(constant_id = 40) const uint kIndex38 = 0u;
layout(constant_id = 41) const uint kIndex39 = 0u;
layout(constant_id = 42) const uint kIndex40 = 0u;
layout(constant_id = 43) const uint kIndex41 = 0u;
layout(constant_id = 44) const uint kIndex42 = 0u;
layout(constant_id = 45) const uint kIndex43 = 0u;
layout(constant_id = 46) const uint kIndex44 = 0u;
layout(constant_id = 47) const uint kIndex45 = 0u;
layout(constant_id = 48) const uint kIndex46 = 0u;
layout(constant_id = 49) const uint kIndex47 = 0u;

layout(std140, binding = 0) uniform View { ClothView view; };
layout(std430, binding = 1) readonly buffer Characters { ClothCharacter characters[]; };
layout(std430, binding = 2) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = 3) readonly buffer Motion { vec4 motion[]; };
layout(std430, binding = 4) readonly buffer DrawList { uint drawList[]; };
layout(std430, binding = 5) readonly buffer Slots { uvec2 slots[]; };
layout(std430, binding = 6) readonly buffer Pool { float pool[]; };
layout(std430, binding = 8) readonly buffer Graph { uint graph[]; };
layout(std430, binding = 10) readonly buffer Draws { uint draws[]; };
layout(std430, binding = 11) buffer Visibility { uint64_t visibility[]; };
layout(push_constant) uniform Push { ClothSplatPush push; };
#define CLOTH_HAS_GRAPH
#include "cloth_common.glsl"

// Pixel coordinates (x, y) and depth of a cape vertex, and its world position.
vec3 project(vec3 world) {
  vec4 clip = view.viewProjection * vec4(world, 1.0);
  return vec3((clip.xy / clip.w * 0.5 + 0.5) * view.viewport.xy, clip.z / clip.w);
}

float edge(vec2 a, vec2 b, vec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

void main() {
  // Surplus lanes redo the last cape (atomicMin is idempotent): control flow stays uniform.
  uint count = draws[5u * kClothSplatLevel + 1u];
  if (count == 0u) return;
  uint character = drawList[kClothSplatLevel * push.characterCount + min(gl_GlobalInvocationID.x, count - 1u)];
  ClothCharacter c = characters[character];
  uint slot = 3u * slots[clothShownState(c, kClothSplatLevel)].x;  // any decode holds the splat level
  vec4 place = placement[character];
  float scale = motion[character].w;
  // The level's triangles; constant after specialization and unrolling.
  const uint kIndices[48] = uint[48](
      kIndex0, kIndex1, kIndex2, kIndex3, kIndex4, kIndex5, kIndex6, kIndex7,
      kIndex8, kIndex9, kIndex10, kIndex11, kIndex12, kIndex13, kIndex14, kIndex15,
      kIndex16, kIndex17, kIndex18, kIndex19, kIndex20, kIndex21, kIndex22, kIndex23,
      kIndex24, kIndex25, kIndex26, kIndex27, kIndex28, kIndex29, kIndex30, kIndex31,
      kIndex32, kIndex33, kIndex34, kIndex35, kIndex36, kIndex37, kIndex38, kIndex39,
      kIndex40, kIndex41, kIndex42, kIndex43, kIndex44, kIndex45, kIndex46, kIndex47);
  vec3 world[kClothSplatMaxVertices];
  vec3 screen[kClothSplatMaxVertices];
  // clothRotateY with the sine and cosine taken once per cape.
  vec2 heading = scale * vec2(cos(place.w), sin(place.w));
  [[unroll]] for (uint k = 0u; k < kClothSplatMaxVertices; ++k) {
    if (k >= kVertices) break;
    uint o = slot + 3u * k;
    vec3 p = vec3(pool[o], pool[o + 1u], pool[o + 2u]);
    world[k] = place.xyz + vec3(heading.x * p.x + heading.y * p.z, scale * p.y, -heading.y * p.x + heading.x * p.z);
    screen[k] = project(world[k]);
  }
  vec3 base = view.viewport.w != 0.0 ? clothLevelTint(kClothSplatLevel) : clothTint(character);
  uint width = uint(view.viewport.x);
  [[unroll]] for (uint t = 0u; t < kClothSplatMaxTriangles; ++t) {
    if (t >= kTriangles) break;
    uint i0 = kIndices[3u * t], i1 = kIndices[3u * t + 1u], i2 = kIndices[3u * t + 2u];
    vec3 p0 = screen[i0], p1 = screen[i1], p2 = screen[i2];
    float area = edge(p0.xy, p1.xy, p2.xy);
    // Pixels whose centres lie inside the bounding box (clamped to the screen).
    vec2 lo = min(min(p0.xy, p1.xy), p2.xy), hi = max(max(p0.xy, p1.xy), p2.xy);
    ivec2 from = max(ivec2(ceil(lo - 0.5)), ivec2(0));
    ivec2 to = min(ivec2(floor(hi - 0.5)), ivec2(view.viewport.xy) - 1);
    if (abs(area) < 1e-8 || from.x > to.x || from.y > to.y) continue;
    vec3 n = normalize(cross(world[i1] - world[i0], world[i2] - world[i0]));
    if (dot(n, view.eye.xyz - world[i0]) < 0.0) n = -n;
    uint colour = packUnorm4x8(vec4(base * (0.35 + 0.65 * max(dot(n, view.light.xyz), 0.0)), 1.0));
    float inverseArea = 1.0 / area;
    for (int y = from.y; y <= to.y; ++y) {
      for (int x = from.x; x <= to.x; ++x) {
        vec2 p = vec2(x, y) + 0.5;
        float b0 = edge(p1.xy, p2.xy, p) * inverseArea, b1 = edge(p2.xy, p0.xy, p) * inverseArea;
        float b2 = 1.0 - b0 - b1;
        if (b0 < 0.0 || b1 < 0.0 || b2 < 0.0) continue;
        float depth = b0 * p0.z + b1 * p1.z + b2 * p2.z;
        if (depth < 0.0 || depth > 1.0) continue;
        // A plain load first: pixels already nearer (the character's own body, mostly) skip the atomic.
        uint at = uint(y) * width + uint(x);
        uint64_t packed = (uint64_t(floatBitsToUint(depth)) << 32) | uint64_t(colour);
        if (packed < visibility[at]) atomicMin(visibility[at], packed);
      }
    }
  }
}
