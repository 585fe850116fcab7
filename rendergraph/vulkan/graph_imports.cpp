// SPDX-License-Identifier: MIT
#include "rendergraph/vulkan/graph_imports.h"

#include "rendergraph/device/resources.h"

namespace sg::vk {

void ImportedResources::bind(rg::ImageHandle handle, const Image& image) {
  bindings_.push_back({handle.index, {image.handle(), VK_NULL_HANDLE, &image.views(), image.aspect()}});
}

void ImportedResources::bind(rg::ImageHandle handle, VkImage image, VkFormat format) {
  bindings_.push_back({handle.index, {image, VK_NULL_HANDLE, nullptr, aspect_of(format)}});
}

void ImportedResources::bind(rg::BufferHandle handle, const Buffer& buffer) {
  bindings_.push_back({handle.index, {VK_NULL_HANDLE, buffer.handle(), nullptr, 0}});
}

rg::ImageHandle GraphImports::import_image(rg::RenderGraph& graph, std::string name, const Image& image,
                                           std::optional<rg::ResourceState> final_state) {
  uint64_t& serial = serials_[name];
  if (serial != image.serial()) {
    states_.forget(name);
    serial = image.serial();
  }
  std::vector<rg::RangeState> initial = states_.initial_states(name);
  const rg::ImageHandle handle =
      graph.import_image(std::move(name), graph_desc(image), std::move(initial), final_state);
  resources_.bind(handle, image);
  return handle;
}

rg::ImageHandle GraphImports::import_image(rg::RenderGraph& graph, std::string name, VkImage image,
                                           VkFormat format, VkExtent2D extent,
                                           rg::ResourceState initial_state, rg::ResourceState final_state) {
  const rg::ImageHandle handle = graph.import_image(
      std::move(name), {extent.width, extent.height, from_vk(format)}, initial_state, final_state);
  resources_.bind(handle, image, format);
  return handle;
}

rg::BufferHandle GraphImports::import_buffer(rg::RenderGraph& graph, std::string name, const Buffer& buffer,
                                             rg::ResourceState state) {
  const rg::BufferHandle handle = graph.import_buffer(std::move(name), {buffer.size()}, state, state);
  resources_.bind(handle, buffer);
  return handle;
}

void GraphImports::remember(const rg::CompiledPlan& plan) {
  states_.remember(plan);
  resources_.clear();
}

}  // namespace sg::vk
