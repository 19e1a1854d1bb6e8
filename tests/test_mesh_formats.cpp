// Every mesh format tetglow reads, each written by the tests' own writers (tests/MeshWriters.h):
// the format is told by the content, a box of volume 24 comes back with its volume and
// tetrahedralizes to it, glTF node hierarchies place their meshes by the product of the node
// transforms (as Blender's importer does, in glTF's Y-up frame), and broken files of every format
// are one-line errors naming the file.
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "MeshWriters.h"
#include "TestMeshes.h"
#include "scene/MeshFile.h"
#include "scene/SceneLoader.h"
#include "tet/TetMesh.h"

namespace tetglow {
namespace {

using test::readError;

struct Sample {
    std::string name, bytes;
};

// Every format of the box, written under names whose extensions say nothing (".mesh"), where the
// format allows it: the content alone must tell the reader.
std::vector<Sample> boxes() {
    const test::PolygonMesh quads = test::boxQuads();
    const TriangleMesh tris = quads.fanned();
    const test::Gltf withBin = test::gltf({tris}, {{"Box", 0, {}, ""}}, {0}, "box-buffer.bin");
    test::writeTemp("boxes/box-buffer.bin", withBin.bin);
    return {{"obj.mesh", test::objText(quads)},
            {"off.mesh", test::offText(quads)},
            {"ply-ascii.mesh", test::plyAscii(quads)},
            {"ply-little.mesh", test::plyBinary(quads, true)},
            {"ply-big.mesh", test::plyBinary(quads, false)},
            {"ply-strips.mesh", test::plyStrips(quads)},
            {"stl-ascii.mesh", test::stlAscii(tris)},
            {"stl-binary.mesh", test::stlBinary(tris, "binary STL from the tests")},
            {"stl-solid-header.mesh", test::stlBinary(tris, "solid box, binary all the same")},
            {"gltf.mesh", withBin.json},
            {"glb.mesh", test::glb(test::gltf({tris}, {{"Box", 0, {}, ""}}, {0}, ""))},
            {"collada-y-up.mesh", test::collada(tris, "Y_UP")},
            {"collada-z-up.mesh", test::collada(tris, "Z_UP")},
            {"fbx-ascii.fbx", test::fbxAscii(quads)}};
}

TEST(MeshFormats, EveryFormatGivesTheBoxAndItsVolume) {
    for (const Sample& s : boxes()) {
        SCOPED_TRACE(s.name);
        const std::string path = test::writeTemp("boxes/" + s.name, s.bytes);
        std::vector<std::string> warnings;
        const TriangleMesh mesh = readMesh(path, &warnings);
        EXPECT_TRUE(warnings.empty()) << warnings.front();
        EXPECT_EQ(mesh.triangles.size(), 12u);
        EXPECT_EQ(mesh.positions.size(), 8u);  // shared corners: STL's and glTF's repeats welded
        EXPECT_NEAR(signedVolume(mesh), 24, 1e-12);
        const TetMesh tets = tetrahedralize(mesh, test::noCache());
        EXPECT_NEAR(tets.volume(), 24, 1e-12);
    }
}

TEST(MeshFormats, AnAsciiPlyIsReadAsPlyNotObj) {
    const std::string path = test::writeTemp("box.ply", test::plyAscii(test::boxQuads()));
    EXPECT_NEAR(signedVolume(readMesh(path)), 24, 1e-12);  // was "not an OBJ line: 'ply'"
}

// The count of triangles in a binary STL decides, not a header that starts with "solid"; a file
// that is neither binary by its size nor ASCII text says so.
TEST(MeshFormats, BinaryStlIsToldBySize) {
    const TriangleMesh tris = test::boxQuads().fanned();
    std::string bytes = test::stlBinary(tris, "solid but binary");
    EXPECT_EQ(readMesh(test::writeTemp("a.stl", bytes)).triangles.size(), 12u);
    bytes.pop_back();
    const std::string path = test::writeTemp("b.stl", bytes);
    EXPECT_EQ(readError(path), path +
                                   ": not an STL file: neither ASCII (text starting with 'solid') nor binary (84 + 50 "
                                   "n bytes for n triangles; this file has 683)");
}

// World positions of the corners of the unit cube [0, 1]^3 under a two-level glTF hierarchy,
// computed from the TRS values by hand (rotations written out as formulas, not matrices):
// Group: translation (1, 2, 3), rotation 90 degrees about y, scale 2;
//   Body (child): translation (0, 1, 0), rotation 90 degrees about z, scale (1, 0.5, 1).
glm::dvec3 bodyCorner(glm::dvec3 p) {
    p *= glm::dvec3(1, 0.5, 1);
    p = {-p.y, p.x, p.z};  // 90 degrees about z
    p += glm::dvec3(0, 1, 0);
    p *= 2.0;
    p = {p.z, p.y, -p.x};  // 90 degrees about y
    return p + glm::dvec3(1, 2, 3);
}

std::string hierarchy(const std::string& name) {
    const std::string s = "0.70710678118654757";  // sin and cos of 45 degrees: a quaternion of 90
    const TriangleMesh cube = box(glm::dvec3(0), glm::dvec3(1));
    const TriangleMesh small = box(glm::dvec3(0), glm::dvec3(0.5));
    const test::Gltf g =
        test::gltf({cube, small},
                   {{"Group",
                     -1,
                     {1, 2},
                     "\"translation\": [1, 2, 3], \"rotation\": [0, " + s + ", 0, " + s + "], \"scale\": [2, 2, 2]"},
                    {"Body",
                     0,
                     {},
                     "\"translation\": [0, 1, 0], \"rotation\": [0, 0, " + s + ", " + s + "], \"scale\": [1, 0.5, 1]"},
                    // A mirror: its winding must be reversed so that it still faces out.
                    {"Fin", 1, {}, "\"matrix\": [-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1]"}},
                   {0}, "");
    return test::writeTemp(name, test::glb(g));
}

TEST(MeshFormats, GltfNodesArePlacedByTheProductOfTheirTransforms) {
    const std::string path = hierarchy("hierarchy.glb");
    const TriangleMesh body = readMesh(path, nullptr, "Body");
    const TriangleMesh cube = box(glm::dvec3(0), glm::dvec3(1));
    ASSERT_EQ(body.positions.size(), cube.positions.size());
    for (const auto& p : cube.positions) {
        const glm::dvec3 expected = bodyCorner(p);
        double nearest = 1e300;
        for (const auto& q : body.positions) nearest = std::min(nearest, glm::length(q - expected));
        EXPECT_LT(nearest, 1e-6) << p.x << ' ' << p.y << ' ' << p.z;
    }
    EXPECT_NEAR(signedVolume(body), 1 * 0.5 * 8, 1e-6);  // scales 2^3 and 0.5

    // The mirrored fin: (x, y, z) -> (5 - x, y, z) under the group's transform, still outward.
    const TriangleMesh fin = readMesh(path, nullptr, "Fin");
    EXPECT_NEAR(signedVolume(fin), 0.125 * 8, 1e-6);
    // Both (the default, and the group by name) hold both parts.
    for (const std::string node : {"", "Group"}) {
        const TriangleMesh all = readMesh(path, nullptr, node);
        EXPECT_EQ(all.triangles.size(), body.triangles.size() + fin.triangles.size()) << node;
        EXPECT_NEAR(signedVolume(all), 4 + 1, 1e-5) << node;  // the quaternions in floats
    }
}

// The same hierarchy as Blender 3.4's glTF importer places it: the corners below are what
// bench/studies/gltf_blender_placement.py prints (Blender's world coordinates, turned back into
// glTF's Y-up frame; printed to 6 decimals, so Blender's float rounding shows as 1e-6).
TEST(MeshFormats, GltfNodesArePlacedWhereBlenderPlacesThem) {
    const std::string path = hierarchy("blender.glb");
    const std::vector<std::pair<std::string, Bounds3>> blender = {
        {"Body", {{1.0, 4.0, 3.0}, {3.0, 6.0, 4.0}}},
        {"Fin", {{0.999999, 2.0, -7.000001}, {1.999999, 3.0, -6.000001}}},
    };
    for (const auto& [node, expected] : blender) {
        const TriangleMesh mesh = readMesh(path, nullptr, node);
        ASSERT_EQ(mesh.positions.size(), 8u) << node;
        // A box's corners are every combination of its bounds.
        for (const auto& p : mesh.positions)
            for (int k = 0; k < 3; ++k)
                EXPECT_LT(std::min(std::abs(p[k] - expected.lo[k]), std::abs(p[k] - expected.hi[k])), 2e-6)
                    << node << " axis " << k;
        const Bounds3 b = bounds(mesh);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(b.lo[k], expected.lo[k], 2e-6) << node << " axis " << k;
            EXPECT_NEAR(b.hi[k], expected.hi[k], 2e-6) << node << " axis " << k;
        }
    }
}

TEST(MeshFormats, ASceneMeshShapeReadsAnyFormatAndNamesANode) {
    const std::string glb = hierarchy("scene/fish.glb");
    test::writeTemp("scene/box.ply", test::plyBinary(test::boxQuads(), false));
    const std::string scene = test::writeTemp("scene/scene.json", R"({
      "camera": {"position": [0, 0, 20], "look_at": [0, 0, 0]},
      "lights": [{"type": "environment", "radiance": 1}],
      "media": [{"shape": {"type": "mesh", "file": "box.ply"}, "sigma_s": 1},
                {"shape": {"type": "mesh", "file": "fish.glb", "node": "Body", "transform": [{"translate": [10, 0, 0]}]}, "sigma_s": 1}]})");
    const SceneDesc desc = loadScene(scene);
    ASSERT_EQ(desc.media.size(), 2u);
    EXPECT_NEAR(signedVolume(desc.media[0].boundary), 24, 1e-12);
    EXPECT_NEAR(signedVolume(desc.media[1].boundary), 4, 1e-5);
    EXPECT_NE(std::find(desc.inputs.begin(), desc.inputs.end(), glb), desc.inputs.end());

