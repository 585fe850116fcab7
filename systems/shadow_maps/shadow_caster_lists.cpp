// SPDX-License-Identifier: MIT
#include "systems/shadow_maps/shadow_caster_lists.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "systems/gpu/gpu_scene.h"

namespace sg {
namespace {

constexpr uint32_t no_group = std::numeric_limits<uint32_t>::max();
// Cells per side at most, however small the lights' reach: few enough to build in one pass
// over the casters.
constexpr uint32_t max_cells_per_side = 64;

bool holds(const scene::Aabb& box, const glm::vec3& point) {
  return glm::all(glm::greaterThanEqual(point, box.min)) && glm::all(glm::lessThanEqual(point, box.max));
}

bool sphere_meets_box(const glm::vec4& sphere, const scene::Aabb& box) {
  const glm::vec3 centre(sphere);
  const glm::vec3 nearest = glm::clamp(centre, box.min, box.max);
  const glm::vec3 d = nearest - centre;
  return glm::dot(d, d) <= sphere.w * sphere.w;
}

}  // namespace

ShadowCasterLists::ShadowCasterLists(vk::VulkanContext& context, uint32_t frames_in_flight)
    : ids_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "shadow caster ids"),
      commands_(context, VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, frames_in_flight, "shadow caster draws") {}

void ShadowCasterLists::begin_frame(const GpuScene& scene, float typical_reach) {
  ids_scratch_.clear();
  commands_scratch_.clear();
  const std::span<const VkDrawIndexedIndirectCommand> groups = scene.caster_groups();
  group_of_.assign(scene.instance_count(), no_group);
  for (uint32_t g = 0; g < groups.size(); ++g) {
    for (uint32_t i = groups[g].firstInstance; i < groups[g].firstInstance + groups[g].instanceCount; ++i) {
      group_of_[i] = g;
    }
  }
  seen_.assign(scene.instance_count(), 0);
  view_stamp_ = 0;
  build_grid(scene, typical_reach);
}

void ShadowCasterLists::build_grid(const GpuScene& scene, float typical_reach) {
  const std::span<const scene::Aabb> bounds = scene.instance_bounds();
  scene::Aabb extent;
  for (uint32_t i = 0; i < bounds.size(); ++i) {
    if (group_of_[i] != no_group) scene::grow(extent, bounds[i]);
  }
  Grid& grid = grid_;
  grid.cell_start.clear();
  grid.cell_ids.clear();
  if (extent.empty()) {
    grid.columns = grid.rows = 0;
    return;
  }
  const glm::vec2 size(extent.max.x - extent.min.x, extent.max.z - extent.min.z);
  grid.origin = {extent.min.x, extent.min.z};
  const float widest = std::max({size.x, size.y, 1e-3f});
  grid.cell_size = std::clamp(typical_reach, widest / float(max_cells_per_side), widest);
  grid.columns = std::clamp(uint32_t(std::ceil(size.x / grid.cell_size)), 1u, max_cells_per_side);
  grid.rows = std::clamp(uint32_t(std::ceil(size.y / grid.cell_size)), 1u, max_cells_per_side);

  // Each caster goes into every cell its box covers: count, prefix-sum, fill.
  const auto cell_range = [&](const scene::Aabb& box, uint32_t& x0, uint32_t& x1, uint32_t& z0,
                              uint32_t& z1) {
    const auto cell = [&](float v, float origin, uint32_t cells) {
      return std::min(uint32_t(std::max(0.0f, (v - origin) / grid.cell_size)), cells - 1);
    };
    x0 = cell(box.min.x, grid.origin.x, grid.columns);
    x1 = cell(box.max.x, grid.origin.x, grid.columns);
    z0 = cell(box.min.z, grid.origin.y, grid.rows);
    z1 = cell(box.max.z, grid.origin.y, grid.rows);
  };
  grid.cell_start.assign(size_t{grid.columns} * grid.rows + 1, 0);
  for (uint32_t i = 0; i < bounds.size(); ++i) {
    if (group_of_[i] == no_group) continue;
    uint32_t x0, x1, z0, z1;
    cell_range(bounds[i], x0, x1, z0, z1);
    for (uint32_t z = z0; z <= z1; ++z) {
      for (uint32_t x = x0; x <= x1; ++x) ++grid.cell_start[z * grid.columns + x + 1];
    }
  }
  for (size_t c = 1; c < grid.cell_start.size(); ++c) grid.cell_start[c] += grid.cell_start[c - 1];
  grid.cell_ids.resize(grid.cell_start.back());
  std::vector<uint32_t>& fill = candidates_;  // reused: the next write position per cell
  fill.assign(grid.cell_start.begin(), grid.cell_start.end() - 1);
  for (uint32_t i = 0; i < bounds.size(); ++i) {
    if (group_of_[i] == no_group) continue;
    uint32_t x0, x1, z0, z1;
    cell_range(bounds[i], x0, x1, z0, z1);
    for (uint32_t z = z0; z <= z1; ++z) {
      for (uint32_t x = x0; x <= x1; ++x) grid.cell_ids[fill[z * grid.columns + x]++] = i;
    }
  }
}

