#pragma once

#include "context/HeadlessContext.h"

namespace vct::render {

/** EGL on Mesa's surfaceless platform: no X server, no window, no pbuffer. */
class EglHeadlessContext final : public HeadlessContext {
public:
    /** Returns null and fills error when no 4.5 core context can be made. */
    static std::unique_ptr<EglHeadlessContext> create(std::string& error);
    ~EglHeadlessContext() override;

    void makeCurrent() override;
    gl::ProcAddressFunction procAddressFunction() const override;
    std::string backendName() const override { return "EGL surfaceless"; }

private:
    EglHeadlessContext() = default;
    void* m_display = nullptr;
    void* m_context = nullptr;
};

} // namespace vct::render