    // A glTF's buffer is one of the scene's inputs too (no output may overwrite it).
    const test::Gltf g = test::gltf({test::boxQuads().fanned()}, {{"Box", 0, {}, ""}}, {0}, "box.bin");
    const std::string bin = test::writeTemp("scene/box.bin", g.bin);
    test::writeTemp("scene/box.gltf", g.json);
    const std::string withBuffer = test::writeTemp("scene/buffer.json", R"({
      "camera": {"position": [0, 0, 20], "look_at": [0, 0, 0]},
      "lights": [{"type": "environment", "radiance": 1}],
      "media": [{"shape": {"type": "mesh", "file": "box.gltf"}, "sigma_s": 1}]})");
    const SceneDesc buffered = loadScene(withBuffer);
    EXPECT_NEAR(signedVolume(buffered.media[0].boundary), 24, 1e-12);
    EXPECT_NE(std::find(buffered.inputs.begin(), buffered.inputs.end(), bin), buffered.inputs.end());

    const std::string bad = test::writeTemp("scene/bad.json", R"({
      "camera": {"position": [0, 0, 20], "look_at": [0, 0, 0]},
      "lights": [{"type": "environment", "radiance": 1}],
      "media": [{"shape": {"type": "mesh", "file": "fish.glb", "node": "Tail"}, "sigma_s": 1}]})");
    try {
        loadScene(bad);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  bad + ": /media/0/shape/file: " + glb + ": no node named 'Tail' (nodes with meshes: 'Body', 'Fin')");
    }
}

