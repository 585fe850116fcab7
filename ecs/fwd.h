// SPDX-License-Identifier: MIT
#pragma once
// The ECS's types, declared, for headers that name them without needing their definitions: a
// header includes this instead of another that would include it back (EnTT's fwd.hpp).
namespace sg::ecs {

class World;
class SparseSet;
class OwningGroup;
template <typename... Components>
class Query;

}  // namespace sg::ecs

namespace sg::jobs {
class ThreadPool;
}  // namespace sg::jobs
