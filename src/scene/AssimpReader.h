// glTF 2.0 (JSON with its buffers, or GLB), FBX and Collada meshes, read by Assimp. Every mesh of
// the file is placed by its node's world transform (the product of the transforms of the node and
// its ancestors, as Assimp's importer builds the hierarchy: glTF and FBX as written, Collada
// turned from Z-up to Y-up), its winding reversed under a mirroring transform (glTF's rule), and
// its equal positions welded per node; a skinned mesh posed by its bones' nodes (linear blend
// skinning, Collada's bind-shape matrix included). Points and lines are skipped with a warning.
// Every file Assimp opens (a glTF's .bin buffers, say) lies in the mesh's folder
// (base/ExternalReference.h) and goes through readInputFile: a regular file, and all of them
// together within the mesh limit. Assimp runs in a child process bounded in memory and time
// (base/ChildProcess.h): a crash or a limit reached is an InputError.
#pragma once
#include <string>
#include <vector>

#include "base/ChildProcess.h"
#include "tet/TriangleMesh.h"

namespace tetglow {

// At most this many triangles once every node's meshes are placed (a node may place a mesh many
// times): about what the largest OBJ file read holds.
inline constexpr size_t kMaxSceneMeshTriangles = size_t(1) << 27;

// The importer's child's memory and time, which grow with the bytes of the file `data` read
// from `path` and of the external buffers in its folder that it names (a .gltf's .bin).
ChildLimits sceneImportLimits(const std::string& data, const std::string& path);

enum class SceneMeshFormat { Gltf, Glb, Fbx, Collada };

// The meshes of the scene file `data` read from `path`. `node`: "" for every mesh, else the
// meshes of the node of that name and of the nodes below it. Throws InputError "<path>: <problem>".
// `up`, when given: the up direction the file states (an FBX file's UpAxis and UpAxisSign), zero
// where it states none.
TriangleMesh parseSceneMeshes(std::string data, const std::string& path, SceneMeshFormat format,
                              const std::string& node, std::vector<std::string>* warnings, glm::dvec3* up = nullptr);

}  // namespace tetglow
