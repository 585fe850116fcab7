// SPDX-License-Identifier: MIT
#pragma once
// A set of world-space triangles that rays are cast against, with Intel Embree. Queries are
// const and safe to run from many threads at once (Embree's rtcIntersect1 and rtcOccluded1 are).
#include <optional>
#include <span>

#include <glm/glm.hpp>
#if SHADOWGRAPH_EMBREE_MAJOR >= 4
#include <embree4/rtcore.h>
#else
#include <embree3/rtcore.h>
#endif

namespace sg::reference {

struct RayHit {
  float distance = 0.0f;   // along the unit direction
  glm::vec3 normal{0.0f};  // the triangle's unit geometric normal, facing the ray's origin
};

class RayScene {
 public:
  // `corners`: three per triangle. Throws std::runtime_error if Embree cannot start.
  explicit RayScene(std::span<const glm::vec3> corners);
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;
  ~RayScene();

  // Whether a triangle lies on the ray from `origin` along the unit `direction` between
  // distances `near` and `far` (far may be infinite).
  bool occluded(glm::vec3 origin, glm::vec3 direction, float near, float far) const;
  // The nearest triangle on that ray beyond `near`, if any.
  std::optional<RayHit> intersect(glm::vec3 origin, glm::vec3 direction, float near = 0.0f) const;

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace sg::reference
