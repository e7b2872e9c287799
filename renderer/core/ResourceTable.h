#pragma once

#include "gl/Texture.h"
#include "gl/TextureDesc.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vct::render {

/** What a texture of the frame belongs to: memory accounting and the NaN check go group by group. */
enum class ResourceGroup {
    Voxels, ///< the voxel grid: counted as voxel memory
    Shadows,
    Screen, ///< per pixel, sized by the output
    PassState, ///< a pass's own working data
};

/** A texture a pass makes: its name in the table, where it lives, and what this frame needs of it. */
struct TextureSlot {
    const char* name; ///< one of core/ResourceNames.h
    ResourceGroup group;
    gl::Texture* texture;
    gl::TextureDesc desc; ///< empty: not needed this frame, so freed
};

/**
 * Every texture the passes make, by name: the pipeline makes each what its pass asks for this frame
 * (allocating, resizing, freeing), and tools loop over it (memory tables, the NaN check, voxel readback).
 * The textures themselves stay where the passes read them (VoxelVolume, ShadowMaps, ScreenTargets, a pass's
 * members); the table holds where they are and who makes them.
 */
class ResourceTable {
public:
    struct Entry {
        std::string name;
        std::string owner; ///< the pass (or tool) that makes it
        ResourceGroup group;
        gl::Texture* texture;
    };

    /**
     * Makes every slot's texture what its description says, registering the slots under @p owner on first
     * sight. Returns whether one was made anew, so the owner must redo its content (freeing loses
     * nothing still needed; a texture zeroed when made where there was none holds what it should). Throws
     * std::logic_error when another owner already registered the name, or the owner moves a slot.
     */
    bool apply(const std::string& owner, const std::vector<TextureSlot>& slots);
    const std::vector<Entry>& entries() const { return m_entries; }
    /** The texture registered under @p name, or null. */
    const gl::Texture* find(std::string_view name) const;
    /** Bytes of the allocated textures of @p group (from their descriptions, no GL query). */
    std::uint64_t byteSize(ResourceGroup group) const;

private:
    std::vector<Entry> m_entries;
};

} // namespace vct::render
