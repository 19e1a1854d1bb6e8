// pbrt-v3 scene files: every supported directive with its parameters and pbrt-v3's defaults;
// anything else an error naming the directive, the file and the line.
#include <algorithm>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "scene/PbrtParser.h"
#include "scene/SceneLoader.h"
#include "scene/SceneWriter.h"

namespace tetglow {
namespace {

// A closed unit cube around the origin, wound outward.
const std::string kCube =
    R"("point P" [-0.5 -0.5 -0.5  0.5 -0.5 -0.5  0.5 0.5 -0.5  -0.5 0.5 -0.5  -0.5 -0.5 0.5  0.5 -0.5 0.5  0.5 0.5 0.5  -0.5 0.5 0.5]
    "integer indices" [0 2 1 0 3 2  4 5 6 4 6 7  0 1 5 0 5 4  2 3 7 2 7 6  1 2 6 1 6 5  0 4 7 0 7 3])";

TEST(Pbrt, EveryDirectiveIsRead) {
    test::writeTemp("parts/lights.pbrt",
                    R"(# included by world.pbrt, named relative to scene.pbrt's folder (pbrt-v3's rule, the fallback)
LightSource "spot" "color I" [5 5 5] "point from" [0 3 0] "point to" [0 0 0] "float coneangle" 40 "float conedeltaangle" 8
)");
    test::writeTemp("parts/world.pbrt", R"(LightSource "point" "rgb I" [1 2 3]
Include "parts/lights.pbrt"
)");
    test::writeTemp(
        "meshes/tri.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const std::string path = test::writeTemp("scene.pbrt", R"(# every directive tetglow reads
Scale -1 1 1
LookAt 0 1 6  0 0.5 0  0 1 0
Camera "perspective" "float fov" [35] "float lensradius" 0 "float focaldistance" 10
Film "image" "integer xresolution" [40] "integer yresolution" [30] "string filename" "out/render.exr" "float diagonal" 35
Sampler "sobol" "integer pixelsamples" 12
Integrator "volpath" "integer maxdepth" [7] "float rrthreshold" 1 "string lightsamplestrategy" "spatial"
PixelFilter "box"
Accelerator "bvh" "integer maxnodeprims" 4
TransformTimes 0 1
ActiveTransform All
MakeNamedMedium "fog" "string type" "homogeneous" "rgb sigma_a" [0.1 0.2 0.3] "rgb sigma_s" [1 2 3] "float scale" 2 "float g" 0.25
MakeNamedMedium "default" "string type" "homogeneous"
WorldBegin
Include "parts/world.pbrt"
LightSource "distant" "rgb L" [0.5 0.5 0.5] "point from" [0 1 0] "point to" [0 0 0]
LightSource "infinite" "rgb L" [0.01 0.02 0.03] "integer nsamples" 4
MakeNamedMaterial "frosted" "string type" "glass" "float eta" 1.7
AttributeBegin
  Material "matte" "rgb Kd" [0.2 0.4 0.6]
  Shape "trianglemesh" "point P" [-3 0 -3  3 0 -3  3 0 3  -3 0 3] "integer indices" [0 2 1 0 3 2] "float uv" [0 0 1 0 1 1 0 1]
  Shape "trianglemesh" "point P" [0 0 0  1 0 0  0 1 0] "rgb Kd" [0.9 0.9 0.9]
AttributeEnd
AttributeBegin
  NamedMaterial "frosted"
  Shape "plymesh" "string filename" "meshes/tri.ply"
  Material "glass" "float index" 1.33
  Shape "plymesh" "string filename" "meshes/tri.ply"
AttributeEnd
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [3 3 3]
  Material "none"
  Translate 0 4 0
  Shape "trianglemesh" "point P" [0 0 0  1 0 0  1 0 1  0 0 1] "integer indices" [0 1 2 0 2 3]
AttributeEnd
AttributeBegin
  MediumInterface "fog" ""
  Material "interface"
  Translate 1 0.5 0
  Shape "trianglemesh" )" + kCube + R"(
AttributeEnd
AttributeBegin
  MediumInterface "default" ""
  Material "glass"
  Translate -1 0.5 0
  Shape "trianglemesh" )" + kCube + R"(
AttributeEnd
AttributeBegin
  Material ""
  Shape "trianglemesh" "point P" [0 0 0  1 0 0  0 1 0]
AttributeEnd
WorldEnd
)");
    std::vector<std::string> warnings;
    const SceneDesc s = loadPbrtScene(path, &warnings);

    EXPECT_EQ(s.camera.fov, 35);
    EXPECT_EQ(s.camera.width, 40);
    EXPECT_EQ(s.camera.height, 30);
    EXPECT_EQ(s.camera.handedness, Handedness::Right);  // Scale -1 1 1 undoes pbrt's mirror
    EXPECT_EQ(s.output, "out/render.exr");              // pbrt-v3: relative to where it runs
    EXPECT_EQ(s.integrator.type, IntegratorType::VolPath);
    EXPECT_EQ(s.integrator.spp, 16);      // sobol rounds 12 up to a power of two
    EXPECT_EQ(s.integrator.maxDepth, 8);  // pbrt's 7 scattering events, and the one that ends the path

    ASSERT_EQ(s.lights.size(), 5u);
    EXPECT_EQ(s.lights[0].type, LightType::Point);  // from the included file
    EXPECT_EQ(s.lights[1].type, LightType::Spot);   // from the file it included
    EXPECT_EQ(s.lights[1].coneAngle, 40);
    EXPECT_EQ(s.lights[1].coneDelta, 8);
    EXPECT_EQ(s.lights[2].type, LightType::Distant);
    EXPECT_EQ(s.lights[3].type, LightType::Environment);
    EXPECT_EQ(s.lights[4].type, LightType::Mesh);
    EXPECT_EQ(s.lights[4].radiance, RGB(3));
    EXPECT_FALSE(s.lights[4].twoSided);
    EXPECT_EQ(s.lights[4].mesh.positions[2], glm::dvec3(1, 4, 1));

    ASSERT_EQ(s.surfaces.size(), 4u);  // the "" triangle is invisible, as in pbrt-v3
    EXPECT_EQ(s.surfaces[0].material.type, MaterialType::Diffuse);
    EXPECT_EQ(s.surfaces[0].material.reflectance, RGB(0.2, 0.4, 0.6));
    EXPECT_EQ(s.surfaces[1].material.reflectance, RGB(0.9));  // a Shape's own Kd overrides the Material's
    EXPECT_EQ(s.surfaces[2].material.type, MaterialType::Dielectric);
    EXPECT_EQ(s.surfaces[2].material.ior, 1.7);   // NamedMaterial
    EXPECT_EQ(s.surfaces[3].material.ior, 1.33);  // a later Material replaces it
    EXPECT_EQ(s.surfaces[3].mesh.triangles.size(), 1u);
    EXPECT_EQ(s.surfaces[0].name, path + ":21 (Shape \"trianglemesh\")");

    ASSERT_EQ(s.media.size(), 2u);
    EXPECT_EQ(s.media[0].sigmaA, RGB(0.2, 0.4, 0.6));  // times "scale"
    EXPECT_EQ(s.media[0].sigmaS, RGB(2, 4, 6));
    EXPECT_EQ(s.media[0].g, 0.25);
    EXPECT_EQ(s.media[0].boundaryMaterial.type, MaterialType::Interface);
    EXPECT_NEAR(signedVolume(s.media[0].boundary), 1, 1e-12);
    EXPECT_EQ(s.media[0].boundary.positions[0], glm::dvec3(0.5, 0, -0.5));
    EXPECT_EQ(s.media[1].sigmaA, RGB(.0011, .0024, .014));  // pbrt-v3's defaults
    EXPECT_EQ(s.media[1].sigmaS, RGB(2.55, 3.21, 3.77));
    EXPECT_EQ(s.media[1].boundaryMaterial.type, MaterialType::Dielectric);
    EXPECT_EQ(s.media[1].boundaryMaterial.ior, 1.5);

    // Only the notes that matter: the sampler's pattern and the emitter's own material.
    for (const auto& w : warnings) EXPECT_EQ(w.find("not used"), std::string::npos) << w;
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find(path + ":6: note: Sampler \"sobol\""), std::string::npos) << warnings[0];
}

TEST(Pbrt, DefaultsArePbrtv3s) {
    const std::string path = test::writeTemp(
        "scene.pbrt",
        "WorldBegin\nLightSource \"point\"\nShape \"trianglemesh\" \"point P\" [0 0 1  1 0 1  0 1 1]\nWorldEnd\n");
    const SceneDesc s = loadPbrtScene(path);
    EXPECT_EQ(s.camera.width, 1280);
    EXPECT_EQ(s.camera.height, 720);
    EXPECT_EQ(s.camera.fov, 90);
    EXPECT_EQ(s.camera.position, glm::dvec3(0));
    EXPECT_EQ(s.camera.lookAt, glm::dvec3(0, 0, 1));
    EXPECT_EQ(s.camera.handedness, Handedness::Left);
    EXPECT_EQ(s.output, "pbrt.exr");
    EXPECT_EQ(s.integrator.spp, 16);
    EXPECT_EQ(s.integrator.maxDepth, 6);
    EXPECT_EQ(s.lights[0].intensity, RGB(1));
    ASSERT_EQ(s.surfaces.size(), 1u);
    EXPECT_EQ(s.surfaces[0].material.type, MaterialType::Diffuse);  // "matte" with Kd 0.5
    EXPECT_EQ(s.surfaces[0].material.reflectance, RGB(0.5));
}

// Each sampler's samples per pixel, as pbrt-v3 counts them; the camera's halffov.
TEST(Pbrt, SamplersGiveTheirSampleCounts) {
    const std::pair<std::string, int> cases[] = {
        {R"(Sampler "halton" "integer pixelsamples" 12)", 12},
        {R"(Sampler "random" "integer pixelsamples" 3)", 3},
        {R"(Sampler "random")", 4},
        {R"(Sampler "stratified" "integer xsamples" 3 "integer ysamples" 5 "bool jitter" "false")", 15},
        {R"(Sampler "02sequence" "integer pixelsamples" 5)", 8},
        {R"(Sampler "maxmindist" "integer pixelsamples" 16)", 16},
    };
    for (const auto& [line, spp] : cases) {
        const std::string path = test::writeTemp(
            "scene.pbrt",
            line + "\nCamera \"perspective\" \"float halffov\" 20\nWorldBegin\nLightSource \"point\"\nWorldEnd\n");
        std::vector<std::string> warnings;
        const SceneDesc s = loadPbrtScene(path, &warnings);
        EXPECT_EQ(s.integrator.spp, spp) << line;
        EXPECT_EQ(s.camera.fov, 40) << line;
        ASSERT_EQ(warnings.size(), 1u) << line;
        EXPECT_NE(warnings[0].find(path + ":1: note: Sampler"), std::string::npos) << warnings[0];
    }
}

// pbrt-v3 renders media only with "volpath": "path" (its default) sees a glass boundary as
// glass and an index-matched one not at all.
TEST(Pbrt, ThePathIntegratorIgnoresMediaAsPbrtDoes) {
    const std::string path = test::writeTemp("scene.pbrt", R"(Integrator "path"
WorldBegin
LightSource "point"
MakeNamedMedium "fog" "string type" "homogeneous"
AttributeBegin
  MediumInterface "fog" ""
  Material "glass"
  Shape "trianglemesh" )" + kCube + R"(
  Material "none"
  Translate 3 0 0
  Shape "trianglemesh" )" + kCube + R"(
AttributeEnd
WorldEnd
)");
    std::vector<std::string> warnings;
    const SceneDesc s = loadPbrtScene(path, &warnings);
    EXPECT_TRUE(s.media.empty());
    ASSERT_EQ(s.surfaces.size(), 1u);
    EXPECT_EQ(s.surfaces[0].material.type, MaterialType::Dielectric);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find(path + ":1: warning: Integrator \"path\" ignores the 2 media"), std::string::npos)
        << warnings[0];
}