TEST(MeshFormats, TetrahedralizeReadsBinaryPly) {
    const std::string path = test::writeTemp("box-big-endian.ply", test::plyBinary(test::boxQuads(), false));
    const test::CommandResult r = test::runTetglow("tetrahedralize --no-cache --json '" + path + "'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\"tet_volume\": 24.0,"), std::string::npos) << r.out;
}

// A glTF's buffers are files too: under the same checks as the mesh itself.
TEST(MeshFormats, FilesAGltfNamesAreRegularFiles) {
    const std::string dir = test::tempDir() + "/fifo";
    std::filesystem::create_directories(dir);
    ASSERT_EQ(::system(("mkfifo '" + dir + "/buffer.bin'").c_str()), 0);
    const test::Gltf g = test::gltf({test::boxQuads().fanned()}, {{"Box", 0, {}, ""}}, {0}, "buffer.bin");
    const std::string path = test::writeTemp("fifo/box.gltf", g.json);
    EXPECT_EQ(readError(path), path + ": " + dir + "/buffer.bin: is a FIFO, not a regular file");
}

// Assimp's JSON parser recurses once per nesting level: a million nested arrays in a glTF's
// "extras" overflowed the stack and killed the process.
TEST(MeshFormats, AGltfNestedTooDeepIsAnErrorNotACrash) {
    const test::Gltf g = test::gltf({test::boxQuads().fanned()}, {{"Box", 0, {}, ""}}, {0}, "box.bin");
    const size_t depth = 1000000;
    std::string json = g.json;
    json.insert(json.size() - 1, ", \"extras\": " + std::string(depth, '[') + std::string(depth, ']'));
    test::writeTemp("deep/box.bin", g.bin);
    const std::string path = test::writeTemp("deep/box.gltf", json);
    EXPECT_EQ(readError(path).rfind(path + ": the gltf importer (Assimp) crashed on this file (", 0), 0u)
        << readError(path);
}

