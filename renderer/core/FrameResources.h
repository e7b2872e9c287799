#pragma once

#include "common/DirectionalStack.glsl"
#include "core/BrickPool.h"
#include "core/EnclosureMap.h"
#include "core/OccupiedCellList.h"
#include "core/ResourceTable.h"
#include "core/VoxelGridFrame.h"
#include "core/VoxelRegion.h"
#include "gl/Framebuffer.h"
#include "gl/Sampler.h"
#include "gl/Texture.h"
#include "scene/Aabb.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace vct::render {

/** Tiles of VoxelVolume::directional: one per direction a cone can travel along an axis. */
constexpr int kDirectionalTiles = STACK_TILES;

/** How far the bounce iteration (passes/VoxelBouncePass) has come for the current first-bounce radiance. */
struct BounceProgress {
    int iterations = 0;
    /// Relative change of the voxels' radiance in the last iteration; once extrapolated, the estimated
    /// relative error of the extrapolated light instead.
    double residual = 0.0;
    bool converged = true; ///< false while iterations are still to come (spread over frames)
    bool extrapolated = false; ///< the iterations' geometric tail was added (VoxelBouncePass)
    /// A converging solve ended at its iteration limit with more change still to come than the tolerance
    /// allows (a closed room of albedo near 1): `converged` only says no more iterations will run.
    bool stoppedAtLimit = false;
};

