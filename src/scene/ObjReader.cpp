#include "scene/ObjReader.h"

#include <filesystem>
#include <sstream>

#include "scene/MeshText.h"

namespace tetglow {
namespace {

// Resolves a 1-based or negative (relative) OBJ index to 0-based.
uint32_t objIndex(const std::string& tok, size_t vertexCount, const std::string& path, size_t line) {
    const std::string first = tok.substr(0, tok.find('/'));
    long idx = 0;
    try {
        size_t used = 0;
        idx = std::stol(first, &used);
        if (used != first.size()) throw std::invalid_argument("");
    } catch (...) {
        throw InputError(atLine(path, line) + "bad face index '" + tok + "'");
    }
    long resolved = idx > 0 ? idx - 1 : static_cast<long>(vertexCount) + idx;
    if (idx == 0 || resolved < 0 || resolved >= static_cast<long>(vertexCount))
        throw InputError(atLine(path, line) + "face index " + first + " out of range (" + std::to_string(vertexCount) +
                         " vertices so far)");
    return static_cast<uint32_t>(resolved);
}

}  // namespace

TriangleMesh parseObj(const std::string& data, const std::string& path, std::vector<std::string>* warnings) {
    std::istringstream in(data);
    TriangleMesh mesh;
    std::string text;
    size_t line = 0;
    const auto dir = std::filesystem::path(path).parent_path();
    while (std::getline(in, text)) {
        ++line;
        if (!text.empty() && text.back() == '\r') text.pop_back();
        std::istringstream ls(text);
        std::string key;
        if (!(ls >> key) || key[0] == '#') continue;
        if (key == "v") {
            std::string tok[3];
            glm::dvec3 p;
            for (int k = 0; k < 3; ++k)
                if (!(ls >> tok[k]) || !parseNumber(tok[k], p[k]))
                    throw InputError(atLine(path, line) + "vertex needs three numbers: '" + text + "'");
            mesh.positions.push_back(p);
        } else if (key == "f") {
            std::vector<uint32_t> poly;
            std::string tok;
            while (ls >> tok) poly.push_back(objIndex(tok, mesh.positions.size(), path, line));
            addPolygon(mesh, poly, atLine(path, line));
        } else if (key == "mtllib") {
            std::string lib;
            std::getline(ls >> std::ws, lib);
            std::error_code ec;  // a name the system refuses (too long) is as missing as an absent one
            if (warnings && !std::filesystem::exists(dir / lib, ec))
                addWarning(*warnings, atLine(path, line) + "material library '" + lib + "' not found; ignored");
        } else if (key == "vn" || key == "vt" || key == "vp" || key == "o" || key == "g" || key == "s" ||
                   key == "usemtl" || key == "l" || key == "p") {
            continue;  // attributes that do not change the shape of the medium
        } else {
            throw InputError(atLine(path, line) + "not an OBJ line: '" + text.substr(0, 40) + "'");
        }
    }
    return mesh;
}

}  // namespace tetglow
