// A scene built in headless Blender and written by Blender's own glTF exporter: tetglow reads the
// lights in Cycles' units (a point or spot light of P watts: P / (4 pi) W/sr; a sun of strength S:
// S W/m^2), the camera's field of view,
// the glass and its absorbing volume, and renders the .glb as Cycles renders the Blender scene,
// and as the Cycles peer in ../shared/peers renders the .glb converted to JSON, within their noise.
// Skipped where Blender is missing (the peer's comparison where the peer is).
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>

#include "TestMeshes.h"
#include "render/ImageIO.h"
#include "scene/SceneLoader.h"

namespace tetglow {
namespace {

namespace fs = std::filesystem;

constexpr int kSpp = 128;
constexpr double kWatts = 400, kSun = 0.5, kLensAngle = 0.8, kIor = 1.45, kDensity = 1.5;
// At least 1 / e, so that Cycles can be given the same absorption (below).
const glm::dvec3 kColour(0.9, 0.7, 0.45);

// The scene in Blender's Z-up frame: a camera, a point and a spot light of kWatts, a sun, a diffuse floor and an ico
// sphere of glass (Principled BSDF, transmission 1) holding an absorbing volume. Blender 3.4's
// exporter writes KHR_materials_volume only from a Volume Absorption node (Color, and Density as
// 1 / attenuationDistance; a Principled Volume gives none) and only where a "glTF Material Output"
// group gives a non-zero Thickness (the group its importer makes), so the script adds one.
const char* const kBlenderScript = R"(
import bpy, math, sys
out, cycles_exr = sys.argv[sys.argv.index('--') + 1:][:2]
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = 48, 36, 100
scene['tetglow'] = {'resolution': [48, 36]}  # glTF has no resolution: the scene's extras carry it
cam = bpy.data.objects.new('Eye', bpy.data.cameras.new('Eye'))
cam.data.angle = @ANGLE@
cam.location = (0.3, -4.5, 1.6)
cam.rotation_euler = (math.radians(72), 0, math.radians(4))
scene.collection.objects.link(cam)
scene.camera = cam
lamp = bpy.data.lights.new('Lamp', 'POINT')
lamp.energy = @WATTS@
lamp.shadow_soft_size = 0
lamp_object = bpy.data.objects.new('Lamp', lamp)
lamp_object.location = (1.5, -1.0, 3.0)
scene.collection.objects.link(lamp_object)
sun = bpy.data.lights.new('Sun', 'SUN')
sun.energy = @SUN@
sun.angle = 0
sun_object = bpy.data.objects.new('Sun', sun)
sun_object.rotation_euler = (math.radians(30), 0, math.radians(50))
scene.collection.objects.link(sun_object)
spot = bpy.data.lights.new('Spot', 'SPOT')
spot.energy = @WATTS@
spot.shadow_soft_size = 0
spot.spot_size = math.radians(60)
spot.spot_blend = 0  # a hard edge: tetglow's falloff band is not Cycles' smoothstep
spot_object = bpy.data.objects.new('Spot', spot)
spot_object.location = (-1.5, -1.0, 2.5)
# Pointing up, at nothing: its units are checked, not its image. Cycles 3.4 multiplies a spot's
# intensity by the cosine to its axis, which glTF's spot (constant inside the inner cone) drops.
spot_object.rotation_euler = (math.pi, 0, 0)
scene.collection.objects.link(spot_object)

def principled(name):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    return m, m.node_tree.nodes['Principled BSDF']

bpy.ops.mesh.primitive_plane_add(size=8, location=(0, 0, -0.8))
floor, p = principled('Floor')
p.inputs['Base Color'].default_value = (0.6, 0.55, 0.5, 1)
p.inputs['Metallic'].default_value = 0
bpy.context.object.data.materials.append(floor)

bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=3, radius=0.8, location=(0, 0, 0))
glass, p = principled('Glass')
p.inputs['Base Color'].default_value = (1, 1, 1, 1)  # glTF and Cycles tint transmitted light by it
p.inputs['Transmission'].default_value = 1
p.inputs['Roughness'].default_value = 0
p.inputs['IOR'].default_value = @IOR@
nodes, links = glass.node_tree.nodes, glass.node_tree.links
volume = nodes.new('ShaderNodeVolumeAbsorption')
volume.inputs['Color'].default_value = (@R@, @G@, @B@, 1)
volume.inputs['Density'].default_value = @DENSITY@
links.new(volume.outputs['Volume'], nodes['Material Output'].inputs['Volume'])
group = bpy.data.node_groups.new('glTF Material Output', 'ShaderNodeTree')
group.inputs.new('NodeSocketFloat', 'Thickness')
settings = nodes.new('ShaderNodeGroup')
settings.node_tree = group
settings.inputs['Thickness'].default_value = 1
bpy.context.object.data.materials.append(glass)

bpy.ops.export_scene.gltf(filepath=out, export_format='GLB', export_cameras=True, export_lights=True,
                          export_extras=True)

# Cycles renders the Blender scene itself, with two changes that keep what the glTF says: the
# floor's Principled BSDF (Disney diffuse, not Lambertian) becomes a Diffuse BSDF of its colour,
# and the absorption colour c becomes 1 + ln(c), as Cycles absorbs Density (1 - Color) per unit
# length where glTF says -ln(c) / attenuationDistance.
nt = floor.node_tree
diffuse = nt.nodes.new('ShaderNodeBsdfDiffuse')
diffuse.inputs['Color'].default_value = nt.nodes['Principled BSDF'].inputs['Base Color'].default_value
nt.links.new(diffuse.outputs['BSDF'], nt.nodes['Material Output'].inputs['Surface'])
volume.inputs['Color'].default_value = (1 + math.log(@R@), 1 + math.log(@G@), 1 + math.log(@B@), 1)
scene.render.engine = 'CYCLES'
c = scene.cycles
c.device, c.samples, c.seed, c.use_adaptive_sampling, c.use_denoising = 'CPU', int(@SPP@), 2, False, False
c.pixel_filter_type, c.filter_width = 'BOX', 1.0
c.sample_clamp_direct = c.sample_clamp_indirect = c.light_sampling_threshold = 0.0
c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = c.volume_bounces = 62
c.transparent_max_bounces = 1024
c.caustics_reflective = c.caustics_refractive = True
c.blur_glossy = 0.0
scene.render.threads_mode, scene.render.threads = 'FIXED', 2
scene.view_settings.view_transform = 'Standard'
scene.render.image_settings.file_format, scene.render.image_settings.color_depth = 'OPEN_EXR', '32'
scene.render.filepath = cycles_exr
bpy.ops.render.render(write_still=True)
)";

