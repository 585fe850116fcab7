// The lighting pass's light resources, beside the instance buffer of scene_interface.glsl. shadow_sampling.glsl says which sampler each binding expects.
#ifndef SG_LIGHTS_INTERFACE_GLSL
#define SG_LIGHTS_INTERFACE_GLSL

#include "bindings.glsl"
#include "light_record.glsl"

// Every light of the frame (sg::shadows::GpuLight on the C++ side).
layout(std430, set = 0, binding = lights_binding) readonly buffer Lights { Light lights[]; };
// 2D shadow maps: one depth array; a light owns the region shadow_rect of layer info.w.
layout(set = 0, binding = shadow_maps_binding) uniform sampler2DArray shadow_atlas;
// The same image through a comparison sampler, for hardware PCF.
layout(set = 0, binding = shadow_maps_compare_binding) uniform sampler2DArrayShadow shadow_atlas_compare;
// Point lights' cube maps of distance / far; cube info.w is layers 6 * info.w + face.
layout(set = 0, binding = shadow_cubes_binding) uniform samplerCubeArray shadow_cubes;

#endif
