#include "scene/SceneShapes.h"

#include <cmath>
#include <iostream>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vector_relational.hpp>

#include "scene/MeshFile.h"
#include "tet/Shapes.h"

namespace tetglow {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxSubdivisions = 7;  // 327,680 triangles
constexpr int kMaxSides = 65536;

// One step of a "transform": {"scale": ...}, {"rotate": ...}, {"translate": ...} or {"matrix": ...}.
glm::dmat4 readOperation(JsonObject& o) {
    const JsonValue scale = o["scale"], rotate = o["rotate"], translate = o["translate"], matrix = o["matrix"];
    o.rejectUnknownKeys();  // a misspelt operation is named as such, not as a missing one
    if (bool(scale) + bool(rotate) + bool(translate) + bool(matrix) != 1)
        o.self().fail("exactly one of \"scale\", \"rotate\", \"translate\", \"matrix\"");
    if (scale) return glm::scale(glm::dmat4(1), scale.vec3OrScalar());
    if (translate) return glm::translate(glm::dmat4(1), translate.vec3());
    if (rotate) {
        const auto r = rotate.numbers(4);
        const glm::dvec3 axis(r[1], r[2], r[3]);
        if (axis == glm::dvec3(0)) rotate.fail("[angle in degrees, axis x, y, z] with a non-zero axis");
        return glm::rotate(glm::dmat4(1), glm::radians(r[0]), axis);
    }
    const auto a = matrix.numbers(16);
    if (a[12] != 0 || a[13] != 0 || a[14] != 0 || a[15] != 1)
        matrix.fail("a row-major affine 4x4 matrix (last row 0, 0, 0, 1)");
    glm::dmat4 m;
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) m[col][row] = a[4 * row + col];  // glm is column-major
    return m;
}

// The operations in order: the first one is applied to the positions first.
glm::dmat4 readTransform(const JsonValue& v) {
    glm::dmat4 m(1);
    for (const JsonValue& op : v.array()) m = op.readObject(readOperation) * m;
    if (glm::determinant(glm::dmat3(m)) == 0) v.error("the transform is singular (determinant 0)");
    return m;
}

// Positions through `m` (placePositions); a mirroring transform flips the winding so that
// outward stays outward.
void place(const JsonValue& shape, TriangleMesh& mesh, const glm::dmat4& m) {
    if (const size_t bad = placePositions(mesh.positions, m); bad != SIZE_MAX)
        shape.error("vertex " + std::to_string(bad) + " has a coordinate outside [-1e12, 1e12] once placed");
    if (glm::determinant(glm::dmat3(m)) < 0)
        for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
}

// A mesh shape's "file", and of a glTF, FBX or Collada file the "node" it names ("" for all).
TriangleMesh readShapeMesh(const JsonValue& file, const JsonValue& node, const fs::path& dir) {
    const std::string path = (dir / file.string()).string();
    std::vector<std::string> warnings;
    try {
        TriangleMesh mesh = readMesh(path, &warnings, node ? node.string() : "");
        for (const auto& w : warnings) std::cerr << file.where() << ": warning: " << w << '\n';
        return mesh;
    } catch (const InputError& e) {
        file.error(e.what());
    }
}

TriangleMesh readSphere(JsonObject& o) {
    const glm::dvec3 center = o["center"].vec3();
    const double radius = o["radius"].number(kPositive);
    const JsonValue subdivisions = o["subdivisions"];
    return icosphere(subdivisions ? int(subdivisions.integer(0, kMaxSubdivisions)) : 4, radius, center);
}

TriangleMesh readBox(JsonObject& o) {
    const glm::dvec3 lo = o["min"].vec3();
    const JsonValue max = o["max"];
    const glm::dvec3 hi = max.vec3();
    if (!glm::all(glm::lessThan(lo, hi))) max.fail("a corner above \"min\" on every axis");
    return box(lo, hi);
}

TriangleMesh readDisk(JsonObject& o) {
    const glm::dvec3 center = o["center"].vec3();
    const JsonValue normal = o["normal"];
    const glm::dvec3 n = normal.vec3();
    if (n == glm::dvec3(0)) normal.fail("a non-zero direction");
    const double radius = o["radius"].number(kPositive);
    const JsonValue sides = o["sides"];
    return disk(center, n, radius, sides ? int(sides.integer(3, kMaxSides)) : 64);
}

enum class ShapeType { Mesh, Sphere, Box, Quad, Disk };

}  // namespace

size_t placePositions(std::vector<glm::dvec3>& positions, const glm::dmat4& m) {
    for (size_t i = 0; i < positions.size(); ++i) {
        const glm::dvec3 q(m * glm::dvec4(positions[i], 1));
        const glm::dvec3 p(roundToFloat(q.x), roundToFloat(q.y), roundToFloat(q.z));
        if (!kCoordinate.contains(p.x) || !kCoordinate.contains(p.y) || !kCoordinate.contains(p.z)) return i;
        positions[i] = p;
    }
    return SIZE_MAX;
}

Parallelogram readParallelogram(JsonObject& o) {
    Parallelogram p;
    p.corner = o["corner"].vec3();
    p.edge0 = o["edge0"].vec3();
    const JsonValue edge1 = o["edge1"];
    p.edge1 = edge1.vec3();
    if (glm::cross(p.edge0, p.edge1) == glm::dvec3(0)) edge1.fail("a non-zero edge not parallel to edge0");
    return p;
}

Shape readShape(JsonObject& o, const fs::path& dir, bool closed) {
    const JsonValue type = o["type"];
    const auto t = type.choice<ShapeType>({{"mesh", ShapeType::Mesh},
                                           {"sphere", ShapeType::Sphere},
                                           {"box", ShapeType::Box},
                                           {"quad", ShapeType::Quad},
                                           {"disk", ShapeType::Disk}});
    if (closed && (t == ShapeType::Quad || t == ShapeType::Disk))
        type.fail("a closed shape (\"mesh\", \"sphere\" or \"box\") around the medium");
    Shape s;
    switch (t) {
        case ShapeType::Mesh: {
            const JsonValue file = o["file"], node = o["node"];
            s.file = file.string();
            s.mesh = readShapeMesh(file, node, dir);
            break;
        }
        case ShapeType::Sphere: s.mesh = readSphere(o); break;
        case ShapeType::Box: s.mesh = readBox(o); break;
        case ShapeType::Quad: {
            const Parallelogram p = readParallelogram(o);
            s.mesh = quad(p.corner, p.edge0, p.edge1);
            break;
        }
        case ShapeType::Disk: s.mesh = readDisk(o); break;
    }
    const JsonValue transform = o["transform"];
    place(o.self(), s.mesh, transform ? readTransform(transform) : glm::dmat4(1));
    return s;
}

}  // namespace tetglow