// Broken files: one line that starts with the file's name, for every format.
TEST(MeshFormats, BrokenFilesAreOneLineErrors) {
    const test::PolygonMesh quads = test::boxQuads();
    const TriangleMesh tris = quads.fanned();
    std::string stlTruncated = test::stlAscii(tris);
    stlTruncated.resize(stlTruncated.size() / 2);
    std::string plyOutOfRange = test::plyAscii(quads);
    plyOutOfRange.replace(plyOutOfRange.rfind("4 1 3 7 5"), 9, "4 1 3 7 9");
    std::string stripOutOfRange = test::plyStrips(quads);
    stripOutOfRange.replace(stripOutOfRange.rfind(" -1 "), 4, " -2 ");
    const test::Gltf g = test::gltf({tris}, {{"Box", 0, {}, ""}}, {0}, "missing.bin");
    std::string glbTruncated = test::glb(test::gltf({tris}, {{"Box", 0, {}, ""}}, {0}, ""));
    glbTruncated.resize(100);
    std::string daeBroken = test::collada(tris, "Y_UP");
    daeBroken.resize(daeBroken.size() / 2);
    const std::vector<std::pair<Sample, std::string>> cases = {
        {{"bad.obj", "v 0 0 0\nf 1 2 3\n"}, ":2: face index 2 out of range (1 vertices so far)"},
        {{"bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"}, ":6: face index 7 out of range"},
        {{"bad.ply", plyOutOfRange}, ": face 5: vertex index 9 out of range (8 vertices)"},
        {{"strip.ply", stripOutOfRange}, ": strip 0: vertex index -2 out of range (8 vertices)"},
        {{"half.stl", stlTruncated}, ":44: the ASCII STL file ends inside a solid (no 'endsolid')"},
        {{"nothing.stl", std::string(100, '\x01')},
         ": not an STL file: neither ASCII (text starting with 'solid') nor binary (84 + 50 n bytes for n triangles; "
         "this file has 100)"},
        {{"nobin.gltf", g.json}, ": " + test::tempDir() + "/broken/missing.bin: no such file"},
        {{"short.glb", glbTruncated},
         ": cannot read the glb file: No suitable reader found for the file format of file \"" + test::tempDir() +
             "/broken/short.glb\""},
        {{"broken.dae", daeBroken}, ": cannot read the dae file: "},
        {{"broken.fbx", "; FBX 7.4.0 project file\nObjects:  {\n"}, ": cannot read the fbx file: "},
        {{"random.bin", std::string("\x7f\x01\x02garbage", 10)},
         ": binary file, not a mesh tetglow reads (OBJ, OFF, PLY, STL, glTF, GLB, FBX, Collada)"},
    };
    for (const auto& [sample, expected] : cases) {
        const std::string path = test::writeTemp("broken/" + sample.name, sample.bytes);
        const std::string m = readError(path);
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
        EXPECT_EQ(m.rfind(path + expected, 0), 0u) << m;
    }
}

