#include "passes/EnclosurePass.h"

#include "core/EnclosedSpace.h"
#include "core/FrameContext.h"
#include "core/ResourceNames.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace vct::render {

VoxelGridFrame EnclosurePass::mapGrid(const FrameContext& frame)
{
    VoxelGridFrame grid = frame.sceneGrid;
    grid.resolution = std::min(grid.resolution, EnclosedSpace::kMaxResolution);
    return grid;
}

PassDeclaration EnclosurePass::declare() const
{
    return { {}, { resource::kEnclosure } };
}

std::vector<TextureSlot> EnclosurePass::textures(const FrameContext& frame)
{
    gl::TextureDesc desc;
    if (frame.settings.enclosedSpace && frame.enclosure)
        desc = gl::TextureDesc::volume(GL_R8, mapGrid(frame).resolution);
    gl::Texture* texture = frame.enclosure ? &frame.enclosure->texture : nullptr;
    if (!texture)
        return {};
    return { { resource::kEnclosure, ResourceGroup::Voxels, texture, desc } };
}

PassDecision EnclosurePass::plan(const FrameContext& frame) const
{
    if (!frame.settings.enclosedSpace)
        return { PassDecision::Action::Skip, "enclosed_space=off" };
    if (!frame.enclosure)
        return { PassDecision::Action::Skip, "no map to fill" };
    if (m_staticGeometry == 0)
        return { PassDecision::Action::Run, "no valid output yet" };
    if (m_staticGeometry != frame.versions.staticGeometry || !(m_grid == mapGrid(frame)))
        return { PassDecision::Action::Run, "static geometry or grid changed" };
    return { PassDecision::Action::Reuse, "static geometry unchanged" };
}

void EnclosurePass::execute(FrameContext& frame)
{
    EnclosureMap& map = *frame.enclosure;
    const VoxelGridFrame grid = mapGrid(frame);
    EnclosedSpace space(grid.resolution);
    const glm::mat4 toGrid = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f / grid.voxelSize()))
        * glm::translate(glm::mat4(1.0f), -grid.origin);
    for (const Mesh& mesh : frame.scene.scene().meshes)
        if (mesh.visible && !mesh.dynamic)
            space.addMesh(mesh.positions, mesh.indices, toGrid * mesh.transform);
    space.solve();
    const std::vector<std::uint8_t> texels = space.texels();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage3D(map.texture.id(), 0, 0, 0, 0, grid.resolution, grid.resolution, grid.resolution,
        GL_RED, GL_UNSIGNED_BYTE, texels.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    map.grid = grid;
    map.enclosedCells = space.enclosedCells();
    map.inUse = true;
    ++map.version;
    m_grid = grid;
    m_staticGeometry = frame.versions.staticGeometry;
}

void EnclosurePass::release(FrameContext& frame)
{
    if (frame.enclosure)
        frame.enclosure->inUse = false;
    m_staticGeometry = 0;
}

} // namespace vct::render
