#pragma once

namespace vct::gl {

/** A context's function lookup: eglGetProcAddress, OSMesaGetProcAddress or QOpenGLContext::getProcAddress. */
using ProcAddressFunction = void* (*)(const char* name);

/**
 * Loads GL 4.5 core entry points for the context that is current now through glad.
 * Returns false when the context is older than 4.5 or a 4.5 entry point is missing.
 */
bool loadGl(ProcAddressFunction getProcAddress);

} // namespace vct::gl