/** The voxel grid's textures. Level 0 of `radiance` is written by injection, the rest by the mip pass. */
struct VoxelVolume {
    VoxelGridFrame frame;
    /// voxel_mode=sparse: level 0 of albedo, normal, emission, radiance and bounced keeps only the bricks in
    /// `bricks`, in pools of poolBricks bricks (common/VoxelBricks.glsl); brickTable (r32ui, a texel per
    /// brick) names where each one is, and is bound at BRICK_TABLE_UNIT for every pass.
    bool sparse = false;
    BrickPool bricks = BrickPool(0);
    glm::ivec3 poolBricks { 0 };
    gl::Texture brickTable;
    bool brickTableStale = false; ///< `bricks` gained bricks the table does not show yet
    /// Grows when every brick was allocated again, in another order: light kept from before is in the wrong
    /// places (a moving object's new bricks keep the layout).
    std::uint64_t brickLayout = 0;
    /** Level 0 of one of the grid's voxel textures: the grid itself, or its brick pool when sparse (which
     * keeps no levels above: sparse grids need anisotropic mips). */
    gl::TextureDesc level0(GLenum format, int levels = 1) const
    {
        if (!sparse)
            return gl::TextureDesc::volume(format, frame.resolution, levels);
        const glm::ivec3 texels = poolBricks * BrickPool::kBrickTexels;
        return gl::TextureDesc::brickPool(format, texels.x, texels.y, texels.z).zeroedWhenMade();
    }
    /// The voxelizer averages into these in place, as 32-bit words (common/VoxelWords.glsl).
    gl::Texture albedo; ///< rgba8: albedo, a = opacity (1 where any surface touches the voxel).
    gl::Texture normal; ///< rgba8 snorm: averaged unit normal (shorter where normals cancel).
    gl::Texture
        emission; ///< r11f_g11f_b10f: averaged emitted radiance; only for scenes with emissive materials.
    /// rgba16f: premultiplied outgoing radiance, a = opacity; level 0 only where cones do not read its box
    /// levels (anisotropic mips, or the bounced volume in use), else the full mip chain.
    gl::Texture radiance;
    /// rgba8, full mip chain: 1 where a voxel is occupied; above, per axis (rgb), the opacity a ray along
    /// that axis meets crossing the texel (inject/DownsampleOpacity.comp). The area lights' shadow cones
    /// trace it (common/AreaLights.glsl); built by light injection when there are area lights.
    gl::Texture opacity;
    std::uint64_t opacityVersion = 0; ///< the materialsVersion `opacity` was built for
    /// With anisotropic mips: levels 1..N-1 for cones travelling +x, -x, +y, -y, +z, -z (texture level k =
    /// grid level k+1; a cone wanting the grid's top level N reads N-1), as six tiles of one
    /// gl::Texture::create3DStack in that order (kDirectionalTiles).
    gl::Texture directional;
    /// With bounces != 1 (VoxelBouncePass): the radiance after the bounce iteration, L = L_direct + albedo *
    /// (what the cells gathered from the previous iterate), and its directional chains when anisotropic (then
    /// level 0 only), else its full box mip chain. Empty otherwise. Cones sample these when present.
    gl::Texture bounced;
    gl::Texture bouncedDirectional;
    /// The bounce iteration's gather, one texel per cell of RenderSettings::bounceCellSize^3 voxels, laid out
    /// as the irradiance cache's (rgba16f: sum_i w_i L_i along the cell normal, against it for two-sided
    /// cells, and the cell normal, rgba8 snorm, with w = 0 none, 0.5 one-sided, 1 two-sided), but over every
    /// occupied cell.
    gl::Texture bounceIrradiance;
    gl::Texture bounceIrradianceBack;
    gl::Texture bounceCellNormal;
    /// With higher bounces on coarser cells (RenderSettings::higherBounceCellSize above bounceCellSize), the
    /// same three over cells of that size: what they gathered from the current iterate; and what they
    /// gathered from the first-bounce light, front and back (higherBounceBase*), which the reinjection
    /// subtracts, so that the bounce cells' finer gather of that light stays its part
    /// (passes/VoxelBouncePass).
    gl::Texture higherBounceIrradiance;
    gl::Texture higherBounceIrradianceBack;
    gl::Texture higherBounceCellNormal;
    gl::Texture higherBounceBase;
    gl::Texture higherBounceBaseBack;
    /// How much the last gather of the iterate changed each cell's (higherBounceChange*): what a later
    /// iteration's reinjection adds (bounce/ReinjectBounce.comp).
    gl::Texture higherBounceChange;
    gl::Texture higherBounceChangeBack;
    /// With the irradiance cache (VoxelIrradiancePass), one texel per cell of
    /// RenderSettings::irradianceCellSize^3 voxels, all rgba16f: rgb = sum_i w_i L_i of the diffuse cones
    /// gathered from the cell's surface along its normal (irradiance) and, for two-sided cells, against it
    /// (irradianceBack), a = ambient visibility, a = -1 where not gathered; irradianceNormal: the cell
    /// normal (rgba8 snorm), w = 0 none, 0.5 one-sided, 1 two-sided. Only cells some traced pixel looks up
    /// are gathered: irradianceRequested (r32ui) is 1 where a cell was gathered for the current voxel light,
    /// 0 elsewhere, where the three hold their cleared values.
    gl::Texture irradiance;
    gl::Texture irradianceBack;
    gl::Texture irradianceNormal;
    gl::Texture irradianceRequested;
    std::uint64_t materialsVersion = 0; ///< Grows each time albedo/normal/emission are rewritten.
    /// What the last rewrite redid: the whole grid, or some regions (around a moved object or an edited
    /// material, the slabs a stepping grid newly covers); disjoint only in the last case.
    std::vector<VoxelRegion> changedRegions;
    bool partialRewrite = false; ///< false after a whole rebuild (changedRegions is then the whole grid)
    /// The last rewrite moved the voxels the grid's old and new places share by this many voxels
    /// (core/VolumeShift) instead of voxelizing them again: a pass whose output followed the old place moves
    /// it the same way and redoes changedRegions only.
    std::optional<glm::ivec3> shiftedBy;
    bool dynamicMoved = false; ///< a dynamic object moved or changed material: its shadow moved too
    Aabb dynamicBounds; ///< World bounds of the dynamic meshes now, and at the rewrite before.
    Aabb previousDynamicBounds;
    std::uint64_t radianceVersion = 0; ///< Grows each time level 0 of radiance is rewritten.
    std::uint64_t bouncedVersion = 0; ///< Grows each time the bounce iteration rewrites `bounced`.
    BounceProgress bounceProgress;
    /// With anisotropic mips cones read level 0 of their volume and the directional chains only, so the
    /// volume has no box-filtered levels of its own. The voxel inspector, readVoxels and the NaN check look
    /// at them here: the cone volume's level 0 and its box levels, made when first looked at (Renderer's
    /// ensureInspectionMips) for the version in inspectionMipsKey.
    gl::Texture inspectionMips;
    std::uint64_t inspectionMipsKey = 0;
    std::uint64_t inspectionMipsSerial = 0; ///< the texture inspectionMipsKey's levels were built in
    /// The occupied voxels as the voxelizer listed them while drawing: every static voxel as of the last full
    /// static rebuild (a material edit moves no geometry, so the list stays whole) and every dynamic voxel as
    /// of the last dynamic rewrite. Together they name every occupied voxel, those both layers reach twice.
    OccupiedCellList staticVoxels;
    OccupiedCellList dynamicVoxels;
    /** The lists that together name every occupied voxel: the static one, and the dynamic one if there are
     * dynamic meshes. */
    std::vector<const OccupiedCellList*> occupiedVoxels(bool dynamicMeshes) const
    {
        if (dynamicMeshes)
            return { &staticVoxels, &dynamicVoxels };
        return { &staticVoxels };
    }

