// Files whose geometry is intact are read as Blender and Assimp read them, whatever else about
// them is unusual: a PLY header line that is no keyword, an OBJ saved as UTF-16, a Collada skin
// whose bind-shape matrix places the mesh; glTF 1.0, which Assimp places wrongly or not at all,
// is refused in one line that says what to do. `tetrahedralize --node` picks a node as a scene
// file's "node" does.
#include <gtest/gtest.h>

#include "MeshWriters.h"
#include "TestMeshes.h"
#include "scene/MeshFile.h"

namespace tetglow {
namespace {

using test::readError;

// A scanner's free-text line and an obj_info line in the header: skipped, the first with a warning.
TEST(ReaderLeniency, APlyHeaderLineThatIsNoKeywordIsSkippedWithAWarning) {
    std::string ply = test::plyAscii(test::boxQuads());
    ply.insert(ply.find("element"), "Created by ScanStation 2.1\nobj_info scanned 2026-12-07\n");
    const std::string path = test::writeTemp("free-text.ply", ply);
    std::vector<std::string> warnings;
    const TriangleMesh mesh = readMesh(path, &warnings);
    EXPECT_EQ(signedVolume(mesh), 24);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], path +
                               ":4: PLY header: skipped the line 'Created by ScanStation 2.1' (not format, element, "
                               "property or end_header)");
}

// The text as UTF-16 with its byte-order mark, in the byte order asked for.
std::string utf16(const std::string& utf8Ascii, bool little) {
    std::string out = little ? "\xFF\xFE" : "\xFE\xFF";
    for (char c : utf8Ascii) {
        const char unit[2] = {little ? c : '\0', little ? '\0' : c};
        out.append(unit, 2);
    }
    return out;
}

// Notepad's "Unicode" OBJ was "binary file, not a mesh"; a letter beyond ASCII (a surrogate pair,
// U+1D4AA, in a comment) decodes too.
TEST(ReaderLeniency, AUtf16ObjIsDecoded) {
    for (bool little : {true, false}) {
        std::string bytes = utf16("# box\n" + test::objText(test::boxQuads()), little);
        const std::string pair = little ? std::string("\x35\xD8\xAA\xDC", 4) : std::string("\xD8\x35\xDC\xAA", 4);
        bytes.insert(2 + 2 * 5, pair);  // after "# box"
        const std::string path = test::writeTemp(little ? "utf16le.obj" : "utf16be.obj", bytes);
        EXPECT_EQ(signedVolume(readMesh(path)), 24) << path;
    }
    std::string halfPair = utf16("v 0 0 0\n", true);
    halfPair += std::string("\x35\xD8", 2);
    const std::string path = test::writeTemp("half-pair.obj", halfPair);
    EXPECT_EQ(readError(path), path +
                                   ": UTF-16 text that does not decode at byte 18 (half a surrogate pair); save it as "
                                   "UTF-8 (in Notepad: Save As, Encoding UTF-8)");
}

// The box as a skin of one joint bound where it stands, with a bind-shape matrix that moves it
// 5 along x: Blender shows it at [5, 7] x [0, 3] x [0, 4]; it was read at the origin.
TEST(ReaderLeniency, AColladaSkinIsPlacedByItsBindShapeMatrix) {
    const std::string path =
        test::writeTemp("skin.dae", test::collada(test::boxQuads(), "Y_UP", "1 0 0 5 0 1 0 0 0 0 1 0 0 0 0 1"));
    const TriangleMesh mesh = readMesh(path);
    const Bounds3 b = bounds(mesh);
    EXPECT_EQ(b.lo, glm::dvec3(5, 0, 0));
    EXPECT_EQ(b.hi, glm::dvec3(7, 3, 4));
    EXPECT_NEAR(signedVolume(mesh), 24, 1e-12);
}

// glTF 1.0 as JSON (dictionaries keyed by name) and as a binary glTF 1 (KHR_binary_glTF): the
// first was read with its node transforms composed in the wrong order, the second got Assimp's
// "No suitable reader found".
TEST(ReaderLeniency, Gltf1IsRefusedInOneLine) {
    const std::string json =
        R"({"asset": {"version": "1.0"}, "scene": "s", "scenes": {"s": {"nodes": ["n"]}},
            "nodes": {"n": {"meshes": ["m"], "translation": [1, 0, 0], "rotation": [0, 0, 0.70710678, 0.70710678]}},
            "meshes": {"m": {"primitives": [{"attributes": {"POSITION": "p"}, "indices": "i", "mode": 4}]}},
            "accessors": {"p": {"bufferView": "v", "byteOffset": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                          "i": {"bufferView": "v", "byteOffset": 36, "componentType": 5123, "count": 3, "type": "SCALAR"}},
            "bufferViews": {"v": {"buffer": "b", "byteOffset": 0, "byteLength": 42}},
            "buffers": {"b": {"uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIA", "byteLength": 42}}})";
    std::string glb = "glTF";
    for (uint32_t word : {1u, uint32_t(20 + json.size()), uint32_t(json.size()), 0u})
        for (int k = 0; k < 4; ++k) glb += char(word >> (8 * k) & 0xff);
    glb += json;
    for (const auto& [name, bytes] : {std::pair<std::string, std::string>{"one.gltf", json}, {"one.glb", glb}}) {
        const std::string path = test::writeTemp("gltf1/" + name, bytes);
        EXPECT_EQ(readError(path), path + ": glTF 1.0 is not supported; re-export as glTF 2.0");
    }
}

// Letters standing on a ground quad: the quad is no part of a medium, and --node leaves it out.
TEST(ReaderLeniency, TetrahedralizeTakesANodeAsSceneFilesDo) {
    TriangleMesh letters = box(glm::dvec3(0), glm::dvec3(1, 3, 1));
    const TriangleMesh second = box(glm::dvec3(2, 0, 0), glm::dvec3(3, 3, 1));
    const uint32_t base = uint32_t(letters.positions.size());
    letters.positions.insert(letters.positions.end(), second.positions.begin(), second.positions.end());
    for (const auto& t : second.triangles) letters.triangles.push_back({base + t[0], base + t[1], base + t[2]});
    TriangleMesh ground;
    ground.positions = {{-1, 0, -1}, {4, 0, -1}, {4, 0, 2}, {-1, 0, 2}};
    ground.triangles = {{0, 2, 1}, {0, 3, 2}};
    const std::string path = test::writeTemp(
        "letters.glb",
        test::glb(test::gltf({letters, ground}, {{"Letters", 0, {}, ""}, {"Ground", 1, {}, ""}}, {0, 1}, "")));
    const test::CommandResult r =
        test::runTetglow("tetrahedralize --no-cache --json --node Letters '" + path + "'", 60);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\"tet_volume\": 6.0,"), std::string::npos) << r.out;

    test::expectOneLineError(test::runTetglow("tetrahedralize --no-cache --node Tree '" + path + "'", 60), 1,
                             path + ": no node named 'Tree' (nodes with meshes: 'Letters', 'Ground')");
}

}  // namespace
}  // namespace tetglow
