#include "core/ShaderLibrary.h"

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace vct::render {

const std::map<std::string, std::string>& embeddedShaderSources();

namespace {

std::optional<std::string> readFile(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    if (!file)
        return std::nullopt;
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

std::optional<std::string> embedded(const std::string& path)
{
    const auto& sources = embeddedShaderSources();
    const auto it = sources.find(path);
    if (it == sources.end())
        return std::nullopt;
    return it->second;
}

std::optional<std::string> defaultLookup(const std::string& path)
{
    if (const char* dir = std::getenv("VCT_SHADER_DIR"); dir && *dir)
        if (std::optional<std::string> text = readFile(std::string(dir) + "/" + path))
            return text;
    return embedded(path);
}

GLenum stageOf(const std::string& path)
{
    const auto ends
        = [&](const char* ext) { return path.size() > 5 && path.compare(path.size() - 5, 5, ext) == 0; };
    if (ends(".vert"))
        return GL_VERTEX_SHADER;
    if (ends(".geom"))
        return GL_GEOMETRY_SHADER;
    if (ends(".frag"))
        return GL_FRAGMENT_SHADER;
    if (ends(".comp"))
        return GL_COMPUTE_SHADER;
    throw std::runtime_error("shader file '" + path + "' has no stage extension (.vert .geom .frag .comp)");
}

std::string keyOf(const ProgramDesc& desc)
{
    std::string key;
    for (const std::string& file : desc.stageFiles)
        key += file + '\n';
    key += '\n';
    for (const std::string& define : desc.defines)
        key += define + '\n';
    return key;
}

} // namespace

ShaderLibrary::ShaderLibrary()
    : m_lookup(defaultLookup)
{
}

ShaderLibrary::ShaderLibrary(Lookup lookup)
    : m_lookup(std::move(lookup))
{
}

std::string ShaderLibrary::expand(const std::string& path, int depth, std::vector<std::string>& files) const
{
    if (depth > 16)
        throw std::runtime_error("shader includes nest too deep at '" + path + "'");
    const std::optional<std::string> text = m_lookup(path);
    if (!text)
        throw std::runtime_error("shader file '" + path + "' not found");
    const int fileIndex = int(files.size());
    files.push_back(path);
    std::istringstream in(*text);
    std::ostringstream out;
    std::string line;
    int lineNumber = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        const auto start = line.find_first_not_of(" \t");
        if (start != std::string::npos && line.compare(start, 8, "#include") == 0) {
            const auto open = line.find('"', start);
            const auto close = line.find('"', open + 1);
            if (open == std::string::npos || close == std::string::npos)
                throw std::runtime_error(path + ":" + std::to_string(lineNumber) + ": malformed #include");
            out << expand(line.substr(open + 1, close - open - 1), depth + 1, files);
            out << "#line " << lineNumber + 1 << " " << fileIndex << "\n";
        } else {
            out << line << "\n";
        }
    }
    return out.str();
}

std::string ShaderLibrary::preprocess(const std::string& path, const std::vector<std::string>& defines) const
{
    std::vector<std::string> files;
    std::string body = expand(path, 0, files);
    std::ostringstream out;
    out << "#version 450 core\n";
    for (const std::string& define : defines)
        out << "#define " << define << "\n";
    out << "#line 1 0\n" << body;
    return out.str();
}

const gl::Program& ShaderLibrary::program(const ProgramDesc& asked) const
{
    ProgramDesc desc = asked;
    desc.defines.insert(desc.defines.end(), m_sharedDefines.begin(), m_sharedDefines.end());
    const std::string key = keyOf(desc);
    if (const auto it = m_programs.find(key); it != m_programs.end())
        return it->second.program;
    gl::Program built = build(desc);
    return m_programs.emplace(key, Kept { desc, std::move(built) }).first->second.program;
}

void ShaderLibrary::setSharedDefines(std::vector<std::string> defines)
{
    m_sharedDefines = std::move(defines);
}

std::vector<std::string> ShaderLibrary::reload(Lookup lookup)
{
    m_lookup = std::move(lookup);
    std::vector<std::string> failures;
    for (auto& [key, kept] : m_programs) {
        try {
            kept.program = build(kept.desc);
        } catch (const std::exception& e) {
            failures.push_back(kept.desc.name + ": " + e.what());
        }
    }
    return failures;
}

ShaderLibrary::Lookup ShaderLibrary::folderLookup(const std::string& dir)
{
    // A file the folder lacks keeps its built-in text, as VCT_SHADER_DIR does.
    return [dir](const std::string& path) -> std::optional<std::string> {
        if (std::optional<std::string> text = readFile(dir + "/" + path))
            return text;
        return embedded(path);
    };
}

gl::Program ShaderLibrary::build(const ProgramDesc& desc) const
{
    std::vector<gl::ShaderStageSource> stages;
    for (const std::string& file : desc.stageFiles)
        stages.push_back({ stageOf(file), desc.name + " (" + file + ")", preprocess(file, desc.defines) });
    return gl::Program(stages);
}

} // namespace vct::render
