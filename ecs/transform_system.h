// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>

#include "ecs/fwd.h"
#include "ecs/world.h"

namespace sg::ecs {

// Recomputes WorldTransform for every entity (with LocalTransform and WorldTransform) whose
// local transform or parent changed after `since`, together with all of its descendants:
// world = parent's world * local. Parents are computed before their children, and subtrees
// where nothing changed are not visited. An entity whose parent is gone is treated as a root.
//
// Run it once per frame after the systems that move things, passing the tick of its previous
// run (0 the first time, to compute everything). With `threads`, entities outside any hierarchy
// (no Parent, no Children) are computed on them.
void update_world_transforms(World& world, Tick since, jobs::ThreadPool* threads = nullptr);

// Entities per parallel task of a per-entity update that costs tens of nanoseconds (a matrix, a
// sine): a frame's few thousand moving things then share the threads (a task is handed out for
// a compare-exchange, so a few microseconds of work a task pay for it).
inline constexpr std::size_t motion_entities_per_task = 256;

}  // namespace sg::ecs
