// The far body: a far-level character whose whole figure is under kFarBodyPixels tall on
// screen is splatted as one ellipsoid (its standing height, kFarBodyWidth of it across) instead
// of its far level's joints: one sprite, not a dozen, for a figure whose limbs are a pixel wide.
// Placed from three joints the far level always synthesizes, the torso's and the legs' centre
// joints; their mean heights (CoverageParts.parts) give the character's scale. A cached
// character's three are read from its pose's FarBodyPose (cache_fill.comp), the same points as
// in its cache entry, and placed by the same arithmetic (placeCachedPoint). Needs
// joint_lod.glsl and joint_fetch.glsl first. CPU twin: render::farBodyMatrix
// (engine/render/joint_far_body_cpu.cpp).
#ifndef THRONG_JOINT_FAR_BODY_GLSL
#define THRONG_JOINT_FAR_BODY_GLSL

layout(constant_id = 2) const float kFarBodyPixels = kSplatFarBodyPixels;

layout(std430, binding = kRenderBindingFarBodyPoses) readonly buffer FarBodyPoses { FarBodyPose farBodyPoses[]; };

// A part's centre, A·(0, bonePoint, 0, 1) of its joint's draw matrix, from the joint's point and
// its parent's (the root's own twice).
vec3 partPoint(CoveragePart part, vec4 parent, vec4 joint) {
  return bonePoint(parent, joint, part.parent < 0, part.bonePoint);
}

vec3 cachedPartPoint(CoveragePart part, vec4 parent, vec4 joint, CharacterPose pose) {
  return partPoint(part, placeCachedPoint(parent, pose.placed), placeCachedPoint(joint, pose.placed));
}

vec3 jointsPartPoint(CoveragePart part, uint base) {
  return partPoint(part, joints[base + partBoneStart(part)].positionRadius, joints[base + part.joint].positionRadius);
}

// The body ellipsoid as a joint draw matrix; a zero matrix (never visible) where the joints
// give no scale. base: the character's first joint in the chunk's joints binding.
JointMatrix farBodyMatrix(CharacterPose pose, uint base) {
  CoveragePart torso = lodParts.parts[kPartTorso];
  CoveragePart left = lodParts.parts[kPartLeftLeg];
  CoveragePart right = lodParts.parts[kPartRightLeg];
  vec3 spine, knees;
  if (pose.source != kPoseInJoints) {
    FarBodyPose f = farBodyPoses[pose.source / push.jointCount];
    spine = cachedPartPoint(torso, f.torsoParent, f.torso, pose);
    knees = 0.5 * (cachedPartPoint(left, f.leftLegParent, f.leftLeg, pose) +
                   cachedPartPoint(right, f.rightLegParent, f.rightLeg, pose));
  } else {
    spine = jointsPartPoint(torso, base);
    knees = 0.5 * (jointsPartPoint(left, base) + jointsPartPoint(right, base));
  }
  float meanSpan = torso.centre.y - 0.5 * (left.centre.y + right.centre.y);
  float scale = meanSpan > 0.0 ? (spine.y - knees.y) / meanSpan : 0.0;
  if (!(scale > 0.0)) return JointMatrix(vec4(0.0), vec4(0.0), vec4(0.0));
  float height = lodParts.body.x * scale;
  float radius = kFarBodyWidth * height;
  vec3 bottom = spine - vec3(0.0, torso.centre.y * scale, 0.0);
  return JointMatrix(vec4(radius, 0.0, 0.0, bottom.x), vec4(0.0, height, 0.0, bottom.y),
                     vec4(0.0, 0.0, radius, bottom.z));
}

// Whether the character is drawn as its far body (the LOD levels on, the far level, the body
// under kFarBodyPixels tall on screen), with its sprite.
bool farBody(CharacterPose pose, uint base, uint flags, uvec4 mask, FrameUniforms frame, out JointSprite s) {
  s.visible = false;
  if ((flags & (kDrawUseMasks | kDrawLodLevels)) != (kDrawUseMasks | kDrawLodLevels)) return false;
  if (mask.z != kLevelFar || (mask.x | mask.y) == 0u || kFarBodyPixels <= 0.0) return false;
  s = jointSprite(farBodyMatrix(pose, base), frame);
  return s.visible && s.hi.y - s.lo.y < kFarBodyPixels;
}

// The body's one colour and depth, packed as the visibility buffer holds them: where the ray
// through the centre of its screen box meets it (on a miss, which only a degenerate body has,
// the ray's nearest approach).
uint64_t farBodyShade(JointSprite s, vec3 tint) {
  vec3 dir = pixelRay(0.5 * (s.lo + s.hi), frame);
  float t;
  vec3 n;
  hitJoint(frame.eye.xyz, dir, s.inverse0, s.inverse1, s.inverse2, t, n);
  vec4 clip = frame.viewProjection * vec4(frame.eye.xyz + t * dir, 1.0);
  float depth = clamp(clip.z / clip.w, 0.0, 1.0);
  uint colour = packUnorm4x8(vec4(shadeJoint(tint, n, dir, frame.lightDirection.xyz), 1.0));
  return (uint64_t(floatBitsToUint(depth)) << 32) | uint64_t(colour);
}

// Whether the ray through `pixel` meets the body in front of the eye: the eye `o` and the
// ray in unit-sphere space (inv), the ray unnormalized (the signs below do not depend on its
// length).
bool farBodyPixel(vec3 o, mat3 inv, vec2 pixel) {
  vec2 ndc = pixel / frame.viewport.xy * 2.0 - 1.0;
  vec3 d = inv * (frame.rayForward.xyz + ndc.x * frame.rayRight.xyz + ndc.y * frame.rayDown.xyz);
  return dot(o, d) < 0.0 && unitSphereDiscriminant(o, d) >= 0.0;
}

#endif
