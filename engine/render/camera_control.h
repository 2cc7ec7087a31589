#pragma once
// Interactive camera moves for the viewer, on render::Camera directly (eye, target): orbit
// about the target, pan in the view plane, zoom along the view ray, and free flight. A camera
// nobody touched stays bit-identical to the preset, so the viewer matches `throng render`.
#include "render/camera.h"

namespace throng::render {

constexpr float kOrbitDegreesPerPixel = 0.3f;
constexpr float kMaxPitchDegrees = 89.0f;
constexpr float kZoomPerStep = 0.85f;  // distance factor per wheel step (positive steps zoom in)
constexpr float kMinDistance = 0.5f;

// Yaw about +y through the target by -dx, pitch by +dy (pixels dragged); the distance to the
// target is kept and the pitch stays within ±kMaxPitchDegrees.
void orbitCamera(Camera& camera, float dxPixels, float dyPixels);
// Moves eye and target together so the point at the target's depth follows the mouse.
void panCamera(Camera& camera, float dxPixels, float dyPixels, float viewportHeight);
// Distance to the target × kZoomPerStep^steps, kept within [kMinDistance, farPlane / 2].
void zoomCamera(Camera& camera, float steps);
// `axes` = (right, up, forward) in [-1, 1]; forward follows the view direction, up is world +y.
// The speed grows with the distance to the target so flying works at every scale.
void flyCamera(Camera& camera, glm::vec3 axes, float seconds, float speedFactor = 1.0f);
float flySpeed(const Camera& camera);  // metres per second at speedFactor 1

float cameraDistance(const Camera& camera);
float cameraPitchDegrees(const Camera& camera);
float cameraYawDegrees(const Camera& camera);

}  // namespace throng::render
