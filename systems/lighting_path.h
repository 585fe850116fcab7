#pragma once

namespace sg {

// How the frame is lit. forward: one pass shades every light at every pixel. deferred: a
// G-buffer, light lists per screen tile, and per light group a compute pass over the tiles that
// group reaches (a pixel pays only for its tile's lights and each light's own algorithm).
// automatic: whichever measured faster on the device's kind (SceneRenderer says which).
enum class LightingPath { automatic, forward, deferred };

}  // namespace sg
