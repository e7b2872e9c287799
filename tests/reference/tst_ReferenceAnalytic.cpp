#include "TestSupport.h"

#include "document/SceneLoader.h"
#include "reference/Pcg32.h"
#include "reference/PhongBsdf.h"
#include "reference/ReferenceRenderer.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace vct;

/**
 * The reference path tracer against answers known in closed form: the white furnace (a closed emitting box,
 * radiance E / (1 - albedo) everywhere), direct light from point and directional lights, and the framing and
 * one-sidedness of emitters against the GL renderer's projection.
 */
class ReferenceAnalyticTest : public QObject {
    Q_OBJECT

private slots:
    void whiteFurnace_data();
    void whiteFurnace();
    void pointLightDirect();
    void directionalLightDirect();
    void framingMatchesGlProjection();
    void emitterBackFaceIsDark();
    void zeroBouncesShowsEmittersOnly();
    void phongSamplingMatchesItsDensity();
};

namespace {

constexpr double kPi = std::numbers::pi;

/** The cube [-1,1]^3 with every face turned inwards, one material. */
render::Scene closedBox(const render::Material& material)
{
    render::Scene scene;
    scene.materials = { material };
    std::vector<glm::vec3> positions;
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : { -1.0f, 1.0f }) {
            glm::vec3 centre(0.0f), u(0.0f), v(0.0f);
            centre[axis] = sign;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = 1.0f;
            // quad() winds counter-clockwise around cross(u, v); flip it where that points out of the box.
            if (glm::dot(glm::cross(u, v), centre) > 0.0f)
                std::swap(u, v);
            for (const glm::vec3& p :
                test::quad(centre - u - v, centre + u - v, centre + u + v, centre - u + v))
                positions.push_back(p);
        }
    scene.meshes.push_back(test::makeTriangles(positions));
    return scene;
}

/** The infinite-looking floor y = 0, facing up, 40 m across. */
render::Mesh floorPlane()
{
    return test::makeTriangles(test::quad({ -20, 0, 20 }, { 20, 0, 20 }, { 20, 0, -20 }, { -20, 0, -20 }));
}

/** The GL renderer's matrices (Renderer.cpp), written out independently of the path tracer's camera. */
struct GlFraming {
    glm::mat4 view;
    glm::mat4 projection;
    glm::vec4 viewport;

    GlFraming(const render::Camera& camera, int width, int height)
        : view(glm::lookAt(camera.position, camera.lookAt, camera.up))
        , projection(
              glm::perspective(glm::radians(camera.fovYDeg), float(width) / float(height), 0.01f, 100.0f))
        , viewport(0.0f, 0.0f, float(width), float(height))
    {
    }

    /** Image position of a world point: x right, y down from the top edge, in pixels. */
    glm::vec2 toImage(const glm::vec3& world) const
    {
        const glm::vec3 window = glm::project(world, view, projection, viewport);
        return { window.x, viewport.w - window.y };
    }

    /** Unit direction through an image position (x right, y down). */
    glm::vec3 direction(const render::Camera& camera, const glm::vec2& image) const
    {
        const glm::vec3 onFar
            = glm::unProject(glm::vec3(image.x, viewport.w - image.y, 1.0f), view, projection, viewport);
        return glm::normalize(onFar - camera.position);
    }
};

render::RadianceImage renderReference(const render::Scene& scene, const render::Camera& camera, int width,
    int height, int spp, int maxBounces = 64)
{
    render::ReferenceSettings settings;
    settings.maxBounces = maxBounces;
    render::ReferenceRenderer renderer(scene, camera, width, height, settings);
    renderer.render(spp);
    return renderer.image();
}

glm::dvec3 mean(const render::RadianceImage& image)
{
    glm::dvec3 sum(0.0);
    for (const glm::vec3& p : image.pixels)
        sum += glm::dvec3(p);
    return sum / double(image.pixels.size());
}

} // namespace

void ReferenceAnalyticTest::whiteFurnace_data()
{
    QTest::addColumn<float>("albedo");
    QTest::addColumn<float>("emission");
    QTest::newRow("albedo 0.5") << 0.5f << 1.0f;
    QTest::newRow("albedo 0.8") << 0.8f << 0.6f;
}

