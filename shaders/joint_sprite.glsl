// What the joint draw and the joint splat share: the ellipsoid of a joint draw matrix, its
// screen footprint, the ray/ellipsoid hit, the character tint and the lighting. One definition
// so both paths shade identically (CPU twin: engine/render/joint_splat_cpu.cpp).
#ifndef THRONG_JOINT_SPRITE_GLSL
#define THRONG_JOINT_SPRITE_GLSL

struct JointSprite {
  vec4 inverse0;  // rows of the world → unit-sphere affine map
  vec4 inverse1;
  vec4 inverse2;
  vec4 clip;      // clip-space centre
  vec2 lo, hi;    // the ellipsoid's exact screen bounding box, pixels
  float sizePx;   // its larger side
  bool visible;
};

// The joint draw matrix maps the unit mesh space (sphere of radius 1 around (0, 0.5, 0),
// squashed to y in [0, 1]) to the world; B·u + c maps the unit sphere u to the world.
JointSprite jointSprite(JointMatrix a, FrameUniforms frame) {
  JointSprite s;
  vec3 t = vec3(a.row0.w, a.row1.w, a.row2.w);
  vec3 b0 = vec3(a.row0.x, a.row1.x, a.row2.x);
  vec3 b1 = 0.5 * vec3(a.row0.y, a.row1.y, a.row2.y);
  vec3 b2 = vec3(a.row0.z, a.row1.z, a.row2.z);
  vec3 centre = t + b1;
  vec3 axisLengthSq = vec3(dot(b0, b0), dot(b1, b1), dot(b2, b2));
  s.clip = frame.viewProjection * vec4(centre, 1.0);
  float radius = sqrt(max(axisLengthSq.x, max(axisLengthSq.y, axisLengthSq.z)));
  s.visible = min(axisLengthSq.x, min(axisLengthSq.y, axisLengthSq.z)) >= 1e-10 && s.clip.w > radius;
  if (!s.visible) {
    s.sizePx = 0.0;
    return s;
  }
  // B = R·S, so B⁻¹ = S⁻² Bᵀ: rows are the columns over their squared lengths.
  vec3 r0 = b0 / axisLengthSq.x, r1 = b1 / axisLengthSq.y, r2 = b2 / axisLengthSq.z;
  s.inverse0 = vec4(r0, -dot(r0, centre));
  s.inverse1 = vec4(r1, -dot(r1, centre));
  s.inverse2 = vec4(r2, -dot(r2, centre));
  // Exact screen bounding box of the projected ellipsoid (the quadric method of Sigg et al.
  // 2006): with T = VP·[B c] mapping the unit sphere to clip space and D = diag(1,1,1,-1),
  // the x extent is (b ± sqrt(b² - a·c)) / a for a = rw·D·rw, b = rx·D·rw, c = rx·D·rx.
  mat4 t4 = frame.viewProjection * mat4(vec4(b0, 0.0), vec4(b1, 0.0), vec4(b2, 0.0), vec4(centre, 1.0));
  vec4 rx = vec4(t4[0].x, t4[1].x, t4[2].x, t4[3].x);
  vec4 ry = vec4(t4[0].y, t4[1].y, t4[2].y, t4[3].y);
  vec4 rw = vec4(t4[0].w, t4[1].w, t4[2].w, t4[3].w);
  const vec4 d = vec4(1.0, 1.0, 1.0, -1.0);
  float qa = dot(rw, d * rw);
  float bx = dot(rx, d * rw), cx = dot(rx, d * rx);
  float by = dot(ry, d * rw), cy = dot(ry, d * ry);
  if (qa >= 0.0) {  // the ellipsoid reaches the camera plane: leave it out
    s.visible = false;
    s.sizePx = 0.0;
    return s;
  }
  float hx = sqrt(max(bx * bx - qa * cx, 0.0)), hy = sqrt(max(by * by - qa * cy, 0.0));
  vec2 ndcLo = vec2(min((bx + hx) / qa, (bx - hx) / qa), min((by + hy) / qa, (by - hy) / qa));
  vec2 ndcHi = vec2(max((bx + hx) / qa, (bx - hx) / qa), max((by + hy) / qa, (by - hy) / qa));
  s.lo = (ndcLo * 0.5 + 0.5) * frame.viewport.xy;
  s.hi = (ndcHi * 0.5 + 0.5) * frame.viewport.xy;
  s.sizePx = max(s.hi.x - s.lo.x, s.hi.y - s.lo.y) + 2.0;
  return s;
}

