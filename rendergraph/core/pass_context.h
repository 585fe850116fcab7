// SPDX-License-Identifier: MIT
#pragma once

#include <concepts>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <typeinfo>

namespace sg::rg {

// What a pass's execute function receives. Core knows nothing of command recording: the executor
// wraps its own recorder object (for Vulkan: the command buffer and the pass's physical
// resources), and the pass unwraps it with get<T>(). Asking for the wrong type throws
// std::logic_error instead of reinterpreting memory.
class PassContext {
 public:
  template <class Recorder>
  requires(!std::same_as<Recorder, PassContext> &&
           !std::is_const_v<Recorder>) explicit PassContext(Recorder& recorder)
      : recorder_(&recorder), type_(&typeid(Recorder)) {}

  template <class Recorder>
  Recorder& get() const {
    if (*type_ != typeid(Recorder)) {
      throw std::logic_error(std::string("PassContext holds ") + type_->name() + ", not " +
                             typeid(Recorder).name());
    }
    return *static_cast<Recorder*>(recorder_);
  }

 private:
  void* recorder_;
  const std::type_info* type_;
};

}  // namespace sg::rg
