// SPDX-License-Identifier: MIT
// ECS against plain std::vector structure-of-arrays doing the same work, over a million
// entities. Each case comes in pairs (…/ecs and …/raw) so the output reads as a ratio.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <memory>
#include <numeric>
#include <random>
#include <thread>
#include <vector>

#include "ecs/jobs/thread_pool.h"
#include "ecs/query.h"
#include "ecs/transform.h"
#include "ecs/world.h"

namespace {

using sg::ecs::Entity;
using sg::ecs::LocalTransform;
using sg::ecs::Tick;
using sg::ecs::World;
using sg::ecs::WorldTransform;

constexpr std::uint32_t entity_count = 1'000'000;
constexpr float dt = 1.0f / 60.0f;

struct Position {
  float x, y, z;
};
struct Velocity {
  float x, y, z;
};
struct Acceleration {
  float x, y, z;
};
struct Health {
  float value;
};

// Frees what a timed iteration built without counting it: freeing is not creating or destroying.
template <typename T>
void free_untimed(benchmark::State& state, std::unique_ptr<T>& owner) {
  state.PauseTiming();
  owner.reset();
  state.ResumeTiming();
}

Velocity velocity_of(std::uint32_t i) { return {1.0f, static_cast<float>(i % 7), -1.0f}; }

// The raw baseline: one vector per component, entity i at index i.
struct RawArrays {
  std::vector<Position> positions;
  std::vector<Velocity> velocities;
  std::vector<Acceleration> accelerations;
};

RawArrays make_raw_arrays() {
  RawArrays raw;
  for (std::uint32_t i = 0; i < entity_count; ++i) {
    raw.positions.push_back({0.0f, 0.0f, 0.0f});
    raw.velocities.push_back(velocity_of(i));
    raw.accelerations.push_back({0.0f, -9.8f, 0.0f});
  }
  return raw;
}

std::unique_ptr<World> make_world(std::vector<Entity>* entities = nullptr) {
  auto world = std::make_unique<World>();
  for (std::uint32_t i = 0; i < entity_count; ++i) {
    const Entity entity = world->create();
    world->add<Position>(entity, 0.0f, 0.0f, 0.0f);
    world->add<Velocity>(entity, velocity_of(i));
    world->add<Acceleration>(entity, 0.0f, -9.8f, 0.0f);
    if (entities != nullptr) entities->push_back(entity);
  }
  return world;
}

void integrate(Position& position, const Velocity& velocity) {
  position.x += velocity.x * dt;
  position.y += velocity.y * dt;
  position.z += velocity.z * dt;
}

void integrate(Position& position, const Velocity& velocity, const Acceleration& acceleration) {
  position.x += (velocity.x + acceleration.x * dt) * dt;
  position.y += (velocity.y + acceleration.y * dt) * dt;
  position.z += (velocity.z + acceleration.z * dt) * dt;
}

// Each iteration is one frame: a new tick, so every write is a first write and is logged.
void iterate2_ecs(benchmark::State& state) {
  const std::unique_ptr<World> world = make_world();
  for (auto _ : state) {
    world->advance_tick();
    world->query<Position, const Velocity>().for_each(
        [](Position& position, const Velocity& velocity) { integrate(position, velocity); });
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

void iterate2_raw(benchmark::State& state) {
  RawArrays raw = make_raw_arrays();
  for (auto _ : state) {
    for (std::size_t i = 0; i < raw.positions.size(); ++i) {
      integrate(raw.positions[i], raw.velocities[i]);
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

void iterate3_ecs(benchmark::State& state) {
  const std::unique_ptr<World> world = make_world();
  for (auto _ : state) {
    world->advance_tick();
    world->query<Position, const Velocity, const Acceleration>().for_each(
        [](Position& position, const Velocity& velocity, const Acceleration& acceleration) {
          integrate(position, velocity, acceleration);
        });
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

void iterate3_raw(benchmark::State& state) {
  RawArrays raw = make_raw_arrays();
  for (auto _ : state) {
    for (std::size_t i = 0; i < raw.positions.size(); ++i) {
      integrate(raw.positions[i], raw.velocities[i], raw.accelerations[i]);
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

// The form a game loop writes: two of the three components change each frame.
void integrate_both(Position& position, Velocity& velocity, const Acceleration& acceleration) {
  velocity.x += acceleration.x * dt;
  velocity.y += acceleration.y * dt;
  velocity.z += acceleration.z * dt;
  integrate(position, velocity);
}

// Arg 0: the components were added together (the pools share one order); 1: each was added in a
// pass of its own over the entities in a different order (creation order, reversed, shuffled), as
// when systems attach components as they discover entities, so every pool holds the same
// entities in another order.
std::unique_ptr<World> make_world_in_orders() {
  auto world = std::make_unique<World>();
  std::vector<Entity> entities;
  for (std::uint32_t i = 0; i < entity_count; ++i) entities.push_back(world->create());
  for (std::uint32_t i = 0; i < entity_count; ++i) world->add<Position>(entities[i], 0.0f, 0.0f, 0.0f);
  for (std::uint32_t i = entity_count; i-- > 0;) world->add<Velocity>(entities[i], velocity_of(i));
  std::vector<std::uint32_t> shuffled(entity_count);
  std::iota(shuffled.begin(), shuffled.end(), 0u);
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(11));
  for (const std::uint32_t i : shuffled) world->add<Acceleration>(entities[i], 0.0f, -9.8f, 0.0f);
  return world;
}

// The first pass and tick are timed on their own (first_ms): they pay for putting pools that
// were filled in other orders into entity order.
void iterate3_write2_ecs(benchmark::State& state) {
  const std::unique_ptr<World> world = state.range(0) == 0 ? make_world() : make_world_in_orders();
  const auto pass = [&] {
    world->advance_tick();
    world->query<Position, Velocity, const Acceleration>().for_each(
        [](Position& position, Velocity& velocity, const Acceleration& acceleration) {
          integrate_both(position, velocity, acceleration);
        });
  };
  const auto start = std::chrono::steady_clock::now();
  pass();
  world->advance_tick();
  state.counters["first_ms"] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  for (auto _ : state) {
    pass();
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

void iterate3_write2_raw(benchmark::State& state) {
  RawArrays raw = make_raw_arrays();
  for (auto _ : state) {
    for (std::size_t i = 0; i < raw.positions.size(); ++i) {
      integrate_both(raw.positions[i], raw.velocities[i], raw.accelerations[i]);
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

void create2_ecs(benchmark::State& state) {
  for (auto _ : state) {
    auto world = std::make_unique<World>();
    for (std::uint32_t i = 0; i < entity_count; ++i) {
      const Entity entity = world->create();
      world->add<Position>(entity, 0.0f, 0.0f, 0.0f);
      world->add<Velocity>(entity, velocity_of(i));
    }
    benchmark::DoNotOptimize(world->entity_count());
    free_untimed(state, world);
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

void create2_raw(benchmark::State& state) {
  for (auto _ : state) {
    auto raw = std::make_unique<RawArrays>();
    std::vector<std::uint32_t> ids;  // stands for the entity handles
    for (std::uint32_t i = 0; i < entity_count; ++i) {
      ids.push_back(i);
      raw->positions.push_back({0.0f, 0.0f, 0.0f});
      raw->velocities.push_back(velocity_of(i));
    }
    benchmark::DoNotOptimize(ids.data());
    free_untimed(state, raw);
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

void create2_bulk_ecs(benchmark::State& state) {
  for (auto _ : state) {
    auto world = std::make_unique<World>();
    benchmark::DoNotOptimize(
        world->create_many(entity_count, Position{0.0f, 0.0f, 0.0f}, Velocity{1.0f, 0.0f, -1.0f}));
    free_untimed(state, world);
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

// The bulk form of create2/raw: sized once, filled with copies.
void create2_bulk_raw(benchmark::State& state) {
  for (auto _ : state) {
    auto raw = std::make_unique<RawArrays>();
    std::vector<std::uint32_t> ids(entity_count);
    std::iota(ids.begin(), ids.end(), 0u);
    raw->positions.assign(entity_count, Position{0.0f, 0.0f, 0.0f});
    raw->velocities.assign(entity_count, Velocity{1.0f, 0.0f, -1.0f});
    benchmark::DoNotOptimize(ids.data());
    free_untimed(state, raw);
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

// Destroys every entity of a fresh world with `destroy(world, entities)`, world set-up untimed;
// with `keep_removals`, the world records every removal (World::keep_removals).
template <class Destroy>
void destroy_all(benchmark::State& state, Destroy destroy, bool keep_removals = false) {
  for (auto _ : state) {
    state.PauseTiming();
    std::vector<Entity> entities;
    std::unique_ptr<World> world = make_world(&entities);
    if (keep_removals) world->keep_removals<Position, Velocity, Acceleration>();
    state.ResumeTiming();
    destroy(*world, entities);
    benchmark::DoNotOptimize(world->entity_count());
    free_untimed(state, world);
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

void destroy_bulk_ecs(benchmark::State& state) {
  destroy_all(state, [](World& world, const std::vector<Entity>& entities) { world.destroy_many(entities); });
}

void destroy_bulk_kept_ecs(benchmark::State& state) {
  destroy_all(
      state, [](World& world, const std::vector<Entity>& entities) { world.destroy_many(entities); }, true);
}

void destroy_ecs(benchmark::State& state) {
  destroy_all(state, [](World& world, const std::vector<Entity>& entities) {
    for (const Entity entity : entities) world.destroy(entity);
  });
}

// Destroying entity i from raw arrays that must stay dense: swap-remove each array through an
// id -> index map, the least a packed layout needs.
void destroy_raw(benchmark::State& state) {
  for (auto _ : state) {
    state.PauseTiming();
    auto raw_owner = std::make_unique<RawArrays>(make_raw_arrays());
    RawArrays& raw = *raw_owner;
    std::vector<std::uint32_t> index_of_id(entity_count);
    std::iota(index_of_id.begin(), index_of_id.end(), 0u);
    std::vector<std::uint32_t> id_at(index_of_id);
    state.ResumeTiming();
    for (std::uint32_t id = 0; id < entity_count; ++id) {
      const std::uint32_t index = index_of_id[id];
      const std::uint32_t last_id = id_at.back();
      raw.positions[index] = raw.positions.back();
      raw.velocities[index] = raw.velocities.back();
      raw.accelerations[index] = raw.accelerations.back();
      raw.positions.pop_back();
      raw.velocities.pop_back();
      raw.accelerations.pop_back();
      id_at[index] = last_id;
      id_at.pop_back();
      index_of_id[last_id] = index;
    }
    benchmark::DoNotOptimize(raw.positions.size());
    free_untimed(state, raw_owner);
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

// `Grouped`: Health and Position form an owning group, so every add joins it and every remove
// leaves it (a swap in each of the two pools): what a group costs structural changes.
template <bool Grouped>
void add_remove_ecs(benchmark::State& state) {
  std::vector<Entity> entities;
  const std::unique_ptr<World> world = make_world(&entities);
  if (Grouped) world->group<Position, Health>();
  for (auto _ : state) {
    for (const Entity entity : entities) world->add<Health>(entity, 1.0f);
    for (const Entity entity : entities) world->remove<Health>(entity);
    world->forget_removals_before(world->tick() + 1);
    world->advance_tick();
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

// Adding then removing a component kept in its own dense array with an id -> index map.
void add_remove_raw(benchmark::State& state) {
  std::vector<float> health;
  std::vector<std::uint32_t> id_at;
  std::vector<std::uint32_t> index_of_id(entity_count);
  for (auto _ : state) {
    for (std::uint32_t id = 0; id < entity_count; ++id) {
      index_of_id[id] = static_cast<std::uint32_t>(health.size());
      health.push_back(1.0f);
      id_at.push_back(id);
    }
    for (std::uint32_t id = 0; id < entity_count; ++id) {
      const std::uint32_t index = index_of_id[id];
      health[index] = health.back();
      id_at[index] = id_at.back();
      index_of_id[id_at[index]] = index;
      health.pop_back();
      id_at.pop_back();
    }
    benchmark::DoNotOptimize(health.data());
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

// What the same add+remove costs in an archetype layout: each structural change moves the
// entity's whole row (Position, Velocity, Acceleration) to the table of its new component set
// and swap-removes it from the old one. Only the data movement is modelled, not the archetype
// lookup, so this is a lower bound.
void add_remove_archetype_model(benchmark::State& state) {
  RawArrays without_health = make_raw_arrays();
  RawArrays with_health;
  std::vector<float> health;
  const auto move_row = [](RawArrays& from, std::size_t index, RawArrays& to) {
    to.positions.push_back(from.positions[index]);
    to.velocities.push_back(from.velocities[index]);
    to.accelerations.push_back(from.accelerations[index]);
    from.positions[index] = from.positions.back();
    from.velocities[index] = from.velocities.back();
    from.accelerations[index] = from.accelerations.back();
    from.positions.pop_back();
    from.velocities.pop_back();
    from.accelerations.pop_back();
  };
  for (auto _ : state) {
    // Moving from the back keeps the benchmark free of an id map; real tables need one more.
    while (!without_health.positions.empty()) {
      move_row(without_health, without_health.positions.size() - 1, with_health);
      health.push_back(1.0f);
    }
    while (!with_health.positions.empty()) {
      move_row(with_health, with_health.positions.size() - 1, without_health);
      health.pop_back();
    }
    benchmark::DoNotOptimize(without_health.positions.data());
  }
  state.SetItemsProcessed(state.iterations() * entity_count);
}

std::vector<std::uint32_t> random_indices(std::uint32_t count) {
  std::vector<std::uint32_t> indices(entity_count);
  std::iota(indices.begin(), indices.end(), 0u);
  std::shuffle(indices.begin(), indices.end(), std::mt19937{42});
  indices.resize(count);
  return indices;
}

// Arg: percent of entities written each frame. Times only the read of the changes.
void changed_since_ecs(benchmark::State& state) {
  std::vector<Entity> entities;
  const std::unique_ptr<World> world = make_world(&entities);
  const std::vector<std::uint32_t> written =
      random_indices(entity_count / 100 * static_cast<std::uint32_t>(state.range(0)));
  for (auto _ : state) {
    state.PauseTiming();
    const Tick last_frame = world->tick();
    world->advance_tick();
    for (const std::uint32_t index : written) world->get_mut<Position>(entities[index]).x += 1.0f;
    state.ResumeTiming();
    float sum = 0.0f;
    world->query<const Position>()
        .changed_since<Position>(last_frame)
        .for_each([&](const Position& position) { sum += position.x; });
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * written.size());
}

// Without a change log, plain arrays with a tick per element must scan every element.
void changed_since_raw(benchmark::State& state) {
  RawArrays raw = make_raw_arrays();
  std::vector<Tick> ticks(entity_count, 1);
  Tick tick = 1;
  const std::vector<std::uint32_t> written =
      random_indices(entity_count / 100 * static_cast<std::uint32_t>(state.range(0)));
  for (auto _ : state) {
    state.PauseTiming();
    const Tick last_frame = tick++;
    for (const std::uint32_t index : written) {
      raw.positions[index].x += 1.0f;
      ticks[index] = tick;
    }
    state.ResumeTiming();
    float sum = 0.0f;
    for (std::size_t i = 0; i < ticks.size(); ++i) {
      if (ticks[i] > last_frame) sum += raw.positions[i].x;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * written.size());
}

// Sparse iteration: every entity has a Position, every tenth also a Velocity. Each pass is
// timed on its own and reported per visited entity, so a periodic slow pass (work paid inside
// the query every few ticks) shows up as worst or median far above best.
constexpr std::uint32_t sparse_stride = 10;
constexpr std::uint32_t sparse_visited = entity_count / sparse_stride;

class PassTimer {
 public:
  void start() { start_ = std::chrono::steady_clock::now(); }
  void stop() {
    passes_.push_back(
        std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start_).count());
  }
  void report(benchmark::State& state, std::uint32_t visited) {
    std::sort(passes_.begin(), passes_.end());
    state.counters["best_ns"] = passes_.front() / visited;
    state.counters["median_ns"] = passes_[passes_.size() / 2] / visited;
    state.counters["worst_ns"] = passes_.back() / visited;
  }

 private:
  std::chrono::steady_clock::time_point start_;
  std::vector<double> passes_;
};

// The entities that get a Velocity, in the order they get it: every tenth, or (`scattered`) as
// many picked at random and given it in random order, as when things start moving one by one
// during play. Both visit the same number of entities.
std::vector<std::uint32_t> sparse_members(bool scattered) {
  std::vector<std::uint32_t> members;
  if (!scattered) {
    for (std::uint32_t i = 0; i < entity_count; i += sparse_stride) members.push_back(i);
    return members;
  }
  std::vector<std::uint32_t> all(entity_count);
  std::iota(all.begin(), all.end(), 0u);
  std::shuffle(all.begin(), all.end(), std::mt19937(7));
  members.assign(all.begin(), all.begin() + sparse_visited);
  return members;
}

// Arg: 0 writes Position (so every visit is change-tracked), 1 only reads both. `Grouped`
// declares the (Position, Velocity) owning group first, so the query walks its members without
// lookups.
template <bool Scattered, bool Grouped>
void sparse_iterate_ecs(benchmark::State& state) {
  World world;
  if (Grouped) world.group<Position, Velocity>();
  std::vector<Entity> entities;
  for (std::uint32_t i = 0; i < entity_count; ++i) {
    entities.push_back(world.create());
    world.add<Position>(entities.back(), 0.0f, 0.0f, 0.0f);
  }
  for (const std::uint32_t i : sparse_members(Scattered)) world.add<Velocity>(entities[i], velocity_of(i));
  PassTimer timer;
  float sum = 0.0f;
  for (auto _ : state) {
    world.advance_tick();
    timer.start();
    if (state.range(0) == 0) {
      world.query<Position, const Velocity>().for_each(
          [](Position& position, const Velocity& velocity) { integrate(position, velocity); });
    } else {
      world.query<const Position, const Velocity>().for_each(
          [&](const Position& position, const Velocity& velocity) { sum += position.x * velocity.x; });
    }
    benchmark::ClobberMemory();
    timer.stop();
  }
  benchmark::DoNotOptimize(sum);
  timer.report(state, sparse_visited);
  state.SetItemsProcessed(state.iterations() * sparse_visited);
}

// What a user would write without an ECS: the indices of the entities that move, beside their
// velocities. Arg as for sparse_iterate/ecs.
template <bool Scattered>
void sparse_iterate_raw(benchmark::State& state) {
  std::vector<Position> positions(entity_count, Position{0.0f, 0.0f, 0.0f});
  const std::vector<std::uint32_t> moving = sparse_members(Scattered);
  std::vector<Velocity> velocities;
  for (const std::uint32_t i : moving) velocities.push_back(velocity_of(i));
  PassTimer timer;
  float sum = 0.0f;
  for (auto _ : state) {
    timer.start();
    if (state.range(0) == 0) {
      for (std::size_t k = 0; k < moving.size(); ++k) integrate(positions[moving[k]], velocities[k]);
    } else {
      for (std::size_t k = 0; k < moving.size(); ++k) sum += positions[moving[k]].x * velocities[k].x;
    }
    benchmark::ClobberMemory();
    timer.stop();
  }
  benchmark::DoNotOptimize(sum);
  timer.report(state, sparse_visited);
  state.SetItemsProcessed(state.iterations() * sparse_visited);
}

// World matrices from local transforms, the per-frame work that parallel iteration is for.
// Arg: threads; 1 is the serial for_each, more a thread pool of that many (the caller included).
void transform_update_ecs(benchmark::State& state) {
  World world;
  world.create_many(entity_count, LocalTransform{glm::vec3{1.0f, 2.0f, 3.0f}}, WorldTransform{});
  sg::jobs::ThreadPool threads(static_cast<unsigned>(state.range(0)) - 1);
  const auto update = [](const LocalTransform& local, WorldTransform& world_transform) {
    world_transform.matrix = sg::ecs::to_matrix(local);
  };
  for (auto _ : state) {
    world.advance_tick();
    auto query = world.query<const LocalTransform, WorldTransform>();
    if (state.range(0) == 1) {
      query.for_each(update);
    } else {
      query.for_each_parallel(threads, update);
    }
    benchmark::ClobberMemory();
  }
  state.counters["threads"] = static_cast<double>(threads.thread_count());
  state.SetItemsProcessed(state.iterations() * entity_count);
}

// What one ThreadPool batch costs beyond its tasks: a frame runs a dozen or more batches of a
// few dozen short tasks (lights, views, moved instances), so this overhead multiplies. Arg 0:
// threads (the caller included); Arg 1: microseconds of serial work between batches, untimed
// (0: back to back, as within a phase; 1000: the workers have gone back to sleep). Each of
// 4 tasks per thread spins for about a microsecond.
void thread_pool_batch(benchmark::State& state) {
  sg::jobs::ThreadPool threads(static_cast<unsigned>(state.range(0)) - 1);
  const auto gap = std::chrono::microseconds(state.range(1));
  const auto spin = [](std::chrono::nanoseconds duration) {
    const auto until = std::chrono::steady_clock::now() + duration;
    while (std::chrono::steady_clock::now() < until) {
    }
  };
  const std::size_t tasks = 4 * threads.thread_count();
  for (auto _ : state) {
    spin(gap);
    const auto start = std::chrono::steady_clock::now();
    threads.run(tasks, [&](std::size_t) { spin(std::chrono::microseconds(1)); });
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
}

// Arg: threads; 1 is one loop, more what a user would write by hand: that many std::threads
// each frame (the caller included), each over its share of the arrays.
void transform_update_raw(benchmark::State& state) {
  const std::vector<LocalTransform> locals(entity_count, LocalTransform{glm::vec3{1.0f, 2.0f, 3.0f}});
  std::vector<WorldTransform> worlds(entity_count);
  const auto update = [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) worlds[i].matrix = sg::ecs::to_matrix(locals[i]);
  };
  const auto thread_count = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) {
    if (thread_count == 1) {
      update(0, entity_count);
    } else {
      std::vector<std::thread> threads;
      for (std::size_t t = 1; t < thread_count; ++t) {
        threads.emplace_back(update, entity_count * t / thread_count, entity_count * (t + 1) / thread_count);
      }
      update(0, entity_count / thread_count);
      for (std::thread& thread : threads) thread.join();
    }
    benchmark::ClobberMemory();
  }
  state.counters["threads"] = static_cast<double>(thread_count);
  state.SetItemsProcessed(state.iterations() * entity_count);
}

}  // namespace

BENCHMARK(iterate2_ecs)->Name("iterate2/ecs")->Unit(benchmark::kMillisecond);
BENCHMARK(iterate2_raw)->Name("iterate2/raw")->Unit(benchmark::kMillisecond);
BENCHMARK(iterate3_ecs)->Name("iterate3/ecs")->Unit(benchmark::kMillisecond);
BENCHMARK(iterate3_raw)->Name("iterate3/raw")->Unit(benchmark::kMillisecond);
BENCHMARK(iterate3_write2_ecs)->Name("iterate3_write2/ecs")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(iterate3_write2_raw)->Name("iterate3_write2/raw")->Unit(benchmark::kMillisecond);
// Each sparse case writes (Arg 0) and reads (Arg 1).
void write_and_read(benchmark::internal::Benchmark* sparse) {
  sparse->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
}
BENCHMARK(sparse_iterate_ecs<false, false>)->Name("sparse_iterate/ecs")->Apply(write_and_read);
BENCHMARK(sparse_iterate_ecs<false, true>)->Name("sparse_iterate/ecs_group")->Apply(write_and_read);
BENCHMARK(sparse_iterate_raw<false>)->Name("sparse_iterate/raw")->Apply(write_and_read);
BENCHMARK(sparse_iterate_ecs<true, false>)->Name("sparse_scattered/ecs")->Apply(write_and_read);
BENCHMARK(sparse_iterate_ecs<true, true>)->Name("sparse_scattered/ecs_group")->Apply(write_and_read);
BENCHMARK(sparse_iterate_raw<true>)->Name("sparse_scattered/raw")->Apply(write_and_read);
// Thread counts: 1 to 16, for the lent 16-core machine; this VM has 2 cores.
BENCHMARK(thread_pool_batch)
    ->Name("thread_pool/batch")
    ->ArgsProduct({{2, 4, 16}, {0, 1000}})
    ->Iterations(2000)  // a fixed count: with the untimed gaps, a minimum time would take minutes
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(transform_update_ecs)
    ->Name("transform_update/ecs")
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(transform_update_raw)
    ->Name("transform_update/raw")
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(create2_ecs)->Name("create2/ecs")->Unit(benchmark::kMillisecond);
BENCHMARK(create2_raw)->Name("create2/raw")->Unit(benchmark::kMillisecond);
BENCHMARK(create2_bulk_ecs)->Name("create2_bulk/ecs")->Unit(benchmark::kMillisecond);
BENCHMARK(create2_bulk_raw)->Name("create2_bulk/raw")->Unit(benchmark::kMillisecond);
BENCHMARK(destroy_bulk_ecs)->Name("destroy_bulk/ecs")->Unit(benchmark::kMillisecond);
BENCHMARK(destroy_bulk_kept_ecs)->Name("destroy_bulk/ecs_removals_kept")->Unit(benchmark::kMillisecond);
BENCHMARK(destroy_ecs)->Name("destroy/ecs")->Unit(benchmark::kMillisecond);
BENCHMARK(destroy_raw)->Name("destroy/raw")->Unit(benchmark::kMillisecond);
BENCHMARK(add_remove_ecs<false>)->Name("add_remove/ecs")->Unit(benchmark::kMillisecond);
BENCHMARK(add_remove_ecs<true>)->Name("add_remove/ecs_group")->Unit(benchmark::kMillisecond);
BENCHMARK(add_remove_raw)->Name("add_remove/raw")->Unit(benchmark::kMillisecond);
BENCHMARK(add_remove_archetype_model)->Name("add_remove/archetype_model")->Unit(benchmark::kMillisecond);
BENCHMARK(changed_since_ecs)->Name("changed_since/ecs")->Arg(1)->Arg(10)->Unit(benchmark::kMicrosecond);
BENCHMARK(changed_since_raw)->Name("changed_since/raw")->Arg(1)->Arg(10)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
