#include "debug/TrilinearRateProbe.h"

#include "core/ShaderLibrary.h"
#include "core/VoxelGridFrame.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/TimerQuery.h"
#include "gl/VertexArray.h"

#include <glm/vec2.hpp>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace vct::render {

struct TrilinearRateProbe::State {
    ShaderLibrary shaders;
    gl::Program program;
    gl::VertexArray emptyVao;
    gl::Texture volume;
    gl::Texture target;
    gl::Framebuffer framebuffer;
};

TrilinearRateProbe::TrilinearRateProbe()
    : m_state(std::make_unique<State>())
{
}

TrilinearRateProbe::~TrilinearRateProbe() = default;

TrilinearRate TrilinearRateProbe::measure(
    int width, int height, int volumeSize, int repeats, int rays, int steps)
{
    if (width < 1 || height < 1 || volumeSize < 1 || repeats < 1 || rays < 1 || steps < 1)
        throw std::invalid_argument("TrilinearRateProbe::measure: sizes and counts must be positive");
    State& st = *m_state;
    if (!st.program) {
        st.program = st.shaders.build(
            { "trilinear rate probe", { "common/FullScreen.vert", "probe/TrilinearRate.frag" }, {} });
        st.emptyVao = gl::VertexArray::create();
    }
    const int levels = VoxelGridFrame { glm::vec3(0.0f), 1.0f, volumeSize }.levelCount();
    if (!st.volume || st.volume.width() != volumeSize) {
        // Same storage, filter and wrap as the voxel radiance (gl::Texture::create3D with a full chain).
        st.volume = gl::Texture::create3D(GL_RGBA16F, volumeSize, levels);
        const float value[4] = { 0.25f, 0.5f, 0.75f, 0.5f };
        for (int level = 0; level < levels; ++level)
            glClearTexImage(st.volume.id(), level, GL_RGBA, GL_FLOAT, value);
    }
    if (!st.target || st.target.width() != width || st.target.height() != height) {
        st.target = gl::Texture::create2D(GL_RGBA16F, width, height);
        st.framebuffer = gl::Framebuffer::create();
        st.framebuffer.attachColor(0, st.target);
        st.framebuffer.finish(1);
    }

    st.framebuffer.bind();
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    st.program.use();
    st.program.set("uRays", rays);
    st.program.set("uSteps", steps);
    st.program.set("uMaxLevel", float(levels - 1));
    st.program.set("uSize", glm::vec2(float(width), float(height)));
    st.volume.bindUnit(0);
    st.emptyVao.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3); // untimed: llvmpipe compiles the shader on its first draw
    glFinish();

    gl::TimerQuery timer = gl::TimerQuery::create();
    std::vector<double> ms;
    for (int i = 0; i < repeats; ++i) {
        timer.begin();
        // llvmpipe takes a timestamp per tile as it rasterizes the batch holding it, so a start stamp in the
        // draw's own batch would read the start of the last tile and time one tile. Flushed alone, it reads
        // the end of the previous batch, as a pass's start stamp in the pipeline does; checked against the
        // CPU clock around glFinish (within 1 %).
        glFlush();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        timer.end();
        ms.push_back(timer.elapsedMs());
    }
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    std::sort(ms.begin(), ms.end());
    TrilinearRate rate;
    rate.medianMs = ms.size() % 2 ? ms[ms.size() / 2] : 0.5 * (ms[ms.size() / 2 - 1] + ms[ms.size() / 2]);
    rate.width = width;
    rate.height = height;
    rate.volumeSize = volumeSize;
    rate.samplesPerPixel = rays * steps;
    rate.samplesPerDraw
        = std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(rays) * std::uint64_t(steps);
    rate.samplesPerSecond = rate.medianMs > 0.0 ? double(rate.samplesPerDraw) / (rate.medianMs * 1e-3) : 0.0;
    return rate;
}

} // namespace vct::render
