#include "scene/OffReader.h"

#include <cmath>
#include <sstream>

#include "scene/MeshText.h"

namespace tetglow {

TriangleMesh parseOff(const std::string& data, const std::string& path) {
    std::istringstream in(data);
    // Tokens with '#' comments removed, tracking the line of each token for messages.
    std::vector<std::pair<std::string, size_t>> toks;
    std::string text;
    for (size_t line = 1; std::getline(in, text); ++line) {
        std::istringstream ls(text.substr(0, text.find('#')));
        for (std::string t; ls >> t;) toks.push_back({t, line});
    }
    size_t i = 0;
    auto next = [&](const char* what) -> const std::pair<std::string, size_t>& {
        if (i >= toks.size()) throw InputError(path + ": OFF file ends early, expected " + what);
        return toks[i++];
    };
    auto integer = [&](const char* what) {
        const auto& [tok, line] = next(what);
        double v;
        if (!parseNumber(tok, v) || v < 0 || v != std::floor(v) || v > 4e9)
            throw InputError(atLine(path, line) + "expected " + what + ", got '" + tok + "'");
        return static_cast<size_t>(v);
    };
    if (next("OFF header").first != "OFF") throw InputError(path + ": OFF file must start with 'OFF'");
    TriangleMesh mesh;
    const size_t nv = integer("vertex count"), nf = integer("face count");
    integer("edge count");
    for (size_t v = 0; v < nv; ++v) {
        glm::dvec3 p;
        for (int k = 0; k < 3; ++k) {
            const auto& [tok, line] = next("vertex coordinate");
            if (!parseNumber(tok, p[k])) throw InputError(atLine(path, line) + "bad coordinate '" + tok + "'");
        }
        mesh.positions.push_back(p);
    }
    for (size_t f = 0; f < nf; ++f) {
        const size_t line = i < toks.size() ? toks[i].second : 0;
        const size_t size = integer("face size");
        // Checked before allocating: a size of 2e9 must not reserve 8 GB for a file that ends here.
        if (size > toks.size() - i)
            throw InputError(atLine(path, line) + "face of " + std::to_string(size) + " vertices, but only " +
                             std::to_string(toks.size() - i) + " numbers follow");
        std::vector<uint32_t> poly(size);
        for (auto& v : poly) {
            v = static_cast<uint32_t>(integer("vertex index"));
            if (v >= nv) throw InputError(atLine(path, line) + "face index " + std::to_string(v) + " out of range");
        }
        addPolygon(mesh, poly, atLine(path, line));
    }
    return mesh;
}

}  // namespace tetglow
