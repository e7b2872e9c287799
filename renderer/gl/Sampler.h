#pragma once

#include "gl/Handle.h"

namespace vct::gl {

void deleteSampler(GLuint id);

/**
 * A sampler object: filtering and comparison state that overrides a texture's own on the unit it is bound to.
 * It lets one texture be read two ways at once, as the shadow maps are: by comparison for visibility and as
 * plain depth for the soft shadows' blocker search.
 */
class Sampler {
public:
    Sampler() = default;
    /** Nearest-texel reads of raw depth, no comparison, clamped to the edge. */
    static Sampler createRawDepth();

    GLuint id() const { return m_handle.id(); }
    explicit operator bool() const { return bool(m_handle); }
    void bindUnit(GLuint unit) const { glBindSampler(unit, id()); }

private:
    Handle<deleteSampler> m_handle;
};

} // namespace vct::gl