TEST(Pbrt, LoadSceneKnowsPbrtByExtensionOrContent) {
    const std::string text =
        "# no extension to go by\nLookAt 0 0 5 0 0 0 0 1 0\nCamera \"perspective\"\nWorldBegin\nLightSource "
        "\"point\"\nWorldEnd\n";
    EXPECT_EQ(loadScene(test::writeTemp("scene.txt", text)).lights.size(), 1u);
    EXPECT_EQ(loadScene(test::writeTemp("scene.pbrt", "\n" + text)).lights.size(), 1u);
    EXPECT_TRUE(looksLikePbrt("  # comment\n\nWorldBegin"));
    EXPECT_FALSE(looksLikePbrt("{\"camera\": {}}"));
    EXPECT_FALSE(looksLikePbrt("Cameras"));
}

// pbrt-v3 (core/parser.cpp) resolves every Include against the first file's folder.
TEST(Pbrt, IncludesAreRelativeToTheIncludingFile) {
    test::writeTemp("parts/a.pbrt", "LightSource \"point\"\nInclude \"b.pbrt\"\n");
    test::writeTemp("parts/b.pbrt", "LightSource \"point\"\n");
    const std::string path = test::writeTemp("scene.pbrt", "WorldBegin\nInclude \"parts/a.pbrt\"\nWorldEnd\n");
    std::vector<std::string> warnings;
    EXPECT_EQ(loadPbrtScene(path, &warnings).lights.size(), 2u);
    EXPECT_TRUE(warnings.empty());
    // pbrt-v3's own rule, the first file's folder, is the fallback.
    test::writeTemp("parts/a.pbrt",
                    "LightSource \"point\"\nInclude \"parts/b.pbrt\"\nWorldEnd\n");  // WorldEnd in an included file
    test::writeTemp("scene.pbrt", "WorldBegin\nInclude \"parts/a.pbrt\"\n");
    EXPECT_EQ(loadPbrtScene(path, &warnings).lights.size(), 2u);
    // Where both exist and differ, the including file's folder wins, with a warning.
    test::writeTemp("b.pbrt", "LightSource \"point\"\nLightSource \"point\"\n");
    test::writeTemp("parts/a.pbrt", "LightSource \"point\"\nInclude \"b.pbrt\"\nWorldEnd\n");
    EXPECT_EQ(loadPbrtScene(path, &warnings).lights.size(), 2u);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], test::tempDir() + "/parts/a.pbrt:2: warning: Include reads " + test::tempDir() +
                               "/parts/b.pbrt; pbrt-v3 would read " + test::tempDir() + "/b.pbrt");
    test::writeTemp("parts/a.pbrt", "Include \"none.pbrt\"\n");
    try {
        loadPbrtScene(path);
        FAIL() << "none.pbrt does not exist";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  test::tempDir() + "/parts/a.pbrt:1: Include: " + test::tempDir() + "/parts/none.pbrt: no such file");
    }
}

