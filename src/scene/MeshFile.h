// Every mesh file tetglow reads goes through readMeshFile: JSON mesh shapes (media, cavities,
// surfaces, mesh lights), pbrt-v3's plymesh, tetrahedralize and compare-boundary. The format is
// told by the content, the extension deciding only where the content does not:
//   OBJ: scene/ObjReader.h; OFF: scene/OffReader.h (their polygons: tet/PolygonTriangulation.h);
//   PLY: scene/PlyReader.h; STL: scene/StlReader.h; glTF 2.0 and GLB, FBX, Collada, through Assimp:
//   scene/AssimpReader.h (glTF 1.0 refused: scene/GltfVersion.h). UTF-16 text is decoded first
//   (scene/TextEncoding.h).
#pragma once
#include <string>
#include <vector>

#include "tet/TriangleMesh.h"

namespace tetglow {

struct MeshFile {
    TriangleMesh mesh;
    std::vector<glm::dvec3> normals;  // per vertex where the file gives them (PLY's nx, ny, nz), else empty
    // The up direction the format or the file states, and where that comes from; zero and "" for
    // formats with no convention (OBJ, OFF, PLY, STL).
    glm::dvec3 up{0};
    std::string upFrom;
};

// The mesh in the file at `path` (a regular file within kMaxMeshFileBytes, with every file it
// names). `node`: for glTF, GLB, FBX and Collada, "" takes every mesh, a name the meshes of that
// node and the nodes below it; other formats have no nodes, and a name is an error. Throws
// InputError "<path>: <problem>" (with the line for text formats); warnings go to `warnings`.
MeshFile readMeshFile(const std::string& path, const std::string& node = "",
                      std::vector<std::string>* warnings = nullptr);

// readMeshFile's mesh alone.
inline TriangleMesh readMesh(const std::string& path, std::vector<std::string>* warnings = nullptr,
                             const std::string& node = "") {
    return readMeshFile(path, node, warnings).mesh;
}

}  // namespace tetglow
