// SPDX-License-Identifier: MIT
#pragma once
// Edited lights and the camera, kept beside a scene so that the next run starts where the user
// left off: `<scene file>.shadowgraph.json`, or for a built-in scene `<name>.shadowgraph.json`
// in the working folder. The file lists every light by name (unnamed ones as "light N", N their
// order among the scene's lights): its type, local position and rotation, parameters and shadow
// settings; and the camera's eye, target and up. `schema_version` says which form of the file
// this is, `generator` which engine wrote it.
#include <filesystem>
#include <string>

#include "systems/scene/camera.h"
#include "systems/scene/scene.h"

namespace sg {

// The sidecar's form: raised when a key changes meaning or goes away (added keys keep it). A file
// without schema_version is read as version 1; a newer one than this is refused, not misread.
inline constexpr int sidecar_schema_version = 1;

std::filesystem::path sidecar_path(const std::string& scene);

// Writes the sidecar (replacing it). Throws std::runtime_error naming the path on failure.
void save_sidecar(const std::filesystem::path& path, const scene::Scene& scene,
                  const scene::CameraPose& pose);

// Makes `scene`'s lights those of the sidecar: lights it names take its values (the entity,
// and so its place in the hierarchy, stays), lights it lacks are removed, lights only it has are
// added as roots; the pose becomes its camera. Throws std::runtime_error "PATH: ENTRY: problem"
// for malformed content, leaving the scene unchanged.
void apply_sidecar(const std::filesystem::path& path, scene::Scene& scene, scene::CameraPose& pose);

}  // namespace sg