    /// Voxels holding a surface, for the statistics: counted from the voxelizer's lists once a frame that
    /// voxelized has been submitted (Renderer::renderFrame), when occupiedCountStale says they changed.
    std::size_t occupiedCount = 0;
    bool occupiedCountStale = false;

    /** The volume cones trace through: after the second bounce when there is one, else first-bounce radiance.
     */
    const gl::Texture& coneRadiance() const { return bounced ? bounced : radiance; }
    /** Which light coneRadiance() holds: the bounced volume's version, or the first-bounce one's (top bit
     * clear). */
    std::uint64_t coneRadianceKey() const
    {
        return bounced ? (bouncedVersion | (std::uint64_t(1) << 63)) : radianceVersion;
    }
    const gl::Texture& coneDirectional() const { return bounced ? bouncedDirectional : directional; }
};

/** Shadow maps of all lights: point lights as cube layers, directional lights as 2D layers, both plain
 * rasterised depth. Nothing writes gl_FragDepth, so llvmpipe keeps its early depth test and skips hidden
 * fragments. */
struct ShadowMaps {
    gl::Texture
        pointDepth; ///< depth32f cube map array: each face's perspective depth over [pointNear, pointFar].
    gl::Texture directionalDepth; ///< depth32f 2D array.
    gl::Sampler rawDepth; ///< reads either map as plain depth (soft shadows' blocker search)
    gl::Framebuffer framebuffer;
    int size = 0;
    float pointNear = 1e-4f; ///< metres: the cube faces' near plane (depth 0)
    float pointFar = 1.0f; ///< metres: the cube faces' far plane (depth 1)
    std::vector<glm::mat4> directionalMatrices; ///< world to light clip space, one per directional light
    std::uint64_t version = 0; ///< Grows each time the maps are redrawn.
};

/** Per-pixel buffers of the current output size. */
struct ScreenTargets {
    int width = 0, height = 0;
    int indirectDivisor = 1; ///< the indirect targets are width/divisor x height/divisor (rounded up)
    /// rgba32ui: the g-buffer's one target: normal, albedo, front face, material index and view depth, packed
    /// (shaders/common/GBufferSurface.glsl); material 0 = no surface.
    gl::Texture surface;
    /// depth32f + stencil8: the stencil holds each pixel's class (common/PixelClass.glsl), from the
    /// g-buffer's materials, so the composite runs each shader variant on its own pixels only.
    gl::Texture depth;
    gl::Framebuffer gbuffer;
    gl::Texture indirectDiffuse; ///< rgba16f: cosine-weighted incoming radiance, a = ambient visibility.
    /// rgba32f: what the composite's upsampling weighs each traced pixel by: the tangent plane of the pixel
    /// it was traced from (unit normal, offset dot(p - camera, n)), 0 where no surface.
    gl::Texture indirectGuide;
    gl::Texture indirectStencil; ///< depth24 + stencil8 at the traced size: the traced pixels' classes
    gl::Framebuffer indirectTarget;
    /// The specular cone's own grid, width/specularDivisor x height/specularDivisor (rounded up).
    int specularDivisor = 1;
    gl::Texture specular; ///< rgba16f: radiance along the specular cone.
    gl::Texture specularGuide; ///< rgba32f: the specular grid's tangent planes, as indirectGuide
    gl::Texture specularStencil; ///< depth24 + stencil8: the specular grid's pixel classes
    gl::Framebuffer specularTarget;
    /// The area lights' shadow grid (passes/AreaLightPass), width/areaDivisor x height/areaDivisor (rounded
    /// up): the share of each traced pixel's area-light irradiance its shadow cones let through (rgba16f, a),
    /// its guide (rgba32f, as indirectGuide), stencil and framebuffer.
    int areaDivisor = 1;
    gl::Texture areaShadow;
    gl::Texture areaShadowGuide;
    gl::Texture areaShadowStencil;
    gl::Framebuffer areaShadowTarget;
    gl::Texture final; ///< rgba32f: linear radiance of the frame.
    gl::Framebuffer finalTarget; ///< with the g-buffer's depth and stencil, read only

    /** The side of a grid of traced pixels, one per divisor x divisor block (rounded up). */
    static int tracedSize(int side, int divisor) { return (side + divisor - 1) / divisor; }
    /**
     * The three textures of one grid of traced pixels, one per @p divisor block: its values (rgba16f), guide
     * (rgba32f, fetched) and pixel classes (depth24 + stencil8), named by @p names; empty when not @p needed.
     */
    std::vector<TextureSlot> tracedGrid(const char* const (&names)[3], gl::Texture& values,
        gl::Texture& guide, gl::Texture& stencil, int divisor, bool needed) const;
};

} // namespace vct::render
