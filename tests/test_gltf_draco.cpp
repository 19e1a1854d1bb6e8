// glTF files compressed with KHR_draco_mesh_compression, written by libdraco's encoder here: a
// mesh file read through Assimp (tetrahedralize) and a scene read by tetglow's own accessor
// reader give the shape the uncompressed file gives, and broken Draco data is one line naming the
// file and the primitive.
#include <algorithm>
#include <array>
#include <functional>
#include <tuple>

#include <gtest/gtest.h>

#include "GltfBuilder.h"
#include "TestMeshes.h"
#include "scene/MeshFile.h"
#include "scene/SceneLoader.h"
#include "tet/Shapes.h"
#include "tet/TetMesh.h"

namespace tetglow {
namespace {

using nlohmann::json;
using test::GltfBuilder;

constexpr const char* kPrimitive = "/meshes/0/primitives/0/extensions/KHR_draco_mesh_compression";

// How the Draco data is coded: quantization bits (0: exact) and the connectivity coding.
struct Coding {
    const char* name;
    int bits;
    bool sequential;
};
constexpr Coding kCodings[] = {{"edgebreaker", 0, false}, {"sequential", 0, true}, {"quantized14", 14, false}};

const TriangleMesh& boxMesh() {
    static const TriangleMesh m = box({0, 0, 0}, {2, 3, 4});  // volume 24
    return m;
}

// A scene: a camera and `mesh` as a scattering medium, Draco-compressed with `coding` or not.
GltfBuilder mediumScene(const TriangleMesh& mesh, const Coding* coding) {
    GltfBuilder b;
    b.addNode({{"name", "Eye"}, {"camera", b.addCamera(0.6, 1.5)}, {"translation", {1, 1.5, 12}}});
    b.addLight({{"type", "point"}, {"intensity", 683}});
    b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {1, 8, 2}}});
    const int medium = b.addMaterial({{"extras", {{"tetglow", {{"sigma_s", 1}}}}}});
    const int m = coding ? b.addDracoMesh(mesh, medium, coding->bits, coding->sequential) : b.addMesh(mesh, medium);
    b.addNode({{"name", "Body"}, {"mesh", m}});
    return b;
}

// The triangles as sets of corner positions, each turned to start at its least corner: equal for
// meshes of the same triangles whatever the order of their vertices and triangles.
std::vector<std::array<glm::dvec3, 3>> triangleSet(const TriangleMesh& m) {
    const auto less = [](const glm::dvec3& a, const glm::dvec3& b) {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    };
    std::vector<std::array<glm::dvec3, 3>> out;
    for (const auto& t : m.triangles) {
        std::array<glm::dvec3, 3> c = {m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]};
        while (less(c[1], c[0]) || less(c[2], c[0])) c = {c[1], c[2], c[0]};
        out.push_back(c);
    }
    std::sort(out.begin(), out.end(), [&](const auto& a, const auto& b) {
        return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), less);
    });
    return out;
}

// Read through Assimp, with 16-bit and with 32-bit indices: Assimp 5.2's own decoding drops
// 32-bit ones ("Invalid accessor without data"), so tetglow decodes the Draco data before it.
TEST(GltfDraco, BoxTetrahedralizesToItsVolumeAsAMeshFile) {
    for (const auto& [coding, indexType] :
         {std::pair{kCodings[0], 5123}, {kCodings[0], 5125}, {kCodings[1], 5125}, {kCodings[2], 5123}}) {
        const std::string name = std::string(coding.name) + std::to_string(indexType);
        SCOPED_TRACE(name);
        GltfBuilder b;
        b.addNode({{"name", "Box"}, {"mesh", b.addDracoMesh(boxMesh(), -1, coding.bits, coding.sequential)}});
        b.json["accessors"][1]["componentType"] = indexType;
        const std::string dir = test::tempDir() + "/";
        for (const std::string& path : {b.writeGltf(dir + name + ".gltf"), b.writeGlb(dir + name + ".glb")}) {
            std::vector<std::string> warnings;
            const TriangleMesh mesh = readMesh(path, &warnings);  // through Assimp and its libdraco
            EXPECT_TRUE(warnings.empty()) << warnings.front();
            EXPECT_EQ(mesh.triangles.size(), 12u);
            // Exact coding keeps the volume to the last bit; 14 bits move a corner by at most 2^-14 of 4.
            const double tolerance = coding.bits ? 24 * 3 * 4.0 / 16383 : 1e-12;
            EXPECT_NEAR(signedVolume(mesh), 24, tolerance);
            const test::CommandResult r = test::runTetglow("tetrahedralize --no-cache --json '" + path + "'");
            ASSERT_EQ(r.exitCode, 0) << r.err;
            if (!coding.bits) {
                EXPECT_NE(r.out.find("\"tet_volume\": 24.0,"), std::string::npos) << r.out;
            }
        }
    }
}

