// Descriptor binding numbers of the joint renderer (engine/render: crowd_renderer.cpp,
// joint_splat.cpp), named once for the shaders and the C++. The renderer's passes share one
// numbering (the joint draw, the joint splat, the ground and the resolves), so a buffer
// bound to several of them has one number; included like shared_types.h.
#ifndef THRONG_RENDER_BINDINGS_H
#define THRONG_RENDER_BINDINGS_H

#ifdef __cplusplus
#include <cstdint>
namespace throng::gpu_types {
using uint = uint32_t;
#endif

const uint kRenderBindingJoints = 0u;      // the chunk's JointMatrix, synthesized this frame
const uint kRenderBindingFrame = 1u;       // FrameUniforms (uniform)
const uint kRenderBindingVisibility = 2u;  // the splat's (depth bits << 32 | colour) per pixel
const uint kRenderBindingDraws = 3u;       // VkDrawIndirectCommand per chunk
const uint kRenderBindingNearList = 4u;    // joints left to the graphics pipeline
const uint kRenderBindingMasks = 5u;       // coverage LOD, per character
const uint kRenderBindingPlacement = 6u;   // joint_fetch.glsl: cached characters' root transform
const uint kRenderBindingMotion = 7u;
const uint kRenderBindingPoseSource = 8u;
const uint kRenderBindingCacheData = 9u;
const uint kRenderBindingGroups = 10u;     // kDrawGroupTint: a uint per character
const uint kRenderBindingLodLevels = 11u;  // kDrawLodLevels: CoverageParts (uniform)
const uint kRenderBindingWalls = 12u;      // walls.vert: segments (ax, az, bx, bz) as texels
const uint kRenderBindingSprites = 13u;    // the splat's sprites (joint_splat_common.glsl)
const uint kRenderBindingPixelOwners = 14u;  // per reserved pixel entry: its sprite and pixel
const uint kRenderBindingSplatCounters = 15u;  // sprites and pixels reserved this frame
const uint kRenderBindingGroundVisibility = 16u;  // ground.comp: the ground as visibility words
const uint kRenderBindingFramePlanes = 17u;  // visibility_planes.comp: colour plane, depth plane
const uint kRenderBindingWalkList = 19u;      // characters whose joints are splatted, per chunk
const uint kRenderBindingListCounts = 20u;    // per chunk: each list's length and dispatch
const uint kRenderBindingOnScreenList = 21u;  // characters on screen, per chunk
const uint kRenderBindingFarBodyPoses = 22u;  // joint_far_body.glsl: FarBodyPose per cached pose

// The splat's work lists: a joint reserves a sprite and one entry per pixel of its silhouette,
// and the pixel pass shades one pixel per invocation, so a 20×20 joint next to a 2×2 one costs
// its own pixels and not the 2×2 lanes' idle wait. Fixed capacities (48 MiB; specialization
// constants 0 and 1 of the splat shaders, so tests can shrink them): a joint that does not fit
// is listed for the graphics pipeline's draw, like one too wide to splat, as correct and slower.
const uint kSplatSpriteCapacity = 262144u;
const uint kSplatSpriteBytes = 64u;          // SplatSprite
const uint kSplatPixelCapacity = 4194304u;   // 4 Mi pixel entries (a 1280×720 frame 4.5 times)
const uint kSplatEntryBytes = 8u;            // a pixel entry: 64 bits
// A pixel entry names its screen pixel from the start, x | y << 16 in its high 32 bits, and its
// sprite in the low 32, so the pixel pass finds its pixel without the sprite's box. An entry
// reserved past a capacity has kSplatNoSprite for its sprite.
const uint kSplatNoSprite = 0xFFFFFFFFu;     // an entry's sprite bits: no entry
const uint kSplatMaxSpritePixels = 64u;      // the largest maxPixels a splat accepts
// The walk reserves a joint's sprite and its pixel entries as one word (joint_splat_reserve.glsl):
// the entries in the low kSplatReserveSpriteShift bits, the sprite above. A subgroup (at most
// 128 lanes) of boxes of at most kSplatMaxSpritePixels² pixels stays below that (joint_splat.cpp).
const uint kSplatReserveSpriteShift = 24u;
const uint kSplatPixelGroups = 1024u;        // workgroups of the pixel pass (grid-stride)
const uint kSplatWalkGroupSize = 64u;        // joint_splat_walk.comp's workgroup
const uint kSplatBodyGroupSize = 64u;        // joint_splat.comp's and joint_splat_list.comp's
const uint kSplatListRun = 8u;               // characters per invocation of joint_splat_list.comp
// Per chunk in the list-counts buffer, two lists, each as its length followed by the
// VkDispatchIndirectCommand of the pass that reads it (x = workgroups for the list; y = z = 1,
// but the walk's y is a row per joint when it walks per joint, render::SplatWalk): the
// characters on screen (joint_splat_list.comp), read by the far-body pass, and the characters
// whose joints are walked (joint_splat.comp), read by the walk (one invocation per listed
// character; a chunk's list is short enough for any device's workgroup count, jointChunks).
// Dispatched by its list's length, a pass costs nothing for characters off screen: lavapipe runs
// a pass's every line for every 8 lanes, taken or not, and a grid-stride loop's body once for
// every 8 lanes even when no lane has work.
const uint kSplatListArgsWords = 8u;
const uint kSplatOnScreenArgs = 0u;
const uint kSplatWalkArgs = 4u;

// The frame's planes (visibility_planes.comp, copied into the target's colour and depth images):
// the colour plane from word 0, the depth plane from this word, a multiple of four so that both
// planes hold whole runs of four pixels.
#ifdef __cplusplus
inline
#endif
uint visibilityDepthPlane(uint pixels) { return (pixels + 3u) & ~3u; }
const uint kPlanesGroups = 1024u;  // visibility_planes.comp's workgroups at most (grid-stride)
// visibility_planes.comp's push constant: 1 when the depth plane is written, 0 when only the colour
// plane is (nothing drawn after the splat reads the depths but near joints, and those read the
// visibility buffer: joints_over_splat.frag).
const uint kPlanesWithDepth = 1u;

// The far body (joint_far_body.glsl): a far-level character under this many pixels tall on
// screen is splatted as one ellipsoid its standing height tall and kFarBodyWidth of it across
// (specialization constant 2 of joint_splat.comp; 0 draws every character by its joints).
const float kSplatFarBodyPixels = 12.0;
const float kFarBodyWidth = 0.08;

#ifdef __cplusplus
}  // namespace throng::gpu_types
#endif
#endif