std::string replaced(std::string text, const std::string& key, double value) {
    for (size_t at; (at = text.find(key)) != std::string::npos;) text.replace(at, key.size(), std::to_string(value));
    return text;
}

bool onPath(const std::string& program) {
    return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

int runQuiet(const std::string& command, const std::string& log) {
    return std::system((command + " >" + log + " 2>&1 </dev/null").c_str());
}

// Per-block z-scores of the grey difference of two independent renders: z = mean(d) / (std(d) /
// sqrt(n)) in each block of `block` x `block` pixels, about N(0, 1) where both are unbiased.
struct BlockZ {
    double meanZ = 0, stdZ = 0, maxAbsZ = 0;
    int blocks = 0;
};
BlockZ blockZ(const Image& a, const Image& b, int block) {
    std::vector<double> zs;
    for (int by = 0; by + block <= a.height; by += block)
        for (int bx = 0; bx + block <= a.width; bx += block) {
            double sum = 0, sum2 = 0;
            const int n = block * block;
            for (int y = by; y < by + block; ++y)
                for (int x = bx; x < bx + block; ++x) {
                    const glm::vec3 d = a.at(x, y) - b.at(x, y);
                    const double g = (d.x + d.y + d.z) / 3;
                    sum += g;
                    sum2 += g * g;
                }
            const double mean = sum / n, var = (sum2 - n * mean * mean) / (n - 1);
            if (var > 1e-14) zs.push_back(mean / std::sqrt(var / n));
        }
    BlockZ r;
    r.blocks = int(zs.size());
    for (const double z : zs) r.meanZ += z / double(zs.size());
    for (const double z : zs) {
        r.stdZ += (z - r.meanZ) * (z - r.meanZ) / double(zs.size());
        r.maxAbsZ = std::max(r.maxAbsZ, std::abs(z));
    }
    r.stdZ = std::sqrt(r.stdZ);
    return r;
}

// The two renders of one scene agree within their own noise: equal means, and block z-scores
// about N(0, 1) (printed, for the record).
void expectWithinNoise(const Image& a, const Image& b, const std::string& what) {
    ASSERT_EQ(a.width, b.width) << what;
    ASSERT_EQ(a.height, b.height) << what;
    glm::dvec3 meanA(0), meanB(0);
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        meanA += glm::dvec3(a.pixels[i]) / double(a.pixels.size());
        meanB += glm::dvec3(b.pixels[i]) / double(b.pixels.size());
    }
    const BlockZ z = blockZ(a, b, 6);
    std::printf("tetglow mean %.5f %.5f %.5f, %s %.5f %.5f %.5f; %d blocks: mean z %.2f, std z %.2f, max |z| %.2f\n",
                meanA.x, meanA.y, meanA.z, what.c_str(), meanB.x, meanB.y, meanB.z, z.blocks, z.meanZ, z.stdZ,
                z.maxAbsZ);
    EXPECT_GT(meanA.x, 0.01) << what;           // the floor is lit
    ASSERT_GE(z.blocks, 24) << what;            // half the image or more is noisy floor and sphere (of 48 blocks)
    EXPECT_LT(std::abs(z.meanZ), 1.0) << what;  // 5 sigma of the mean of 24 or more independent z
    EXPECT_LT(z.stdZ, 1.6) << what;
    EXPECT_LT(z.maxAbsZ, 5) << what;
}

