// SPDX-License-Identifier: MIT
#pragma once

// Building a frame graph: import the resources that outlive the frame, then add passes. Each pass
// declares what it reads and writes in a setup function that runs immediately, and records its
// commands later in an execute function:
//
//   ImageHandle depth{};
//   graph.add_pass("depth prepass",
//       [&](PassBuilder& b) {
//         depth = b.create_image("depth", {1920, 1080, Format::d32_sfloat});
//         depth = b.write(depth, Usage::depth_attachment);
//       },
//       [=](const vk::PassRecorder& rec) { draw_depth(rec); });
//
// The execute function takes either the PassContext or the executor's recorder type directly
// (unwrapped with PassContext::get); without a queue, a pass runs on the graphics queue.
//
// Mistakes (stale versions, conflicting usages, bad ranges...) are recorded where they are made
// and reported together by compile(); a graph with errors does not compile.

#include <concepts>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "rendergraph/core/graph_error.h"
#include "rendergraph/core/pass_context.h"
#include "rendergraph/core/resource_types.h"
#include "rendergraph/core/usage.h"

namespace sg::rg {

using ExecuteFn = std::function<void(PassContext&)>;

namespace detail {
// The last parameter type of a callable object with one non-template call operator.
template <class CallOperator>
struct last_parameter;
template <class R, class C, class... Ps>
struct last_parameter<R (C::*)(Ps...) const> {
  using type = std::tuple_element_t<sizeof...(Ps) - 1, std::tuple<Ps...>>;
};
template <class R, class C, class... Ps>
struct last_parameter<R (C::*)(Ps...)> {
  using type = std::tuple_element_t<sizeof...(Ps) - 1, std::tuple<Ps...>>;
};
template <class Execute>
using recorder_of =
    std::remove_cvref_t<typename last_parameter<decltype(&std::remove_cvref_t<Execute>::operator())>::type>;
}  // namespace detail

// An execute function as the graph stores it: one that takes a PassContext as it is, one that
// takes a recorder (`const vk::PassRecorder&`) wrapped to unwrap the context first.
template <class Execute>
ExecuteFn to_execute_fn(Execute&& execute) {
  if constexpr (std::is_invocable_v<Execute&, PassContext&>) {
    return ExecuteFn(std::forward<Execute>(execute));
  } else {
    using Recorder = detail::recorder_of<Execute>;
    return
        [fn = std::forward<Execute>(execute)](PassContext& context) mutable { fn(context.get<Recorder>()); };
  }
}

// The same for a pass whose setup returned `data`: the execute function takes the data first.
template <class Data, class Execute>
ExecuteFn to_execute_fn(Data data, Execute&& execute) {
  if constexpr (std::is_invocable_v<Execute&, const Data&, PassContext&>) {
    return [data = std::move(data), fn = std::forward<Execute>(execute)](PassContext& context) mutable {
      fn(data, context);
    };
  } else {
    using Recorder = detail::recorder_of<Execute>;
    return [data = std::move(data), fn = std::forward<Execute>(execute)](PassContext& context) mutable {
      fn(data, context.get<Recorder>());
    };
  }
}

// One declared use of a resource by a pass. `version` is the version read, or for a write the
// version it produces (the write consumes version - 1). `range` is resolved (no `remaining`).
struct ResourceAccess {
  std::uint32_t resource = invalid_index;
  std::uint32_t version = 0;
  Usage usage = Usage::sampled_fragment;
  Direction direction = Direction::read;
  SubresourceRange range;
  ResourceState state;
  std::optional<ClearValue> clear;  // attachment writes only; none: keep the earlier contents
};

// Whether `access`'s resource holds contents before the access: a read reads what an earlier pass
// wrote; a write replaces a version an earlier pass wrote, or whatever an imported resource
// brought. A transient's first write (version 1) starts from nothing, so a write there without a
// clear need not load anything. (A read-only depth attachment must load: Vulkan's DONT_CARE
// leaves it undefined, which tilers and synchronization validation both take at its word.)
inline bool has_earlier_contents(const ResourceAccess& access, bool imported) {
  return imported || access.direction == Direction::read || access.version > 1;
}

struct PassDeclaration {
  std::string name;
  QueueType queue = QueueType::graphics;
  bool side_effects = false;
  std::vector<ResourceAccess> accesses;
  ExecuteFn execute;
};

struct ResourceDeclaration {
  std::string name;
  ResourceKind kind = ResourceKind::image;
  ImageDesc image;    // images only
  BufferDesc buffer;  // buffers only
  bool imported = false;
  std::vector<RangeState> initial_states;    // imported only; resolved ranges
  std::optional<ResourceState> final_state;  // imported only
  // producers[v] is the pass that wrote version v; version 0 has none (invalid_index).
  std::vector<std::uint32_t> producers{invalid_index};

