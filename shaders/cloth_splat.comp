#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_EXT_control_flow_attributes : require
// Cloth playback, far capes: one invocation per cape at the splat level projects its vertices,
// sets each triangle up as planes over the screen (barycentrics b0, b1 and depth, a·x + b·y + c),
// then walks the pixels of the cape's bounding box once, stepping the planes along each row; at
// each pixel the nearest triangle covering its centre (the first on equal depth) gives
// (depth bits << 32 | colour), kept with one 64-bit atomicMin in the joint renderer's visibility
// buffer like joint_splat.comp; the renderer's resolve (visibility_planes.comp, or
// splat_resolve.frag) writes it with depth. Flat two-sided
// shading per triangle. Twin: secondary::splatCapesCpu (the same planes and steps).
//
// Why this shape (lavapipe runs 8 lanes in lock step and executes every branch with a mask, so
// the straight-line code runs for every cape and a loop runs as long as its slowest lane; a load
// or an atomic with per-lane addresses is a loop over the lanes):
// - one pixel loop over the cape's box instead of one per triangle: the per-lane memory loops
//   (a load, then the atomic when nearer) run once per pixel, not once per triangle and pixel;
// - per pixel and triangle only additions and compares (planes stepped, no edge functions);
// - vertices, character and placement read as 64-bit words (half the per-lane loads);
// - the level's mesh baked in (specialization constants) and used through macros, so every
//   vertex and triangle index is a constant after specialization.
#include "cloth_types.h"
#include "cloth_bindings.h"

layout(local_size_x = 64) in;
layout(constant_id = kClothSplatConstantVertices) const uint kVertices = 0u;  // of the splat level (<= kClothSplatMaxVertices)
layout(constant_id = kClothSplatConstantTriangles) const uint kTriangles = 0u;  // (<= kClothSplatMaxTriangles)
layout(constant_id = kClothSplatConstantIndices + 0u) const uint kIndex0 = 0u;
layout(constant_id = kClothSplatConstantIndices + 1u) const uint kIndex1 = 0u;
layout(constant_id = kClothSplatConstantIndices + 2u) const uint kIndex2 = 0u;
layout(constant_id = kClothSplatConstantIndices + 3u) const uint kIndex3 = 0u;
layout(constant_id = kClothSplatConstantIndices + 4u) const uint kIndex4 = 0u;
layout(constant_id = kClothSplatConstantIndices + 5u) const uint kIndex5 = 0u;
layout(constant_id = kClothSplatConstantIndices + 6u) const uint kIndex6 = 0u;
layout(constant_id = kClothSplatConstantIndices + 7u) const uint kIndex7 = 0u;
layout(constant_id = kClothSplatConstantIndices + 8u) const uint kIndex8 = 0u;
layout(constant_id = kClothSplatConstantIndices + 9u) const uint kIndex9 = 0u;
layout(constant_id = kClothSplatConstantIndices + 10u) const uint kIndex10 = 0u;
layout(constant_id = kClothSplatConstantIndices + 11u) const uint kIndex11 = 0u;
layout(constant_id = kClothSplatConstantIndices + 12u) const uint kIndex12 = 0u;
layout(constant_id = kClothSplatConstantIndices + 13u) const uint kIndex13 = 0u;
layout(constant_id = kClothSplatConstantIndices + 14u) const uint kIndex14 = 0u;
layout(constant_id = kClothSplatConstantIndices + 15u) const uint kIndex15 = 0u;
layout(constant_id = kClothSplatConstantIndices + 16u) const uint kIndex16 = 0u;
layout(constant_id = kClothSplatConstantIndices + 17u) const uint kIndex17 = 0u;
layout(constant_id = kClothSplatConstantIndices + 18u) const uint kIndex18 = 0u;
layout(constant_id = kClothSplatConstantIndices + 19u) const uint kIndex19 = 0u;
layout(constant_id = kClothSplatConstantIndices + 20u) const uint kIndex20 = 0u;
layout(constant_id = kClothSplatConstantIndices + 21u) const uint kIndex21 = 0u;
layout(constant_id = kClothSplatConstantIndices + 22u) const uint kIndex22 = 0u;
layout(constant_id = kClothSplatConstantIndices + 23u) const uint kIndex23 = 0u;
layout(constant_id = kClothSplatConstantIndices + 24u) const uint kIndex24 = 0u;
layout(constant_id = kClothSplatConstantIndices + 25u) const uint kIndex25 = 0u;
layout(constant_id = kClothSplatConstantIndices + 26u) const uint kIndex26 = 0u;
layout(constant_id = kClothSplatConstantIndices + 27u) const uint kIndex27 = 0u;
layout(constant_id = kClothSplatConstantIndices + 28u) const uint kIndex28 = 0u;
layout(constant_id = kClothSplatConstantIndices + 29u) const uint kIndex29 = 0u;
layout(constant_id = kClothSplatConstantIndices + 30u) const uint kIndex30 = 0u;
layout(constant_id = kClothSplatConstantIndices + 31u) const uint kIndex31 = 0u;
layout(constant_id = kClothSplatConstantIndices + 32u) const uint kIndex32 = 0u;
layout(constant_id = kClothSplatConstantIndices + 33u) const uint kIndex33 = 0u;
layout(constant_id = kClothSplatConstantIndices + 34u) const uint kIndex34 = 0u;
layout(constant_id = kClothSplatConstantIndices + 35u) const uint kIndex35 = 0u;
layout(constant_id = kClothSplatConstantIndices + 36u) const uint kIndex36 = 0u;
layout(constant_id = kClothSplatConstantIndices + 37u) const uint kIndex37 = 0u;
layout(constant_id = kClothSplatConstantIndices + 38u) const uint kIndex38 = 0u;
layout(constant_id = kClothSplatConstantIndices + 39u) const uint kIndex39 = 0u;
layout(constant_id = kClothSplatConstantIndices + 40u) const uint kIndex40 = 0u;
layout(constant_id = kClothSplatConstantIndices + 41u) const uint kIndex41 = 0u;
layout(constant_id = kClothSplatConstantIndices + 42u) const uint kIndex42 = 0u;
layout(constant_id = kClothSplatConstantIndices + 43u) const uint kIndex43 = 0u;
layout(constant_id = kClothSplatConstantIndices + 44u) const uint kIndex44 = 0u;
layout(constant_id = kClothSplatConstantIndices + 45u) const uint kIndex45 = 0u;
layout(constant_id = kClothSplatConstantIndices + 46u) const uint kIndex46 = 0u;
layout(constant_id = kClothSplatConstantIndices + 47u) const uint kIndex47 = 0u;

