// pbrt-v3 scenes, checked number for number against pbrt-v3's own formulas, written out here
// as pbrt-v3 has them (core/transform.cpp, cameras/perspective.cpp, lights/spot.cpp,
// lights/point.cpp, shapes/triangle.cpp), on row-major matrices like pbrt's Matrix4x4.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "TestMeshes.h"
#include "scene/Camera.h"
#include "scene/Light.h"
#include "scene/PbrtParser.h"

namespace tetglow {
namespace {

// ---- pbrt-v3 ----------------------------------------------------------------------------

struct M4 {
    double m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
};

M4 operator*(const M4& a, const M4& b) {
    M4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j] + a.m[i][3] * b.m[3][j];
    return r;
}

M4 inverse(const M4& a) {  // not a convention: any inverse will do
    glm::dmat4 g;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) g[j][i] = a.m[i][j];
    g = glm::inverse(g);
    M4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = g[j][i];
    return r;
}

M4 Translate(double x, double y, double z) {
    M4 r;
    r.m[0][3] = x;
    r.m[1][3] = y;
    r.m[2][3] = z;
    return r;
}

M4 Scale(double x, double y, double z) {
    M4 r;
    r.m[0][0] = x;
    r.m[1][1] = y;
    r.m[2][2] = z;
    return r;
}

M4 Rotate(double theta, glm::dvec3 a) {
    a = glm::normalize(a);
    const double s = std::sin(theta * std::numbers::pi / 180), c = std::cos(theta * std::numbers::pi / 180);
    M4 r;
    r.m[0][0] = a.x * a.x + (1 - a.x * a.x) * c;
    r.m[0][1] = a.x * a.y * (1 - c) - a.z * s;
    r.m[0][2] = a.x * a.z * (1 - c) + a.y * s;
    r.m[1][0] = a.x * a.y * (1 - c) + a.z * s;
    r.m[1][1] = a.y * a.y + (1 - a.y * a.y) * c;
    r.m[1][2] = a.y * a.z * (1 - c) - a.x * s;
    r.m[2][0] = a.x * a.z * (1 - c) - a.y * s;
    r.m[2][1] = a.y * a.z * (1 - c) + a.x * s;
    r.m[2][2] = a.z * a.z + (1 - a.z * a.z) * c;
    return r;
}

M4 LookAt(glm::dvec3 pos, glm::dvec3 look, glm::dvec3 up) {
    M4 cameraToWorld;
    const glm::dvec3 dir = glm::normalize(look - pos);
    const glm::dvec3 right = glm::normalize(glm::cross(glm::normalize(up), dir));
    const glm::dvec3 newUp = glm::cross(dir, right);
    for (int i = 0; i < 3; ++i) {
        cameraToWorld.m[i][0] = right[i];
        cameraToWorld.m[i][1] = newUp[i];
        cameraToWorld.m[i][2] = dir[i];
        cameraToWorld.m[i][3] = pos[i];
    }
    return inverse(cameraToWorld);
}

// pbrtTransform: the file's 16 numbers, transposed.
M4 FileMatrix(const double t[16]) {
    M4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = t[4 * j + i];
    return r;
}

glm::dvec3 point(const M4& a, const glm::dvec3& p) {
    glm::dvec3 r;
    for (int i = 0; i < 3; ++i) r[i] = a.m[i][0] * p.x + a.m[i][1] * p.y + a.m[i][2] * p.z + a.m[i][3];
    const double w = a.m[3][0] * p.x + a.m[3][1] * p.y + a.m[3][2] * p.z + a.m[3][3];
    return r / w;
}

glm::dvec3 vector(const M4& a, const glm::dvec3& v) {
    glm::dvec3 r;
    for (int i = 0; i < 3; ++i) r[i] = a.m[i][0] * v.x + a.m[i][1] * v.y + a.m[i][2] * v.z;
    return r;
}

