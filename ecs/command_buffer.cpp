// SPDX-License-Identifier: MIT
#include "ecs/command_buffer.h"

namespace sg::ecs {

void CommandBuffer::apply() {
  // Swapped out first so that a command recording into this buffer cannot invalidate the loop.
  std::vector<std::function<void(World&)>> commands;
  commands.swap(commands_);
  for (const std::function<void(World&)>& command : commands) command(*world_);
}

}  // namespace sg::ecs