// Inside a closed box whose walls all emit E and reflect albedo rho, radiance is the same everywhere and in
// every direction: L = E + rho L, so L = E / (1 - rho). Any energy lost or gained (a bad BSDF normalisation,
// a wrong MIS weight, biased Russian roulette, light leaking through edges) shows up as a different number.
void ReferenceAnalyticTest::whiteFurnace()
{
    QFETCH(float, albedo);
    QFETCH(float, emission);
    render::Material material;
    material.albedo = glm::vec3(albedo);
    material.emission = glm::vec3(emission);
    const render::Scene scene = closedBox(material);
    render::Camera camera;
    camera.position = { 0.1f, 0.05f, 0.2f };
    camera.lookAt = { 0.4f, -0.3f, -1.0f };
    camera.fovYDeg = 90.0f;
    const int spp = 1024;
    const render::RadianceImage image = renderReference(scene, camera, 16, 16, spp);
    const double expected = double(emission) / (1.0 - double(albedo));
    const glm::dvec3 average = mean(image);
    double worst = 0.0;
    for (const glm::vec3& p : image.pixels)
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(double(p[c]) / expected - 1.0));
    qInfo("furnace albedo %.1f: expected %.4f, image mean %.4f %.4f %.4f, worst pixel off by %.2f%% (%d spp)",
        double(albedo), expected, average.r, average.g, average.b, 100.0 * worst, spp);
    for (int c = 0; c < 3; ++c)
        QVERIFY2(std::abs(average[c] / expected - 1.0) < 0.01, qPrintable(QString::number(average[c])));
    // Single pixels are noisy: Russian roulette makes the path length random. The worst of the 256 pixels at
    // 1024 spp measured 4.5% (albedo 0.5) and 8.4% (albedo 0.8), about 3 standard deviations; 15% is about 5.
    // A per-pixel bias would shift the mean above; this catches single broken pixels (edges, corners).
    QVERIFY2(worst < 0.15, qPrintable(QString::number(worst)));
}

// One Lambert plane under a point light, direct light only: L = rho / pi * I / d^2 * cos(theta), averaged
// over each pixel's area (computed here on an 8 x 8 grid of rays framed with the GL matrices).
void ReferenceAnalyticTest::pointLightDirect()
{
    render::Scene scene;
    render::Material grey;
    grey.albedo = { 0.5f, 0.6f, 0.7f };
    scene.materials = { grey };
    scene.meshes = { floorPlane() };
    render::PointLight light;
    light.position = { 0.4f, 1.2f, -0.3f };
    light.intensity = { 2.0f, 3.0f, 4.0f };
    scene.pointLights = { light };
    render::Camera camera;
    camera.position = { 0.0f, 3.0f, 0.0f };
    camera.lookAt = { 0.0f, 0.0f, 0.0f };
    camera.up = { 0.0f, 0.0f, -1.0f };
    camera.fovYDeg = 60.0f;
    const int width = 64, height = 48;
    const render::RadianceImage image = renderReference(scene, camera, width, height, 1024, 1);

    const GlFraming framing(camera, width, height);
    double worst = 0.0;
    glm::dvec3 sumImage(0.0), sumExpected(0.0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            glm::dvec3 expected(0.0);
            constexpr int kGrid = 8;
            for (int j = 0; j < kGrid; ++j)
                for (int i = 0; i < kGrid; ++i) {
                    const glm::vec2 at(
                        float(x) + (float(i) + 0.5f) / kGrid, float(y) + (float(j) + 0.5f) / kGrid);
                    const glm::dvec3 dir(framing.direction(camera, at));
                    const glm::dvec3 hit
                        = glm::dvec3(camera.position) + dir * (-double(camera.position.y) / dir.y);
                    const glm::dvec3 toLight = glm::dvec3(light.position) - hit;
                    const double d2 = glm::dot(toLight, toLight);
                    const double cosTheta = toLight.y / std::sqrt(d2);
                    expected += glm::dvec3(grey.albedo) / kPi * glm::dvec3(light.intensity) * (cosTheta / d2);
                }
            expected /= double(kGrid * kGrid);
            const glm::dvec3 actual(image.at(x, y));
            sumImage += actual;
            sumExpected += expected;
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(actual[c] / expected[c] - 1.0));
        }
    const glm::dvec3 ratio = sumImage / sumExpected;
    qInfo("point light: image / analytic mean %.5f %.5f %.5f, worst pixel %.3f%%", ratio.r, ratio.g, ratio.b,
        100.0 * worst);
    for (int c = 0; c < 3; ++c)
        QVERIFY2(std::abs(ratio[c] - 1.0) < 0.002, qPrintable(QString::number(ratio[c])));
    // Only the pixel jitter is random here; the light's falloff varies by up to 5% across a pixel, which 1024
    // jittered samples average to within about 0.2% (measured worst pixel 0.3%).
    QVERIFY2(worst < 0.01, qPrintable(QString::number(worst)));
}