  std::uint32_t mip_count() const { return kind == ResourceKind::image ? image.mips : 1; }
  std::uint32_t layer_count() const { return kind == ResourceKind::image ? image.layers : 1; }
  SubresourceRange whole() const { return {0, mip_count(), 0, layer_count()}; }
};

class RenderGraph;

// The setup function's view of its pass: every call adds one declaration to that pass.
class PassBuilder {
 public:
  // A transient resource, owned by the graph for this frame; its first write creates it.
  [[nodiscard]] ImageHandle create_image(std::string name, const ImageDesc& desc);
  [[nodiscard]] BufferHandle create_buffer(std::string name, const BufferDesc& desc);

  void read(ImageHandle image, Usage usage, SubresourceRange range = SubresourceRange::all());
  void read(BufferHandle buffer, Usage usage);
  // Returns the version this pass produces; later passes must use it instead of `image`.
  [[nodiscard]] ImageHandle write(ImageHandle image, Usage usage,
                                  SubresourceRange range = SubresourceRange::all());
  // An attachment write that first clears the range to `clear` (color or depth attachments).
  [[nodiscard]] ImageHandle write(ImageHandle image, Usage usage, ClearValue clear,
                                  SubresourceRange range = SubresourceRange::all());
  [[nodiscard]] BufferHandle write(BufferHandle buffer, Usage usage);

  // The pass is kept even if nothing reads what it writes (readbacks, debug output).
  void mark_side_effects();

 private:
  friend class RenderGraph;
  PassBuilder(RenderGraph& graph, std::uint32_t pass) : graph_(graph), pass_(pass) {}

  // Validates and records one access; returns the version read or produced, or nullopt when the
  // declaration was rejected (the error is recorded on the graph).
  std::optional<std::uint32_t> declare(std::uint32_t resource, std::uint32_t version, ResourceKind kind,
                                       Usage usage, Direction direction, const SubresourceRange& range,
                                       std::optional<ClearValue> clear = std::nullopt);

  RenderGraph& graph_;
  std::uint32_t pass_;
};

class RenderGraph {
 public:
  // An image that outlives the frame (swapchain image, shadow atlas, cube-map array, history).
  // `initial_states` says how each range was last used (ranges not listed start undefined); a
  // graph that writes the image must give `final_state`, the state every subresource is left in.
  ImageHandle import_image(std::string name, const ImageDesc& desc, std::vector<RangeState> initial_states,
                           std::optional<ResourceState> final_state = std::nullopt);
  ImageHandle import_image(std::string name, const ImageDesc& desc, ResourceState initial_state,
                           std::optional<ResourceState> final_state = std::nullopt);
  BufferHandle import_buffer(std::string name, const BufferDesc& desc, ResourceState initial_state,
                             std::optional<ResourceState> final_state = std::nullopt);

  // Runs `setup` now to collect the pass's declarations; `execute` runs when the executor records
  // the pass (an empty one records nothing). Returns the pass's declaration index.
  //
  // The execute function's captures are taken before setup runs, so what setup decides (the
  // handles of transients it creates) reaches execute as setup's return value: a setup that
  // returns data hands it to execute as the first argument,
  //   [&](PassBuilder& b) { return Out{b.write(b.create_buffer(...), ...)}; },
  //   [](const Out& out, const vk::PassRecorder& rec) { ... rec.buffer(out.list) ... }
  template <std::invocable<PassBuilder&> Setup, class Execute = ExecuteFn>
  std::uint32_t add_pass(std::string name, QueueType queue, Setup&& setup, Execute&& execute = {}) {
    PassBuilder builder = begin_pass(std::move(name), queue);
    using Data = std::invoke_result_t<Setup&, PassBuilder&>;
    if constexpr (std::is_void_v<Data>) {
      std::forward<Setup>(setup)(builder);
      passes_[builder.pass_].execute = to_execute_fn(std::forward<Execute>(execute));
    } else {
      Data data = std::forward<Setup>(setup)(builder);
      passes_[builder.pass_].execute = to_execute_fn(std::move(data), std::forward<Execute>(execute));
    }
    return builder.pass_;
  }
  template <std::invocable<PassBuilder&> Setup, class Execute = ExecuteFn>
  std::uint32_t add_pass(std::string name, Setup&& setup, Execute&& execute = {}) {
    return add_pass(std::move(name), QueueType::graphics, std::forward<Setup>(setup),
                    std::forward<Execute>(execute));
  }

  std::span<const PassDeclaration> passes() const { return passes_; }
  std::span<const ResourceDeclaration> resources() const { return resources_; }
  std::span<const GraphError> errors() const { return errors_; }

 private:
  friend class PassBuilder;

  PassBuilder begin_pass(std::string name, QueueType queue);
  std::uint32_t add_resource(std::string name, ResourceKind kind);
  void report(ErrorKind kind, std::string message);

  std::vector<PassDeclaration> passes_;
  std::vector<ResourceDeclaration> resources_;
  std::vector<GraphError> errors_;
};

// `range` with `remaining` counts replaced, or nullopt when it does not fit in the resource.
std::optional<SubresourceRange> resolve(const SubresourceRange& range, const ResourceDeclaration& resource);

}  // namespace sg::rg
