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
    /**
     * Trilinear reads within the mip level nearest the one asked for, outside the texture zero, as the voxel
     * volumes' own border: a cone's sample then reads one level where a blend of two read two.
     */
    static Sampler createNearestLevel();

    GLuint id() const { return m_handle.id(); }
    explicit operator bool() const { return bool(m_handle); }
    void bindUnit(GLuint unit) const { glBindSampler(unit, id()); }

private:
    static Sampler create(GLenum minFilter, GLenum magFilter, GLenum wrap);

    Handle<deleteSampler> m_handle;
};

} // namespace vct::gl
