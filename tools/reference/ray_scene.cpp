// SPDX-License-Identifier: MIT
#include "tools/reference/ray_scene.h"

#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace sg::reference {
namespace {

RTCRay make_ray(glm::vec3 origin, glm::vec3 direction, float near, float far) {
  RTCRay ray{};
  ray.org_x = origin.x;
  ray.org_y = origin.y;
  ray.org_z = origin.z;
  ray.dir_x = direction.x;
  ray.dir_y = direction.y;
  ray.dir_z = direction.z;
  ray.tnear = near;
  ray.tfar = far;
  ray.mask = UINT32_MAX;
  return ray;
}

}  // namespace

RayScene::RayScene(std::span<const glm::vec3> corners) {
  device_ = rtcNewDevice(nullptr);
  if (device_ == nullptr) {
    throw std::runtime_error("Embree could not start (rtcNewDevice: error " +
                             std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
  }
  scene_ = rtcNewScene(device_);
  const size_t triangles = corners.size() / 3;
  if (triangles > 0) {
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(glm::vec3), corners.size()));
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), triangles));
    if (vertices == nullptr || indices == nullptr) {
      rtcReleaseGeometry(geometry);
      throw std::runtime_error("Embree could not allocate " + std::to_string(triangles) + " triangles");
    }
    std::memcpy(vertices, corners.data(), corners.size() * sizeof(glm::vec3));
    for (uint32_t i = 0; i < triangles * 3; ++i) indices[i] = i;
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  rtcCommitScene(scene_);
}

RayScene::~RayScene() {
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

bool RayScene::occluded(glm::vec3 origin, glm::vec3 direction, float near, float far) const {
  RTCRay ray = make_ray(origin, direction, near, far);
#if SHADOWGRAPH_EMBREE_MAJOR >= 4
  rtcOccluded1(scene_, &ray);
#else
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(scene_, &context, &ray);
#endif
  // Embree marks a blocked ray by setting tfar to -infinity.
  return ray.tfar < 0.0f;
}

std::optional<RayHit> RayScene::intersect(glm::vec3 origin, glm::vec3 direction, float near) const {
  RTCRayHit query{};
  query.ray = make_ray(origin, direction, near, std::numeric_limits<float>::infinity());
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
#if SHADOWGRAPH_EMBREE_MAJOR >= 4
  rtcIntersect1(scene_, &query);
#else
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(scene_, &context, &query);
#endif
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  glm::vec3 normal(query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z);
  const float length = glm::length(normal);
  normal = length > 0.0f ? normal / length : -direction;  // a degenerate triangle faces the ray
  if (glm::dot(normal, direction) > 0.0f) normal = -normal;
  return RayHit{query.ray.tfar, normal};
}

}  // namespace sg::reference
