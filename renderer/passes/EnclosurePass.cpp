#include "passes/EnclosurePass.h"

#include "core/EnclosedSpace.h"
#include "core/FrameContext.h"
#include "core/ResourceNames.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <future>
#include <vector>

namespace vct::render {

VoxelGridFrame EnclosurePass::mapGrid(const FrameContext& frame)
{
    VoxelGridFrame grid = frame.sceneGrid;
    grid.resolution = std::min(grid.resolution, EnclosedSpace::kMaxResolution);
    return grid;
}

bool EnclosurePass::needed(const FrameContext& frame)
{
    return frame.settings.enclosedSpace && frame.enclosure
        && (frame.shape.diffuseCones || frame.shape.irradianceCache || frame.shape.bounceVolume);
}

EnclosurePass::Key EnclosurePass::keyOf(const FrameContext& frame)
{
    return { frame.versions.staticGeometry, mapGrid(frame) };
}

PassDeclaration EnclosurePass::declare() const
{
    return { {}, { resource::kEnclosure } };
}

std::vector<TextureSlot> EnclosurePass::textures(const FrameContext& frame)
{
    if (!frame.enclosure)
        return {};
    // Sampled filtered: a gather whose start lies in a wall's cell beside enclosed space still counts as
    // enclosed (common/ConeTracing.glsl, startsEnclosed).
    const gl::TextureDesc desc
        = needed(frame) ? gl::TextureDesc::volume(GL_R8, mapGrid(frame).resolution) : gl::TextureDesc {};
    return { { resource::kEnclosure, ResourceGroup::Voxels, &frame.enclosure->texture, desc } };
}

PassDecision EnclosurePass::plan(const FrameContext& frame) const
{
    if (!frame.settings.enclosedSpace)
        return { PassDecision::Action::Skip, "enclosed_space=off" };
    if (!needed(frame))
        return { PassDecision::Action::Skip, "no diffuse gather reads it" };
    if (!m_key)
        return { PassDecision::Action::Run, "no valid output yet" };
    if (!(*m_key == keyOf(frame)))
        return { PassDecision::Action::Run, "static geometry or grid changed" };
    return { PassDecision::Action::Reuse, "static geometry unchanged" };
}

void EnclosurePass::execute(FrameContext& frame)
{
    EnclosureMap& map = *frame.enclosure;
    map.abandon();
    const VoxelGridFrame grid = mapGrid(frame);
    const glm::mat4 toGrid = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f / grid.voxelSize()))
        * glm::translate(glm::mat4(1.0f), -grid.origin);
    // The build reads the scene's static meshes in place: the renderer takes it (EnclosureMap::finish) before
    // the frame ends, while the scene cannot change.
    struct Part {
        const Mesh* mesh;
        glm::mat4 toGrid;
    };
    std::vector<Part> parts;
    for (const Mesh& mesh : frame.scene.scene().meshes)
        if (mesh.visible && !mesh.dynamic)
            parts.push_back({ &mesh, toGrid * mesh.transform });
    // On a worker thread: the marking and the flood are CPU work the GL's voxelization, issued next, does not
    // wait for (docs/BENCHMARKS.md, "Enclosed space").
    map.pending = std::async(std::launch::async, [parts = std::move(parts), resolution = grid.resolution] {
        EnclosedSpace space(resolution);
        for (const Part& part : parts)
            space.addMesh(part.mesh->positions, part.mesh->indices, part.toGrid);
        space.solve();
        return EnclosureMap::Build { space.texels(), space.enclosedCells() };
    });
    map.grid = grid;
    map.inUse = true;
    ++map.version;
    m_key = keyOf(frame);
}

void EnclosurePass::release(FrameContext& frame)
{
    if (frame.enclosure) {
        frame.enclosure->abandon();
        frame.enclosure->inUse = false;
    }
    m_key.reset();
}

} // namespace vct::render