TEST(GltfDraco, SceneGivesTheTetsOfTheUncompressedScene) {
    const std::string dir = test::tempDir();
    const SceneDesc plain = loadScene(mediumScene(icosphere(2, 1.5), nullptr).writeGlb(dir + "/plain.glb"));
    ASSERT_EQ(plain.media.size(), 1u);
    const TetMesh plainTets = tetrahedralize(plain.media[0].boundary, test::noCache());
    for (const Coding& coding : kCodings) {
        SCOPED_TRACE(coding.name);
        const GltfBuilder b = mediumScene(icosphere(2, 1.5), &coding);
        for (const std::string& path :
             {b.writeGlb(dir + "/" + coding.name + ".glb"), b.writeGltf(dir + "/" + coding.name + ".gltf")}) {
            const SceneDesc s = loadScene(path);
            ASSERT_EQ(s.media.size(), 1u);
            const TriangleMesh& boundary = s.media[0].boundary;
            EXPECT_EQ(boundary.triangles.size(), 320u);
            EXPECT_EQ(boundary.positions.size(), 162u);
            const TetMesh tets = tetrahedralize(boundary, test::noCache());
            if (coding.bits) {  // quantized: the same sphere to within the grid's step
                EXPECT_NEAR(tets.volume(), plainTets.volume(), 1e-3 * plainTets.volume());
                continue;
            }
            // Exact coding: the same triangles (in the decoder's order), so the same tets.
            EXPECT_TRUE(triangleSet(boundary) == triangleSet(plain.media[0].boundary));
            EXPECT_EQ(tets.tets.size(), plainTets.tets.size());
            EXPECT_NEAR(tets.volume(), plainTets.volume(), 1e-12);
        }
    }
}

