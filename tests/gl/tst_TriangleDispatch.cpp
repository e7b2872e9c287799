#include "GlTestContext.h"
#include "TestSupport.h"

#include "core/GpuScene.h"
#include "gl/Buffer.h"
#include "gl/Program.h"

#include <QtTest>

#include <set>

using namespace vct;

namespace {

constexpr int kMeshTriangles[2] = { 300, 201 };
constexpr int kMaxTriangles = 1000; // per mesh, in the shader's table of visits

// Visits every triangle it is given: counts it in a table by its material (one per mesh) and its own number
// (its lowest vertex / 3, as the meshes below have three vertices of their own per triangle), checks the
// vertex it reads there carries that number in x, and lists the odd-numbered ones.
const char* const kVisitShader = R"(#version 450 core
layout(local_size_x = 64) in;
layout(std430, binding = 2) readonly buffer Vertices { float uVertices[]; };
layout(std430, binding = 3) readonly buffer Indices { uint uIndices[]; };
layout(std430, binding = 4) writeonly buffer ListedIndices { uint uListed[]; };
layout(std430, binding = 5) buffer ListedCommands { uint uCommands[]; };
layout(std430, binding = 6) buffer Visits { uint uVisits[]; };
uniform uint uFirstIndex;
uniform uint uTriangleCount;
uniform uint uVertexCount;
uniform uint uListRun;
uniform uint uListFirst;
uniform int uMaterialIndex;
void main()
{
    uint triangle = gl_GlobalInvocationID.x;
    if (triangle >= uTriangleCount)
        return;
    uint first = uFirstIndex + 3u * triangle;
    uvec3 index = uvec3(uIndices[first], uIndices[first + 1u], uIndices[first + 2u]);
    uint lowest = min(index.x, min(index.y, index.z));
    uint number = lowest / 3u;
    bool vertexRight = lowest < uVertexCount && uVertices[8u * lowest] == float(number);
    atomicAdd(uVisits[uint(uMaterialIndex) * 1000u + number], vertexRight ? 1u : 100u);
    if (number % 2u == 1u) {
        uint slot = uListFirst + atomicAdd(uCommands[5u * uListRun], 3u);
        uListed[slot] = index.x;
        uListed[slot + 1u] = index.y;
        uListed[slot + 2u] = index.z;
    }
}
)";

// Triangle k of a mesh: x = k at its first corner, so the shader can tell it read the right vertices.
render::Mesh numberedTriangles(int count, int material)
{
    std::vector<glm::vec3> positions;
    for (int k = 0; k < count; ++k) {
        const float x = float(k);
        positions.insert(positions.end(), { { x, 0.0f, 0.0f }, { x + 0.5f, 0.0f, 0.0f }, { x, 0.5f, 0.0f } });
    }
    return test::makeTriangles(positions, material);
}

std::vector<std::uint32_t> readBuffer(const gl::Buffer& buffer, std::size_t words)
{
    std::vector<std::uint32_t> data(words);
    glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(words * sizeof(std::uint32_t)), data.data());
    return data;
}

} // namespace

class TriangleDispatchTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void everyTriangleOnceAndListedInItsRun_data();
    void everyTriangleOnceAndListedInItsRun();
    void noGlErrors();

private:
    test::GlTestContext m_gl;
};

void TriangleDispatchTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

void TriangleDispatchTest::everyTriangleOnceAndListedInItsRun_data()
{
    QTest::addColumn<unsigned>("maxGroups");
    QTest::newRow("one dispatch a run") << 65535u;
    // Five and four dispatches of one workgroup: the parts of a run a model of millions of triangles takes.
    QTest::newRow("a workgroup a dispatch") << 1u;
}

void TriangleDispatchTest::everyTriangleOnceAndListedInItsRun()
{
    QFETCH(unsigned, maxGroups);
    render::Scene scene;
    scene.materials = { render::Material {}, render::Material {} };
    for (int mesh = 0; mesh < 2; ++mesh)
        scene.meshes.push_back(numberedTriangles(kMeshTriangles[mesh], mesh));
    const render::GpuScene gpu(scene);
    const gl::Program program({ { GL_COMPUTE_SHADER, "visit triangles", kVisitShader } });
    const std::vector<std::uint32_t> zeros(2 * kMaxTriangles, 0u);
    gl::Buffer visits(zeros.size() * sizeof(std::uint32_t), zeros.data(), 0);
    visits.bindBase(GL_SHADER_STORAGE_BUFFER, 6);

    render::ListedTriangles listed;
    render::TriangleDispatch dispatch;
    dispatch.vertexBinding = 2;
    dispatch.groupSize = 64;
    dispatch.listed = &listed;
    dispatch.maxGroups = maxGroups;
    gpu.dispatchTriangles(program, render::DrawOptions {}, 0, dispatch);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);

    const std::vector<std::uint32_t> seen = readBuffer(visits, zeros.size());
    for (int mesh = 0; mesh < 2; ++mesh)
        for (int k = 0; k < kMaxTriangles; ++k) {
            const std::uint32_t expected = k < kMeshTriangles[mesh] ? 1u : 0u;
            QVERIFY2(seen[std::size_t(mesh * kMaxTriangles + k)] == expected,
                qPrintable(QString("mesh %1, triangle %2: %3 visits (100 a visit that read the wrong vertex)")
                               .arg(mesh)
                               .arg(k)
                               .arg(seen[std::size_t(mesh * kMaxTriangles + k)])));
        }

    // One run a mesh (no culling), each with its command and its segment of the listed indices.
    QCOMPARE(listed.runMeshes, (std::vector<std::size_t> { 0, 1 }));
    const std::vector<std::uint32_t> commands
        = readBuffer(listed.commands, 2 * render::ListedTriangles::kCommandWords);
    const std::size_t total = 3 * std::size_t(kMeshTriangles[0] + kMeshTriangles[1]);
    const std::vector<std::uint32_t> indices = readBuffer(listed.indices, total);
    std::uint32_t segment = 0;
    for (int mesh = 0; mesh < 2; ++mesh) {
        const std::uint32_t* command = &commands[std::size_t(mesh) * render::ListedTriangles::kCommandWords];
        const std::uint32_t odd = std::uint32_t(kMeshTriangles[mesh] / 2);
        QCOMPARE(command[0], 3 * odd); // indices to draw
        QCOMPARE(command[1], 1u); // one instance
        QCOMPARE(command[2], segment); // from the run's segment
        std::set<std::uint32_t> numbers;
        for (std::uint32_t i = 0; i < command[0]; i += 3)
            numbers.insert(
                std::min({ indices[segment + i], indices[segment + i + 1], indices[segment + i + 2] }) / 3);
        QCOMPARE(numbers.size(), std::size_t(odd));
        for (const std::uint32_t n : numbers)
            QVERIFY2(n % 2 == 1 && n < std::uint32_t(kMeshTriangles[mesh]), qPrintable(QString::number(n)));
        segment += 3 * std::uint32_t(kMeshTriangles[mesh]);
    }
}

void TriangleDispatchTest::noGlErrors()
{
    const auto errors = m_gl.renderer->takeGlErrors();
    QVERIFY2(errors.empty(), errors.empty() ? "" : errors.front().c_str());
}

QTEST_GUILESS_MAIN(TriangleDispatchTest)
#include "tst_TriangleDispatch.moc"
