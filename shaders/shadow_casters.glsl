// SPDX-License-Identifier: MIT
// The casters a shadow view draws (systems/shadow_maps/shadow_caster_lists.h): instance k of a view's draw
// is instance view_instances[k] of the Instances buffer.
#ifndef SG_SHADOW_CASTERS_GLSL
#define SG_SHADOW_CASTERS_GLSL

#include "bindings.glsl"

layout(std430, set = 0, binding = view_instances_binding) readonly buffer ViewInstances { uint view_instances[]; };

#endif