// Ray from the eye through a pixel centre (gl_FragCoord convention).
vec3 pixelRay(vec2 pixel, FrameUniforms frame) {
  vec2 ndc = pixel / frame.viewport.xy * 2.0 - 1.0;
  return normalize(frame.rayForward.xyz + ndc.x * frame.rayRight.xyz + ndc.y * frame.rayDown.xyz);
}

// (o·d)² − |d|²·(|o|² − 1): ≥ 0 where the ray o + t·d meets the unit sphere, written as
// |d|² − |o × d|² (Lagrange's identity). The eye is hundreds of radii from a thin bone, and the
// textbook form's two terms would cancel to their rounding. CPU twin: unitSphereDiscriminantCpu.
float unitSphereDiscriminant(vec3 o, vec3 d) {
  vec3 across = cross(o, d);
  return dot(d, d) - dot(across, across);
}

// Hit of the ray with the ellipsoid: true with the world hit distance and world normal.
bool hitJoint(vec3 eye, vec3 dir, vec4 inverse0, vec4 inverse1, vec4 inverse2, out float t, out vec3 normal) {
  mat3 inv = transpose(mat3(inverse0.xyz, inverse1.xyz, inverse2.xyz));
  vec3 o = inv * eye + vec3(inverse0.w, inverse1.w, inverse2.w);
  vec3 d = inv * dir;
  float a = dot(d, d), b = dot(o, d);
  float disc = unitSphereDiscriminant(o, d);
  t = (-b - sqrt(max(disc, 0.0))) / a;
  normal = normalize(transpose(inv) * (o + t * d));
  return disc >= 0.0 && t > 0.0;
}

uint hashIndex(uint x) {
  x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16;
  return x;
}

vec3 hueToRgb(float h) {
  vec3 k = abs(fract(vec3(h) + vec3(0.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0);
  return clamp(k - 1.0, 0.0, 1.0);
}

vec3 characterTint(uint character) {
  uint h = hashIndex(character);
  return mix(hueToRgb(float(h & 1023u) / 1024.0), vec3(0.85), 0.25) * (0.75 + 0.25 * float((h >> 10) & 3u) / 3.0);
}

// A storyboard group's colour: hues a golden-ratio step apart, so neighbouring group numbers
// differ strongly; the character's own hash shades it a little, so individuals still read.
vec3 groupTint(uint group, uint character) {
  vec3 base = mix(hueToRgb(fract(0.08 + 0.618034 * float(group))), vec3(0.85), 0.15);
  return base * (0.8 + 0.2 * float(hashIndex(character) & 3u) / 3.0);
}

// Paper Fig. 8: near characters green, mid yellow, far red.
vec3 levelTint(uint level) {
  return level >= 2u ? vec3(0.25, 0.8, 0.3) : level == 1u ? vec3(0.95, 0.8, 0.2) : vec3(0.9, 0.25, 0.2);
}

// Directional + sky ambient + a little rim so silhouettes read at a distance; gamma-encoded.
vec3 shadeJoint(vec3 tint, vec3 n, vec3 dir, vec3 light) {
  float diffuse = max(dot(n, light), 0.0);
  float sky = 0.5 + 0.5 * n.y;
  float edge = 1.0 - max(dot(n, -dir), 0.0);
  float rim = edge * edge * edge;
  vec3 col = tint * (0.28 + 0.22 * sky + 0.75 * diffuse) + 0.12 * rim;
  return vec3(gammaEncode(col.x), gammaEncode(col.y), gammaEncode(col.z));
}

#endif
