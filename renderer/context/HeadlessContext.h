#pragma once

#include "gl/GlLoader.h"

#include <memory>
#include <string>

namespace vct::render {

/** A GL 4.5 core context with no window; the renderer draws into its own framebuffers. */
class HeadlessContext {
public:
    virtual ~HeadlessContext() = default;
    virtual void makeCurrent() = 0;
    virtual gl::ProcAddressFunction procAddressFunction() const = 0;
    virtual std::string backendName() const = 0;
    /** Backend, GL_VERSION and GL_RENDERER, for logs and --stats. */
    std::string description() const { return backendName() + ", " + m_glInfo; }

    /**
     * Creates a context with backend "egl" (surfaceless, default) or "osmesa", makes it current and loads GL
     * through glad. On failure returns null and sets error to a message naming what was tried.
     */
    static std::unique_ptr<HeadlessContext> create(const std::string& backend, std::string& error);
    /**
     * The command lines' choice: @p backend when the user named one (@p chosen), else EGL with OSMesa as the
     * second choice, since a machine without EGL's surfaceless platform may still have OSMesa. The error then
     * names both attempts.
     */
    static std::unique_ptr<HeadlessContext> createPreferring(
        const std::string& backend, bool chosen, std::string& error);

private:
    std::string m_glInfo;
};

} // namespace vct::render
