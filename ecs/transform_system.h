#pragma once

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
void update_world_transforms(World& world, Tick since, ThreadPool* threads = nullptr);

}  // namespace sg::ecs
