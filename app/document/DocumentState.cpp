#include "DocumentState.h"

#include <algorithm>

namespace vct::doc {

bool sameMaterial(const render::Material& a, const render::Material& b)
{
    return a.name == b.name && a.albedo == b.albedo && a.emission == b.emission && a.specular == b.specular
        && a.shininess == b.shininess && a.albedoTexture == b.albedoTexture && a.doubleSided == b.doubleSided;
}

bool sameCamera(const render::Camera& a, const render::Camera& b)
{
    return a.position == b.position && a.lookAt == b.lookAt && a.up == b.up && a.fovYDeg == b.fovYDeg
        && a.nearPlane == b.nearPlane;
}

bool sameSettings(const render::RenderSettings& a, const render::RenderSettings& b)
{
    // By the printed rows: exactly what a project file keeps.
    return a.describe() == b.describe();
}

bool sameDocument(const DocumentState& a, const DocumentState& b)
{
    return a.sources == b.sources && a.nodes == b.nodes && a.lights == b.lights && a.nextId == b.nextId
        && std::equal(
            a.materials.begin(), a.materials.end(), b.materials.begin(), b.materials.end(), sameMaterial)
        && sameCamera(a.camera, b.camera) && sameSettings(a.settings, b.settings)
        && std::equal(a.bookmarks.begin(), a.bookmarks.end(), b.bookmarks.begin(), b.bookmarks.end(),
            [](const CameraBookmark& x, const CameraBookmark& y) {
                return x.name == y.name && sameCamera(x.camera, y.camera);
            });
}

} // namespace vct::doc
