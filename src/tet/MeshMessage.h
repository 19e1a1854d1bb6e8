// A triangle mesh as bytes and back (base/ByteMessage.h): what a child process that reads or
// splits a mesh hands its parent.
#pragma once
#include "base/ByteMessage.h"
#include "tet/TriangleMesh.h"

namespace tetglow {

inline void addMesh(ByteWriter& out, const TriangleMesh& mesh) {
    out.add(mesh.positions);
    out.add(mesh.triangles);
}

// The mesh addMesh wrote; every index must name one of its positions.
inline TriangleMesh takeMesh(ByteReader& in) {
    TriangleMesh mesh;
    mesh.positions = in.items<glm::dvec3>();
    mesh.triangles = in.items<std::array<uint32_t, 3>>();
    for (const auto& t : mesh.triangles)
        for (uint32_t v : t)
            if (v >= mesh.positions.size()) in.lost();
    return mesh;
}

}  // namespace tetglow