// A directional light's irradiance is the same on the whole plane: L = rho / pi * E * cos(theta), exactly.
void ReferenceAnalyticTest::directionalLightDirect()
{
    render::Scene scene;
    render::Material grey;
    grey.albedo = { 0.5f, 0.6f, 0.7f };
    scene.materials = { grey };
    scene.meshes = { floorPlane() };
    render::DirectionalLight sun;
    sun.direction = { 0.3f, -1.0f, 0.2f }; // travelling down: it lights the top of the floor
    sun.irradiance = { 1.5f, 1.0f, 0.5f };
    scene.directionalLights = { sun };
    render::Camera camera;
    camera.position = { 0.0f, 2.0f, 2.0f };
    camera.lookAt = { 0.0f, 0.0f, 0.0f };
    camera.fovYDeg = 30.0f;
    const render::RadianceImage image = renderReference(scene, camera, 16, 16, 4, 8);
    const double cosTheta = 1.0 / glm::length(glm::dvec3(sun.direction));
    const glm::dvec3 expected = glm::dvec3(grey.albedo) / kPi * glm::dvec3(sun.irradiance) * cosTheta;
    for (const glm::vec3& p : image.pixels)
        for (int c = 0; c < 3; ++c)
            QVERIFY2(std::abs(double(p[c]) / expected[c] - 1.0) < 1e-5,
                qPrintable(QString("%1 vs %2").arg(double(p[c])).arg(expected[c])));

    // Light travelling up reaches only the underside, which the camera does not see.
    scene.directionalLights.front().direction = -sun.direction;
    const render::RadianceImage dark = renderReference(scene, camera, 16, 16, 4, 8);
    QCOMPARE(mean(dark), glm::dvec3(0.0));
}

// An emitting rectangle facing the camera: pixels entirely inside its projection (by the GL matrices, with a
// non-square image) read exactly its radiance, pixels entirely outside read black. Off by a pixel, flipped or
// stretched framing fails here.
void ReferenceAnalyticTest::framingMatchesGlProjection()
{
    render::Scene scene;
    render::Material light;
    light.albedo = glm::vec3(0.0f);
    light.emission = { 3.0f, 2.0f, 1.0f };
    scene.materials = { light };
    const float x0 = 0.2f, x1 = 0.9f, y0 = -0.6f, y1 = -0.1f;
    scene.meshes
        = { test::makeTriangles(test::quad({ x0, y0, 0 }, { x1, y0, 0 }, { x1, y1, 0 }, { x0, y1, 0 })) };
    render::Camera camera; // the reference camera: (0, 0, 3.8) looking at the origin, 40 degrees
    const int width = 64, height = 40;
    const render::RadianceImage image = renderReference(scene, camera, width, height, 16);

    const GlFraming framing(camera, width, height);
    const glm::vec2 topLeft = framing.toImage({ x0, y1, 0.0f }),
                    bottomRight = framing.toImage({ x1, y0, 0.0f });
    int inside = 0, outside = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::vec3 p = image.at(x, y);
            constexpr float kMargin = 1e-3f; // pixels; GL's and the tracer's float rounding differ this much
            if (float(x) > topLeft.x + kMargin && float(x + 1) < bottomRight.x - kMargin
                && float(y) > topLeft.y + kMargin && float(y + 1) < bottomRight.y - kMargin) {
                ++inside;
                QVERIFY2(glm::length(p - light.emission) < 1e-5f,
                    qPrintable(QString("pixel %1,%2 inside: %3").arg(x).arg(y).arg(double(p.r))));
            } else if (float(x + 1) < topLeft.x - kMargin || float(x) > bottomRight.x + kMargin
                || float(y + 1) < topLeft.y - kMargin || float(y) > bottomRight.y + kMargin) {
                ++outside;
                QVERIFY2(p == glm::vec3(0.0f),
                    qPrintable(QString("pixel %1,%2 outside: %3").arg(x).arg(y).arg(double(p.r))));
            }
        }
    qInfo("rectangle spans x %.2f..%.2f, y %.2f..%.2f pixels; %d pixels inside, %d outside",
        double(topLeft.x), double(bottomRight.x), double(topLeft.y), double(bottomRight.y), inside, outside);
    QVERIFY(inside > 40);
    QVERIFY(outside > 1500);
}

