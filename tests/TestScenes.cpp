#include "TestScenes.h"

#include "TestMeshes.h"

#include "render/Renderer.h"
#include "tet/Shapes.h"

namespace tetglow::test {

MediumDesc sphereMedium(const RGB& sigmaA, const RGB& sigmaS, double g, int subdivisions) {
    MediumDesc m;
    m.name = "sphere";
    m.boundary = roundedToFloat(icosphere(subdivisions, 1.0));
    m.sigmaA = sigmaA;
    m.sigmaS = sigmaS;
    m.g = g;
    return m;
}

SceneDesc sceneWith(const MediumDesc& medium, int resolution) {
    SceneDesc s;
    s.camera.position = {0.3, 0.2, 4};
    s.camera.lookAt = {0, 0, 0};
    s.camera.fov = 35;
    s.camera.width = s.camera.height = resolution;
    s.media.push_back(medium);
    return s;
}

LightDesc environment(double radiance) {
    LightDesc l;
    l.type = LightType::Environment;
    l.radiance = RGB(radiance);
    return l;
}

LightDesc pointLight(const glm::dvec3& position, const RGB& intensity) {
    LightDesc l;
    l.type = LightType::Point;
    l.position = position;
    l.intensity = intensity;
    return l;
}

LightDesc spotLight(const glm::dvec3& position, const glm::dvec3& lookAt, const RGB& intensity, double coneAngle,
                    double coneDelta, double radius) {
    LightDesc l = pointLight(position, intensity);
    l.type = LightType::Spot;
    l.lookAt = lookAt;
    l.coneAngle = coneAngle;
    l.coneDelta = coneDelta;
    l.radius = radius;
    return l;
}

LightDesc quadLight(const glm::dvec3& corner, const glm::dvec3& edge0, const glm::dvec3& edge1, const RGB& radiance) {
    LightDesc l;
    l.type = LightType::Quad;
    l.corner = corner;
    l.edge0 = edge0;
    l.edge1 = edge1;
    l.radiance = radiance;
    return l;
}

SceneDesc glowingSphereUnderQuad(int resolution) {
    MediumDesc m = sphereMedium(RGB(0.2, 0.5, 0.1), RGB(0.8, 0.6, 1.2), 0.5);
    m.emission = RGB(0.1, 0.2, 0.9);
    SceneDesc desc = sceneWith(m, resolution);
    desc.lights.push_back(environment(0.3));
    desc.lights.push_back(quadLight({-1, 3, -1}, {0, 0, 2}, {2, 0, 0}, RGB(5)));
    return desc;
}

RGB meanImage(const Scene& scene, Integrator&& integrator, int spp) {
    RenderOptions options;
    options.spp = spp;
    const Image image = render(scene, integrator, options).image;
    RGB sum(0);
    for (const glm::vec3& p : image.pixels) sum += RGB(p);
    return sum / double(image.pixels.size());
}

}  // namespace tetglow::test
