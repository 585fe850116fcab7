// SPDX-License-Identifier: MIT
#include "rendergraph/vulkan/graph_executor.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "rendergraph/core/pass_context.h"
#include "rendergraph/device/context.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/device/vulkan_error.h"
#include "rendergraph/vulkan/pass_recorder.h"

namespace sg::vk {
namespace {

// Plans kept per slot: enough for a frame that alternates between a few graph shapes.
constexpr size_t transient_sets_per_slot = 4;

UniqueDescriptorPool create_frame_descriptor_pool(VkDevice device) {
  // Sized for the handful of per-frame sets each pass allocates; exhausting it is a VulkanError
  // naming vkAllocateDescriptorSets, not silent corruption.
  const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1024},
                                        {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 256},
                                        {VK_DESCRIPTOR_TYPE_SAMPLER, 64},
                                        {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 256},
                                        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1024},
                                        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 256}};
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.maxSets = 512;
  info.poolSizeCount = static_cast<uint32_t>(std::size(sizes));
  info.pPoolSizes = sizes;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  check(vkCreateDescriptorPool(device, &info, nullptr, &pool), "vkCreateDescriptorPool");
  return UniqueDescriptorPool(device, pool);
}

VkExtent2D mip_extent(const rg::ImageDesc& desc, uint32_t mip) {
  return {std::max(1u, desc.width >> mip), std::max(1u, desc.height >> mip)};
}

bool is_attachment(rg::Usage usage) {
  return usage == rg::Usage::color_attachment || usage == rg::Usage::depth_attachment;
}

}  // namespace

VkImageView PassRecorder::view(rg::ImageHandle image, rg::SubresourceRange range,
                               std::optional<VkImageViewType> type) const {
  const PhysicalResource& resource = resources_[image.index];
  const rg::ImageDesc& desc = descriptions_[image.index].image;
  if (resource.views == nullptr) {
    throw std::logic_error("image resource " + std::to_string(image.index) +
                           " was bound without views (a swapchain image?); it can only be copied");
  }
  if (range.mip_count == rg::remaining) range.mip_count = desc.mips - range.base_mip;
  if (range.layer_count == rg::remaining) range.layer_count = desc.layers - range.base_layer;
  if (!type) {
    const bool whole_cubes = desc.cube_compatible && range.base_layer % 6 == 0 && range.layer_count % 6 == 0;
    type = range.layer_count == 1 ? VK_IMAGE_VIEW_TYPE_2D
           : whole_cubes ? (range.layer_count == 6 ? VK_IMAGE_VIEW_TYPE_CUBE : VK_IMAGE_VIEW_TYPE_CUBE_ARRAY)
                         : VK_IMAGE_VIEW_TYPE_2D_ARRAY;
  }
  return resource.views->get({range.base_mip, range.mip_count, range.base_layer, range.layer_count, *type});
}

void PassRecorder::set_full_viewport() const { set_viewport({{0, 0}, render_extent_}); }

void PassRecorder::set_viewport(const VkRect2D& area) const {
  const VkViewport viewport{float(area.offset.x),
                            float(area.offset.y),
                            float(area.extent.width),
                            float(area.extent.height),
                            0.0f,
                            1.0f};
  vkCmdSetViewport(cmd_, 0, 1, &viewport);
  vkCmdSetScissor(cmd_, 0, 1, &area);
}

VkDescriptorSet PassRecorder::allocate_set(const PipelineLayout& layout) const {
  const VkDescriptorSetLayout set_layout = layout.set_layout();
  VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  info.descriptorPool = frame_descriptors_;
  info.descriptorSetCount = 1;
  info.pSetLayouts = &set_layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  check(vkAllocateDescriptorSets(context_.device(), &info, &set), "vkAllocateDescriptorSets");
  return set;
}

GraphExecutor::GraphExecutor(VulkanContext& context, uint32_t frames_in_flight)
    : context_(context), timer_(context, frames_in_flight), slots_(frames_in_flight) {
  for (Slot& slot : slots_) slot.descriptors = create_frame_descriptor_pool(context.device());
}

GraphExecutor::~GraphExecutor() = default;

TransientResources& GraphExecutor::transients_for(Slot& slot,
                                                  const std::shared_ptr<const rg::CompiledPlan>& plan) {
  auto& sets = slot.transients;
  // The GPU has finished this slot's previous frame, so sets of plans nobody holds any more can
  // go now; a live plan's set is kept even while unused (its shape may come back).
  std::erase_if(sets, [](const CachedTransients& set) { return set.plan.expired(); });
  const auto found = std::find_if(sets.begin(), sets.end(),
                                  [&](const CachedTransients& set) { return set.key == plan.get(); });
  if (found != sets.end()) {
    std::rotate(sets.begin(), found, found + 1);
  } else {
    sets.insert(sets.begin(), {plan, plan.get(), std::make_unique<TransientResources>(context_, *plan)});
    if (sets.size() > transient_sets_per_slot) sets.pop_back();
  }
  return *sets.front().resources;
}

