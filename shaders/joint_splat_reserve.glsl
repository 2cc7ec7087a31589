// The joint splat's two passes (joint_splat.comp, joint_splat_walk.comp) share this: the
// work-list reservations and how a sprite or a far body gets its pixels. Needs the Frame,
// Visibility, Draws, NearList, Masks, Groups, Sprites, PixelOwners and SplatCounters bindings,
// the push block and joint_splat_common.glsl first.
#ifndef THRONG_JOINT_SPLAT_RESERVE_GLSL
#define THRONG_JOINT_SPLAT_RESERVE_GLSL

// Pixels whose centres lie inside the sprite's bounding box; false when there are none.
bool spriteBox(JointSprite s, out ivec2 lo, out ivec2 hi) {
  lo = max(ivec2(ceil(s.lo - 0.5)), ivec2(0));
  hi = min(ivec2(floor(s.hi - 0.5)), ivec2(frame.viewport.xy) - 1);
  return hi.x >= lo.x && hi.y >= lo.y;
}

// One reservation per subgroup (its lanes' sprites and pixels summed), not two atomics per
// joint on two shared counters: lavapipe runs a lane's atomics one at a time. Returns the first
// pixel entry; `fits` when the sprite (if any) and every entry are below the capacities. The
// caller gives every entry reserved below the capacity its value, kSplatNoEntry when the entries
// are not kept (in the
// loop that writes them: a loop of its own here would run its body for every caller, its lanes
// masked off). A lane's sprite and entries travel as one word (render_bindings.h,
// kSplatReserveSpriteShift), so one sum and one scan over the subgroup serve both: lavapipe runs
// each as a loop over the lanes.
const uint kReservePixelMask = (1u << kSplatReserveSpriteShift) - 1u;

uint reserveEntries(uint spriteCount, uint pixelCount, out uint sprite, out bool fits) {
  uint spriteBase = 0u, firstBase = 0u;
  uint word = (spriteCount << kSplatReserveSpriteShift) | pixelCount;
  uint total = subgroupAdd(word);
  if (subgroupElect()) {
    uint spriteTotal = total >> kSplatReserveSpriteShift;
    spriteBase = spriteTotal > 0u ? atomicAdd(counters.sprites, spriteTotal) : 0u;
    firstBase = atomicAdd(counters.pixels, total & kReservePixelMask);
  }
  uint before = subgroupExclusiveAdd(word);
  sprite = subgroupBroadcastFirst(spriteBase) + (before >> kSplatReserveSpriteShift);
  uint first = subgroupBroadcastFirst(firstBase) + (before & kReservePixelMask);
  fits = (spriteCount == 0u || sprite < kSpriteCapacity) &&
         first <= kPixelCapacity - min(pixelCount, kPixelCapacity);
  return first;
}

// The ray through pixel centre (x, y) meets a sprite's ellipsoid where its direction d, in the
// ellipsoid's unit-sphere space, lies in the cone from the eye o around the sphere:
// m·|d⊥|² ≤ (d·ô)², d⊥ being d's part across ô = o / |o| and m = |o|² − 1 (hitJoint's test,
// rearranged). d is linear in the pixel, d = dc + (x − lo.x)·dx + (y − lo.y)·dy from the box's
// first pixel, so each row is a quadratic in x whose roots bound the row's span. Taken from the
// box, not the screen's corner, every term stays of the box's size (the eye is hundreds of
// radii away: from the corner, rounding would swamp them). m uses a sphere 1/256 larger, so
// rounding never leaves out a pixel the ray-cast hits.
struct Silhouette {
  float a, invA;         // the quadratic's x² coefficient, the same in every row, and 1 / a
  vec2 halfB;            // its half x coefficient: halfB.x + r·halfB.y in row lo.y + r
  vec3 c;                // its constant: c.x + r·(2·c.y + r·c.z)
};

