// SPDX-License-Identifier: MIT
#pragma once
// Ray-traced visibility of one light from every surface point of a frame: the reference the
// engine's shadows are measured against. 1 is fully lit, 0 fully shadowed; pixels without a
// surface point get 0 (callers mask them with SurfacePoint::valid).
#include <cstdint>
#include <vector>

#include "ecs/jobs/thread_pool.h"
#include "tools/reference/ray_scene.h"
#include "tools/reference/reference_lights.h"
#include "tools/reference/surface_points.h"

namespace sg::reference {

// One surface point's visibility of `light` (1 lit, 0 shadowed) seen from a camera at `eye`:
// hard_visibility's ray, and soft_visibility's rays jittered for `pixel`.
float hard_visible(const RayScene& casters, const SurfacePoint& point, glm::vec3 eye,
                   const ReferenceLight& light);
float soft_visible(const RayScene& casters, const SurfacePoint& point, glm::vec3 eye,
                   const ReferenceLight& light, uint32_t samples, glm::uvec2 pixel);

// One ray per pixel: to a point or spot light's position, against a directional light's
// direction (unbounded), or against a cylinder light's direction back to the plane of its
// position (a point behind that plane is not lit by it at all and counts as lit here).
std::vector<float> hard_visibility(const RayScene& casters, const SurfacePoints& points,
                                   const ReferenceLight& light, jobs::ThreadPool& pool);

// The fraction of `samples` rays (rounded up to a square, stratified and jittered per pixel)
// that reach an emitter of the light's `light_size`: a disc of that diameter facing the point
// (point, spot), or a cone of directions that wide seen from one unit away (directional,
// cylinder). What PCSS approximates.
std::vector<float> soft_visibility(const RayScene& casters, const SurfacePoints& points,
                                   const ReferenceLight& light, uint32_t samples, jobs::ThreadPool& pool);

}  // namespace sg::reference
