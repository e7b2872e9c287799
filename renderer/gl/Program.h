#pragma once

#include "gl/Handle.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <string>
#include <unordered_map>
#include <vector>

namespace vct::gl {

void deleteProgram(GLuint id);

/** One shader stage's preprocessed source, with a name for error messages. */
struct ShaderStageSource {
    GLenum stage = 0;
    std::string name;
    std::string source;
};

/** A linked GLSL program. Uniform locations are cached by name. */
class Program {
public:
    Program() = default;
    /** Compiles and links; throws std::runtime_error with the driver's log and the stage name on failure. */
    explicit Program(const std::vector<ShaderStageSource>& stages);

    GLuint id() const { return m_handle.id(); }
    explicit operator bool() const { return bool(m_handle); }
    void use() const;
    GLint location(const char* name) const;
    void set(const char* name, int v) const;
    void set(const char* name, unsigned v) const;
    void set(const char* name, float v) const;
    void set(const char* name, const glm::vec2& v) const;
    void set(const char* name, const glm::vec3& v) const;
    void set(const char* name, const glm::ivec3& v) const;
    void set(const char* name, const glm::vec4& v) const;
    void set(const char* name, const glm::mat3& v) const;
    void set(const char* name, const glm::mat4& v) const;
    void set(const char* name, const std::vector<glm::vec4>& v) const;
    void set(const char* name, const std::vector<float>& v) const;

private:
    Handle<deleteProgram> m_handle;
    mutable std::unordered_map<std::string, GLint> m_locations;
};

} // namespace vct::gl
