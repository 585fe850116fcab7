// SPDX-License-Identifier: MIT
#pragma once
// The Vulkan layer's types, declared, for headers that only name them (EnTT's fwd.hpp): a pass's
// header says `const vk::Buffer&` without including the device layer.
namespace sg::vk {

struct ContextOptions;  // rendergraph/device/context.h
class VulkanContext;    // rendergraph/device/context.h
class Buffer;           // rendergraph/device/resources.h
class Image;            // rendergraph/device/resources.h
class FrameRing;        // rendergraph/device/frame_ring.h
class Swapchain;        // rendergraph/device/swapchain.h
class PassRecorder;     // rendergraph/vulkan/pass_recorder.h
struct FrameTimings;    // rendergraph/vulkan/graph_executor.h

}  // namespace sg::vk
