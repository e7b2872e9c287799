#pragma once

#include "core/ConeSet.h"
#include "core/FrameResources.h"
#include "core/FrameShape.h"
#include "core/GpuScene.h"
#include "core/ResourceTable.h"
#include "core/ShaderLibrary.h"
#include "scene/Camera.h"
#include "scene/RenderSettings.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <cstdint>
#include <vector>

namespace vct::render {

class ConeSampleCounter;

/**
 * Counters that grow when something a pass depends on changes. A pass remembers the values it last ran
 * with, so "can I reuse my output?" is an exact comparison rather than a guess. Settings have no counter:
 * each pass's key holds the settings it reads.
 */
struct ChangeVersions {
    std::uint64_t staticGeometry = 1; ///< Static meshes, their materials, or the grid.
    std::uint64_t dynamicGeometry = 1;
    std::uint64_t staticMaterials = 0; ///< Albedo/emission of a material a static mesh uses: voxels only.
    std::uint64_t dynamicMaterials = 0; ///< The same for dynamic meshes.

    /** What the static and the dynamic voxel layers depend on; each grows whenever one of its parts does. */
    std::uint64_t staticVoxels() const { return staticGeometry + staticMaterials; }
    std::uint64_t dynamicVoxels() const { return dynamicGeometry + dynamicMaterials; }
    std::uint64_t lightPlacement = 1; ///< Light count, positions, directions, shadow flags: shadow maps.
    std::uint64_t lightValues = 1; ///< Anything about lights, intensities included: injection.
};

/** Everything a pass may read or write during one frame. */
struct FrameContext {
    const ShaderLibrary& shaders;
    GpuScene& scene;
    const RenderSettings& settings;
    const ChangeVersions& versions;
    VoxelVolume& voxels;
    ShadowMaps& shadows;
    ScreenTargets& screen;
    const ConeSet& diffuseCones;
    /// World bounds of the static meshes whose material changed since the last frame (their voxels only).
    Aabb staticMaterialEdits;
    Camera camera;
    glm::mat4 view { 1.0f };
    glm::mat4 projection { 1.0f };
    /// Full-resolution pixel (x, y, 1) to the world-space ray through it whose component along the camera's
    /// forward axis is 1: a surface at view depth z is camera.position + pixelToRay * (x, y, 1) * z
    /// (shaders/common/GBufferSurface.glsl).
    glm::mat3 pixelToRay { 1.0f };
    /// Set only while vct-bench perf counts the cone pass's 3D texture fetches (an untimed shader variant).
    ConeSampleCounter* coneSampleCounter = nullptr;
    /// At most this many bounce iterations a frame (Renderer::setBounceIterationsPerFrame); 0 = all of them.
    int bounceIterationsPerFrame = 0;
    /// What the frame calls for, decided once before the passes plan (FrameShape::of).
    FrameShape shape;
    /// Every texture made so far, by name (core/ResourceNames.h): how a pass reads what another keeps as its
    /// own member rather than in VoxelVolume or ScreenTargets.
    const ResourceTable* resources = nullptr;
    /// The grid fitted around the scene: `voxels.frame` for a dense grid, the coarsest level of a clipmap
    /// (core/ClipmapLayout), from which each level follows the camera.
    VoxelGridFrame sceneGrid;
    /// A clipmap's levels coarser than `voxels`, finest first (core/ClipLevelPass): where cones that leave
    /// `voxels` go on tracing. Empty for a dense grid.
    std::vector<const VoxelVolume*> coarserLevels;
    /// The space no light can leave (EnclosurePass fills it, the diffuse gathers read it); null in contexts
    /// without one, where gathers scale nothing.
    EnclosureMap* enclosure = nullptr;
    /// Passes that time their phases (core/PhaseTimes) report them (Renderer::setPhaseTimes).
    bool phaseTimes = false;
};

} // namespace vct::render