// The view is read as a storage buffer, not a uniform buffer: with it in a uniform buffer every
// dispatch of this shader cost ≈ 2.5 ms more on lavapipe (Mesa 22.3.6) whatever the number of
// capes (GPU timestamps: 3.0 → 0.5 ms for 400 capes); the mark pass shows no such cost.
layout(std430, binding = kClothSplatBindingView) readonly buffer View { ClothView view; };
// ClothCharacter as two words: (state | node << 32, blendSource | countdown << 32).
layout(std430, binding = kClothSplatBindingCharacters) readonly buffer Characters { uint64_t characterWords[]; };
layout(std430, binding = kClothSplatBindingPlacement) readonly buffer Placement { uint64_t placementWords[]; };  // vec4
layout(std430, binding = kClothSplatBindingMotion) readonly buffer Motion { vec4 motion[]; };
layout(std430, binding = kClothSplatBindingDrawList) readonly buffer DrawList { uint drawList[]; };
layout(std430, binding = kClothSplatBindingSlots) readonly buffer Slots { uvec2 slots[]; };
// Floats, 3 per vertex; a slot starts at a multiple of 4 vertices, so at a whole 64-bit word.
layout(std430, binding = kClothSplatBindingPool) readonly buffer Pool { uint64_t poolWords[]; };
layout(std430, binding = kClothSplatBindingGraph) readonly buffer Graph { uint graph[]; };
layout(std430, binding = kClothSplatBindingDraws) readonly buffer Draws { uint draws[]; };
layout(std430, binding = kClothSplatBindingVisibility) buffer Visibility { uint64_t visibility[]; };
layout(push_constant) uniform Push { ClothSplatPush push; };
#define CLOTH_HAS_GRAPH
#include "cloth_common.glsl"

