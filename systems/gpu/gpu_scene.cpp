// SPDX-License-Identifier: MIT
#include "systems/gpu/gpu_scene.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>
#include <utility>

#include "ecs/query.h"
#include "ecs/transform.h"
#include "rendergraph/device/upload.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "systems/gpu/changed_items_copy.h"
#include "systems/gpu/shader_bindings.h"
#include "systems/scene/material.h"
#include "systems/scene/mesh_instance.h"

namespace sg {
namespace {

const scene::Material default_material;  // what an instance without a Material looks like

}  // namespace

void scene_vertex_input(vk::GraphicsPipelineDesc& desc, VertexInput input) {
  desc.vertex_bindings = {{0, sizeof(scene::Vertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  desc.vertex_attributes = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<uint32_t>(offsetof(scene::Vertex, position))}};
  if (input == VertexInput::position) return;
  if (input == VertexInput::surface) {
    desc.vertex_attributes.push_back(
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<uint32_t>(offsetof(scene::Vertex, normal))});
  }
  desc.vertex_attributes.push_back(
      {2, 0, VK_FORMAT_R32G32_SFLOAT, static_cast<uint32_t>(offsetof(scene::Vertex, uv))});
}

uint32_t draw_class_of(const scene::Material& material) {
  return (material.double_sided ? draw_double_sided : 0u) |
         (material.alpha_mode == scene::AlphaMode::mask ? draw_masked : 0u) |
         (material.alpha_mode == scene::AlphaMode::blend ? draw_blended : 0u);
}

GpuScene::GpuScene(vk::VulkanContext& context, const scene::MeshLibrary& meshes, uint32_t frames_in_flight)
    : meshes_(meshes.meshes),
      instances_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "instances"),
      draws_(context, VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, frames_in_flight, "indirect draws"),
      uploaded_at_(frames_in_flight, 0) {
  if (meshes.indices.empty()) return;  // nothing to draw, and Vulkan refuses empty buffers
  // Storage too: shadow_raster.comp reads the geometry itself.
  constexpr VkBufferUsageFlags dst = VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  vertices_ = vk::Buffer(
      context, {meshes.vertices.size() * sizeof(scene::Vertex), dst | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                vk::MemoryUsage::gpu_only, "scene vertices"});
  indices_ =
      vk::Buffer(context, {meshes.indices.size() * sizeof(uint32_t), dst | VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                           vk::MemoryUsage::gpu_only, "scene indices"});
  vk::UploadBatch upload(context);
  upload.copy(vertices_, std::span<const scene::Vertex>(meshes.vertices));
  upload.copy(indices_, std::span<const uint32_t>(meshes.indices));
  upload.submit();
}

void GpuScene::gather(const ecs::World& world, jobs::ThreadPool* pool) {
  // The frame's writes carry the tick the previous gather ran at (the frame loop advances the
  // tick just before gathering), so "new" means written at or after it.
  const ecs::Tick since = gathered_at_ == 0 ? 0 : gathered_at_ - 1;
  gathered_at_ = world.tick();
  ++gathers_;
  if (gathers_ == 1 || !gather_changes(world, since, pool)) gather_all(world, pool);
}

void GpuScene::place(const ecs::World& world, size_t i) {
  const ecs::Entity entity = items_[i].entity;
  const glm::mat4& model = world.try_get<ecs::WorldTransform>(entity)->matrix;
  const scene::Material* found = world.try_get<scene::Material>(entity);
  const scene::Material& material = found ? *found : default_material;
  const float texture =
      material.base_color_texture == scene::no_texture ? -1.0f : float(material.base_color_texture);
  const float cutoff = material.alpha_mode == scene::AlphaMode::mask    ? material.alpha_cutoff
                       : material.alpha_mode == scene::AlphaMode::blend ? transparent_cutoff
                                                                        : 0.0f;
  // A surface that receives no shadow carries its shininess negated (GpuInstance::material).
  const float shininess = items_[i].receiver ? material.shininess : -material.shininess;
  sorted_[i] = {model, glm::vec4(glm::vec3(material.base_color), material.specular),
                glm::vec4(shininess, texture, material.base_color.a, cutoff),
                glm::uvec4(items_[i].light_layers, 0u, 0u, 0u)};
  bounds_[i] = scene::transformed(meshes_[items_[i].mesh].bounds, model);
  keys_[i] = ecs::entity_key(entity);
}

