#pragma once

#include "image/RadianceImage.h"
#include "reference/ReferenceSettings.h"
#include "scene/Camera.h"
#include "scene/Scene.h"

namespace vct::ui {

/**
 * Everything a reference comparison needs, copied from the document when it starts: the job works on this
 * snapshot, so later edits cannot race with it (they only make its result stale).
 */
struct ReferenceRequest {
    render::Scene scene;
    render::Camera camera;
    /** The cone-traced image of the same view at the comparison size; its size is the reference's size. */
    render::RadianceImage vctImage;
    /** Samples per pixel to stop at (>= 1). */
    int targetSpp = 256;
    /**
     * Samples per pixel of the first pass; each later pass doubles the total (4, 8, 16, ...), so the view
     * refreshes often early on, when the image changes most, and the refresh cost stays a small share later.
     */
    int firstPassSpp = 4;
    /** Linear multiplier of the display tone mapping, which SSIM is computed on. */
    float exposure = 1.0f;
    render::ReferenceSettings settings;
};

} // namespace vct::ui