double det3(const M4& a) {
    return a.m[0][0] * (a.m[1][1] * a.m[2][2] - a.m[1][2] * a.m[2][1]) -
           a.m[0][1] * (a.m[1][0] * a.m[2][2] - a.m[1][2] * a.m[2][0]) +
           a.m[0][2] * (a.m[1][0] * a.m[2][1] - a.m[1][1] * a.m[2][0]);
}

// PerspectiveCamera: the raster position of world point p.
glm::dvec2 raster(const M4& worldToCamera, double fov, int xres, int yres, const glm::dvec3& p) {
    const glm::dvec3 c = point(worldToCamera, p);
    const double invTan = 1 / std::tan(fov * std::numbers::pi / 360);
    const glm::dvec2 screen(invTan * c.x / c.z, invTan * c.y / c.z);
    const double frame = double(xres) / yres;
    const glm::dvec2 lo = frame > 1 ? glm::dvec2(-frame, -1) : glm::dvec2(-1, -1 / frame);
    const glm::dvec2 hi = -lo;
    return {(screen.x - lo.x) / (hi.x - lo.x) * xres, (hi.y - screen.y) / (hi.y - lo.y) * yres};
}

void CoordinateSystem(const glm::dvec3& v1, glm::dvec3& v2, glm::dvec3& v3) {
    if (std::abs(v1.x) > std::abs(v1.y))
        v2 = glm::dvec3(-v1.z, 0, v1.x) / std::sqrt(v1.x * v1.x + v1.z * v1.z);
    else
        v2 = glm::dvec3(0, v1.z, -v1.y) / std::sqrt(v1.y * v1.y + v1.z * v1.z);
    v3 = glm::cross(v1, v2);
}

// CreateSpotLight and SpotLight::Falloff.
struct PbrtSpot {
    M4 lightToWorld;
    double cosTotal, cosStart;
    PbrtSpot(const M4& l2w, glm::dvec3 from, glm::dvec3 to, double coneangle, double conedelta) {
        const glm::dvec3 dir = glm::normalize(to - from);
        glm::dvec3 du, dv;
        CoordinateSystem(dir, du, dv);
        M4 dirToZ;
        for (int j = 0; j < 3; ++j) {
            dirToZ.m[0][j] = du[j];
            dirToZ.m[1][j] = dv[j];
            dirToZ.m[2][j] = dir[j];
        }
        lightToWorld = l2w * Translate(from.x, from.y, from.z) * inverse(dirToZ);
        cosTotal = std::cos(coneangle * std::numbers::pi / 180);
        cosStart = std::cos((coneangle - conedelta) * std::numbers::pi / 180);
    }
    glm::dvec3 position() const { return point(lightToWorld, glm::dvec3(0)); }
    double falloff(const glm::dvec3& w) const {
        const double cosTheta = glm::normalize(vector(inverse(lightToWorld), w)).z;
        if (cosTheta < cosTotal) return 0;
        if (cosTheta > cosStart) return 1;
        const double delta = (cosTheta - cosTotal) / (cosStart - cosTotal);
        return (delta * delta) * (delta * delta);
    }
};

// ---- tests --------------------------------------------------------------------------------

const std::string kHeader = R"(LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective"
WorldBegin
LightSource "point" "rgb I" [1 1 1]
)";

const std::string kTriangle = R"(Shape "trianglemesh" "point P" [0.3 0 0  1 0.2 0  0 1 0.5] "integer indices" [0 1 2])";
const glm::dvec3 kP[3] = {{0.3, 0, 0}, {1, 0.2, 0}, {0, 1, 0.5}};

SceneDesc load(const std::string& text) {
    std::vector<std::string> warnings;
    return loadPbrtScene(test::writeTemp("scene.pbrt", text), &warnings);
}

