#include "SceneCompare.h"

#include <filesystem>

#include <gtest/gtest.h>

namespace tetglow::test {

void expectSameMesh(const TriangleMesh& a, const TriangleMesh& b, const std::string& what) {
    EXPECT_EQ(a.positions, b.positions) << what;
    EXPECT_EQ(a.triangles, b.triangles) << what;
}

void expectSameMaterial(const MaterialDesc& a, const MaterialDesc& b, const std::string& what) {
    EXPECT_EQ(a.type, b.type) << what;
    EXPECT_EQ(a.reflectance, b.reflectance) << what;
    EXPECT_EQ(a.ior, b.ior) << what;
}

void expectSameScene(const SceneDesc& a, const SceneDesc& b) {
    EXPECT_EQ(a.camera.position, b.camera.position);
    EXPECT_EQ(a.camera.lookAt, b.camera.lookAt);
    EXPECT_EQ(a.camera.up, b.camera.up);
    EXPECT_EQ(a.camera.fov, b.camera.fov);
    EXPECT_EQ(a.camera.width, b.camera.width);
    EXPECT_EQ(a.camera.height, b.camera.height);
    EXPECT_EQ(a.camera.handedness, b.camera.handedness);
    EXPECT_TRUE(a.turntable.frames == b.turntable.frames && a.turntable.center == b.turntable.center &&
                a.turntable.axis == b.turntable.axis && a.turntable.degrees == b.turntable.degrees);
    const IntegratorDesc &i = a.integrator, &j = b.integrator;
    EXPECT_TRUE(i.type == j.type && i.spp == j.spp && i.maxDepth == j.maxDepth && i.seed == j.seed &&
                i.boundary == j.boundary && i.stepSize == j.stepSize && i.parityRays == j.parityRays);
    EXPECT_TRUE(i.photons == j.photons && i.k == j.k && i.radius == j.radius && i.estimate == j.estimate &&
                i.alpha == j.alpha && i.boundaryCorrection == j.boundaryCorrection && i.finalGather == j.finalGather &&
                i.timeLimit == j.timeLimit);
    // Both name the same file: pbrt's Film filename is relative to the working directory, JSON's
    // "output" to the scene file's folder.
    if (a.output.empty() || b.output.empty())
        EXPECT_EQ(a.output, b.output);
    else
        EXPECT_EQ(std::filesystem::absolute(a.output).lexically_normal(),
                  std::filesystem::absolute(b.output).lexically_normal());
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (size_t k = 0; k < a.lights.size(); ++k) {
        const LightDesc &l = a.lights[k], &m = b.lights[k];
        const std::string what = "light " + std::to_string(k);
        EXPECT_TRUE(l.type == m.type && l.intensity == m.intensity && l.radiance == m.radiance &&
                    l.irradiance == m.irradiance)
            << what;
        EXPECT_TRUE(l.position == m.position && l.lookAt == m.lookAt && l.coneAngle == m.coneAngle &&
                    l.coneDelta == m.coneDelta && l.radius == m.radius && l.direction == m.direction &&
                    l.twoSided == m.twoSided)
            << what;
        EXPECT_TRUE(l.corner == m.corner && l.edge0 == m.edge0 && l.edge1 == m.edge1) << what;
        expectSameMesh(l.mesh, m.mesh, what);
    }
    ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
    for (size_t k = 0; k < a.surfaces.size(); ++k) {
        expectSameMesh(a.surfaces[k].mesh, b.surfaces[k].mesh, "surface " + std::to_string(k));
        expectSameMaterial(a.surfaces[k].material, b.surfaces[k].material, "surface " + std::to_string(k));
    }
    ASSERT_EQ(a.media.size(), b.media.size());
    for (size_t k = 0; k < a.media.size(); ++k) {
        const MediumDesc &m = a.media[k], &n = b.media[k];
        const std::string what = "medium " + std::to_string(k);
        expectSameMesh(m.boundary, n.boundary, what);
        EXPECT_TRUE(m.sigmaA == n.sigmaA && m.sigmaS == n.sigmaS && m.g == n.g && m.emission == n.emission) << what;
        EXPECT_TRUE(m.density.type == n.density.type && m.density.offset == n.density.offset &&
                    m.density.gradient == n.density.gradient && m.density.frequency == n.density.frequency &&
                    m.density.amplitude == n.density.amplitude && m.density.seed == n.density.seed)
            << what;
        expectSameMaterial(m.boundaryMaterial, n.boundaryMaterial, what);
        EXPECT_TRUE(m.tetOptions.radiusEdgeRatio == n.tetOptions.radiusEdgeRatio &&
                    m.tetOptions.maxVolume == n.tetOptions.maxVolume)
            << what;
    }
}

}  // namespace tetglow::test
