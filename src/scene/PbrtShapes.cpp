#include "scene/PbrtShapes.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "base/ExternalReference.h"
#include "scene/MeshFile.h"
#include "scene/PbrtTransform.h"
#include "scene/SceneShapes.h"

namespace tetglow {
namespace {

using Class = PbrtParamClass;

struct ObjectMesh {
    TriangleMesh mesh;
    std::vector<glm::dvec3> normals;  // per vertex, or empty
};

ObjectMesh readTriangleMesh(PbrtParams& p, const PbrtLocation& where) {
    ObjectMesh m;
    m.mesh.positions = p.getTriples("P", Class::Point3);
    if (m.mesh.positions.empty()) pbrtError(where, p.directive() + ": \"point P\" is required");
    const size_t n = m.mesh.positions.size();
    std::vector<int> indices = p.getInts("indices");
    if (indices.empty()) {
        // pbrt-v3 takes a lone triangle without indices.
        if (n != 3) pbrtError(where, p.directive() + ": \"integer indices\" is required");
        indices = {0, 1, 2};
    }
    if (const PbrtParam* given = p.find("indices", Class::Integer)) {
        if (indices.size() % 3)
            p.fail(*given, "expected a multiple of 3 indices, got " + std::to_string(indices.size()));
        for (int i : indices)
            if (i < 0 || size_t(i) >= n)
                p.fail(*given, "index " + std::to_string(i) + " out of range (" + std::to_string(n) + " points)");
    }
    for (size_t i = 0; i < indices.size(); i += 3)
        m.mesh.triangles.push_back({uint32_t(indices[i]), uint32_t(indices[i + 1]), uint32_t(indices[i + 2])});
    m.normals = p.getTriples("N", Class::Normal);
    if (!m.normals.empty() && m.normals.size() != n)
        p.fail(*p.find("N", Class::Normal),
               "expected one normal per point (" + std::to_string(n) + "), got " + std::to_string(m.normals.size()));
    // Texture coordinates, tangents and face indices only feed textures: no effect here.
    for (const char* name : {"uv", "st"}) {
        p.find(name, Class::Point2);
        p.find(name, Class::Float);
    }
    p.find("S", Class::Vector3);
    p.find("faceIndices", Class::Integer);
    return m;
}

ObjectMesh readPlyMesh(PbrtParams& p, const PbrtLocation& where, const std::filesystem::path& searchDir,
                       std::vector<std::string>& warnings) {
    const std::string file = p.getString("filename", "");
    if (file.empty()) pbrtError(where, p.directive() + ": \"string filename\" is required");
    if (const PbrtParam* map = p.find("displacementmap", Class::Texture)) p.fail(*map, "displacement is not supported");
    p.find("discarddegenerateUVs", Class::Bool);  // uv only feed textures
    try {
        MeshFile read = readMeshFile(resolveReference(searchDir, file).string(), "", &warnings);
        return {std::move(read.mesh), std::move(read.normals)};
    } catch (const InputError& e) {
        pbrtError(where, p.directive() + ": " + e.what());
    }
}

// pbrt-v3 cuts holes where "alpha" or "shadowalpha" is 0; only opaque shapes are supported.
void requireOpaque(PbrtParams& p) {
    for (const char* name : {"alpha", "shadowalpha"}) {
        if (const PbrtParam* texture = p.find(name, Class::Texture))
            p.fail(*texture, "alpha textures are not supported");
        if (p.getFloat(name, 1) != 1) p.fail(*p.find(name, Class::Float), "only 1 (opaque) is supported");
    }
}

}  // namespace

PbrtMesh readPbrtMesh(const std::string& type, PbrtParams& params, const PbrtLocation& where,
                      const glm::dmat4& objectToWorld, bool reverseOrientation, const std::filesystem::path& searchDir,
                      std::vector<std::string>& warnings) {
    ObjectMesh object;
    if (type == "trianglemesh")
        object = readTriangleMesh(params, where);
    else if (type == "plymesh")
        object = readPlyMesh(params, where, searchDir, warnings);
    else
        pbrtError(where, "Shape \"" + type + "\" is not supported (supported: trianglemesh, plymesh)");
    requireOpaque(params);

    const glm::dmat3 linear(objectToWorld);
    const double det = glm::determinant(linear);
    if (!isAffine(objectToWorld) || !(std::abs(det) > 0))
        pbrtError(where, params.directive() + ": the transform is singular or projective");
    PbrtMesh out;
    out.hasNormals = !object.normals.empty();
    out.swapsHandedness = det < 0;
    out.mesh.positions = object.mesh.positions;
    if (placePositions(out.mesh.positions, objectToWorld) != SIZE_MAX)
        pbrtError(where, params.directive() + ": a vertex has a coordinate outside [-1e12, 1e12] once transformed");
    // pbrt-v3 (Triangle::Intersect): the normal is cross(p1 - p0, p2 - p0) of the world-space
    // points, negated when ReverseOrientation and a mirroring transform disagree; with "N" it is
    // instead turned to the side of the (likewise negated) interpolated shading normal.
    const double sign = reverseOrientation != out.swapsHandedness ? -1 : 1;
    const glm::dmat3 normalToWorld = glm::transpose(glm::inverse(linear));
    for (auto t : object.mesh.triangles) {
        const glm::dvec3 ccw = glm::cross(out.mesh.positions[t[1]] - out.mesh.positions[t[0]],
                                          out.mesh.positions[t[2]] - out.mesh.positions[t[0]]);
        bool flip = sign < 0;
        if (out.hasNormals) {
            const glm::dvec3 shading =
                normalToWorld * (object.normals[t[0]] + object.normals[t[1]] + object.normals[t[2]]);
            flip = glm::dot(ccw, sign * shading) < 0;
        }
        if (flip) std::swap(t[1], t[2]);
        out.mesh.triangles.push_back(t);
    }
    return out;
}

}  // namespace tetglow
