#include "gl/GlLoader.h"

#include <glad/gl.h>

namespace vct::gl {

namespace {
ProcAddressFunction g_lookup = nullptr;
GLADapiproc lookupThunk(const char* name)
{
    return reinterpret_cast<GLADapiproc>(g_lookup(name));
}
} // namespace

bool loadGl(ProcAddressFunction getProcAddress)
{
    if (!getProcAddress)
        return false;
    g_lookup = getProcAddress;
    const int version = gladLoadGL(lookupThunk);
    return version != 0 && GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) >= 45;
}

} // namespace vct::gl
