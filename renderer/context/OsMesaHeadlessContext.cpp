#include "context/OsMesaHeadlessContext.h"

// Only the OSMesa header here: glad and the system GL header must not meet in one file.
#include <GL/osmesa.h>

namespace vct::render {

namespace {

void* osmesaLookup(const char* name)
{
    return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
}

} // namespace

std::unique_ptr<OsMesaHeadlessContext> OsMesaHeadlessContext::create(std::string& error)
{
    const int attributes[]
        = { OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8, OSMESA_PROFILE,
              OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0 };
    OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context) {
        error = "OSMesaCreateContextAttribs(GL 4.5 core) returned no context";
        return nullptr;
    }
    std::unique_ptr<OsMesaHeadlessContext> result(new OsMesaHeadlessContext);
    result->m_context = context;
    if (!OSMesaMakeCurrent(context, result->m_buffer.data(), GL_UNSIGNED_BYTE, 1, 1)) {
        error = "OSMesaMakeCurrent failed";
        return nullptr;
    }
    return result;
}

OsMesaHeadlessContext::~OsMesaHeadlessContext()
{
    if (m_context)
        OSMesaDestroyContext(static_cast<OSMesaContext>(m_context));
}

void OsMesaHeadlessContext::makeCurrent()
{
    OSMesaMakeCurrent(static_cast<OSMesaContext>(m_context), m_buffer.data(), GL_UNSIGNED_BYTE, 1, 1);
}

gl::ProcAddressFunction OsMesaHeadlessContext::procAddressFunction() const
{
    return osmesaLookup;
}

} // namespace vct::render
