#pragma once
// Camera and light in the hand: mouse motion in pixels turned into orbit, pan, zoom and light
// moves. Pure functions of the camera, so the tests and the script replay get what the mouse
// gets.
#include <penumbra/penumbra.h>

namespace penumbra::viewer {

// Turns the camera about its target: dx pixels of horizontal motion turn it about the up axis,
// dy tilt it (kept short of the poles, where "up" would flip).
void orbitCamera(Camera& camera, float dx, float dy);
// Moves camera and target together in the image plane, so that the point at the target's depth
// follows the mouse in a frame `frame_height` pixels tall.
void panCamera(Camera& camera, float dx, float dy, int frame_height);
// Moves the camera towards its target (steps > 0) or away, by 10 % of the distance a step.
void zoomCamera(Camera& camera, float steps);
// Drags a light by the mouse: in the horizontal plane through its centre (right-left along the
// camera's right, up-down along its forward direction flattened), or with `vertical` along the
// vertical line through it; the light moves as far as a point at its distance on screen would.
void dragLight(Light& light, const Camera& camera, float dx, float dy, int frame_height,
               bool vertical);

}  // namespace penumbra::viewer
