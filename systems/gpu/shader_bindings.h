// SPDX-License-Identifier: MIT
#pragma once
// The descriptor binding numbers the engine's shaders declare (shaders/bindings.glsl), for the
// passes that bind them: sg::bindings::lights_binding and so on.
namespace sg::bindings {
#include "shaders/bindings.glsl"
}  // namespace sg::bindings