// Each line goes in place of line 4 of a small scene; the error must name that line, the
// directive and what is wrong.
TEST(Pbrt, UnsupportedInputIsAnErrorNamingFileAndLine) {
    struct Case {
        std::string line, message;
    };
    const Case cases[] = {
        {R"(Shape "sphere" "float radius" 1)", "Shape \"sphere\" is not supported (supported: trianglemesh, plymesh)"},
        {R"(Shape "trianglemesh" "point P" [0 0 0 1 0 0 0 1 0] "integer indices" [0 1 3])",
         "Shape \"trianglemesh\": parameter \"integer indices\": index 3 out of range (3 points)"},
        {R"(Shape "trianglemesh" "point P" [0 0 0 1 0 0 0 1 0] "float alpha" 0)",
         "parameter \"float alpha\": only 1 (opaque) is supported"},
        {R"(Shape "plymesh" "string filename" "none.ply")",
         "Shape \"plymesh\": " + test::tempDir() + "/none.ply: no such file"},
        {R"(LightSource "goniometric")",
         "LightSource \"goniometric\" is not supported (supported: point, spot, distant, infinite)"},
        {R"(LightSource "infinite" "string mapname" "sky.exr")", "environment maps are not supported"},
        {R"(LightSource "point" "blackbody I" [5500 1])",
         "LightSource \"point\": parameter \"blackbody I\": only RGB colours (\"rgb\" or \"color\") are supported, not "
         "\"blackbody\""},
        {R"(LightSource "point" "spectrum I" "spds/lamp.spd")", "parameter \"spectrum I\": only RGB colours"},
        {R"(LightSource "spot" "float coneangle" 120)", "LightSource \"spot\": \"coneangle\" must be in (0, 90]"},
        {"Scale 1 2 1\nLightSource \"spot\"", "LightSource \"spot\": under a non-uniform scale or shear"},
        {R"(AreaLightSource "blackbody")", "AreaLightSource \"blackbody\" is not supported (supported: diffuse)"},
        {R"(Material "plastic")",
         "Material \"plastic\" is not supported (supported: matte, glass, \"\", none, interface)"},
        {R"(Material "matte" "float sigma" 20)",
         "Material \"matte\": parameter \"float sigma\": Oren-Nayar roughness is not supported"},
        {R"(Material "matte" "texture Kd" "checks")",
         "Material \"matte\": parameter \"texture Kd\": textures are not supported"},
        {R"(Material "glass" "rgb Kr" [0.5 0.5 0.5])",
         "Material \"glass\": parameter \"rgb Kr\": only 1 (clear glass) is supported"},
        {R"(Material "glass" "float uroughness" 0.1)", "rough glass is not supported"},
        {R"(Texture "checks" "spectrum" "checkerboard")", "Texture is not supported"},
        {R"(ObjectBegin "tree")", "ObjectBegin is not supported"},
        {R"(MakeNamedMedium "smoke" "string type" "heterogeneous")",
         "MakeNamedMedium \"smoke\": type \"heterogeneous\" is not supported (supported: homogeneous)"},
        {"MediumInterface \"fog\" \"air\"\nShape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0]",
         "Shape: MediumInterface names medium \"air\", which no MakeNamedMedium made"},
        {"MediumInterface \"fog\" \"fog\"\nMaterial \"\"\nShape \"trianglemesh\" " + kCube,
         "Shape: MediumInterface \"fog\" \"fog\" says the shape lies in medium \"fog\", but it lies in no medium"},
        {"MediumInterface \"smoke\" \"\"\nShape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0]",
         "Shape: MediumInterface names medium \"smoke\", which no MakeNamedMedium made"},
        {"MediumInterface \"fog\" \"\"\nMaterial \"\"\nReverseOrientation\nShape \"trianglemesh\" " + kCube,
         "the normals around medium \"fog\" point inwards"},
        {"NamedMaterial \"velvet\"\nShape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0]",
         "Shape: NamedMaterial \"velvet\" was not made by MakeNamedMaterial"},
        {"Camera \"perspective\"", "Camera is only allowed before WorldBegin"},
        {"Rotate 30 0 0", "Rotate expects 4 numbers"},
        {"Rotate 30 0 0 0", "Rotate: the axis must not be zero"},
        {"ConcatTransform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0]", "ConcatTransform expects [16 numbers], got ']'"},
        {"ActiveTransform StartTime", "ActiveTransform StartTime: motion blur is not supported"},
        {"AttributeEnd", "AttributeEnd without AttributeBegin"},
        {"Sphere", "unknown directive \"Sphere\""},
        {"\"float radius\" 1", "expected a directive, got 'float radius'"},
        {R"(Shape "trianglemesh" "floaty P" [0 0 0])", "Shape \"trianglemesh\": unknown parameter type \"floaty\""},
        {R"(Shape "trianglemesh" "point P" [0 0 0 1 0])",
         "parameter \"point P\": expected a multiple of 3 numbers, got 5"},
        {R"(Shape "trianglemesh" "point P" [0 0 x])",
         "parameter \"point P\": expected a finite number of float range (|x| <= 3.40282e38), got 'x'"},
        {R"(LightSource "point" "bool twosided" "yes")",
         "parameter \"bool twosided\": expected \"true\" or \"false\", got \"yes\""},
        {"LightSource \"point\" \"string name\" \"unterminated", "unterminated string"},
        {"WorldEnd\nWorldBegin", "WorldBegin after WorldEnd"},
    };
    const std::string head =
        "Camera \"perspective\"\nMakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\nWorldBegin\n";
    for (const Case& c : cases) {
        const std::string path = test::writeTemp("scene.pbrt", head + c.line + "\nLightSource \"point\"\nWorldEnd\n");
        try {
            loadPbrtScene(path);
            ADD_FAILURE() << "no error for: " << c.line;
        } catch (const InputError& e) {
            const std::string message = e.what();
            // On one of the case's lines (a Shape after the settings it breaks comes last).
            bool placed = false;
            for (int line = 4; line <= 4 + int(std::count(c.line.begin(), c.line.end(), '\n')); ++line)
                placed |= message.rfind(path + ":" + std::to_string(line) + ": ", 0) == 0;
            EXPECT_TRUE(placed) << message;
            EXPECT_NE(message.find(c.message), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
}

// Shapes inside shapes, each MediumInterface naming its inside and outside: the media nest as
// the meshes do, a shape with only an outside medium is a cavity, and a stated outside that the
// meshes contradict is an error naming the shape.
std::string nestedPbrt(const std::string& middleInterface) {
    return R"(Camera "perspective"
Integrator "volpath"
MakeNamedMedium "water" "string type" "homogeneous" "rgb sigma_a" [0.1 0.1 0.1] "rgb sigma_s" [1 1 1]
MakeNamedMedium "ink" "string type" "homogeneous" "rgb sigma_a" [2 2 2] "rgb sigma_s" [0 0 0]
WorldBegin
LightSource "point"
AttributeBegin
  MediumInterface "water" ""
  Material "glass"
  Scale 2 2 2
  Shape "trianglemesh" )" +
           kCube + R"(
AttributeEnd
AttributeBegin
  MediumInterface )" +
           middleInterface + R"(
  Material "none"
  Shape "trianglemesh" )" +
           kCube + R"(
AttributeEnd
AttributeBegin
  MediumInterface "" "ink"
  Material "glass" "float index" 1
  Scale 0.3 0.3 0.3
  Shape "trianglemesh" )" +
           kCube + R"(
