// Descriptor binding numbers and specialization-constant ids of the cloth playback passes
// (engine/secondary/cloth_gpu*), named once for the shaders and the C++ jobs; included like
// cloth_types.h. The passes that read the same buffer mostly keep its number, but each pass has
// its own list: a number is only meaningful within one pass.
#ifndef THRONG_CLOTH_BINDINGS_H
#define THRONG_CLOTH_BINDINGS_H

#ifdef __cplusplus
#include <cstdint>
namespace throng::gpu_types {
using uint = uint32_t;
#endif

// cloth_advance.comp: each character's walk through the cloth graph.
const uint kClothAdvanceBindingMotion = 0u;
const uint kClothAdvanceBindingCharacters = 1u;
const uint kClothAdvanceBindingGraph = 2u;

// cloth_mark.comp: per character, its cape's level, the states it shows, its level's draw.
const uint kClothMarkBindingView = 0u;  // uniform
const uint kClothMarkBindingCharacters = 1u;
const uint kClothMarkBindingPlacement = 2u;
const uint kClothMarkBindingMotion = 3u;
const uint kClothMarkBindingCounters = 4u;
const uint kClothMarkBindingStateLevel = 5u;
const uint kClothMarkBindingUsedStates = 6u;
const uint kClothMarkBindingDraws = 7u;
const uint kClothMarkBindingDrawList = 8u;
const uint kClothMarkBindingGraph = 10u;

// cloth_args.comp: the indirect dispatch sizes.
const uint kClothArgsBindingCounters = 4u;
const uint kClothArgsBindingDraws = 7u;
const uint kClothArgsBindingDispatchArgs = 9u;

// cloth_classify.comp: each used state's pool slot and its level's decode list.
const uint kClothClassifyBindingLevels = 3u;
const uint kClothClassifyBindingCounters = 4u;
const uint kClothClassifyBindingStateLevel = 5u;
const uint kClothClassifyBindingUsedStates = 6u;
const uint kClothClassifyBindingSlots = 7u;
const uint kClothClassifyBindingLevelLists = 8u;

// cloth_decode.comp: the listed states' vertices into the pool.
const uint kClothDecodeBindingMean = 0u;
const uint kClothDecodeBindingBases = 1u;
const uint kClothDecodeBindingCoefficients = 2u;
const uint kClothDecodeBindingLevels = 3u;
const uint kClothDecodeBindingCounters = 4u;
const uint kClothDecodeBindingLevelLists = 6u;
const uint kClothDecodeBindingSlots = 7u;
const uint kClothDecodeBindingPool = 8u;
const uint kClothDecodeConstantLanes = 0u;  // rows shared per round

// cloth.vert, cloth.frag: the near capes' draw.
const uint kClothDrawBindingView = 0u;  // uniform
const uint kClothDrawBindingCharacters = 1u;
const uint kClothDrawBindingPlacement = 2u;
const uint kClothDrawBindingMotion = 3u;
const uint kClothDrawBindingDrawList = 4u;
const uint kClothDrawBindingSlots = 5u;
const uint kClothDrawBindingPool = 6u;
const uint kClothDrawBindingRemap = 7u;
const uint kClothDrawBindingGraph = 8u;

// cloth_splat.comp: the far capes, into the joint renderer's visibility buffer.
const uint kClothSplatBindingView = 0u;  // a storage buffer (cloth_splat.comp says why)
const uint kClothSplatBindingCharacters = 1u;
const uint kClothSplatBindingPlacement = 2u;
const uint kClothSplatBindingMotion = 3u;
const uint kClothSplatBindingDrawList = 4u;
const uint kClothSplatBindingSlots = 5u;
const uint kClothSplatBindingPool = 6u;
const uint kClothSplatBindingGraph = 8u;
const uint kClothSplatBindingDraws = 10u;
const uint kClothSplatBindingVisibility = 11u;
// Its specialization constants: the splat level's mesh, then its indices from
// kClothSplatConstantIndices on (3 per triangle, kClothSplatMaxTriangles triangles).
const uint kClothSplatConstantVertices = 0u;
const uint kClothSplatConstantTriangles = 1u;
const uint kClothSplatConstantIndices = 2u;

#ifdef __cplusplus
}  // namespace throng::gpu_types
#endif
#endif
