#pragma once

#include "gl/Program.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace vct::render {

/** A program declared as data: its stage files (stage from the extension) and preprocessor defines. */
struct ProgramDesc {
    std::string name;
    std::vector<std::string> stageFiles; ///< Paths relative to shaders/, e.g. "voxelize/Voxelize.geom".
    std::vector<std::string> defines; ///< "NAME" or "NAME VALUE".
};

/**
 * Finds shader text, expands `#include "path"` and builds programs. Text comes from an injected lookup so
 * tests and hot reload can read from anywhere; the default reads VCT_SHADER_DIR when set, otherwise the
 * sources embedded at build time.
 */
class ShaderLibrary {
public:
    using Lookup = std::function<std::optional<std::string>(const std::string& path)>;

    ShaderLibrary();
    explicit ShaderLibrary(Lookup lookup);

    /** Throws std::runtime_error naming the file when a stage is missing or does not compile. */
    gl::Program build(const ProgramDesc& desc) const;
    /** The full text of one stage with includes expanded, for tests and error reports. */
    std::string preprocess(const std::string& path, const std::vector<std::string>& defines) const;

private:
    std::string expand(const std::string& path, int depth, std::vector<std::string>& files) const;
    Lookup m_lookup;
};

} // namespace vct::render