bool GpuScene::gather_changes(const ecs::World& world, ecs::Tick since, jobs::ThreadPool* pool) {
  // Anything that adds, removes or reorders instances is rare (editing, streaming): it regathers
  // everything. Moves and material edits touch only their instances.
  if (!world.removed_since<scene::MeshInstance>(since).empty() ||
      !world.removed_since<ecs::WorldTransform>(since).empty() ||
      !world.removed_since<scene::Material>(since).empty()) {
    return false;
  }
  bool reordered = false;
  world.query<const scene::MeshInstance>().changed_since<scene::MeshInstance>(since).for_each(
      [&](const scene::MeshInstance&) { reordered = true; });
  if (reordered) return false;

  // The changes are marked on the pool, by instance (written_at_) and by chunk: thousands of
  // moving instances took 0.05 ms to look up on one thread (an H200 host, 2026-12-01). Material edits are
  // rare, and looked up here.
  chunk_changed_.assign(chunk_bounds_.size(), 0);
  std::atomic<bool> unknown{false};
  // Marks the entity's instance written, and returns it; npos for an entity that is no instance.
  const auto note = [&](ecs::Entity entity) {
    const uint32_t at = entity.index < place_of_.size() ? place_of_[entity.index] : ecs::SparseSet::npos;
    if (at == ecs::SparseSet::npos || items_[at].entity != entity) {
      unknown.store(true, std::memory_order_relaxed);  // it became an instance by gaining a component
      return ecs::SparseSet::npos;
    }
    written_at_[at] = gathers_;
    std::atomic_ref(chunk_changed_[at / instances_per_chunk]).store(1, std::memory_order_relaxed);
    return at;
  };
  world.query<const ecs::WorldTransform, const scene::MeshInstance>()
      .changed_since<ecs::WorldTransform>(since)
      .for_each_parallel(
          pool,
          [&](ecs::Entity entity, const ecs::WorldTransform&, const scene::MeshInstance&) { note(entity); },
          changes_per_task);
  // A material whose draw class changed moves its instance to another class's draws.
  bool reclassed = false;
  world.query<const scene::Material, const ecs::WorldTransform, const scene::MeshInstance>()
      .changed_since<scene::Material>(since)
      .for_each([&](ecs::Entity entity, const scene::Material& material, const ecs::WorldTransform&,
                    const scene::MeshInstance&) {
        const uint32_t at = note(entity);
        reclassed =
            reclassed || (at != ecs::SparseSet::npos && items_[at].draw_class != draw_class_of(material));
      });
  if (unknown.load(std::memory_order_relaxed) || reclassed) return false;
  regrown_chunks_.clear();
  for (uint32_t chunk = 0; chunk < chunk_changed_.size(); ++chunk) {
    if (chunk_changed_[chunk] != 0) regrown_chunks_.push_back(chunk);
  }
  changed_.clear();
  bounds_before_.clear();
  bounds_after_.clear();
  if (regrown_chunks_.empty()) return true;

  // One task per changed chunk re-places its marked instances and then regrows the chunk's
  // bounds from what it just wrote, in its own cache: bounds written by other cores took longer
  // to read back than the re-placing itself. Each lists its instances in its own stretch of
  // replaced_by_chunk_, gathered into changed_ and their bounds after.
  replaced_by_chunk_.resize(instance_count());
  chunk_changes_.assign(chunk_bounds_.size(), 0);
  jobs::run_in_pieces(pool, regrown_chunks_.size(), 1, [&](size_t begin, size_t end) {
    for (size_t n = begin; n < end; ++n) {
      const uint32_t chunk = regrown_chunks_[n];
      const size_t first = size_t{chunk} * instances_per_chunk;
      const size_t last = std::min(first + instances_per_chunk, bounds_.size());
      size_t listed = first;
      for (size_t i = first; i < last; ++i) {
        if (written_at_[i] != gathers_) continue;
        const scene::Aabb before = bounds_[i];
        place(world, i);
        replaced_by_chunk_[listed++] = {static_cast<uint32_t>(i), before, bounds_[i]};
        const bool moved = bounds_[i].min != before.min || bounds_[i].max != before.max;
        if (moved && moved_at_[i] == 0) moved_at_[i] = gathers_;
      }
      chunk_changes_[chunk] = static_cast<uint32_t>(listed - first);
      regrow_chunk(chunk);
    }
  });
  for (const uint32_t chunk : regrown_chunks_) {
    const size_t first = size_t{chunk} * instances_per_chunk;
    for (size_t k = first; k < first + chunk_changes_[chunk]; ++k) {
      const Replacement& entry = replaced_by_chunk_[k];
      changed_.push_back(entry.instance);
      bounds_before_.push_back(entry.before);
      bounds_after_.push_back(entry.after);
      if (moved_at_[entry.instance] == gathers_) moving_.push_back(entry.instance);
    }
  }
  grow_scene_bounds();
  return true;
}

