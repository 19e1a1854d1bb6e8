// `tetglow convert`: a scene written back as JSON (meshes as OBJ beside it) reads back as the
// same SceneDesc, and a pbrt-v3 medium-in-mesh scene renders to the same bytes either way.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "SceneCompare.h"
#include "TestMeshes.h"
#include "render/ImageIO.h"
#include "scene/SceneLoader.h"
#include "scene/SceneWriter.h"

namespace tetglow {
namespace {

TEST(SceneWriter, EveryJsonFieldReadsBackTheSame) {
    std::filesystem::create_directories(test::tempDir() + "/in/meshes");
    writeObj(icosphere(1, 0.3), test::tempDir() + "/in/meshes/ball.obj");
    const std::string path = test::writeTemp("in/scene.json", R"({
  "camera": {"position": [0.1, 0.2, 5], "look_at": [0, 0.1, 0], "up": [0.1, 1, 0], "fov": 33.3, "resolution": [31, 17], "handedness": "left"},
  "turntable": {"frames": 12, "center": [0.5, 0, 0.25], "axis": [0.1, 1, 0], "degrees": 90.5},
  "integrator": {"type": "photon", "spp": 3, "max_depth": 9, "seed": 12, "boundary": "parity", "step": 0.013, "parity_rays": 3,
                 "photons": 1234, "k": 7, "radius": 0.05, "estimate": "knn-march", "alpha": 0.5, "boundary_correction": false, "final_gather": true,
                 "time": 2.5},
  "output": "../out/x.exr",
  "lights": [
    {"type": "point", "position": [1, 2, 3], "intensity": 0.7, "scale": 3},
    {"type": "spot", "position": [0, 5, 0], "look_at": [0.1, 0, 0], "cone_angle": 20, "cone_delta": 4, "intensity": [1, 2, 3], "radius": 0.1},
    {"type": "distant", "direction": [0.3, -1, 0.2], "irradiance": [1, 0.5, 2]},
    {"type": "quad", "corner": [0, 3, 0], "edge0": [1, 0, 0], "edge1": [0, 0, 1], "radiance": [4, 4, 4], "two_sided": true},
    {"type": "mesh", "shape": {"type": "sphere", "center": [0, 3, 0], "radius": 0.2, "subdivisions": 1}, "radiance": [1, 2, 3], "scale": 0.1},
    {"type": "environment", "radiance": [0.1, 0.2, 0.3]}
  ],
  "surfaces": [
    {"shape": {"type": "quad", "corner": [-5, -1, -5], "edge0": [0, 0, 10], "edge1": [10, 0, 0]}, "material": {"type": "diffuse", "reflectance": [0.8, 0.7, 0.1]}},
    {"shape": {"type": "disk", "center": [0, 2, 0], "normal": [0, -1, 0], "radius": 0.5, "sides": 16, "transform": [{"rotate": [10, 1, 0, 0]}]}, "material": {"type": "dielectric", "ior": 1.4}},
    {"shape": {"type": "box", "min": [3, 0, 0], "max": [4, 1, 1]}, "material": {"type": "interface"}}
  ],
  "media": [
    {"shape": {"type": "mesh", "file": "meshes/ball.obj", "transform": [{"scale": [-1, 1, 1]}, {"translate": [0.1, 0.2, 0.3]}]},
     "sigma_a": [0.1, 0.2, 0.3], "sigma_s": 1.7, "scale": 2, "g": -0.4, "emission": [0, 0.5, 0],
     "density": {"type": "linear", "offset": 0.9, "gradient": [0, 0.1, 0]}, "boundary": {"type": "dielectric", "ior": 1.33},
     "tetgen": {"quality": 1.5, "max_volume": 0.01}},
    {"shape": {"type": "sphere", "center": [1.5, 0, 0], "radius": 0.4, "subdivisions": 2},
     "density": {"type": "noise", "offset": 2, "amplitude": 0.25, "frequency": 8, "seed": 3}},
    {"shape": {"type": "box", "min": [-3, 0, 0], "max": [-2, 1, 1]}, "density": {"type": "constant", "value": 0.3}}
  ]
})");
    const SceneDesc original = loadScene(path);
    const std::string out = test::tempDir() + "/converted/again.json";
    std::filesystem::create_directories(test::tempDir() + "/converted");
    const auto meshes = writeScene(original, out);
    EXPECT_EQ(meshes.size(), 7u);  // 3 surfaces, 3 media, 1 mesh light
    test::expectSameScene(original, loadScene(out));
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The cube [-0.5, 0.5]^3 as a PLY file of quads, wound outward.
const std::string kCubePly = R"(ply
format ascii 1.0
element vertex 8
property float x
property float y
property float z
element face 6
property list uchar int vertex_indices
end_header
-0.5 -0.5 -0.5
0.5 -0.5 -0.5
-0.5 0.5 -0.5
0.5 0.5 -0.5
-0.5 -0.5 0.5
0.5 -0.5 0.5
-0.5 0.5 0.5
0.5 0.5 0.5
4 0 2 3 1
4 4 5 7 6
4 0 1 5 4
4 2 6 7 3
4 0 4 6 2
4 1 3 7 5
)";

// A fog cube behind glass and a smoke cube with an index-matched boundary on a diffuse floor,
// lit by a point light, a spot light and a quad area light.
const std::string kMediaScene = R"(LookAt 0.5 2 5  0 0.4 0  0 1 0
Camera "perspective" "float fov" 38
Film "image" "integer xresolution" 32 "integer yresolution" 24 "string filename" "media.exr"
Sampler "halton" "integer pixelsamples" 4
Integrator "volpath" "integer maxdepth" 12
WorldBegin
LightSource "point" "rgb I" [8 8 8] "point from" [2 3 2]
LightSource "spot" "rgb I" [40 35 30] "point from" [-1 4 1] "point to" [-0.6 0 0] "float coneangle" 25 "float conedeltaangle" 6
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [6 6 6]
  Material "none"
  Translate 0 3 0
  Shape "trianglemesh" "point P" [-0.5 0 -0.5  0.5 0 -0.5  0.5 0 0.5  -0.5 0 0.5] "integer indices" [0 2 1 0 3 2]
AttributeEnd
Material "matte" "rgb Kd" [0.6 0.55 0.5]
Shape "trianglemesh" "point P" [-4 0 -4  4 0 -4  4 0 4  -4 0 4] "integer indices" [0 2 1 0 3 2]
MakeNamedMedium "fog" "string type" "homogeneous" "rgb sigma_a" [0.2 0.1 0.05] "rgb sigma_s" [1.5 2 2.5] "float g" 0.4
MakeNamedMedium "smoke" "string type" "homogeneous" "float scale" 0.5
AttributeBegin
  MediumInterface "fog" ""
  Material "glass" "float eta" 1.33
  Translate 0.6 0.5 0
  Rotate 20 0 1 0
  Shape "plymesh" "string filename" "meshes/cube.ply"
AttributeEnd
AttributeBegin
  MediumInterface "smoke" ""
  Material "none"
  Translate -0.8 0.4 0.3
  Scale 0.8 0.8 0.8
  Shape "plymesh" "string filename" "meshes/cube.ply"
AttributeEnd
WorldEnd
)";

