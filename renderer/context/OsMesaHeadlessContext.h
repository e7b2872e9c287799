#pragma once

#include "context/HeadlessContext.h"

#include <vector>

namespace vct::render {

/** Mesa's off-screen context. Removed from Mesa 25.1, hence the second choice after EGL. */
class OsMesaHeadlessContext final : public HeadlessContext {
public:
    static std::unique_ptr<OsMesaHeadlessContext> create(std::string& error);
    ~OsMesaHeadlessContext() override;

    void makeCurrent() override;
    gl::ProcAddressFunction procAddressFunction() const override;
    std::string backendName() const override { return "OSMesa"; }

private:
    OsMesaHeadlessContext() = default;
    void* m_context = nullptr;
    // OSMesa insists on a colour buffer to make current; we draw into our own framebuffers, so 1x1 suffices.
    std::vector<unsigned char> m_buffer = std::vector<unsigned char>(4);
};

} // namespace vct::render
