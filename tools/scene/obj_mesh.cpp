// OBJ meshes (see obj_mesh.h).
#include "scene/obj_mesh.h"

#include <tiny_obj_loader.h>

#include <cmath>

namespace pf::scene {

bool loadObjMesh(const std::string& file, std::vector<glm::dvec3>& vertices, std::vector<glm::dvec3>& normals,
                 std::string& error) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.mtl_search_path = "";
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(file, config)) {
    error = "cannot read OBJ file '" + file + "'" + (reader.Error().empty() ? "" : ": " + reader.Error());
    while (!error.empty() && error.back() == '\n') error.pop_back();
    return false;
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const size_t position_count = attrib.vertices.size() / 3;
  std::vector<glm::dvec3> smooth(position_count, glm::dvec3(0));
  std::vector<int> position_of;  // per emitted vertex
  bool all_normals = true;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& idx = shape.mesh.indices;
    for (size_t f = 0; f + 2 < idx.size(); f += 3) {
      glm::dvec3 p[3];
      for (int k = 0; k < 3; ++k) {
        const tinyobj::index_t& i = idx[f + k];
        if (i.vertex_index < 0 || static_cast<size_t>(i.vertex_index) >= position_count) {
          error = "OBJ file '" + file + "': a face refers to a vertex that does not exist";
          return false;
        }
        p[k] = glm::dvec3(attrib.vertices[3 * i.vertex_index], attrib.vertices[3 * i.vertex_index + 1],
                          attrib.vertices[3 * i.vertex_index + 2]);
        vertices.push_back(p[k]);
        position_of.push_back(i.vertex_index);
        if (i.normal_index >= 0 && static_cast<size_t>(i.normal_index) < attrib.normals.size() / 3) {
          normals.emplace_back(attrib.normals[3 * i.normal_index], attrib.normals[3 * i.normal_index + 1],
                               attrib.normals[3 * i.normal_index + 2]);
        } else {
          normals.emplace_back(0.0);
          all_normals = false;
        }
      }
      const glm::dvec3 area_normal = glm::cross(p[1] - p[0], p[2] - p[0]);
      for (int k = 0; k < 3; ++k) smooth[idx[f + k].vertex_index] += area_normal;
    }
  }
  if (vertices.empty()) {
    error = "OBJ file '" + file + "' holds no triangles";
    return false;
  }
  if (!all_normals)
    for (size_t v = 0; v < vertices.size(); ++v) {
      const glm::dvec3 n = smooth[position_of[v]];
      const double len = glm::length(n);
      normals[v] = len > 0 ? n / len : glm::dvec3(0, 0, 1);
    }
  return true;
}

}  // namespace pf::scene