void GpuScene::regrow_scene_bounds(jobs::ThreadPool* pool) {
  chunk_bounds_.resize((bounds_.size() + instances_per_chunk - 1) / instances_per_chunk);
  jobs::run_in_pieces(pool, chunk_bounds_.size(), 1, [&](size_t begin, size_t end) {
    for (size_t chunk = begin; chunk < end; ++chunk) regrow_chunk(chunk);
  });
  grow_scene_bounds();
}

void GpuScene::regrow_chunk(size_t chunk) {
  scene::Aabb& bounds = chunk_bounds_[chunk] = {};
  const size_t last = std::min(bounds_.size(), (chunk + 1) * instances_per_chunk);
  for (size_t i = chunk * instances_per_chunk; i < last; ++i) scene::grow(bounds, bounds_[i]);
}

void GpuScene::grow_scene_bounds() {
  scene_bounds_ = {};
  for (const scene::Aabb& chunk : chunk_bounds_) scene::grow(scene_bounds_, chunk);
}

void GpuScene::gather_all(const ecs::World& world, jobs::ThreadPool* pool) {
  // Only what orders the instances here; their data is read below, in parallel.
  items_.clear();
  world.query<const ecs::WorldTransform, const scene::MeshInstance>().for_each(
      [&](ecs::Entity entity, const ecs::WorldTransform&, const scene::MeshInstance& mesh) {
        const scene::Material* material = world.try_get<scene::Material>(entity);
        const auto draw_class = static_cast<uint8_t>(draw_class_of(material ? *material : default_material));
        items_.push_back({mesh.mesh, mesh.casts_shadow, mesh.receives_shadow, draw_class, mesh.light_layers,
                          mesh.shadow_layers, entity});
      });
  if (items_.size() > max_instances) {
    throw std::length_error("the scene has " + std::to_string(items_.size()) + " mesh instances; at most " +
                            std::to_string(max_instances) + " can be drawn");
  }
  // By draw class, then mesh, casters first within each: a counting sort (classes and meshes
  // are few, instances many).
  const size_t meshes = meshes_.size();
  slot_starts_.assign(2 * draw_class_count * meshes + 1, 0);
  const auto slot_of = [meshes](const Item& item) {
    return 2 * (item.draw_class * meshes + item.mesh) + (item.caster ? 0 : 1);
  };
  for (const Item& item : items_) ++slot_starts_[slot_of(item) + 1];
  for (size_t s = 1; s < slot_starts_.size(); ++s) slot_starts_[s] += slot_starts_[s - 1];
  sorted_items_.resize(items_.size());
  for (const Item& item : items_) sorted_items_[slot_starts_[slot_of(item)]++] = item;
  std::swap(items_, sorted_items_);

  const size_t count = items_.size();
  place_of_.assign(place_of_.size(), ecs::SparseSet::npos);
  for (size_t i = 0; i < count; ++i) {
    const uint32_t index = items_[i].entity.index;
    if (index >= place_of_.size()) place_of_.resize(size_t{index} + 1, ecs::SparseSet::npos);
    place_of_[index] = static_cast<uint32_t>(i);
  }
  written_at_.assign(count, 0);
  moved_at_.assign(count, 0);
  moving_.clear();
  laid_out_at_ = gathers_;
  changed_.clear();
  bounds_before_.clear();
  bounds_after_.clear();

  // Per instance, in its sorted place: its record, world bounds and key. Reading the components
  // and the bounds' eight corners are most of a full gather, and independent: chunks of them run
  // on the pool's threads (the world is only read).
  sorted_.resize(count);
  bounds_.resize(count);
  keys_.resize(count);
  constexpr size_t piece = 256;  // small, so threads that wake late still find work
  jobs::run_in_pieces(pool, count, piece, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) place(world, i);
  });
  regrow_scene_bounds(pool);

  commands_.clear();
  triangles_ = 0;
  class_commands_.fill({});
  caster_groups_.clear();
  first_cut_out_group_ = 0;  // the opaque groups come first: their count
  // One command per (draw class, mesh) over its instances, and a caster group over its casters
  // (first).
  for (size_t begin = 0; begin < count;) {
    const uint32_t mesh = items_[begin].mesh;
    const uint8_t draw_class = items_[begin].draw_class;
    const scene::MeshRange& range = meshes_[mesh];
    size_t end = begin;
    uint32_t casters = 0;
    for (; end < count && items_[end].mesh == mesh && items_[end].draw_class == draw_class; ++end) {
      casters += items_[end].caster;
    }
    if (range.index_count > 0) {
      CommandRange& commands = class_commands_[draw_class];
      if (commands.count == 0) commands.first = static_cast<uint32_t>(commands_.size());
      ++commands.count;
      const VkDrawIndexedIndirectCommand command{range.index_count, static_cast<uint32_t>(end - begin),
                                                 range.first_index, static_cast<int32_t>(range.vertex_offset),
                                                 static_cast<uint32_t>(begin)};
      commands_.push_back(command);
      triangles_ += uint64_t{range.index_count / 3} * command.instanceCount;
      if (casters > 0) {
        VkDrawIndexedIndirectCommand group = command;
        group.instanceCount = casters;
        if (!(draw_class & (draw_masked | draw_blended))) ++first_cut_out_group_;
        caster_groups_.push_back(group);
      }
    }
    begin = end;
  }
}

