#include "scene/StlReader.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <sstream>

#include "scene/MeshWeld.h"

namespace tetglow {
namespace {

constexpr size_t kHeader = 84, kRecord = 50;

uint32_t littleUint32(const char* b) {
    uint32_t x;
    std::memcpy(&x, b, 4);
    return std::endian::native == std::endian::little ? x : __builtin_bswap32(x);
}

float littleFloat(const char* b) { return std::bit_cast<float>(littleUint32(b)); }

TriangleMesh parseBinary(const std::string& data) {
    TriangleMesh mesh;
    const size_t n = littleUint32(data.data() + 80);
    mesh.positions.reserve(3 * n);
    for (size_t t = 0; t < n; ++t) {
        const char* record = data.data() + kHeader + kRecord * t;
        for (int k = 0; k < 3; ++k) {
            const char* v = record + 12 + 12 * k;  // after the normal
            mesh.positions.emplace_back(littleFloat(v), littleFloat(v + 4), littleFloat(v + 8));
        }
        mesh.triangles.push_back({uint32_t(3 * t), uint32_t(3 * t + 1), uint32_t(3 * t + 2)});
    }
    return mesh;
}

// Where a line of an ASCII STL file may stand, by its first word: inside what, leading into what.
enum class Block { None, Solid, Facet, Loop };
struct Keyword {
    const char* word;
    Block from, to;
};
constexpr Keyword kKeywords[] = {{"solid", Block::None, Block::Solid},   {"facet", Block::Solid, Block::Facet},
                                 {"outer", Block::Facet, Block::Loop},   {"vertex", Block::Loop, Block::Loop},
                                 {"endloop", Block::Loop, Block::Facet}, {"endfacet", Block::Facet, Block::Solid},
                                 {"endsolid", Block::Solid, Block::None}};

TriangleMesh parseAscii(const std::string& data, const std::string& path) {
    TriangleMesh mesh;
    std::istringstream in(data);
    std::string text, word;
    size_t line = 0, corners = 0;  // corners: vertices of the open loop
    Block block = Block::None;
    auto fail = [&](const std::string& problem) {
        return InputError(path + ":" + std::to_string(line) + ": " + problem);
    };
    while (std::getline(in, text)) {
        ++line;
        std::istringstream ls(text);
        if (!(ls >> word)) continue;
        const Keyword* k = nullptr;
        for (const Keyword& candidate : kKeywords)
            if (word == candidate.word && block == candidate.from) k = &candidate;
        if (!k || (word == "vertex" && corners == 3) || (word == "endloop" && corners != 3))
            throw fail("unexpected '" + shorten(word, 40) + "' in an ASCII STL file");
        block = k->to;
        if (word == "outer") corners = 0;
        if (word != "vertex") continue;
        std::string tok[3], extra;
        glm::dvec3 p;
        bool ok = ls >> tok[0] >> tok[1] >> tok[2] && !(ls >> extra);
        for (int c = 0; c < 3 && ok; ++c) {
            char* end = nullptr;
            p[c] = std::strtod(tok[c].c_str(), &end);
            ok = *end == '\0';
        }
        if (!ok) throw fail("vertex needs three numbers: '" + shorten(text, 60) + "'");
        mesh.positions.push_back(p);
        if (++corners == 3) {
            const uint32_t v = uint32_t(mesh.positions.size());
            mesh.triangles.push_back({v - 3, v - 2, v - 1});
        }
    }
    if (block != Block::None) throw fail("the ASCII STL file ends inside a solid (no 'endsolid')");
    return mesh;
}

}  // namespace

bool isBinaryStl(const std::string& data) {
    return data.size() >= kHeader && (data.size() - kHeader) % kRecord == 0 &&
           (data.size() - kHeader) / kRecord == littleUint32(data.data() + 80);
}

TriangleMesh parseStl(const std::string& data, const std::string& path) {
    TriangleMesh mesh;
    if (isBinaryStl(data)) {
        mesh = parseBinary(data);
    } else {
        const size_t start = data.find_first_not_of(" \t\r\n");
        const bool text = std::none_of(data.begin(), data.end(),
                                       [](char c) { return (unsigned char)c < 32 && !std::isspace((unsigned char)c); });
        if (!text || start == std::string::npos || data.compare(start, 5, "solid") != 0)
            throw InputError(path +
                             ": not an STL file: neither ASCII (text starting with 'solid') nor binary (84 + 50 n "
                             "bytes for n triangles; this file has " +
                             std::to_string(data.size()) + ")");
        mesh = parseAscii(data, path);
    }
    if (mesh.triangles.empty()) throw InputError(path + ": no triangles in the STL file");
    weldEqualPositions(mesh);
    return mesh;
}

}  // namespace tetglow
