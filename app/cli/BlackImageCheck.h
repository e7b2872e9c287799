#pragma once

#include "image/RadianceImage.h"
#include "scene/Camera.h"
#include "scene/Scene.h"

#include <string>

namespace vct::cli {

/**
 * Why an image came out entirely black, when the scene says it should not have: an empty string when some
 * pixel is lit or the scene has nothing to light it with. A render that writes black and exits 0 hides a lost
 * camera or geometry; vct-render prints this as a warning.
 */
std::string blackImageWarning(
    const render::RadianceImage& image, const render::Scene& scene, const render::Camera& camera);

} // namespace vct::cli