void GpuScene::upload(uint32_t slot, jobs::ThreadPool* pool) {
  // Megabytes a frame with many instances, so a slot gets only the records written since it was
  // last uploaded, unless the layout changed or its buffer is new. Copies run in chunks on the
  // pool, as writes into mapped GPU memory go faster from several cores; chunks of 1,024 records,
  // as the instances that moved are often of one mesh, so consecutive, and in chunks of 4,096 the
  // stress scene's moving crates fell to one or two threads.
  const std::span<const GpuInstance> instances(sorted_);
  const bool grows = instances_.buffer(slot).size() < instances.size_bytes();
  const vk::Buffer& buffer = instances_.reserve(slot, instances.size_bytes());
  auto* mapped = static_cast<GpuInstance*>(buffer.mapped());
  const uint64_t uploaded_at = std::exchange(uploaded_at_[slot], gathers_);
  copy_changed_items(mapped, instances, std::span<const uint64_t>(written_at_), uploaded_at,
                     grows || uploaded_at < laid_out_at_, 1024, pool);
  draws_.write(slot, std::span<const VkDrawIndexedIndirectCommand>(commands_));
}

void GpuScene::draw_camera_pass(const vk::PassRecorder& rec,
                                std::span<const VkPipeline, draw_class_count> pipelines,
                                const vk::PipelineLayout& layout, VkDescriptorSet set,
                                const FrameConstants& constants, uint32_t slot) const {
  rec.set_full_viewport();
  if (commands_.empty() || !bind_geometry(rec.cmd())) return;
  layout.bind(rec.cmd(), set);  // once: the classes' pipelines share the layout
  layout.push(rec.cmd(), constants);
  for (uint32_t draw_class = 0; draw_class < draw_class_count; ++draw_class) {
    const CommandRange& commands = class_commands_[draw_class];
    if (commands.count == 0 || (draw_class & draw_blended)) continue;
    vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines[draw_class]);
    vkCmdDrawIndexedIndirect(rec.cmd(), draws_.buffer(slot).handle(),
                             commands.first * sizeof(VkDrawIndexedIndirectCommand), commands.count,
                             sizeof(VkDrawIndexedIndirectCommand));
  }
}