Silhouette silhouette(JointSprite s, ivec2 lo) {
  mat3 inv = transpose(mat3(s.inverse0.xyz, s.inverse1.xyz, s.inverse2.xyz));
  vec3 o = inv * frame.eye.xyz + vec3(s.inverse0.w, s.inverse1.w, s.inverse2.w);
  vec3 axis = normalize(o);
  vec2 ndc = (vec2(lo) + 0.5) / frame.viewport.xy * 2.0 - 1.0;
  vec3 dc = inv * (frame.rayForward.xyz + ndc.x * frame.rayRight.xyz + ndc.y * frame.rayDown.xyz);
  vec3 dx = inv * frame.rayRight.xyz * (2.0 / frame.viewport.x);
  vec3 dy = inv * frame.rayDown.xyz * (2.0 / frame.viewport.y);
  vec3 along = vec3(dot(dc, axis), dot(dx, axis), dot(dy, axis));  // d·ô of dc, dx, dy
  vec3 across0 = dc - along.x * axis, acrossX = dx - along.y * axis, acrossY = dy - along.z * axis;
  const float grown = 1.0 + 1.0 / 256.0;
  float m = dot(o, o) - grown * grown;
  Silhouette c;
  c.a = m * dot(acrossX, acrossX) - along.y * along.y;
  c.invA = 1.0 / c.a;
  c.halfB = vec2(m * dot(across0, acrossX) - along.x * along.y, m * dot(acrossY, acrossX) - along.z * along.y);
  c.c = vec3(m * dot(across0, across0) - along.x * along.x, m * dot(across0, acrossY) - along.x * along.z,
             m * dot(acrossY, acrossY) - along.z * along.z);
  return c;
}

// The pixels x..y of row `row` whose centres the silhouette holds, within the box lo..hi
// (x > y: none).
ivec2 silhouetteRow(Silhouette c, int row, ivec2 lo, ivec2 hi) {
  float r = float(row - lo.y);
  float halfB = c.halfB.x + r * c.halfB.y;
  float disc = halfB * halfB - c.a * (c.c.x + r * (2.0 * c.c.y + r * c.c.z));
  if (!(c.a > 0.0)) return ivec2(lo.x, hi.x);  // not an ellipse (never for a sprite in front)
  if (disc < 0.0) return ivec2(1, 0);
  float h = sqrt(disc);
  float first = max(ceil((-halfB - h) * c.invA), 0.0), last = min(floor((-halfB + h) * c.invA), float(hi.x - lo.x));
  return first <= last ? lo.x + ivec2(int(first), int(last)) : ivec2(1, 0);
}

// Where a walked joint's pixels are ray-cast (specialization constant 3 of
// joint_splat_walk.comp, render::SplatWalk). false: in the pixel pass, from the entries the walk
// reserves (a GPU's: every lane of the pixel pass does equal work). true: by the walk itself,
// row by row of the joint's silhouette (lavapipe's: lanes wait for the largest sprite of their
// eight, which costs less than storing each entry and its sprite and loading them back in the
// pixel pass one lane at a time).
layout(constant_id = 3) const bool kInlinePixels = false;

// A joint too wide to splat (or past full work lists), listed for the graphics pipeline.
void listNearJoint(uint joint) {
  uint slot = atomicAdd(draws[4 * push.chunk], 1u);
  nearList[push.listBase + slot] = joint;
}

// Joint `joint` (chunk-local) as sprite s, its pixels ray-cast here: the pixels of its box whose
// centres its silhouette holds (about two thirds of the box: a slanted bone leaves most of it
// empty). Listed for the graphics pipeline instead when it is too wide.
void splatSpriteInline(uint joint, JointSprite s, vec3 tint, FrameRays f) {
  if (s.sizePx > push.maxPixels) {
    listNearJoint(joint);
    return;
  }
  ivec2 lo, hi;
  if (!spriteBox(s, lo, hi)) return;
  Silhouette c = silhouette(s, lo);
  SpriteRays rays = spriteRays(s.inverse0, s.inverse1, s.inverse2, f);
  for (int y = lo.y; y <= hi.y; ++y) {
    ivec2 span = silhouetteRow(c, y, lo, hi);
    RowRays row = rowRays(rays, f, y);
    for (int x = span.x; x <= span.y; ++x) splatRayPixel(rays, f, row, x, y, tint);
  }
}

