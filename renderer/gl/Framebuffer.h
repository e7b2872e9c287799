#pragma once

#include "gl/Handle.h"
#include "gl/Texture.h"

#include <cstdint>
#include <initializer_list>
#include <vector>

namespace vct::gl {

void deleteFramebuffer(GLuint id);

/** A framebuffer object; attachments are textures owned elsewhere. */
class Framebuffer {
public:
    static Framebuffer create();
    /** A framebuffer with no attachments whose size is given (used by voxelization). */
    static Framebuffer createEmpty(int width, int height);

    GLuint id() const { return m_handle.id(); }
    explicit operator bool() const { return bool(m_handle); }
    void attachColor(int index, const Texture& texture, int level = 0);
    void attachColorLayer(int index, const Texture& texture, int layer);
    /** Depth, or depth and stencil for a depth-stencil format. */
    void attachDepth(const Texture& texture, int level = 0);
    void attachDepthLayer(const Texture& texture, int layer);
    /** Enables draw buffers 0..count-1 and throws std::runtime_error if incomplete. */
    void finish(int colorCount);
    /** Draws only into the listed color attachments (by index), the others set to GL_NONE. */
    void drawTo(std::initializer_list<int> colors);
    void bind() const;
    /**
     * Makes this the framebuffer of @p colors (attachments 0, 1, ...) and @p depth (may be null), all drawn
     * to; made anew only when they are not the textures attached last, so a pass can call it every frame and
     * follow what the pipeline reallocated (Texture::serial).
     */
    void follow(std::initializer_list<const Texture*> colors, const Texture* depth);

private:
    Handle<deleteFramebuffer> m_handle;
    std::vector<std::uint64_t> m_followed; ///< serials of the textures follow() attached, depth last
};

} // namespace vct::gl
