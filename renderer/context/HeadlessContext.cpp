#include "context/HeadlessContext.h"

#include "context/EglHeadlessContext.h"
#include "context/OsMesaHeadlessContext.h"

#include <glad/gl.h>

namespace vct::render {

namespace {

std::string glString(GLenum name)
{
    if (!glad_glGetString)
        return "?";
    const GLubyte* text = glGetString(name);
    return text ? reinterpret_cast<const char*>(text) : "?";
}

} // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create(const std::string& backend, std::string& error)
{
    std::unique_ptr<HeadlessContext> context;
    std::string why;
    if (backend == "egl")
        context = EglHeadlessContext::create(why);
    else if (backend == "osmesa")
        context = OsMesaHeadlessContext::create(why);
    else {
        error = "unknown GL backend '" + backend + "' (use egl or osmesa)";
        return nullptr;
    }
    if (!context) {
        error = "could not create an OpenGL 4.5 core context with " + backend + ": " + why;
        return nullptr;
    }
    if (!gl::loadGl(context->procAddressFunction())) {
        error = "the " + backend + " context does not provide OpenGL 4.5 core (GL_VERSION "
            + glString(GL_VERSION) + ")";
        return nullptr;
    }
    context->m_glInfo = glString(GL_VERSION) + ", " + glString(GL_RENDERER);
    return context;
}

std::unique_ptr<HeadlessContext> HeadlessContext::createPreferring(
    const std::string& backend, bool chosen, std::string& error)
{
    auto context = create(backend, error);
    if (context || chosen)
        return context;
    std::string osmesaError;
    context = create("osmesa", osmesaError);
    if (!context)
        error += "; then " + osmesaError;
    return context;
}

} // namespace vct::render
