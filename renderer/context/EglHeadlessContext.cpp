#include "context/EglHeadlessContext.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

namespace vct::render {

namespace {

void* eglLookup(const char* name)
{
    return reinterpret_cast<void*>(eglGetProcAddress(name));
}

std::string eglErrorText(const char* step)
{
    char code[16];
    snprintf(code, sizeof code, "0x%04x", unsigned(eglGetError()));
    return std::string(step) + " failed (EGL error " + code + ")";
}

} // namespace

std::unique_ptr<EglHeadlessContext> EglHeadlessContext::create(std::string& error)
{
    auto getPlatformDisplay
        = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) {
        error = "eglGetPlatformDisplayEXT is not available";
        return nullptr;
    }
    EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) {
        error = eglErrorText("eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)");
        return nullptr;
    }
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) {
        error = eglErrorText("eglInitialize");
        return nullptr;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        error = eglErrorText("eglBindAPI(EGL_OPENGL_API)");
        eglTerminate(display);
        return nullptr;
    }
    const EGLint attributes[] = { EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
    EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) {
        error = eglErrorText("eglCreateContext(GL 4.5 core)");
        eglTerminate(display);
        return nullptr;
    }
    std::unique_ptr<EglHeadlessContext> result(new EglHeadlessContext);
    result->m_display = display;
    result->m_context = context;
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        error = eglErrorText("eglMakeCurrent(surfaceless)");
        return nullptr;
    }
    return result;
}

EglHeadlessContext::~EglHeadlessContext()
{
    if (m_display) {
        eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (m_context)
            eglDestroyContext(m_display, m_context);
        // eglTerminate would pull the display from under any other context in this process (tests make
        // several).
    }
}

void EglHeadlessContext::makeCurrent()
{
    eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context);
}

gl::ProcAddressFunction EglHeadlessContext::procAddressFunction() const
{
    return eglLookup;
}

} // namespace vct::render
