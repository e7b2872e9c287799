#pragma once

#include "Renderer.h"
#include "context/HeadlessContext.h"

#include <memory>

namespace vct::test {

/**
 * A headless GL context and a renderer on it, for GL tests. Creation failure is a test failure with the
 * reason (never a skip): CI must notice a machine without GL.
 */
struct GlTestContext {
    std::unique_ptr<render::HeadlessContext> context;
    std::unique_ptr<render::Renderer> renderer;
    std::string error;

    /** Creates both; on failure `renderer` is null and `error` says why. */
    static GlTestContext create(const std::string& backend = "egl");
};

} // namespace vct::test
