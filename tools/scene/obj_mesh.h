// Triangle meshes from Wavefront OBJ files (through tinyobjloader), for scene objects.
#pragma once

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace pf::scene {

// Reads `file` as triangles: three entries of `vertices` and `normals` per triangle (faces
// triangulated; where the file gives no normals, each vertex gets the area-weighted average of
// the normals of the faces that share its position). OBJ materials are ignored: the scene's
// material applies. False with `error` (naming the file, and the line where the loader says)
// if the file cannot be read or holds no triangles.
bool loadObjMesh(const std::string& file, std::vector<glm::dvec3>& vertices, std::vector<glm::dvec3>& normals,
                 std::string& error);

}  // namespace pf::scene
