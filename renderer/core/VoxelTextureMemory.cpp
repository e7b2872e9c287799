#include "core/VoxelTextureMemory.h"

#include "core/ResourceTable.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace vct::render {

namespace {

std::string formatName(GLenum format)
{
    switch (format) {
    case GL_RGBA16F:
        return "rgba16f";
    case GL_RGBA8:
        return "rgba8";
    case GL_RGBA8_SNORM:
        return "rgba8 snorm";
    case GL_R11F_G11F_B10F:
        return "r11f g11f b10f";
    case GL_R32F:
        return "r32f";
    case GL_R32UI:
        return "r32ui";
    case GL_R8:
        return "r8";
    case GL_RGBA32F:
        return "rgba32f";
    default: {
        char hex[32];
        std::snprintf(hex, sizeof hex, "format 0x%04x", unsigned(format));
        return hex;
    }
    }
}

std::size_t glReportedBytes(const gl::Texture& texture)
{
    std::size_t total = 0;
    for (int level = 0; level < texture.levels(); ++level) {
        GLint width = 0, height = 0, depth = 0, bits = 0;
        glGetTextureLevelParameteriv(texture.id(), level, GL_TEXTURE_WIDTH, &width);
        glGetTextureLevelParameteriv(texture.id(), level, GL_TEXTURE_HEIGHT, &height);
        glGetTextureLevelParameteriv(texture.id(), level, GL_TEXTURE_DEPTH, &depth);
        for (const GLenum component :
            { GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE, GL_TEXTURE_ALPHA_SIZE,
                GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_STENCIL_SIZE, GL_TEXTURE_SHARED_SIZE }) {
            GLint size = 0;
            glGetTextureLevelParameteriv(texture.id(), level, component, &size);
            bits += size;
        }
        total += std::size_t(width) * std::size_t(height) * std::size_t(depth) * std::size_t(bits) / 8;
    }
    return total;
}

VoxelTextureMemory describe(const std::string& name, const gl::Texture& texture)
{
    VoxelTextureMemory memory { name, formatName(texture.format()), texture.width(), texture.height(),
        texture.depth(), {} };
    // The same halving as gl::Texture::byteSize, kept per level.
    int w = texture.width(), h = texture.height(), d = texture.depth();
    for (int level = 0; level < texture.levels(); ++level) {
        memory.levelBytes.push_back(
            std::size_t(w) * std::size_t(h) * std::size_t(d) * gl::bytesPerTexel(texture.format()));
        w = std::max(1, w / 2);
        h = std::max(1, h / 2);
        d = std::max(1, d / 2);
    }
    memory.glBytes = glReportedBytes(texture);
    return memory;
}

} // namespace

std::size_t VoxelTextureMemory::totalBytes() const
{
    return std::accumulate(levelBytes.begin(), levelBytes.end(), std::size_t(0));
}

std::vector<VoxelTextureMemory> describeVoxelMemory(const ResourceTable& resources)
{
    std::vector<VoxelTextureMemory> list;
    for (const ResourceTable::Entry& entry : resources.entries())
        if (entry.group == ResourceGroup::Voxels && *entry.texture)
            list.push_back(describe(entry.name, *entry.texture));
    return list;
}

} // namespace vct::render