void GraphExecutor::execute(VkCommandBuffer cmd, uint32_t slot_index, uint64_t frame_number,
                            const rg::RenderGraph& graph, const std::shared_ptr<const rg::CompiledPlan>& plan,
                            const ImportedResources& imports) {
  Slot& slot = slots_[slot_index];
  const auto pass_count = static_cast<uint32_t>(plan->passes.size());
  collect_timings(slot_index);
  timer_.begin_frame(cmd, slot_index, pass_count);
  slot.plan = plan;
  slot.frame_number = frame_number;
  check(vkResetDescriptorPool(context_.device(), slot.descriptors.get(), 0), "vkResetDescriptorPool");

  const TransientResources& transients = transients_for(slot, plan);
  physical_.assign(plan->resources.size(), PhysicalResource{});
  for (uint32_t i = 0; i < plan->resources.size(); ++i) {
    const rg::CompiledResource& resource = plan->resources[i];
    if (resource.imported) continue;
    const VkImageAspectFlags aspect =
        resource.kind == rg::ResourceKind::image ? aspect_of(to_vk(resource.image.format)) : 0;
    physical_[i] = {transients.image(i), transients.buffer(i), transients.views(i), aspect};
  }
  for (const auto& [index, resource] : imports.bindings()) {
    if (index < physical_.size() && plan->resources[index].imported) physical_[index] = resource;
  }
  for (uint32_t i = 0; i < plan->resources.size(); ++i) {
    const rg::CompiledResource& resource = plan->resources[i];
    const bool bound = physical_[i].image != VK_NULL_HANDLE || physical_[i].buffer != VK_NULL_HANDLE;
    if (resource.imported && resource.lifetime && !bound) {
      throw std::logic_error("render graph: imported " + std::string(rg::kind_name(resource.kind)) + " '" +
                             resource.name + "' is used by the frame but was not bound");
    }
  }

  PassRecorder recorder(context_, cmd, physical_, plan->resources, slot.descriptors.get());
  for (uint32_t position = 0; position < pass_count; ++position) {
    const rg::CompiledPass& pass = plan->passes[position];
    context_.begin_label(cmd, pass.name.c_str());
    timer_.begin_pass(cmd, slot_index, position);
    record_barriers(cmd, pass.barriers, physical_, barrier_scratch_);
    record_pass(cmd, pass, graph.passes()[pass.declared_index], recorder);
    timer_.end_pass(cmd, slot_index, position);
    context_.end_label(cmd);
  }
  record_barriers(cmd, plan->final_barriers, physical_, barrier_scratch_);
}

void GraphExecutor::collect_timings(uint32_t slot_index) {
  const Slot& slot = slots_[slot_index];
  if (!timer_.collect(slot_index, pass_ms_) || !slot.plan) return;
  if (!latest_timings_) latest_timings_.emplace();
  latest_timings_->frame_number = slot.frame_number;
  latest_timings_->plan = slot.plan;
  latest_timings_->pass_ms.assign(pass_ms_.begin(), pass_ms_.end());
}

void GraphExecutor::record_pass(VkCommandBuffer cmd, const rg::CompiledPass& pass,
                                const rg::PassDeclaration& declaration, PassRecorder& recorder) {
  color_attachments_.clear();
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  bool has_depth = false;
  VkExtent2D extent{~0u, ~0u};
  uint32_t layers = 1;
  for (const rg::ResourceAccess& access : declaration.accesses) {
    if (!is_attachment(access.usage)) continue;
    const rg::ImageDesc& desc = recorder.descriptions_[access.resource].image;
    const rg::SubresourceRange& range = access.range;
    const PhysicalResource& resource = physical_[access.resource];
    if (resource.views == nullptr) {
      throw std::logic_error("render graph: pass '" + pass.name +
                             "' renders to an image bound without views");
    }
    VkRenderingAttachmentInfo attachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    attachment.imageView =
        resource.views->get({range.base_mip, 1, range.base_layer, range.layer_count,
                             range.layer_count == 1 ? VK_IMAGE_VIEW_TYPE_2D : VK_IMAGE_VIEW_TYPE_2D_ARRAY});
    attachment.imageLayout = to_vk(access.state.layout);
    const bool keeps = rg::has_earlier_contents(access, recorder.descriptions_[access.resource].imported);
    attachment.loadOp = access.clear ? VK_ATTACHMENT_LOAD_OP_CLEAR
                        : keeps      ? VK_ATTACHMENT_LOAD_OP_LOAD
                                     : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachment.storeOp =
        access.direction == rg::Direction::write ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_NONE;
    if (access.clear) {
      const rg::ClearValue& clear = *access.clear;
      if (access.usage == rg::Usage::depth_attachment) {
        attachment.clearValue.depthStencil = {clear.depth, 0};
      } else {
        attachment.clearValue.color = {{clear.color[0], clear.color[1], clear.color[2], clear.color[3]}};
      }
    }
    if (access.usage == rg::Usage::depth_attachment) {
      depth = attachment;
      has_depth = true;
    } else {
      color_attachments_.push_back(attachment);
    }
    const VkExtent2D size = mip_extent(desc, range.base_mip);
    extent = {std::min(extent.width, size.width), std::min(extent.height, size.height)};
    layers = std::max(layers, range.layer_count);
  }

  const bool raster = has_depth || !color_attachments_.empty();
  if (raster) {
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, extent};
    rendering.layerCount = layers;
    rendering.colorAttachmentCount = static_cast<uint32_t>(color_attachments_.size());
    rendering.pColorAttachments = color_attachments_.data();
    rendering.pDepthAttachment = has_depth ? &depth : nullptr;
    vkCmdBeginRendering(cmd, &rendering);
    recorder.render_extent_ = extent;
  }
  if (declaration.execute) {
    rg::PassContext context(recorder);
    declaration.execute(context);
  }
  if (raster) {
    vkCmdEndRendering(cmd);
    recorder.render_extent_ = {0, 0};
  }
}

uint64_t GraphExecutor::transient_heap_bytes(uint32_t slot) const {
  const auto& sets = slots_[slot].transients;
  return sets.empty() ? 0 : sets.front().resources->heap_bytes();
}

uint64_t GraphExecutor::transient_unaliased_bytes(uint32_t slot) const {
  const auto& sets = slots_[slot].transients;
  return sets.empty() ? 0 : sets.front().resources->unaliased_bytes();
}

}  // namespace sg::vk
