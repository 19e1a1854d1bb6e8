#include "scene/MeshWriter.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <sstream>

#include <glm/geometric.hpp>

#include "base/Error.h"
#include "base/OutputFile.h"

namespace tetglow {
namespace {

std::string extensionOf(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return e;
}

// Little-endian, as x86 and ARM hold them: the bytes of the value as they are.
template <class T>
void put(std::ostream& out, T value) {
    out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

void writePly(const TriangleMesh& mesh, const std::string& comment, std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\n";
    std::istringstream lines(comment);
    for (std::string line; std::getline(lines, line);)
        out << "comment " << (line.rfind("# ", 0) == 0 ? line.substr(2) : line) << '\n';
    out << "element vertex " << mesh.positions.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
        << "element face " << mesh.triangles.size() << "\nproperty list uchar uint vertex_indices\nend_header\n";
    for (const auto& p : mesh.positions) {
        put(out, float(p.x));
        put(out, float(p.y));
        put(out, float(p.z));
    }
    for (const auto& t : mesh.triangles) {
        put(out, uint8_t(3));
        for (uint32_t v : t) put(out, v);
    }
}

void writeStl(const TriangleMesh& mesh, const std::string& comment, std::ostream& out) {
    char header[80];
    std::memset(header, ' ', sizeof header);
    // The first line, less its "# ", and never "solid" first: readers take that for ASCII STL.
    std::string first = comment.substr(0, comment.find('\n'));
    if (first.rfind("# ", 0) == 0) first.erase(0, 2);
    if (first.rfind("solid", 0) == 0) first.insert(0, "binary ");
    std::memcpy(header, first.data(), std::min(first.size(), sizeof header));
    out.write(header, sizeof header);
    put(out, uint32_t(mesh.triangles.size()));
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const double length = glm::length(n);
        const glm::dvec3 unit = length > 0 ? n / length : glm::dvec3(0);
        for (const glm::dvec3& v : {unit, a, b, c})
            for (int i = 0; i < 3; ++i) put(out, float(v[i]));
        put(out, uint16_t(0));
    }
}

}  // namespace

void checkMeshExtension(const std::string& path) {
    const std::string e = extensionOf(path);
    if (e != ".obj" && e != ".ply" && e != ".stl")
        throw InputError(path + ": a mesh is written as .obj, .ply or .stl, named by its extension" +
                         (e.empty() ? std::string(" (this name has none)") : ", not " + e));
}

void writeMeshFile(const TriangleMesh& mesh, const std::string& path, const std::string& comment) {
    checkMeshExtension(path);
    const std::string e = extensionOf(path);
    if (e == ".obj") return writeObj(mesh, path, comment);
    if (mesh.triangles.size() > UINT32_MAX) throw InputError(path + ": too many triangles for a binary " + e);
    writeStream(path, [&](std::ostream& out) {
        if (e == ".ply")
            writePly(mesh, comment, out);
        else
            writeStl(mesh, comment, out);
    });
}

}  // namespace tetglow
