// The lighting pass's light resources, beside the instance buffer of scene_interface.glsl
// (set 0, binding 0). shadow_sampling.glsl says which sampler each binding expects.
#ifndef SG_LIGHTS_INTERFACE_GLSL
#define SG_LIGHTS_INTERFACE_GLSL

#include "light_record.glsl"

// Every light of the frame (sg::shadows::GpuLight on the C++ side).
layout(std430, set = 0, binding = 1) readonly buffer Lights { Light lights[]; };
// 2D shadow maps: one depth array; a light owns the region shadow_rect of layer info.w.
layout(set = 0, binding = 2) uniform sampler2DArray shadow_atlas;
// The same image through a comparison sampler, for hardware PCF.
layout(set = 0, binding = 3) uniform sampler2DArrayShadow shadow_atlas_compare;
// Point lights' cube maps of distance / far; cube info.w is layers 6 * info.w + face.
layout(set = 0, binding = 4) uniform samplerCubeArray shadow_cubes;

#endif