CasterView ShadowCasterLists::add_view(const GpuScene& scene, const glm::vec4& reach,
                                       scene::LayerMask caster_mask, uint32_t copies) {
  const std::span<const VkDrawIndexedIndirectCommand> groups = scene.caster_groups();
  const std::span<const scene::Aabb> bounds = scene.instance_bounds();
  candidates_.clear();
  if (reach.w < 0.0f) {
    for (const VkDrawIndexedIndirectCommand& group : groups) {
      for (uint32_t i = group.firstInstance; i < group.firstInstance + group.instanceCount; ++i) {
        if (scene.shadow_layers(i) & caster_mask) candidates_.push_back(i);
      }
    }
  } else if (grid_.columns > 0) {
    ++view_stamp_;
    const auto cell = [&](float v, float origin) {
      return int64_t(std::floor((v - origin) / grid_.cell_size));
    };
    const int64_t x0 = std::max<int64_t>(0, cell(reach.x - reach.w, grid_.origin.x));
    const int64_t x1 = std::min<int64_t>(grid_.columns - 1, cell(reach.x + reach.w, grid_.origin.x));
    const int64_t z0 = std::max<int64_t>(0, cell(reach.z - reach.w, grid_.origin.y));
    const int64_t z1 = std::min<int64_t>(grid_.rows - 1, cell(reach.z + reach.w, grid_.origin.y));
    for (int64_t z = z0; z <= z1; ++z) {
      for (int64_t x = x0; x <= x1; ++x) {
        const size_t c = size_t(z) * grid_.columns + size_t(x);
        for (uint32_t k = grid_.cell_start[c]; k < grid_.cell_start[c + 1]; ++k) {
          const uint32_t i = grid_.cell_ids[k];
          if (seen_[i] == view_stamp_) continue;  // a caster spanning cells is tested once
          seen_[i] = view_stamp_;
          if (!(scene.shadow_layers(i) & caster_mask) || !sphere_meets_box(reach, bounds[i])) continue;
          if ((scene.draw_class(i) & draw_blended) && holds(bounds[i], glm::vec3(reach))) continue;
          candidates_.push_back(i);
        }
      }
    }
  }

  // One command per caster group the view kept anything of; order within a group is free.
  CasterView view{static_cast<uint32_t>(commands_scratch_.size()), 0, 0};
  by_group_.resize(groups.size());
  for (const uint32_t i : candidates_) by_group_[group_of_[i]].push_back(i);
  for (uint32_t group = 0; group < groups.size(); ++group) {
    std::vector<uint32_t>& kept = by_group_[group];
    if (kept.empty()) continue;
    VkDrawIndexedIndirectCommand command = groups[group];
    command.instanceCount = static_cast<uint32_t>(kept.size()) * copies;
    command.firstInstance = static_cast<uint32_t>(ids_scratch_.size());
    ids_scratch_.insert(ids_scratch_.end(), kept.begin(), kept.end());
    commands_scratch_.push_back(command);
    ++view.command_count;
    if (group >= scene.first_cut_out_group()) ++view.cut_out_commands;
    kept.clear();
  }
  return view;
}

void ShadowCasterLists::upload(uint32_t slot) {
  ids_.write(slot, std::span<const uint32_t>(ids_scratch_));
  commands_.write(slot, std::span<const VkDrawIndexedIndirectCommand>(commands_scratch_));
}

void ShadowCasterLists::draw(VkCommandBuffer cmd, uint32_t slot, CasterView view, bool cut_out) const {
  const uint32_t opaque = view.command_count - view.cut_out_commands;
  const uint32_t first = cut_out ? view.first_command + opaque : view.first_command;
  const uint32_t count = cut_out ? view.cut_out_commands : opaque;
  if (count == 0) return;
  vkCmdDrawIndexedIndirect(cmd, commands_.buffer(slot).handle(),
                           VkDeviceSize{first} * sizeof(VkDrawIndexedIndirectCommand), count,
                           sizeof(VkDrawIndexedIndirectCommand));
}

}  // namespace sg