AttributeEnd
WorldEnd
)";
}

TEST(Pbrt, NestedShapesWithMediumInterfacesBecomeRegions) {
    const SceneDesc s = loadPbrtScene(test::writeTemp("nested.pbrt", nestedPbrt(R"("ink" "water")")));
    ASSERT_EQ(s.media.size(), 3u);
    EXPECT_FALSE(s.media[0].cavity);
    EXPECT_EQ(s.media[1].sigmaA, RGB(2));
    EXPECT_TRUE(s.media[2].cavity);
    EXPECT_EQ(s.media[2].sigmaS, RGB(0));
    EXPECT_EQ(s.media[2].boundaryMaterial.type, MaterialType::Dielectric);
    // The nesting the reader checked goes with the scene: it is not found twice.
    ASSERT_TRUE(s.nesting);
    EXPECT_EQ(s.nesting->parent, (std::vector<int32_t>{-1, 0, 1}));
    // Converted, the cavity is a cavity of the JSON scene.
    const std::string json = test::tempDir() + "/nested-converted.json";
    writeScene(s, json);
    const SceneDesc back = loadScene(json);
    ASSERT_EQ(back.media.size(), 3u);
    EXPECT_TRUE(back.media[2].cavity);
}

TEST(Pbrt, AStatedOutsideMediumTheMeshesContradictIsAnErrorNamingTheShape) {
    const std::string path = test::writeTemp("nested.pbrt", nestedPbrt(R"("ink" "")"));
    try {
        loadPbrtScene(path);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  path +
                      ":17: Shape: MediumInterface \"ink\" \"\" says the shape lies in no medium, but it lies inside " +
                      path + ":11 (Shape \"trianglemesh\"), medium \"water\" (the nesting is found from the meshes)");
    }
}