// Joint `joint` (chunk-local) as sprite s (f: the frame's rays, frameRays()): with kInlinePixels
// its pixels are ray-cast here; otherwise an entry is reserved for each pixel of its silhouette,
// for the pixel pass, and it is listed for the graphics pipeline's draw instead when it is too
// wide, or when the work lists are full. Not splatted here in that case: lavapipe would run that
// loop's body, ray-cast and all, for every joint with its lanes masked off.
void splatSprite(uint joint, JointSprite s, vec3 tint, FrameRays f) {
  if (kInlinePixels) {
    splatSpriteInline(joint, s, tint, f);
    return;
  }
  ivec2 lo = ivec2(0), hi = ivec2(-1);  // too wide: an empty box, so its lanes skip the rows
  bool wide = s.sizePx > push.maxPixels;
  if (!wide && !spriteBox(s, lo, hi)) return;
  Silhouette c = silhouette(s, lo);
  uint pixelCount = 0u;
  for (int y = lo.y; y <= hi.y; ++y) {
    ivec2 span = silhouetteRow(c, y, lo, hi);
    pixelCount += uint(max(span.y - span.x + 1, 0));
  }
  uint sprite;
  bool fits;
  uint first = reserveEntries(pixelCount > 0u ? 1u : 0u, pixelCount, sprite, fits);
  if (wide || !fits) listNearJoint(joint);
  uint entry = first;
  for (int y = lo.y; y <= hi.y; ++y) {
    ivec2 span = silhouetteRow(c, y, lo, hi);
    for (int x = span.x; x <= span.y; ++x, ++entry)
      if (entry < kPixelCapacity) owners[entry] = fits ? splatEntry(ivec2(x, y), sprite) : kSplatNoEntry;
  }
  if (fits && pixelCount > 0u) sprites[sprite] = SplatSprite(s.inverse0, s.inverse1, s.inverse2, vec4(tint, 0.0));
}

// The pixel of entry i of a box boxWidth wide at lo, the row by a float division (exact for
// boxes this small, and lavapipe divides integers one lane at a time).
ivec2 boxPixel(ivec2 lo, uint boxWidth, uint i) {
  uint row = uint((float(i) + 0.5) / float(boxWidth));
  return lo + ivec2(i - row * boxWidth, row);
}

// A far body: a few pixels, about as many in every lane, so they are covered here rather than
// through a sprite. Shaded once, where the ray through its centre hits it, and at that depth:
// per pixel only whether the ray meets the ellipsoid (farBodyPixel), and an atomicMin where it
// does. Nothing is listed: the frame's resolve reads every pixel. A box of at most 64 pixels
// keeps its hits as bits and visits only those (lanes wait for the most hits, not the largest
// box); a larger one asks each pixel again.
void splatBody(JointSprite s, vec3 tint) {
  ivec2 lo, hi;
  if (!spriteBox(s, lo, hi)) return;
  uint boxWidth = uint(hi.x - lo.x + 1);
  uint pixelCount = boxWidth * uint(hi.y - lo.y + 1);
  mat3 inv = transpose(mat3(s.inverse0.xyz, s.inverse1.xyz, s.inverse2.xyz));
  vec3 o = inv * frame.eye.xyz + vec3(s.inverse0.w, s.inverse1.w, s.inverse2.w);
  uint64_t packed = farBodyShade(s, tint);
  uint width = uint(frame.viewport.x);
  if (pixelCount <= 64u) {
    uint hits = 0u;
    uvec2 hitBits = uvec2(0u);
    for (uint i = 0u; i < pixelCount; ++i) {  // one loop over the box, not rows then columns
      if (!farBodyPixel(o, inv, vec2(boxPixel(lo, boxWidth, i)) + 0.5)) continue;
      ++hits;
      if (i < 32u) hitBits.x |= 1u << i;
      else hitBits.y |= 1u << (i - 32u);
    }
    for (uint k = 0u; k < hits; ++k) {
      bool low = hitBits.x != 0u;
      uint i = low ? uint(findLSB(hitBits.x)) : 32u + uint(findLSB(hitBits.y));
      if (low) hitBits.x &= hitBits.x - 1u;
      else hitBits.y &= hitBits.y - 1u;
      ivec2 xy = boxPixel(lo, boxWidth, i);
      atomicMin(visibility[uint(xy.y) * width + uint(xy.x)], packed);
    }
    return;
  }
  for (uint i = 0u; i < pixelCount; ++i) {
    ivec2 xy = boxPixel(lo, boxWidth, i);
    if (farBodyPixel(o, inv, vec2(xy) + 0.5)) atomicMin(visibility[uint(xy.y) * width + uint(xy.x)], packed);
  }
}

// A character's tint as the flags choose it.
vec3 characterColour(uint character, uvec4 mask) {
  return (push.flags & kDrawTintLevel) != 0u  ? levelTint(mask.z)
         : (push.flags & kDrawGroupTint) != 0u ? groupTint(groups[character], character)
                                               : characterTint(character);
}

uvec4 characterMask(uint character) {
  return (push.flags & (kDrawUseMasks | kDrawTintLevel)) != 0u ? masks[character] : uvec4(0xFFFFFFFFu, 0xFFFFFFFFu, 2u, 0u);
}

#endif