bool GpuScene::has_transparent() const {
  for (uint32_t draw_class = draw_blended; draw_class < draw_class_count; ++draw_class) {
    if ((draw_class & draw_blended) && has_draw_class(draw_class)) return true;
  }
  return false;
}

void GpuScene::order_transparent(const glm::vec3& eye) {
  // (minus the squared distance of the bounds' centre, instance): ascending is farthest first.
  transparent_by_distance_.clear();
  for (uint32_t draw_class = 0; draw_class < draw_class_count; ++draw_class) {
    if (!(draw_class & draw_blended)) continue;
    const CommandRange& range = class_commands_[draw_class];
    for (uint32_t c = range.first; c < range.first + range.count; ++c) {
      for (uint32_t i = commands_[c].firstInstance;
           i < commands_[c].firstInstance + commands_[c].instanceCount; ++i) {
        const glm::vec3 to_centre = 0.5f * (bounds_[i].min + bounds_[i].max) - eye;
        transparent_by_distance_.push_back({-glm::dot(to_centre, to_centre), i});
      }
    }
  }
  std::sort(transparent_by_distance_.begin(), transparent_by_distance_.end());
  transparent_order_.clear();
  for (const auto& [distance, instance] : transparent_by_distance_) transparent_order_.push_back(instance);
}

void GpuScene::draw_transparent(const vk::PassRecorder& rec,
                                std::span<const VkPipeline, draw_class_count> pipelines,
                                const vk::PipelineLayout& layout, VkDescriptorSet set,
                                const FrameConstants& constants) const {
  rec.set_full_viewport();
  if (transparent_order_.empty() || !bind_geometry(rec.cmd())) return;
  layout.bind(rec.cmd(), set);
  layout.push(rec.cmd(), constants);
  uint32_t bound = draw_class_count;  // none yet
  for (const uint32_t i : transparent_order_) {
    if (items_[i].draw_class != bound) {
      bound = items_[i].draw_class;
      vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines[bound]);
    }
    const scene::MeshRange& mesh = meshes_[items_[i].mesh];
    vkCmdDrawIndexed(rec.cmd(), mesh.index_count, 1, mesh.first_index,
                     static_cast<int32_t>(mesh.vertex_offset), i);
  }
}

bool GpuScene::bind_geometry(VkCommandBuffer cmd) const {
  if (vertices_.handle() == VK_NULL_HANDLE) return false;
  const VkBuffer vertex_buffer = vertices_.handle();
  const VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertex_buffer, &zero);
  vkCmdBindIndexBuffer(cmd, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
  return true;
}

}  // namespace sg