TEST(GltfDraco, BoxSceneRendersAndTetrahedralizesToItsVolume) {
    const std::string dir = test::tempDir();
    const std::string path = mediumScene(boxMesh(), &kCodings[0]).writeGlb(dir + "/box.glb");
    const SceneDesc s = loadScene(path);
    ASSERT_EQ(s.media.size(), 1u);
    EXPECT_NEAR(tetrahedralize(s.media[0].boundary, test::noCache()).volume(), 24, 1e-12);
    const test::CommandResult r =
        test::runTetglow("render '" + path + "' --seed 3 --spp 2 --threads 2 --resolution 12x8 -o " + dir + "/box.exr");
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

// Broken Draco data and data that disagrees with its accessors: one line naming the file and
// the primitive, from the scene reader and from `render`.
TEST(GltfDraco, BrokenDataIsAOneLineErrorNamingTheFile) {
    const std::string dir = test::tempDir();
    const auto dracoView = [](GltfBuilder& b) -> json& { return b.json["bufferViews"][0]; };
    const auto overwrite = [&](GltfBuilder& b, size_t from, char byte) {
        const size_t offset = dracoView(b).value("byteOffset", 0), length = dracoView(b)["byteLength"];
        for (size_t i = offset + from; i < offset + length; ++i) b.bin[i] = byte;
    };
    // A Draco mesh that states `triangles` in a dozen bytes, its accessors agreeing.
    const auto claim = [&](GltfBuilder& b, uint32_t triangles) {
        const std::string header = {'D', 'R', 'A', 'C', 'O', 2, 2, 1, 1, 0, 0, 0};  // mesh, Edgebreaker
        std::string varints;
        for (uint32_t v : {3u, triangles}) {  // encoded vertices, triangles
            for (; v >= 0x80; v >>= 7) varints.push_back(char(v | 0x80));
            varints.push_back(char(v));
        }
        const size_t offset = dracoView(b).value("byteOffset", 0);
        b.bin.replace(offset, header.size() + varints.size(), header + varints);
        b.json["accessors"][1]["count"] = 3 * triangles;
    };
    const struct {
        const char* name;
        std::function<void(GltfBuilder&)> edit;
        std::string expected;
    } cases[] = {
        {"truncated", [&](GltfBuilder& b) { dracoView(b)["byteLength"] = 20; },
         "the Draco data cannot be decoded (libdraco: "},
        {"zeroed", [&](GltfBuilder& b) { overwrite(b, 12, 0); }, "the Draco data "},
        {"noise", [&](GltfBuilder& b) { overwrite(b, 16, char(0xA5)); }, "the Draco data "},
        {"notdraco", [&](GltfBuilder& b) { overwrite(b, 0, 'x'); },
         "the Draco data cannot be decoded: it does not start with a Draco header"},
        {"vertices", [](GltfBuilder& b) { b.json["accessors"][0]["count"] = 9; },
         "the Draco data holds 8 vertices, its accessor (/accessors/0) counts 9"},
        {"corners", [](GltfBuilder& b) { b.json["accessors"][1]["count"] = 30; },
         "the Draco data holds 36 triangle corners, its accessor (/accessors/1) counts 30"},
        {"bounds",
         [](GltfBuilder& b) {
             b.json["accessors"][0]["max"] = {2, 3, 2};
         },
         "lies outside the min (0, 0, 0) and max (2, 3, 2) of POSITION (/accessors/0)"},
        {"id",
         [](GltfBuilder& b) {
             b.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]
                   ["POSITION"] = 7;
         },
         "/attributes/POSITION: the Draco data has no attribute with this id"},
        {"strip", [](GltfBuilder& b) { b.json["meshes"][0]["primitives"][0]["mode"] = 5; },
         "/meshes/0/primitives/0/mode: a Draco-compressed primitive holds triangles (mode 4)"},
        {"claim", [&](GltfBuilder& b) { claim(b, 100000000); },
         "the Draco data holds 100000000 triangles and 8 vertices, more than the 1024 MiB limit"},
        {"dense", [&](GltfBuilder& b) { claim(b, 1000000); },
         "the Draco data states 1000000 triangles and 8 vertices in "},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        GltfBuilder b = mediumScene(boxMesh(), &kCodings[0]);
        c.edit(b);
        const std::string path = b.writeGlb(dir + "/" + c.name + ".glb");
        const std::string message = test::errorOf([&] { loadScene(path); });
        EXPECT_EQ(message.rfind(path + ": /", 0), 0u) << message;
        EXPECT_NE(message.find(c.expected), std::string::npos) << message;
        if (c.expected.find("/mode") == std::string::npos && c.expected.find("/attributes") == std::string::npos) {
            EXPECT_NE(message.find(kPrimitive), std::string::npos) << message;
        }
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    GltfBuilder b = mediumScene(boxMesh(), &kCodings[0]);
    dracoView(b)["byteLength"] = 20;
    const std::string path = b.writeGlb(dir + "/cut.glb");
    test::expectOneLineError(test::runTetglow("render '" + path + "' -o " + dir + "/cut.exr"), 1,
                             path + ": " + kPrimitive + ": the Draco data cannot be decoded");
}

// The same broken files read as mesh files, through Assimp: refused in one line naming the file.
TEST(GltfDraco, BrokenMeshFileIsAOneLineErrorNamingTheFile) {
    const std::string dir = test::tempDir();
    GltfBuilder b;
    b.addNode({{"name", "Box"}, {"mesh", b.addDracoMesh(boxMesh())}});
    b.json["bufferViews"][0]["byteLength"] = 20;
    const std::string path = b.writeGlb(dir + "/cut.glb");
    test::expectOneLineError(test::runTetglow("tetrahedralize --no-cache '" + path + "'"), 1, path + ": ");
}

}  // namespace
}  // namespace tetglow