TEST(PbrtConvert, MediumInMeshSceneRendersTheSameBothWays) {
    const std::string dir = test::tempDir();
    test::writeTemp("meshes/cube.ply", kCubePly);
    const std::string pbrt = test::writeTemp("media.pbrt", kMediaScene), json = dir + "/json/media.json";

    const auto converted = test::runTetglow("convert " + pbrt + " -o " + json);
    ASSERT_EQ(converted.exitCode, 0) << converted.err;
    EXPECT_NE(converted.out.find("3 lights, 1 surfaces, 2 media"), std::string::npos) << converted.out;
    EXPECT_TRUE(std::filesystem::exists(dir + "/json/media-medium-1.obj"));
    EXPECT_TRUE(std::filesystem::exists(dir + "/json/media-light-2.obj"));
    EXPECT_NE(slurp(json).find("\"handedness\": \"left\""), std::string::npos);
    test::expectSameScene(loadScene(pbrt), loadScene(json));

    const std::string common = " --seed 5 --threads 2 -o ";
    const auto a = test::runTetglow("render " + pbrt + common + dir + "/from-pbrt.exr");
    ASSERT_EQ(a.exitCode, 0) << a.err;
    const auto b = test::runTetglow("render " + json + common + dir + "/from-json.exr");
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_EQ(slurp(dir + "/from-pbrt.exr"), slurp(dir + "/from-json.exr"));

    // Not a black image: the media, the floor and the light are all there.
    const Image image = readExr(dir + "/from-pbrt.exr");
    ASSERT_EQ(image.width, 32);
    ASSERT_EQ(image.height, 24);
    double sum = 0;
    for (const auto& p : image.pixels) sum += p.x + p.y + p.z;
    EXPECT_GT(sum / image.pixels.size(), 0.01);
}

TEST(PbrtConvert, ErrorsAreOneLine) {
    const std::string pbrt = test::writeTemp("bad.pbrt", "WorldBegin\nShape \"sphere\"\nWorldEnd\n");
    const auto r = test::runTetglow("convert " + pbrt + " -o " + test::tempDir() + "/bad.json");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err,
              "tetglow: error: " + pbrt + ":2: Shape \"sphere\" is not supported (supported: trianglemesh, plymesh)\n");
    EXPECT_FALSE(std::filesystem::exists(test::tempDir() + "/bad.json"));
    EXPECT_EQ(test::runTetglow("convert " + pbrt + " -o " + test::tempDir() + "/bad.txt").exitCode, 1);
}

}  // namespace
}  // namespace tetglow