// Emission leaves the front (counter-clockwise) face only; the back of an emitter shows its albedo, and with
// nothing else in the scene that is black.
void ReferenceAnalyticTest::emitterBackFaceIsDark()
{
    render::Scene scene;
    render::Material light;
    light.emission = { 3.0f, 2.0f, 1.0f };
    scene.materials = { light };
    // Clockwise seen from the camera at +z: the front faces away.
    scene.meshes
        = { test::makeTriangles(test::quad({ -1, -1, 0 }, { -1, 1, 0 }, { 1, 1, 0 }, { 1, -1, 0 })) };
    render::Camera camera;
    const render::RadianceImage back = renderReference(scene, camera, 16, 16, 4);
    QCOMPARE(mean(back), glm::dvec3(0.0));
    scene.meshes
        = { test::makeTriangles(test::quad({ -1, -1, 0 }, { 1, -1, 0 }, { 1, 1, 0 }, { -1, 1, 0 })) };
    const render::RadianceImage front = renderReference(scene, camera, 16, 16, 4);
    QVERIFY(mean(front).r > 1.0);
}

// With no reflections allowed the Cornell box shows its emitters alone, at exactly their radiance.
void ReferenceAnalyticTest::zeroBouncesShowsEmittersOnly()
{
    render::Scene scene;
    QString error;
    QVERIFY2(doc::SceneLoader::load(QStringLiteral("builtin:cornell"), scene, &error), qPrintable(error));
    const render::RadianceImage image = renderReference(scene, scene.camera, 64, 64, 4, 0);
    const glm::vec3 ceilingLight(17.0f, 12.0f, 4.0f);
    int lightPixels = 0, blackPixels = 0;
    for (const glm::vec3& p : image.pixels) {
        lightPixels += p == ceilingLight ? 1 : 0;
        blackPixels += p == glm::vec3(0.0f) ? 1 : 0;
    }
    qInfo("max bounces 0: %d pixels show the ceiling light, %d are black", lightPixels, blackPixels);
    QVERIFY(lightPixels > 4);
    QVERIFY(blackPixels > 64 * 64 * 3 / 4); // everything but the light and the emissive block
}

// Importance sampling is unbiased only if sample() draws directions with the density pdf() reports. Integrate
// the reflectance f cos over the hemisphere twice, by uniform directions and by the BSDF's own samples: the
// two must agree, and the density must integrate to (at most) one.
void ReferenceAnalyticTest::phongSamplingMatchesItsDensity()
{
    const glm::vec3 normal(0.0f, 0.0f, 1.0f);
    const glm::vec3 toViewer = glm::normalize(glm::vec3(std::sin(0.6f), 0.0f, std::cos(0.6f)));
    const render::PhongBsdf bsdf(glm::vec3(0.3f), glm::vec3(0.5f), 20.0f, normal, toViewer);
    render::Pcg32 random(1, 2);
    constexpr int kSamples = 1 << 20;
    double uniformReflectance = 0.0, uniformDensity = 0.0, sampledReflectance = 0.0;
    for (int i = 0; i < kSamples; ++i) {
        // Uniform on the hemisphere: density 1 / (2 pi).
        const float z = random.nextFloat(), phi = 2.0f * float(kPi) * random.nextFloat();
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const glm::vec3 uniform(r * std::cos(phi), r * std::sin(phi), z);
        uniformReflectance += double(bsdf.evaluate(uniform).r * z) * 2.0 * kPi;
        uniformDensity += double(bsdf.pdf(uniform)) * 2.0 * kPi;
        const glm::vec3 sampled = bsdf.sample(random.nextFloat(), { random.nextFloat(), random.nextFloat() });
        const float pdf = bsdf.pdf(sampled);
        if (sampled.z > 0.0f && pdf > 0.0f)
            sampledReflectance += double(bsdf.evaluate(sampled).r * sampled.z / pdf);
    }
    uniformReflectance /= kSamples;
    uniformDensity /= kSamples;
    sampledReflectance /= kSamples;
    qInfo("Phong reflectance %.4f by uniform directions, %.4f by BSDF samples; density integrates to %.4f",
        uniformReflectance, sampledReflectance, uniformDensity);
    QVERIFY2(std::abs(sampledReflectance / uniformReflectance - 1.0) < 0.01,
        qPrintable(QString::number(sampledReflectance)));
    QVERIFY(uniformDensity > 0.9 && uniformDensity < 1.01); // some of the Phong lobe dips below the horizon
    QVERIFY(
        uniformReflectance > 0.5 && uniformReflectance <= 0.8); // albedo + specular, less what grazes away
}

QTEST_GUILESS_MAIN(ReferenceAnalyticTest)
#include "tst_ReferenceAnalytic.moc"
