// SPDX-License-Identifier: MIT
#pragma once
// Which spheres meet any box of a set, without testing every sphere against every box: the
// boxes are binned into a uniform grid over the x-z plane and each sphere is tested only against
// the boxes of the cells it covers. ShadowCache uses it to find the lights whose reach a
// changed caster entered or left.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "systems/scene/aabb.h"

namespace sg::jobs {
class ThreadPool;
}

namespace sg::shadows {

// Whether the sphere (xyz centre, w radius >= 0) and the non-empty box intersect or touch.
bool sphere_meets_box(const glm::vec4& sphere, const scene::Aabb& box);

class SpheresMeetingBoxes {
 public:
  // Sets met[i] = 1 for every sphere i (xyz centre, w radius >= 0) that meets a box of `boxes`
  // (all non-empty), leaving the other elements of `met` as they are (and not testing spheres
  // already met); `met` has spheres.size() elements. Exactly the spheres sphere_meets_box finds,
  // at a cost of about O(spheres + boxes + sphere-box pairs sharing a grid cell): cells are about
  // one mean sphere diameter wide, at most about twice as many as spheres and boxes together. A
  // call allocates nothing once grown. With a `pool`, the spheres are looked up in pieces on it.
  void find(std::span<const glm::vec4> spheres, std::span<const scene::Aabb> boxes, std::span<uint8_t> met,
            jobs::ThreadPool* pool = nullptr);

 private:
  // The grid: cell c holds boxes cell_boxes_[cell_begin_[c]] .. cell_boxes_[cell_begin_[c + 1] - 1].
  std::vector<uint32_t> cell_begin_;
  std::vector<uint32_t> cell_boxes_;
};

}  // namespace sg::shadows
