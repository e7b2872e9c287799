#include "TestSupport.h"

#include "GlTestContext.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcessEnvironment>

namespace vct::test {
namespace {

QString env(const char* name, const QString& fallback)
{
    const QString value = QProcessEnvironment::systemEnvironment().value(QString::fromLatin1(name));
    return value.isEmpty() ? fallback : value;
}

} // namespace

QString sourceDir()
{
    return env("VCT_SOURCE_DIR", QDir::currentPath());
}

QString referenceDir()
{
    return env("VCT_REFERENCE_DIR", sourceDir() + QStringLiteral("/tests/data/reference"));
}

QString outputDir()
{
    const QString dir = env("VCT_TEST_OUTPUT_DIR", QDir::tempPath() + QStringLiteral("/vct-test-output"));
    QDir().mkpath(dir);
    return dir;
}

GlTestContext GlTestContext::create(const std::string& backend)
{
    GlTestContext result;
    result.context = render::HeadlessContext::create(backend, result.error);
    if (!result.context)
        return result;
    try {
        result.renderer = std::make_unique<render::Renderer>(result.context->procAddressFunction());
    } catch (const std::exception& e) {
        result.error = e.what();
    }
    return result;
}

render::Scene floorAndDynamicPlate()
{
    render::Scene s;
    s.materials.push_back({});
    s.meshes.push_back(
        makeTriangles(quad({ 1, 0.5f, 15 }, { 15, 0.5f, 15 }, { 15, 0.5f, 1 }, { 1, 0.5f, 1 })));
    render::Mesh plate = makeTriangles(
        quad({ 3.2f, 4.5f, 4.8f }, { 4.8f, 4.5f, 4.8f }, { 4.8f, 4.5f, 3.2f }, { 3.2f, 4.5f, 3.2f }));
    plate.dynamic = true;
    s.meshes.push_back(plate);
    s.pointLights.push_back({ { 8, 12, 8 }, glm::vec3(50.0f), true });
    return s;
}

render::Mesh makeTriangles(const std::vector<glm::vec3>& positions, int material)
{
    render::Mesh mesh;
    mesh.positions = positions;
    mesh.material = material;
    for (std::size_t i = 0; i + 2 < positions.size(); i += 3) {
        const glm::vec3 n
            = glm::normalize(glm::cross(positions[i + 1] - positions[i], positions[i + 2] - positions[i]));
        for (int k = 0; k < 3; ++k) {
            mesh.normals.push_back(n);
            mesh.indices.push_back(std::uint32_t(i + std::size_t(k)));
        }
    }
    return mesh;
}

std::vector<glm::vec3> quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d)
{
    return { a, b, c, a, c, d };
}

render::Aabb box(glm::vec3 lo, glm::vec3 hi)
{
    render::Aabb b;
    b.extend(lo);
    b.extend(hi);
    return b;
}

glm::ivec2 pixelOf(const render::Camera& camera, glm::vec3 world, int size)
{
    const glm::mat4 view = glm::lookAt(camera.position, camera.lookAt, camera.up);
    // Near and far planes do not move a point across the screen: any pair projects the same.
    const glm::mat4 projection = glm::perspective(glm::radians(camera.fovYDeg), 1.0f, 0.01f, 100.0f);
    const glm::vec3 p = glm::project(world, view, projection, glm::vec4(0, 0, size, size));
    return { int(p.x), size - 1 - int(p.y) };
}

glm::vec3 floorPointOf(const render::Camera& camera, glm::ivec2 pixel, int size, float height)
{
    const glm::vec3 forward = glm::normalize(camera.lookAt - camera.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(right, forward);
    const float t = std::tan(glm::radians(camera.fovYDeg) * 0.5f);
    const float nx = 2.0f * (float(pixel.x) + 0.5f) / float(size) - 1.0f;
    const float ny = 1.0f - 2.0f * (float(pixel.y) + 0.5f) / float(size);
    const glm::vec3 dir = glm::normalize(forward + right * (nx * t) + up * (ny * t));
    return camera.position + dir * ((height - camera.position.y) / dir.y);
}

double floorIrradianceFromOverheadLight(const glm::dvec3& p, double height, double radiance, bool disk)
{
    constexpr int n = 600;
    double sum = 0.0;
    const double cell = 1.0 / n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const glm::dvec3 q(-0.5 + (i + 0.5) * cell, height, -0.5 + (j + 0.5) * cell);
            if (disk && q.x * q.x + q.z * q.z > 0.25)
                continue;
            const glm::dvec3 d = q - p;
            const double r2 = glm::dot(d, d);
            const double cosFloor = d.y / std::sqrt(r2);
            sum += cosFloor * cosFloor / r2 * cell * cell; // cos at the light equals cos at the floor here
        }
    return radiance * sum;
}

double meanAround(const render::RadianceImage& image, glm::ivec2 pixel)
{
    double sum = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            sum += image.at(pixel.x + dx, pixel.y + dy).r / 9.0;
    return sum;
}

double meanRed(const render::RadianceImage& image)
{
    double sum = 0.0;
    for (const glm::vec3& p : image.pixels)
        sum += p.r;
    return image.pixels.empty() ? 0.0 : sum / double(image.pixels.size());
}

QString describe(const glm::vec3& v)
{
    return QStringLiteral("(%1, %2, %3)").arg(double(v.x)).arg(double(v.y)).arg(double(v.z));
}

QString writeFile(const QString& path, const QByteArray& bytes)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(bytes) != bytes.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

} // namespace vct::test