// Each surface's vertices are pbrt's CTM applied to kP (to float precision), and its one
// triangle faces the way pbrt's geometric normal does: flipped when the CTM mirrors.
void expectPlaced(const SurfaceDesc& s, const M4& ctm, const std::string& what) {
    ASSERT_EQ(s.mesh.positions.size(), 3u) << what;
    glm::dvec3 w[3];
    for (int k = 0; k < 3; ++k) {
        w[k] = point(ctm, kP[k]);
        EXPECT_LT(glm::length(s.mesh.positions[k] - w[k]), 1e-6 * (1 + glm::length(w[k]))) << what << " vertex " << k;
    }
    const glm::dvec3 pbrtNormal = glm::cross(w[1] - w[0], w[2] - w[0]) * (det3(ctm) < 0 ? -1.0 : 1.0);
    EXPECT_GT(glm::dot(glm::cross(s.mesh.corner(0, 1) - s.mesh.corner(0, 0), s.mesh.corner(0, 2) - s.mesh.corner(0, 0)),
                       pbrtNormal),
              0)
        << what;
}

TEST(PbrtTransforms, NestedTransformsMatchPbrtsFormulas) {
    const SceneDesc s = load(kHeader + R"(AttributeBegin
  Translate 1 2 3
  Rotate 30 0 1 1
  )" + kTriangle + R"(
  TransformBegin
    Scale 2 -1 0.5
    )" + kTriangle + R"(
  TransformEnd
  ConcatTransform [1 0 0 0  0 1 0 0  0 0 1 0  4 5 6 1]
  )" + kTriangle + R"(
  CoordinateSystem "here"
AttributeEnd
)" + kTriangle + R"(
Transform [0 1 0 0  -1 0 0 0  0 0 1 0  1 1 1 1]
)" + kTriangle + R"(
CoordSysTransform "here"
Rotate -70 1 0 0
)" + kTriangle + R"(
Identity
LookAt 1 2 3  0 0 0  0 1 0
)" + kTriangle + R"(
WorldEnd
)");
    const double shift[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 4, 5, 6, 1};
    const double turn[16] = {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 1, 1, 1, 1};
    const M4 tr = Translate(1, 2, 3) * Rotate(30, {0, 1, 1});
    const M4 expected[] = {tr,
                           tr * Scale(2, -1, 0.5),
                           tr * FileMatrix(shift),
                           M4(),
                           FileMatrix(turn),
                           tr * FileMatrix(shift) * Rotate(-70, {1, 0, 0}),
                           LookAt({1, 2, 3}, {0, 0, 0}, {0, 1, 0})};
    ASSERT_EQ(s.surfaces.size(), std::size(expected));
    for (size_t i = 0; i < std::size(expected); ++i)
        expectPlaced(s.surfaces[i], expected[i], "surface " + std::to_string(i));
    // The file's translation is in elements 12, 13, 14 (pbrt transposes what it reads).
    EXPECT_NEAR(s.surfaces[4].mesh.positions[0].x, 1, 1e-6);
    EXPECT_NEAR(s.surfaces[4].mesh.positions[0].y, 1.3, 1e-6);
}

TEST(PbrtTransforms, OrientationFollowsReverseOrientationAndNormals) {
    const SceneDesc s = load(kHeader + R"(Shape "trianglemesh" "point P" [0 0 0  1 0 0  0 1 0] "integer indices" [0 1 2]
AttributeBegin
  ReverseOrientation
  Shape "trianglemesh" "point P" [0 0 0  1 0 0  0 1 0] "integer indices" [0 1 2]
  Scale -1 1 1
  Shape "trianglemesh" "point P" [0 0 0  1 0 0  0 1 0] "integer indices" [0 1 2]
AttributeEnd
Shape "trianglemesh" "point P" [0 0 0  1 0 0  0 1 0] "integer indices" [0 1 2] "normal N" [0 0 -1  0 0 -1  0 0 -1]
WorldEnd
)");
    ASSERT_EQ(s.surfaces.size(), 4u);
    auto normalZ = [&](int i) {
        const TriangleMesh& m = s.surfaces[size_t(i)].mesh;
        return glm::cross(m.corner(0, 1) - m.corner(0, 0), m.corner(0, 2) - m.corner(0, 0)).z;
    };
    EXPECT_GT(normalZ(0), 0);  // counter-clockwise: +z
    EXPECT_LT(normalZ(1), 0);  // ReverseOrientation
    // pbrt-v3 negates the normal for ReverseOrientation XOR a mirror: here the two flips
    // cancel, so the normal is the mirrored triangle's own cross product, -z.
    EXPECT_LT(normalZ(2), 0);
    EXPECT_LT(normalZ(3), 0);  // turned to the side of N
}