TEST(GltfBlender, ExportedSceneRendersAsCyclesDoes) {
    if (!onPath("blender")) GTEST_SKIP() << "blender is not on PATH (./setup.sh test installs it)";
    const fs::path peer = fs::path(TETGLOW_SOURCE_DIR) / ".." / "shared" / "peers" / "cycles_render.py";
    const std::string dir = test::tempDir(), glb = dir + "/scene.glb";
    std::string script = kBlenderScript;
    for (const auto& [key, value] : {std::pair{"@ANGLE@", kLensAngle},
                                     {"@WATTS@", kWatts},
                                     {"@SUN@", kSun},
                                     {"@IOR@", kIor},
                                     {"@DENSITY@", kDensity},
                                     {"@R@", kColour.x},
                                     {"@G@", kColour.y},
                                     {"@B@", kColour.z},
                                     {"@SPP@", double(kSpp)}})
        script = replaced(script, key, value);
    const std::string scriptPath = test::writeTemp("build_scene.py", script);
    ASSERT_EQ(runQuiet("blender -b --factory-startup --python-exit-code 1 --python " + scriptPath + " -- " + glb + " " +
                           dir + "/cycles.exr",
                       dir + "/blender.log"),
              0)
        << test::readFile(dir + "/blender.log");

    // What the exporter wrote, read in Cycles' units.
    const SceneDesc s = loadScene(glb);
    // Point and spot lights of P watts: P / (4 pi) W/sr; the sun: its strength in W/m^2.
    ASSERT_EQ(s.lights.size(), 3u);
    for (const LightDesc& l : s.lights) {
        const double expected = l.type == LightType::Distant ? kSun : kWatts / (4 * glm::pi<double>());
        for (int k = 0; k < 3; ++k)  // the exporter writes 32-bit floats
            EXPECT_NEAR(emissionOf(l)[k], expected, 1e-6 * expected) << emissionKey(l.type);
        if (l.type == LightType::Spot) {  // Blender's spot_size is the whole cone; its blend a part of the half
            EXPECT_NEAR(l.coneAngle, 30, 1e-4);
            EXPECT_NEAR(l.coneDelta, 0, 1e-4);
        }
    }
    EXPECT_EQ(s.camera.width, 48);
    EXPECT_EQ(s.camera.height, 36);
    // Blender's lens angle spans the wider (horizontal) axis; tetglow's fov the shorter one.
    EXPECT_NEAR(s.camera.fov, 2 * std::atan(std::tan(kLensAngle / 2) * 36 / 48) * 180 / glm::pi<double>(), 1e-4);
    ASSERT_EQ(s.surfaces.size(), 1u);
    EXPECT_EQ(s.surfaces[0].material.type, MaterialType::Diffuse);
    ASSERT_EQ(s.media.size(), 1u);
    EXPECT_EQ(s.media[0].boundaryMaterial.type, MaterialType::Dielectric);
    EXPECT_NEAR(s.media[0].boundaryMaterial.ior, kIor, 1e-6);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.media[0].sigmaA[k], -std::log(kColour[k]) * kDensity, 1e-5);

    // tetglow renders the .glb; Cycles rendered the Blender scene, and the peer renders the .glb
    // converted to JSON.
    const auto rendered = test::runTetglow("render " + glb + " --spp " + std::to_string(kSpp) +
                                           " --seed 1 --threads 2 -o " + dir + "/tetglow.exr");
    ASSERT_EQ(rendered.exitCode, 0) << rendered.err;
    const Image image = readExr(dir + "/tetglow.exr");
    expectWithinNoise(image, readExr(dir + "/cycles.exr"), "Cycles on the Blender scene");
    // Compared with Cycles above; a skip says that the second comparison was not made.
    if (!fs::exists(peer)) GTEST_SKIP() << peer << " is missing: the Cycles peer is not compared";
    const std::string json = dir + "/scene.json";
    const auto converted = test::runTetglow("convert " + glb + " -o " + json);
    ASSERT_EQ(converted.exitCode, 0) << converted.err;
    // The peer predates the integrator's "final_gather" and media's "name", which it does not need.
    nlohmann::json forPeer = nlohmann::json::parse(test::readFile(json));
    forPeer["integrator"].erase("final_gather");
    for (auto& medium : forPeer["media"]) medium.erase("name");
    test::writeTemp("peer.json", forPeer.dump());
    ASSERT_EQ(runQuiet("blender -b --factory-startup --python " + peer.string() + " -- " + dir + "/peer.json" +
                           " --spp " + std::to_string(kSpp) + " --threads 2 --seed 1 --out " + dir + "/peer.exr",
                       dir + "/peer.log"),
              0)
        << test::readFile(dir + "/peer.log");
    expectWithinNoise(image, readExr(dir + "/peer.exr"), "the Cycles peer on the converted JSON");
}

}  // namespace
}  // namespace tetglow
