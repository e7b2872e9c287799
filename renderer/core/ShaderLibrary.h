#pragma once

#include "gl/Program.h"

#include <functional>
#include <map>
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
 * Finds shader text, expands `#include "path"`, builds programs and keeps them: passes ask for
 * program(desc) whenever they draw, and the first ask builds it. Text comes from an injected lookup so tests
 * and hot reload can read from anywhere; the default reads VCT_SHADER_DIR when set, otherwise the sources
 * embedded at build time. reload() rebuilds every kept program from new text (the editor's F5).
 */
class ShaderLibrary {
public:
    using Lookup = std::function<std::optional<std::string>(const std::string& path)>;

    ShaderLibrary();
    explicit ShaderLibrary(Lookup lookup);

    /**
     * The program `desc` describes, built on first use and kept, one per set of stage files and defines (the
     * name only labels messages). The reference stays valid for the library's life; reload() may change the
     * GL program behind it, so callers ask again each frame rather than keep its id. Throws
     * std::runtime_error naming the file when a stage is missing or does not compile.
     */
    const gl::Program& program(const ProgramDesc& desc) const;
    /**
     * Defines program() adds to every program from now on, such as SPARSE_VOXELS for a sparse grid
     * (common/VoxelBricks.glsl): passes ask for the same programs in every storage mode, and those made
     * before stay kept for when the mode comes back. Callers that keep a program across frames ask again
     * after a change.
     */
    void setSharedDefines(std::vector<std::string> defines);
    const std::vector<std::string>& sharedDefines() const { return m_sharedDefines; }
    /** A new program, not kept: for one-off tools and tests. Throws as program() does. */
    gl::Program build(const ProgramDesc& desc) const;

    /**
     * Takes shader text from `lookup` from now on and rebuilds every kept program with it. A program whose
     * new text does not compile keeps its last good build; each failure comes back as one message naming the
     * program and the driver's log. Empty: all rebuilt.
     */
    std::vector<std::string> reload(Lookup lookup);
    /** Shader text read from the folder `dir` (paths relative to it, as under shaders/); the built-in text of
     * a file it lacks. */
    static Lookup folderLookup(const std::string& dir);
    /** Programs kept so far. */
    std::size_t programCount() const { return m_programs.size(); }
    /** The full text of one stage with includes expanded, for tests and error reports. */
    std::string preprocess(const std::string& path, const std::vector<std::string>& defines) const;

private:
    std::string expand(const std::string& path, int depth, std::vector<std::string>& files) const;
    Lookup m_lookup;
    struct Kept {
        ProgramDesc desc;
        gl::Program program;
    };
    // Keyed by stage files and defines; std::map so that references handed out stay put as it grows.
    mutable std::map<std::string, Kept> m_programs;
    std::vector<std::string> m_sharedDefines;
};

} // namespace vct::render