TEST(PbrtCamera, PointsLandOnThePixelsPbrtProjectsThemTo) {
    struct Case {
        std::string prefix;  // transforms before LookAt
        M4 before;
        int xres, yres;
        Handedness handedness;
    };
    const Case cases[] = {
        {"", M4(), 64, 40, Handedness::Left},                            // wide: fov across y
        {"", M4(), 30, 50, Handedness::Left},                            // tall: fov across x
        {"Scale -1 1 1\n", Scale(-1, 1, 1), 48, 48, Handedness::Right},  // the usual fix for pbrt's mirror
        {"Scale 3 3 3\nRotate 20 0 0 1\n", Scale(3, 3, 3) * Rotate(20, {0, 0, 1}), 40, 30, Handedness::Left},
    };
    const glm::dvec3 eye(1, 2, 5), look(0, 0.5, 0), up(0.2, 1, 0);
    const double fov = 50;
    for (const Case& c : cases) {
        const SceneDesc s = load(c.prefix +
                                 "LookAt 1 2 5  0 0.5 0  0.2 1 0\nCamera \"perspective\" \"float fov\" 50\nFilm "
                                 "\"image\" \"integer xresolution\" " +
                                 std::to_string(c.xres) + " \"integer yresolution\" " + std::to_string(c.yres) +
                                 "\nWorldBegin\nLightSource \"point\"\nWorldEnd\n");
        EXPECT_EQ(s.camera.handedness, c.handedness) << c.prefix;
        EXPECT_EQ(s.camera.width, c.xres);
        EXPECT_EQ(s.camera.fov, fov);
        const Camera camera(s.camera);
        const M4 worldToCamera = c.before * LookAt(eye, look, up);
        for (const glm::dvec3 p : {glm::dvec3(0, 0.5, 0), glm::dvec3(0.6, 0.2, -0.3), glm::dvec3(-0.8, 1.1, 0.4),
                                   glm::dvec3(0.3, -0.4, 1)}) {
            const glm::dvec2 r = raster(worldToCamera, fov, c.xres, c.yres, p);
            EXPECT_TRUE(r.x > 0 && r.x < c.xres && r.y > 0 && r.y < c.yres)
                << c.prefix << " raster " << r.x << ", " << r.y;
            const glm::dvec3 d = camera.generateRay(r.x, r.y).d, expected = glm::normalize(p - eye);
            EXPECT_LT(glm::length(d - expected), 1e-9)
                << c.prefix << c.xres << "x" << c.yres << " point " << p.x << ", " << p.y << ", " << p.z;
        }
    }
}

