#include "BuiltinScenes.h"

#include "AtriumGenerator.h"
#include "CameraFile.h"
#include "LightsFile.h"
#include "MeshBuilder.h"
#include "import/ModelImporter.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace vct::doc {

namespace {

const QString kCornellModel = QStringLiteral(":/scenes/cornell/cornell.obj");
const QString kCornellPointModel = QStringLiteral(":/scenes/cornell/cornell_point.obj");
const QString kCornellCamera = QStringLiteral(":/scenes/cornell/cornell.camera.json");
const QString kCornellPointLights = QStringLiteral(":/scenes/cornell/cornell_point.lights.json");
const QString kBunnyModel = QStringLiteral(":/scenes/bunny/bunny.obj");

const glm::vec3 kBunnyAlbedo(0.7f);
// The bunny model looks along -x; turning it 50 degrees shows a three-quarter view to a camera looking along
// +x.
constexpr float kBunnyYawDeg = 50.0f;

bool loadCornell(const QString& model, const QString& lights, render::Scene& scene, QString* error)
{
    if (!ModelImporter::importModel(model, scene, error))
        return false;
    if (!lights.isEmpty() && !LightsFile::read(lights, scene, error))
        return false;
    CameraSetup setup;
    if (!CameraFile::read(kCornellCamera, setup, error))
        return false;
    scene.camera = setup.camera;
    return true;
}

/** Imports the bunny as a grey dynamic mesh, kBunnyHeight tall, its feet at `foot` (lowest point, centred).
 */
bool addBunny(render::Scene& scene, const glm::vec3& foot, QString* error)
{
    const size_t firstMesh = scene.meshes.size();
    const size_t firstMaterial = scene.materials.size();
    if (!ModelImporter::importModel(kBunnyModel, scene, error))
        return false;

    render::Aabb bounds;
    for (size_t i = firstMesh; i < scene.meshes.size(); ++i)
        for (const glm::vec3& p : scene.meshes[i].positions)
            bounds.extend(glm::vec3(scene.meshes[i].transform * glm::vec4(p, 1.0f)));
    const float scale = BuiltinScenes::kBunnyHeight / bounds.size().y;
    const glm::vec3 anchor(bounds.center().x, bounds.min.y, bounds.center().z);
    glm::mat4 placement = glm::translate(glm::mat4(1.0f), foot);
    placement = glm::rotate(placement, glm::radians(kBunnyYawDeg), glm::vec3(0.0f, 1.0f, 0.0f));
    placement = glm::scale(placement, glm::vec3(scale));
    placement = glm::translate(placement, -anchor);

    for (size_t i = firstMesh; i < scene.meshes.size(); ++i) {
        scene.meshes[i].transform = placement * scene.meshes[i].transform;
        scene.meshes[i].dynamic = true;
        scene.meshes[i].name = "bunny";
    }
    for (size_t i = firstMaterial; i < scene.materials.size(); ++i) {
        render::Material& material = scene.materials[i];
        material = render::Material {};
        material.name = "bunny";
        material.albedo = kBunnyAlbedo;
    }
    return true;
}

bool loadAtrium(render::Scene& scene, QString* error)
{
    AtriumGenerator::generate(scene);
    if (!addBunny(scene, { -6.0f, AtriumGenerator::kFloorY, 1.5f }, error))
        return false;

    // Warm light in the middle of the open courtyard. The floor straight below (albedo ~0.5, 6.5 m away)
    // reads albedo/pi * I/d^2 ~ (1.0, 0.8, 0.55) W/(m^2 sr).
    render::PointLight light;
    light.position = { 0.0f, 6.5f, 0.0f };
    light.intensity = { 250.0f, 215.0f, 165.0f };
    light.castsShadows = true;
    scene.pointLights.push_back(light);

    // Eye height near one end, looking down the long axis past the bunny, between the arcades and their
    // cloths.
    scene.camera.position = { -13.0f, 1.7f, 1.2f };
    scene.camera.lookAt = { 0.0f, 3.2f, -0.3f };
    scene.camera.up = { 0.0f, 1.0f, 0.0f };
    scene.camera.fovYDeg = 60.0f;
    scene.camera.nearPlane = 0.05f;
    return true;
}

bool loadBunny(render::Scene& scene, QString* error)
{
    render::Material floorMaterial;
    floorMaterial.name = "floor";
    floorMaterial.albedo = { 0.6f, 0.58f, 0.55f };
    scene.materials.push_back(floorMaterial);
    MeshBuilder floor;
    constexpr float kHalf = 3.0f;
    floor.addGrid(
        { -kHalf, 0.0f, -kHalf }, { 0.0f, 0.0f, 2.0f * kHalf }, { 2.0f * kHalf, 0.0f, 0.0f }, 12, 12);
    scene.meshes.push_back(floor.build("floor", int(scene.materials.size()) - 1));

    if (!addBunny(scene, glm::vec3(0.0f), error))
        return false;

    // The floor under the light (albedo 0.6, 2.6 m) reads about 0.6/pi * 25/2.6^2 ~ 0.7 W/(m^2 sr).
    render::PointLight light;
    light.position = { 1.0f, 2.6f, 1.2f };
    light.intensity = glm::vec3(25.0f);
    scene.pointLights.push_back(light);

    scene.camera.position = { 0.0f, 1.1f, 3.6f };
    scene.camera.lookAt = { 0.0f, 0.55f, 0.0f };
    scene.camera.up = { 0.0f, 1.0f, 0.0f };
    scene.camera.fovYDeg = 40.0f;
    return true;
}

} // namespace

QStringList BuiltinScenes::names()
{
    return { QStringLiteral("atrium"), QStringLiteral("bunny"), QStringLiteral("cornell"),
        QStringLiteral("cornell_point"), QStringLiteral("default") };
}

bool BuiltinScenes::load(const QString& name, render::Scene& scene, QString* error)
{
    render::Scene result;
    QString message;
    bool ok = false;
    if (name == QLatin1String("cornell"))
        ok = loadCornell(kCornellModel, QString(), result, &message);
    else if (name == QLatin1String("cornell_point"))
        ok = loadCornell(kCornellPointModel, kCornellPointLights, result, &message);
    else if (name == QLatin1String("atrium") || name == QLatin1String("default"))
        ok = loadAtrium(result, &message);
    else if (name == QLatin1String("bunny"))
        ok = loadBunny(result, &message);
    else
        message = QStringLiteral("unknown built-in scene \"%1\"; known scenes: %2")
                      .arg(name, names().join(QStringLiteral(", ")));

    if (!ok) {
        if (error)
            *error = QStringLiteral("builtin:%1: %2").arg(name, message);
        return false;
    }
    scene = std::move(result);
    return true;
}

} // namespace vct::doc
