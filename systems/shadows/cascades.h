// SPDX-License-Identifier: MIT
#pragma once
// Cascaded shadow maps for directional lights: the view's depth range cut into slices, nearest
// first, each slice covered by an orthographic map of its own, so that the map texels near the
// camera are small where one map fitted to the whole scene spreads its texels over all of it.
//
// - Slices: a practical split, the blend cascade_log_weight of the logarithmic split (equal
//   texels per pixel at every depth) and the uniform one (no slice too thin near the camera),
//   over the distances from the eye the scene's box spans, within the camera's near and far
//   planes: distances, not view depths, so that turning the camera changes no slice, rounded
//   out to powers of two, so that moving it changes them in steps, not every frame.
// - Each map is square, around the sphere bounding its slice of the view frustum: the sphere's
//   radius depends on the slice and the lens only, not on where the camera looks, so turning
//   the camera leaves the map's size as it is. Its centre, in the light's frame, is snapped to a
//   sixteenth of the map's width, a whole number of texels at every resolution the atlas gives
//   (16 texels and up, powers of two): a moving camera shifts the map by whole texels, so a
//   static shadow's edge does not shimmer, and between steps the map is the same and stays
//   cached. Depths span the whole scene along the light, so casters between the light and the
//   slice are drawn, and a bias means the same distance in every cascade.
// - A slice whose map would be at least half as wide as the map fitted to the whole scene
//   (directional_light_view, as wide as a square of its area) gains little: that map covers it and the slices
//   beyond, and is the last cascade. A camera far from the scene thus gets one map, the fitted one.
//
// The shaders (shaders/shadow_sampling.glsl) pick, per surface point, the first cascade whose
// map holds the point more than cascade_edge_uv inside its edge, and blend it into the next one
// over the cascade_blend_uv beyond that, so the change of resolution at a slice's border is not
// a visible seam.
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "systems/scene/aabb.h"
#include "systems/scene/camera.h"
#include "systems/scene/shadow_settings.h"
#include "systems/shadows/light_views.h"

namespace sg::shadows {

inline constexpr uint32_t max_cascades = scene::max_shadow_cascades;
// Of the practical split, the logarithmic split's share; the uniform one has the rest. At 0.9 a
// camera at eye height in a 200 m hall (near 5 cm, far 256 m) gets slices ending at 6.8, 16, 48
// and 256 m; at 0.75 the first would reach 16 m, its texels over twice as wide.
inline constexpr float cascade_log_weight = 0.9f;
// A map's centre moves in steps of this fraction of its width: 1/16 is one texel of the
// smallest tile (min_shadow_resolution), so a whole number of texels of every tile.
inline constexpr float cascade_snap_fraction = 1.0f / 16.0f;
// In map uv, the band along a cascade's edge its points are not taken from (every kernel's
// taps stay inside the map: 16 texels at 1,024), and the band beyond it where a cascade fades
// into the next. The same constants are CASCADE_EDGE_UV and CASCADE_BLEND_UV in
// shaders/shadow_sampling.glsl.
inline constexpr float cascade_edge_uv = 1.0f / 64.0f;
inline constexpr float cascade_blend_uv = 1.0f / 10.0f;

// The view the cascades cover.
struct CascadeCamera {
  glm::vec3 eye{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};  // unit
  float yfov = 1.0f;                     // radians
  float aspect = 1.0f;                   // width / height
  float near = 0.05f;
  float far = 500.0f;
};

CascadeCamera cascade_camera(const scene::CameraPose& pose, const scene::Camera& lens, float aspect);

// A directional light's cascades: `count` maps, map k covering view depths [splits[k],
// splits[k + 1]] (the last one may be the map fitted to the whole scene, which covers more).
struct CascadeFit {
  uint32_t count = 1;
  std::array<float, max_cascades + 1> splits{};
  std::array<LightView, max_cascades> views{};
};

// At most `most` (1 to max_cascades) cascades of a light shining along unit `direction` over a
// scene within `bounds` (not empty), seen by `camera`. One cascade is the map fitted to the
// whole scene.
CascadeFit fit_cascades(glm::vec3 direction, const scene::Aabb& bounds, const CascadeCamera& camera,
                        uint32_t most);

}  // namespace sg::shadows
