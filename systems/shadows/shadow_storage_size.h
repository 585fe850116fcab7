#pragma once
// How large the shadow storage is: a 2D depth array of `maps.count` layers of
// `maps.resolution` texels square, and a cube-map array of `cubes.count` cubes of
// `cubes.resolution` texels a face. The sizing policy is plain data here so it is tested without
// a GPU; ShadowMapArrays creates the images it asks for.
#include <cstdint>

namespace sg::shadows {

struct ShadowArraySize {
  uint32_t resolution = 0;  // texels, square
  uint32_t count = 0;       // layers (2D maps) or cubes

  friend bool operator==(const ShadowArraySize&, const ShadowArraySize&) = default;
};

struct ShadowStorageSize {
  ShadowArraySize maps;
  ShadowArraySize cubes;

  friend bool operator==(const ShadowStorageSize&, const ShadowStorageSize&) = default;
};

// The storage to have for `needed`, given the `current` one. It never shrinks while running, and
// holds at least one layer and one cube of at least min_resolution texels (so the lighting
// pass's descriptors always have an image to point at). When more layers or cubes are needed
// it grows by half again beyond its current count (to `needed` when that is more): a scene
// gaining lights one at a time recreates its storage, and waits for the GPU, a logarithmic
// number of times rather than once per light.
ShadowStorageSize fit_shadow_storage(const ShadowStorageSize& current, const ShadowStorageSize& needed,
                                     uint32_t min_resolution);

}  // namespace sg::shadows