TEST(PbrtLights, SpotFalloffIsPbrts) {
    struct Case {
        double coneangle, conedelta;
        std::string params;
    };
    const Case cases[] = {{30, 10, "\"float coneangle\" 30 \"float conedeltaangle\" 10"},
                          {30, 5, ""},                      // pbrt-v3's defaults
                          {3, 5, "\"float coneangle\" 3"},  // the default delta wider than the cone
                          {20, 45, "\"float coneangle\" 20 \"float conedeltaangle\" 45"}};
    const M4 l2w = Translate(1, 2, 3) * Rotate(40, {1, 0.5, 0}) * Scale(2, 2, 2);
    const glm::dvec3 from(0.5, 1, 0), to(0.2, -1, 0.4);
    for (const Case& c : cases) {
        const SceneDesc s = load(kHeader +
                                 "Translate 1 2 3\nRotate 40 1 0.5 0\nScale 2 2 2\nLightSource \"spot\" \"rgb I\" [1 2 "
                                 "3] \"rgb scale\" [2 2 2] "
                                 "\"point from\" [0.5 1 0] \"point to\" [0.2 -1 0.4] " +
                                 c.params + "\nWorldEnd\n");
        ASSERT_EQ(s.lights.size(), 2u);
        const auto light = makeLight(s.lights[1], Bounds3());
        const PbrtSpot pbrt(l2w, from, to, c.coneangle, c.conedelta);
        EXPECT_LT(glm::length(s.lights[1].position - pbrt.position()), 1e-12);
        const glm::dvec3 axis = glm::normalize(vector(pbrt.lightToWorld, {0, 0, 1}));
        glm::dvec3 side, unused;
        CoordinateSystem(axis, side, unused);
        int lit = 0, partial = 0;
        for (double degrees = 0; degrees < 50; degrees += 0.5) {
            const double a = degrees * std::numbers::pi / 180;
            const glm::dvec3 q = pbrt.position() + 3.0 * (std::cos(a) * axis + std::sin(a) * side);
            const double f = pbrt.falloff(q - pbrt.position());
            const RGB expected = RGB(2, 4, 6) * f / 9.0;
            const RGB L = light->sample(q, {0.5, 0.5}).L;
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(L[k], expected[k], 1e-9) << c.coneangle << "/" << c.conedelta << " at " << degrees;
            lit += f > 0;
            partial += f > 0 && f < 1;
        }
        EXPECT_GT(lit, 0);
        if (c.conedelta == 10) {
            EXPECT_GT(partial, 10);  // the falloff band was sampled
        }
    }
}

TEST(PbrtLights, PointLightsTranslateFromAfterTheTransform) {
    // pbrt-v3 (lights/point.cpp): Translate(from) * light2world, so the position is from + CTM(0).
    const SceneDesc s = load(R"(LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective"
WorldBegin
AttributeBegin
  Rotate 90 0 0 1
  Translate 1 0 0
  LightSource "point" "rgb I" [1 2 3] "point from" [0 1 0] "rgb scale" [2 2 2]
  LightSource "distant" "rgb L" [1 1 1] "point from" [0 0 0] "point to" [1 0 0]
AttributeEnd
LightSource "distant"
LightSource "infinite" "rgb L" [0.1 0.2 0.3]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [4 4 4] "rgb scale" [0.5 1 2] "bool twosided" "true"
  Shape "trianglemesh" "point P" [0 0 0  1 0 0  1 1 0  0 1 0] "integer indices" [0 1 2  0 2 3]
AttributeEnd
WorldEnd
)");
    ASSERT_EQ(s.lights.size(), 5u);
    EXPECT_EQ(s.lights[0].type, LightType::Point);
    EXPECT_LT(glm::length(s.lights[0].position - glm::dvec3(0, 2, 0)), 1e-12);
    EXPECT_EQ(s.lights[0].intensity, RGB(2, 4, 6));
    EXPECT_EQ(s.lights[1].type, LightType::Distant);  // travels along CTM(to - from): +x turned to +y
    EXPECT_LT(glm::length(glm::normalize(s.lights[1].direction) - glm::dvec3(0, 1, 0)), 1e-12);
    EXPECT_LT(glm::length(glm::normalize(s.lights[2].direction) - glm::dvec3(0, 0, 1)),
              1e-12);  // default: from 0 0 0 to 0 0 1
    EXPECT_EQ(s.lights[2].irradiance, RGB(1));
    EXPECT_EQ(s.lights[3].type, LightType::Environment);
    EXPECT_EQ(s.lights[3].radiance, RGB(0.1, 0.2, 0.3));
    EXPECT_EQ(s.lights[4].type, LightType::Mesh);
    EXPECT_EQ(s.lights[4].radiance, RGB(2, 4, 8));
    EXPECT_TRUE(s.lights[4].twoSided);
    EXPECT_EQ(s.lights[4].mesh.triangles.size(), 2u);
    EXPECT_TRUE(s.surfaces.empty());  // the emitter is a light, not also a surface
}

}  // namespace
}  // namespace tetglow
