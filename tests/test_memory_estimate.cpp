// Memory estimated before it is allocated: a mesh too large to tetrahedralize within the memory
// limit (TETGLOW_MEMORY_LIMIT, else the machine's memory) is refused in a moment with the
// estimate and the limit, naming the file, instead of minutes of validation and TetGen that end
// out of memory. The importer counts what a glTF names besides itself, and bounds instancing.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "MeshWriters.h"
#include "TestMeshes.h"
#include "base/Error.h"
#include "base/Memory.h"
#include "scene/AssimpReader.h"
#include "tet/MeshingMemory.h"
#include "tet/Shapes.h"

namespace tetglow::test {
namespace {

// TETGLOW_MEMORY_LIMIT for this process and the commands it runs, while it lives.
struct MemoryLimit {
    explicit MemoryLimit(const char* value) { ::setenv("TETGLOW_MEMORY_LIMIT", value, 1); }
    ~MemoryLimit() { ::unsetenv("TETGLOW_MEMORY_LIMIT"); }
};

std::string obj(const TriangleMesh& m) {
    PolygonMesh p;
    p.positions = m.positions;
    for (const auto& t : m.triangles) p.faces.push_back({t[0], t[1], t[2]});
    return objText(p);
}

// The user's case, scaled down with the limit: 2 M small triangles used to run out of memory
// after 231 s; a mesh whose estimate exceeds the limit is now refused before validation.
TEST(MemoryEstimate, MeshOverTheLimitIsRefusedWithItsEstimate) {
    const std::string mesh = writeTemp("fine-sphere.obj", obj(icosphere(5)));  // 20480 triangles
    const MemoryLimit limit("64M");
    const auto r = runTetglow("tetrahedralize " + mesh + " --no-cache", 120);
    expectOneLineError(
        r, 1,
        mesh +
            ": 20480 triangles need about 0.164 GB to tetrahedralize (0.0205 GB here, 0.143 GB in TetGen), "
            "more than TetGen's limit of 0.0336 GB (half of the 0.0671 GB of TETGLOW_MEMORY_LIMIT): "
            "use a simpler mesh");
    EXPECT_EQ(
        runTetglow("tetrahedralize " + writeTemp("coarse-sphere.obj", obj(icosphere(2))) + " --no-cache", 120).exitCode,
        0)
        << "320 triangles fit";
}

TEST(MemoryEstimate, LimitMustBeANumberOfBytesWithinTheMachine) {
    const std::string mesh = writeTemp("sphere.obj", obj(icosphere(1)));
    {
        const MemoryLimit limit("lots");
        expectOneLineError(
            runTetglow("tetrahedralize " + mesh), 1,
            "TETGLOW_MEMORY_LIMIT 'lots': expected a number of bytes > 0, with an optional K, M, G or T");
    }
    const MemoryLimit limit("1024T");
    expectOneLineError(runTetglow("tetrahedralize " + mesh), 1,
                       "TETGLOW_MEMORY_LIMIT '1024T' is more than this machine's");
}

TEST(MemoryEstimate, GrowsWithTheTriangles) {
    const MeshingMemory small = meshingMemory(1000), large = meshingMemory(2000000);
    EXPECT_GT(small.here, 0);
    EXPECT_GT(small.tetgen, 0);
    EXPECT_DOUBLE_EQ(large.here, 2000 * small.here);
    EXPECT_DOUBLE_EQ(large.tetgen, 2000 * small.tetgen);
}

// One sphere placed at thousands of nodes used to be flattened, then validated for minutes;
// the instances are now counted first, and a flattened mesh over the limit is refused with
// triangles x instances.
TEST(MemoryEstimate, InstancingIsBoundedBeforeItIsFlattened) {
    const TriangleMesh sphere = icosphere(2);  // 320 triangles
    std::vector<GltfNode> nodes;
    std::vector<int> roots;
    for (int i = 0; i < 2000; ++i) {
        nodes.push_back({"ball" + std::to_string(i), 0, {}, "\"translation\": [" + std::to_string(3 * i) + ", 0, 0]"});
        roots.push_back(i);
    }
    const std::string file = writeTemp("balls.glb", glb(gltf({sphere}, nodes, roots, "")));
    const MemoryLimit limit("1G");
    const auto r = runTetglow("tetrahedralize " + file + " --no-cache", 120);
    expectOneLineError(
        r, 1, file + ": 320 triangles x 2000 instances: 640000 triangles need about 5.12 GB to tetrahedralize");
}

// A .gltf of 601 bytes and its 115 MB .bin used to get the limits of 601 bytes (10 s), where the
// same mesh as one GLB got those of 115 MB.
TEST(MemoryEstimate, ImportLimitsCountExternalBuffers) {
    const std::string dir = tempDir() + "/external";
    std::filesystem::create_directories(dir + "/sub");
    constexpr uint64_t kBin = 115000000;
    for (const char* name : {"/mesh data.bin", "/sub/more.bin", "/outside.bin"}) {
        std::filesystem::path bin = dir + name;
        { std::ofstream{bin}; }
        std::filesystem::resize_file(bin, kBin);  // sparse: no disk needed
    }
    const std::string json =
        R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "mesh%20data.bin", "byteLength": 115000000},
        {"uri" : "sub/./more.bin"}, {"uri": "../external/outside.bin"}, {"uri": "/etc/hostname"},
        {"uri": "data:application/octet-stream;base64,AAAA"}, {"uri": "missing.bin"}]})";
    const ChildLimits external = sceneImportLimits(json, dir + "/mesh.gltf");
    const ChildLimits glb = sceneImportLimits(std::string(json.size() + 2 * kBin, ' '), dir + "/mesh.glb");
    EXPECT_DOUBLE_EQ(external.seconds, glb.seconds) << "two buffers in the folder count, nothing else";
    EXPECT_DOUBLE_EQ(external.memoryBytes, glb.memoryBytes);
    EXPECT_GT(external.seconds, 1000);
}

}  // namespace
}  // namespace tetglow::test