TEST(Pbrt, BrokenFilesAreErrorsToo) {
    auto error = [](const std::string& text) {
        try {
            loadPbrtScene(test::writeTemp("scene.pbrt", text));
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string path = test::tempDir() + "/scene.pbrt";
    EXPECT_EQ(error("LookAt 0 0 1 0 0 0 0 1 0\n"), path + ":1: the file has no WorldBegin");
    EXPECT_EQ(error("WorldBegin\nLightSource \"point\"\n"), path + ":2: the file ends without WorldEnd");
    EXPECT_EQ(error("WorldBegin\nShape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0]\nWorldEnd\n"),
              path + ":3: nothing emits light (pbrt-v3 would render a black image)");
    EXPECT_EQ(
        error("Camera \"perspective\" \"float lensradius\" 0.1\nWorldBegin\nLightSource \"point\"\nWorldEnd\n"),
        path + ":1: Camera \"perspective\": parameter \"float lensradius\": depth of field is not supported (only 0)");
    EXPECT_EQ(error("Integrator \"bdpt\"\nWorldBegin\nLightSource \"point\"\nWorldEnd\n"),
              path + ":1: Integrator \"bdpt\" is not supported (supported: volpath, path)");
    EXPECT_EQ(error("Film \"image\" \"float cropwindow\" [0 0.5 0 1]\nWorldBegin\nLightSource \"point\"\nWorldEnd\n"),
              path + ":1: Film \"image\": parameter \"float cropwindow\": cropping is not supported");
    EXPECT_EQ(error("MediumInterface \"\" \"fog\"\nCamera \"perspective\"\nWorldBegin\nWorldEnd\n"),
              path + ":2: Camera: a camera inside medium \"fog\" is not supported");
}

TEST(Pbrt, UnusedParametersAreWarningsNamingThem) {
    const std::string path = test::writeTemp("scene.pbrt", R"(WorldBegin
LightSource "point" "float scale" 2
Shape "trianglemesh" "point P" [0 0 1  1 0 1  0 1 1]
  "float radius" 3
WorldEnd
)");
    std::vector<std::string> warnings;
    const SceneDesc s = loadPbrtScene(path, &warnings);
    EXPECT_EQ(s.lights[0].intensity, RGB(1));  // pbrt-v3 reads "scale" only as a spectrum
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_EQ(
        warnings[0],
        path + ":2: warning: LightSource \"point\": parameter \"float scale\" is not used (pbrt-v3 ignores it too)");
    EXPECT_EQ(
        warnings[1],
        path + ":4: warning: Shape \"trianglemesh\": parameter \"float radius\" is not used (pbrt-v3 ignores it too)");
}

// A file of nothing but AttributeBegin (2 million of them) took 1.4 GB and printed a warning for
// each: the blocks open at once are bounded, and so are the warnings kept.
TEST(Pbrt, BlockDepthAndWarningsAreBounded) {
    std::string deep = "WorldBegin\n";
    for (int i = 0; i < 1025; ++i) deep += "AttributeBegin\n";
    const std::string path = test::writeTemp("deep.pbrt", deep + "WorldEnd\n");
    try {
        loadPbrtScene(path);
        FAIL() << "1025 open blocks were accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(
            std::string(e.what()),
            path + ":1026: AttributeBegin nested more than 1024 deep (AttributeBegin and TransformBegin together)");
    }
    std::string open = "WorldBegin\nLightSource \"point\"\n";
    for (int i = 0; i < 300; ++i) open += "TransformBegin\n";
    std::vector<std::string> warnings;
    loadPbrtScene(test::writeTemp("open.pbrt", open + "WorldEnd\n"), &warnings);
    ASSERT_EQ(warnings.size(), kMaxWarnings + 1);
    EXPECT_NE(warnings[0].find("TransformBegin without an end before WorldEnd"), std::string::npos) << warnings[0];
    EXPECT_EQ(warnings.back(), "tetglow: warning: more than 100 warnings; the rest are not shown");
}

}  // namespace
}  // namespace tetglow
