#include "tet/TriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/geometric.hpp>

#include "base/InputFile.h"
#include "base/OutputFile.h"
#include "tet/PolygonTriangulation.h"

namespace tetglow {

void Bounds3::extend(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
}

double Bounds3::diagonal() const { return glm::length(hi - lo); }

bool clip(const Bounds3& box, const Ray& ray, double& t0, double& t1) {
    for (int k = 0; k < 3; ++k) {
        const double inv = 1 / ray.d[k];
        double a = (box.lo[k] - ray.o[k]) * inv, b = (box.hi[k] - ray.o[k]) * inv;
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);  // NaN (0 * inf) leaves the bound as it was
    }
    return t0 < t1;
}

Bounds3 bounds(const TriangleMesh& mesh) {
    Bounds3 b;
    for (const auto& p : mesh.positions) b.extend(p);
    return b;
}

double signedVolume(const TriangleMesh& mesh) {
    // Relative to the first vertex, so that large offsets do not cost precision.
    if (mesh.positions.empty()) return 0;
    const glm::dvec3 o = mesh.positions[0];
    double v = 0;
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t)
        v += glm::dot(mesh.corner(t, 0) - o, glm::cross(mesh.corner(t, 1) - o, mesh.corner(t, 2) - o));
    return v / 6.0;
}

namespace {

std::string where(const std::string& path, size_t line) { return path + ":" + std::to_string(line) + ": "; }

// Parses one OBJ/OFF number; "nan" and "inf" parse so that validation can name them.
bool parseNumber(const std::string& tok, double& out) {
    if (tok.empty()) return false;
    char* end = nullptr;
    out = std::strtod(tok.c_str(), &end);
    return end && *end == '\0';
}

// Resolves a 1-based or negative (relative) OBJ index to 0-based.
uint32_t objIndex(const std::string& tok, size_t vertexCount, const std::string& path, size_t line) {
    const std::string first = tok.substr(0, tok.find('/'));
    long idx = 0;
    try {
        size_t used = 0;
        idx = std::stol(first, &used);
        if (used != first.size()) throw std::invalid_argument("");
    } catch (...) {
        throw InputError(where(path, line) + "bad face index '" + tok + "'");
    }
    long resolved = idx > 0 ? idx - 1 : static_cast<long>(vertexCount) + idx;
    if (idx == 0 || resolved < 0 || resolved >= static_cast<long>(vertexCount))
        throw InputError(where(path, line) + "face index " + first + " out of range (" + std::to_string(vertexCount) +
                         " vertices so far)");
    return static_cast<uint32_t>(resolved);
}

}  // namespace

void addPolygon(TriangleMesh& mesh, const std::vector<uint32_t>& poly, const std::string& where) {
    if (poly.size() < 3) throw InputError(where + "face with " + std::to_string(poly.size()) + " vertices");
    triangulatePolygon(mesh.positions, poly, mesh.triangles, where);
}

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
                    throw InputError(where(path, line) + "vertex needs three numbers: '" + text + "'");
            mesh.positions.push_back(p);
        } else if (key == "f") {
            std::vector<uint32_t> poly;
            std::string tok;
            while (ls >> tok) poly.push_back(objIndex(tok, mesh.positions.size(), path, line));
            addPolygon(mesh, poly, where(path, line));
        } else if (key == "mtllib") {
            std::string lib;
            std::getline(ls >> std::ws, lib);
            std::error_code ec;  // a name the system refuses (too long) is as missing as an absent one
            if (warnings && !std::filesystem::exists(dir / lib, ec))
                addWarning(*warnings, where(path, line) + "material library '" + lib + "' not found; ignored");
        } else if (key == "vn" || key == "vt" || key == "vp" || key == "o" || key == "g" || key == "s" ||
                   key == "usemtl" || key == "l" || key == "p") {
            continue;  // attributes that do not change the shape of the medium
        } else {
            throw InputError(where(path, line) + "not an OBJ line: '" + text.substr(0, 40) + "'");
        }
    }
    return mesh;
}

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
            throw InputError(where(path, line) + "expected " + what + ", got '" + tok + "'");
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
            if (!parseNumber(tok, p[k])) throw InputError(where(path, line) + "bad coordinate '" + tok + "'");
        }
        mesh.positions.push_back(p);
    }
    for (size_t f = 0; f < nf; ++f) {
        const size_t line = i < toks.size() ? toks[i].second : 0;
        const size_t size = integer("face size");
        // Checked before allocating: a size of 2e9 must not reserve 8 GB for a file that ends here.
        if (size > toks.size() - i)
            throw InputError(where(path, line) + "face of " + std::to_string(size) + " vertices, but only " +
                             std::to_string(toks.size() - i) + " numbers follow");
        std::vector<uint32_t> poly(size);
        for (auto& v : poly) {
            v = static_cast<uint32_t>(integer("vertex index"));
            if (v >= nv) throw InputError(where(path, line) + "face index " + std::to_string(v) + " out of range");
        }
        addPolygon(mesh, poly, where(path, line));
    }
    return mesh;
}

void writeObj(const TriangleMesh& mesh, std::ostream& out, const std::string& header) {
    if (!header.empty()) out << header;
    out.precision(9);  // enough to round-trip float positions exactly (validation snaps to float)
    for (const auto& p : mesh.positions) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

void writeObj(const TriangleMesh& mesh, const std::string& path, const std::string& header) {
    writeStream(path, [&](std::ostream& out) { writeObj(mesh, out, header); });
}

}  // namespace tetglow
