#include "core/ListedTriangles.h"

#include <utility>

namespace vct::render {

void ListedTriangles::reset(std::vector<std::size_t> meshes, const std::vector<std::uint32_t>& runTriangles)
{
    std::vector<std::uint32_t> words;
    words.reserve(runTriangles.size() * kCommandWords);
    std::uint32_t first = 0;
    for (const std::uint32_t triangles : runTriangles) {
        words.insert(words.end(), { 0u, 1u, first, 0u, 0u });
        first += 3 * triangles;
    }
    const std::size_t indexBytes = std::size_t(first) * sizeof(std::uint32_t);
    const std::size_t commandBytes = words.size() * sizeof(std::uint32_t);
    // Grown, never shrunk: the same passes list about as many triangles every frame.
    if (!indices || indices.size() < indexBytes)
        indices = gl::Buffer(indexBytes, nullptr, 0);
    if (!commands || commands.size() < commandBytes)
        commands = gl::Buffer(commandBytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    // The counts the last listing's shader raised are rewritten here: its writes come first.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    if (commandBytes > 0)
        commands.upload(words.data(), commandBytes);
    runMeshes = std::move(meshes);
}

} // namespace vct::render
