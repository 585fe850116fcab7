#include "tools/reference/scene_triangles.h"

#include "ecs/transform.h"
#include "systems/scene/mesh_instance.h"

namespace sg::reference {

SceneTriangles scene_triangles(const scene::Scene& scene) {
  SceneTriangles out;
  const scene::MeshLibrary& library = scene.meshes;
  scene.world.query<const ecs::WorldTransform, const scene::MeshInstance>().for_each(
      [&](ecs::Entity, const ecs::WorldTransform& world, const scene::MeshInstance& instance) {
        const scene::MeshRange& mesh = library.meshes.at(instance.mesh);
        for (uint32_t i = 0; i < mesh.index_count; ++i) {
          const uint32_t vertex = mesh.vertex_offset + library.indices[mesh.first_index + i];
          const glm::vec3 corner =
              glm::vec3(world.matrix * glm::vec4(library.vertices[vertex].position, 1.0f));
          out.surfaces.push_back(corner);
          if (instance.casts_shadow) out.casters.push_back(corner);
        }
      });
  return out;
}

}  // namespace sg::reference
