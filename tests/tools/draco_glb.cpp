// Writes an OBJ's parts as a Draco-compressed GLB (KHR_draco_mesh_compression), one mesh and one
// node per `o`, as exporters write a multi-part model with Draco on: the benchmark's way to the
// same model as OBJ, plain GLB and Draco GLB (bench/results/export_corpus.py).
//   tetglow_draco_glb IN.obj OUT.glb [BITS]   (BITS: position quantization, 0 = exact, the default;
//                                             "plain": an uncompressed GLB of the same parts)
// Reads what engine_mesh.py writes: v lines, and f lines of 1-based vertex indices (polygons fanned).
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "../GltfBuilder.h"

namespace {

struct Part {
    std::string name;
    tetglow::TriangleMesh mesh;
    std::map<long, uint32_t> local;  // the file's vertex number -> this part's
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3 || argc > 4) {
        std::fprintf(stderr, "usage: %s IN.obj OUT.glb [BITS|plain]\n", argv[0]);
        return 2;
    }
    const std::string mode = argc == 4 ? argv[3] : "0";
    const bool plain = mode == "plain";
    const int bits = plain ? 0 : std::stoi(mode);
    std::ifstream in(argv[1]);
    if (!in) {
        std::fprintf(stderr, "%s: cannot read\n", argv[1]);
        return 1;
    }
    std::vector<glm::dvec3> vertices;
    std::vector<Part> parts(1, Part{"part", {}, {}});
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string key;
        words >> key;
        if (key == "v") {
            glm::dvec3 v;
            words >> v.x >> v.y >> v.z;
            vertices.push_back(v);
        } else if (key == "o") {
            if (!parts.back().mesh.triangles.empty()) parts.emplace_back();
            words >> parts.back().name;
        } else if (key == "f") {
            Part& part = parts.back();
            std::vector<uint32_t> corners;
            for (std::string w; words >> w;) {
                const long v = std::stol(w.substr(0, w.find('/')));
                if (v < 1 || size_t(v) > vertices.size()) {
                    std::fprintf(stderr, "%s: '%s': vertex %ld does not exist\n", argv[1], line.c_str(), v);
                    return 1;
                }
                const auto [at, added] = part.local.try_emplace(v, uint32_t(part.mesh.positions.size()));
                if (added) part.mesh.positions.push_back(vertices[size_t(v - 1)]);
                corners.push_back(at->second);
            }
            for (size_t i = 2; i < corners.size(); ++i)
                part.mesh.triangles.push_back({corners[0], corners[i - 1], corners[i]});
        }
    }
    tetglow::test::GltfBuilder b;
    size_t triangles = 0;
    for (const Part& p : parts) {
        if (p.mesh.triangles.empty()) continue;
        const int mesh = plain ? b.addMesh(p.mesh) : b.addDracoMesh(p.mesh, -1, bits);
        b.addNode({{"name", p.name}, {"mesh", mesh}});
        triangles += p.mesh.triangles.size();
    }
    b.writeGlb(argv[2]);
    std::printf("%s: %zu parts, %zu triangles, %zu bytes of buffer\n", argv[2], parts.size(), triangles, b.bin.size());
    return 0;
}
