// The "shape" objects of scene files (docs/FORMAT.md), placed in world space. For SceneLoader.
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "scene/JsonReader.h"
#include "tet/TriangleMesh.h"

namespace tetglow {

struct Shape {
    TriangleMesh mesh;  // world space, every coordinate a float
    std::string file;   // the mesh file as the scene names it; "" for the built-in shapes
};

// Reads a shape; mesh files are relative to `dir`. `closed`: only the shapes that enclose a
// volume (mesh, sphere, box), as a medium needs; whether a mesh file really is closed is
// checked when it is tetrahedralized.
Shape readShape(JsonObject& o, const std::filesystem::path& dir, bool closed);

// Positions through the affine transform m, each coordinate rounded to float so that every
// consumer sees the same vertices. Returns the index of the first position with a coordinate
// outside kCoordinate afterwards (the positions from there on are left as they were), or SIZE_MAX.
size_t placePositions(std::vector<glm::dvec3>& positions, const glm::dmat4& m);

struct Parallelogram {
    glm::dvec3 corner, edge0, edge1;
};
// "corner", "edge0", "edge1" of a quad shape or a quad light; the edges must span an area.
Parallelogram readParallelogram(JsonObject& o);

}  // namespace tetglow
