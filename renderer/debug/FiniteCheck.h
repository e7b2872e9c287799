#pragma once

#include "core/NonFiniteCount.h"
#include "core/ResourceTable.h"
#include "core/ShaderLibrary.h"
#include "gl/Buffer.h"

#include <cstdint>
#include <string>
#include <vector>

namespace vct::render {

/**
 * Counts non-finite values on the GPU in every float render target and every level of every float voxel
 * texture, with one small readback per resource. For tests, `vct-render --check-finite` and the editor's
 * overlay; never part of the frame loop.
 */
class FiniteCheck {
public:
    /** Counts in every float texture of @p resources: per-pixel targets, voxel textures, passes' own data. */
    std::vector<NonFiniteCount> run(const ShaderLibrary& shaders, const ResourceTable& resources);

private:
    std::uint64_t count(const gl::Texture& texture, int level);
    const gl::Program* m_flat = nullptr;
    const gl::Program* m_volume = nullptr;
    gl::Buffer m_counter;
};

} // namespace vct::render
