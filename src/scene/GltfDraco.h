// KHR_draco_mesh_compression: a glTF primitive whose POSITION and indices are one Draco-compressed
// mesh in a buffer view, decoded by libdraco. Bounded like the uncompressed accessors
// (scene/GltfDocument.h): the counts the Draco data states are checked against the primitive's
// accessors and the mesh limits before libdraco allocates anything for them, and what it decodes
// is checked against the accessors' count, min and max.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/GltfDocument.h"

namespace tetglow {

// The vertices (POSITION, in the decoder's order) and the corners of the triangles (three indices
// each) of `primitive`, whose extensions hold `draco` (its KHR_draco_mesh_compression object).
// Throws InputError "<file>: <JSON pointer>: <problem>" for data libdraco cannot decode or that
// does not match the accessors.
void decodeDracoPrimitive(const GltfDocument& doc, const JsonValue& primitive, const JsonValue& draco,
                          std::vector<glm::dvec3>& positions, std::vector<uint32_t>& indices);

// The glTF or GLB file `data` read from `path` with every Draco-compressed primitive decoded
// into plain accessors (POSITION as floats, indices as 32-bit integers, in one new buffer held as
// a data: URI) and the extension dropped, in the container it came in; nullopt when nothing is
// compressed. For Assimp 5.2, whose own decoding loses 32-bit indices ("Invalid accessor without
// data"), so that a mesh file read through it has its nodes read as before.
std::optional<std::string> withDracoDecoded(const std::string& path, const std::string& data);

}  // namespace tetglow
