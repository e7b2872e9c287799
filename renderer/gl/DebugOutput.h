#pragma once

#include <string>
#include <vector>

namespace vct::gl {

/**
 * Collects KHR_debug errors of the current context. Tests treat any collected error as a failure, so a GL
 * mistake surfaces where it happens instead of as a black image later.
 */
class DebugOutput {
public:
    /** Installs the callback on the current context (synchronous, errors and high severity only). */
    static void enable();
    /** Messages since the last call, and glGetError() codes, cleared on return. */
    static std::vector<std::string> takeErrors();
};

} // namespace vct::gl
