#version 450
#extension GL_GOOGLE_include_directive : require
// A near joint over the splatted picture when nothing else is drawn with depth: the depth
// attachment starts cleared and the splat's depths are read from the visibility buffer, so the
// planes pass writes no depth plane and none is copied in (CrowdRenderer::beginDraw).
#define THRONG_DEPTH_FROM_VISIBILITY
#include "joint_fragment.glsl"