// A file with cameras and lights but no mesh, as a modelling tool exports an empty scene: Assimp
// stands a placeholder skeleton mesh in for its nodes (and marks the scene incomplete), which
// became a medium of that skeleton's volume. It is a file with no triangles.
TEST(MeshFormats, AFileWithoutMeshesHasNoTriangles) {
    const std::string dae =
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
        "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
        "  <asset><unit name=\"meter\" meter=\"1\"/><up_axis>Z_UP</up_axis></asset>\n"
        "  <library_cameras><camera id=\"Camera-camera\" name=\"Camera\"><optics><technique_common><perspective>"
        "<xfov>39.6</xfov><aspect_ratio>1.78</aspect_ratio><znear>0.1</znear><zfar>100</zfar></perspective>"
        "</technique_common></optics></camera></library_cameras>\n"
        "  <library_lights><light id=\"Light-light\" name=\"Light\"><technique_common><point>"
        "<color>1000 1000 1000</color></point></technique_common></light></library_lights>\n"
        "  <library_visual_scenes><visual_scene id=\"Scene\" name=\"Scene\">\n"
        "    <node id=\"Camera\" name=\"Camera\" type=\"NODE\"><matrix sid=\"transform\">1 0 0 7 0 1 0 -6 0 0 1 5 0 0 "
        "0 1"
        "</matrix><instance_camera url=\"#Camera-camera\"/></node>\n"
        "    <node id=\"Light\" name=\"Light\" type=\"NODE\"><matrix sid=\"transform\">1 0 0 4 0 1 0 1 0 0 1 6 0 0 0 1"
        "</matrix><instance_light url=\"#Light-light\"/></node>\n"
        "  </visual_scene></library_visual_scenes>\n"
        "  <scene><instance_visual_scene url=\"#Scene\"/></scene>\n</COLLADA>\n";
    const std::string path = test::writeTemp("empty/camera.dae", dae);
    const std::string m = readError(path);
    EXPECT_EQ(m, path + ": no triangles: the file holds no mesh (only cameras, lights or empty nodes)");
}

// A node name for a format without nodes is an error, not ignored.
TEST(MeshFormats, OnlySceneFormatsHaveNodes) {
    const std::string path = test::writeTemp("box.obj", test::objText(test::boxQuads()));
    EXPECT_EQ(readError(path, "Body"),
              path + ": an OBJ file has no nodes to choose 'Body' from (only glTF, GLB, FBX and Collada files have)");
}

// An element without properties takes no bytes, so its count bounds nothing: pbrt's plymesh
// used to count through one of 10^18 elements.
TEST(MeshFormats, APlyElementWithoutPropertiesIsNotCountedThrough) {
    std::string ply = test::plyAscii(test::boxQuads());
    ply.replace(ply.find("end_header"), 0, "element nothing 1000000000000000000\n");
    test::writeTemp("empty-element/box.ply", ply);
    const std::string scene =
        test::writeTemp("empty-element/box.pbrt",
                        "LookAt 0 0 10 0 0 0 0 1 0\nCamera \"perspective\"\nWorldBegin\nLightSource \"infinite\"\n"
                        "Shape \"plymesh\" \"string filename\" \"box.ply\"\nWorldEnd\n");
    const test::CommandResult r =
        test::runTetglow("convert '" + scene + "' -o '" + test::tempDir() + "/empty-element/out.json'", 20);
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

}  // namespace
}  // namespace tetglow