const uint kMaxWords = (3u * kClothSplatMaxVertices + 1u) / 2u;
const int kNone = 0x3FFFFFFF;

float edge(vec2 a, vec2 b, vec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

// Per triangle of the cape, as planes over the screen: barycentrics b0, b1 and depth z are
// a·x + b·y + c at the pixel centre (x, y); a skipped triangle never covers (b0 = b1 = -1,
// depth 2). Its pixel box only bounds the cape's.
vec3 plane0[kClothSplatMaxTriangles], plane1[kClothSplatMaxTriangles], planeZ[kClothSplatMaxTriangles];
ivec4 box[kClothSplatMaxTriangles];
uint colour[kClothSplatMaxTriangles];
vec3 world[kClothSplatMaxVertices];
vec3 screen[kClothSplatMaxVertices];

void setupTriangle(uint t, uint i0, uint i1, uint i2, vec3 base) {
  vec3 p0 = screen[i0], p1 = screen[i1], p2 = screen[i2];
  float area = edge(p0.xy, p1.xy, p2.xy);
  vec2 lo = min(min(p0.xy, p1.xy), p2.xy), hi = max(max(p0.xy, p1.xy), p2.xy);
  ivec2 from = max(ivec2(ceil(lo - 0.5)), ivec2(0));
  ivec2 to = min(ivec2(floor(hi - 0.5)), ivec2(view.viewport.xy) - 1);
  bool skip = abs(area) < 1e-8 || from.x > to.x || from.y > to.y;
  box[t] = skip ? ivec4(kNone, kNone, -kNone, -kNone) : ivec4(from, to);
  float inverse = 1.0 / area;
  vec2 e0 = vec2(p1.y - p2.y, p2.x - p1.x) * inverse, e1 = vec2(p2.y - p0.y, p0.x - p2.x) * inverse;
  vec3 b0 = vec3(e0, -(e0.x * p1.x + e0.y * p1.y)), b1 = vec3(e1, -(e1.x * p2.x + e1.y * p2.y));
  plane0[t] = skip ? vec3(0.0, 0.0, -1.0) : b0;
  plane1[t] = skip ? vec3(0.0, 0.0, -1.0) : b1;
  planeZ[t] = skip ? vec3(0.0, 0.0, 2.0) : b0 * (p0.z - p2.z) + b1 * (p1.z - p2.z) + vec3(0.0, 0.0, p2.z);
  vec3 n = normalize(cross(world[i1] - world[i0], world[i2] - world[i0]));
  if (dot(n, view.eye.xyz - world[i0]) < 0.0) n = -n;
  colour[t] = packUnorm4x8(vec4(base * (0.35 + 0.65 * max(dot(n, view.light.xyz), 0.0)), 1.0));
}

// Triangle t of the level: its corners are specialization constants 3t, 3t + 1, 3t + 2.
#define SETUP(t, a, b, c) if (t < kTriangles) setupTriangle(t, a, b, c, base)

void main() {
  // Surplus lanes redo the last cape (atomicMin is idempotent): control flow stays uniform.
  uint count = draws[5u * kClothSplatLevel + 1u];
  if (count == 0u) return;
  uint character = drawList[kClothSplatLevel * push.characterCount + min(gl_GlobalInvocationID.x, count - 1u)];
  uvec2 stateNode = unpackUint2x32(characterWords[2u * character]);
  ClothCharacter c = ClothCharacter(stateNode.x, stateNode.y, kClothNone, 0u);
  uint word = 3u * slots[clothShownState(c, kClothSplatLevel)].x / 2u;  // any decode holds the splat level
  vec4 place = vec4(uintBitsToFloat(unpackUint2x32(placementWords[2u * character])),
                    uintBitsToFloat(unpackUint2x32(placementWords[2u * character + 1u])));
  float scale = characterScale(motion[character]);
  // The level's vertices as floats: 3 per vertex, rounded up to whole words (the slot holds them).
  float v[2u * kMaxWords];
  [[unroll]] for (uint w = 0u; w < kMaxWords; ++w) {
    if (w >= (3u * kVertices + 1u) / 2u) break;
    vec2 pair = uintBitsToFloat(unpackUint2x32(poolWords[word + w]));
    v[2u * w] = pair.x;
    v[2u * w + 1u] = pair.y;
  }
  // clothRotateY with the sine and cosine taken once per cape.
  vec2 heading = scale * vec2(cos(place.w), sin(place.w));
  [[unroll]] for (uint k = 0u; k < kClothSplatMaxVertices; ++k) {
    if (k >= kVertices) break;
    vec3 p = vec3(v[3u * k], v[3u * k + 1u], v[3u * k + 2u]);
    world[k] = place.xyz + vec3(heading.x * p.x + heading.y * p.z, scale * p.y, -heading.y * p.x + heading.x * p.z);
    vec4 clip = view.viewProjection * vec4(world[k], 1.0);
    screen[k] = vec3((clip.xy / clip.w * 0.5 + 0.5) * view.viewport.xy, clip.z / clip.w);
  }
  vec3 base = view.viewport.w != 0.0 ? clothLevelTint(kClothSplatLevel) : clothTint(character);
  SETUP(0u, kIndex0, kIndex1, kIndex2);
  SETUP(1u, kIndex3, kIndex4, kIndex5);
  SETUP(2u, kIndex6, kIndex7, kIndex8);
  SETUP(3u, kIndex9, kIndex10, kIndex11);
  SETUP(4u, kIndex12, kIndex13, kIndex14);
  SETUP(5u, kIndex15, kIndex16, kIndex17);
  SETUP(6u, kIndex18, kIndex19, kIndex20);
  SETUP(7u, kIndex21, kIndex22, kIndex23);
  SETUP(8u, kIndex24, kIndex25, kIndex26);
  SETUP(9u, kIndex27, kIndex28, kIndex29);
  SETUP(10u, kIndex30, kIndex31, kIndex32);
  SETUP(11u, kIndex33, kIndex34, kIndex35);
  SETUP(12u, kIndex36, kIndex37, kIndex38);
  SETUP(13u, kIndex39, kIndex40, kIndex41);
  SETUP(14u, kIndex42, kIndex43, kIndex44);
  SETUP(15u, kIndex45, kIndex46, kIndex47);
  ivec4 cape = ivec4(kNone, kNone, -kNone, -kNone);
  [[unroll]] for (uint t = 0u; t < kClothSplatMaxTriangles; ++t) {
    if (t >= kTriangles) break;
    cape = ivec4(min(cape.xy, box[t].xy), max(cape.zw, box[t].zw));
  }
  uint width = uint(view.viewport.x);
  for (int y = cape.y; y <= cape.w; ++y) {
    vec2 start = vec2(float(cape.x), float(y)) + 0.5;
    float r0[kClothSplatMaxTriangles], r1[kClothSplatMaxTriangles], rz[kClothSplatMaxTriangles];
    [[unroll]] for (uint t = 0u; t < kClothSplatMaxTriangles; ++t) {
      if (t >= kTriangles) break;
      r0[t] = plane0[t].x * start.x + plane0[t].y * start.y + plane0[t].z;
      r1[t] = plane1[t].x * start.x + plane1[t].y * start.y + plane1[t].z;
      rz[t] = planeZ[t].x * start.x + planeZ[t].y * start.y + planeZ[t].z;
    }
    for (int x = cape.x; x <= cape.z; ++x) {
      float nearest = 2.0;
      uint nearestColour = 0u;
      [[unroll]] for (uint t = 0u; t < kClothSplatMaxTriangles; ++t) {
        if (t >= kTriangles) break;
        float b0 = r0[t], b1 = r1[t], z = rz[t];
        float b2 = 1.0 - b0 - b1;
        bool inside = min(min(b0, b1), b2) >= 0.0 && z >= 0.0 && z <= 1.0 && z < nearest;
        nearest = inside ? z : nearest;
        nearestColour = inside ? colour[t] : nearestColour;
        r0[t] = b0 + plane0[t].x;
        r1[t] = b1 + plane1[t].x;
        rz[t] = z + planeZ[t].x;
      }
      uint at = uint(y) * width + uint(x);
      uint64_t packed = (uint64_t(floatBitsToUint(nearest)) << 32) | uint64_t(nearestColour);
      if (nearest <= 1.0 && packed < visibility[at]) atomicMin(visibility[at], packed);
    }
  }
}
