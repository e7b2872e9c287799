#include "gl/Program.h"

#include <glm/gtc/type_ptr.hpp>

#include <stdexcept>

namespace vct::gl {

void deleteProgram(GLuint id)
{
    glDeleteProgram(id);
}

namespace {

std::string shaderLog(GLuint shader)
{
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(length > 0 ? length : 1), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log;
}

} // namespace

Program::Program(const std::vector<ShaderStageSource>& stages)
{
    const GLuint program = glCreateProgram();
    m_handle = Handle<deleteProgram>(program);
    std::vector<GLuint> shaders;
    for (const ShaderStageSource& stage : stages) {
        const GLuint shader = glCreateShader(stage.stage);
        const char* text = stage.source.c_str();
        glShaderSource(shader, 1, &text, nullptr);
        glCompileShader(shader);
        GLint ok = 0;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            const std::string log = shaderLog(shader);
            glDeleteShader(shader);
            for (GLuint s : shaders)
                glDeleteShader(s);
            throw std::runtime_error("GLSL compile error in " + stage.name + ":\n" + log);
        }
        glAttachShader(program, shader);
        shaders.push_back(shader);
    }
    glLinkProgram(program);
    for (GLuint s : shaders) {
        glDetachShader(program, s);
        glDeleteShader(s);
    }
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
        std::string log(std::size_t(length > 0 ? length : 1), '\0');
        glGetProgramInfoLog(program, length, nullptr, log.data());
        std::string names;
        for (const ShaderStageSource& stage : stages)
            names += " " + stage.name;
        throw std::runtime_error("GLSL link error in" + names + ":\n" + log);
    }
}

void Program::use() const
{
    glUseProgram(id());
}

GLint Program::location(const char* name) const
{
    auto it = m_locations.find(name);
    if (it == m_locations.end())
        it = m_locations.emplace(name, glGetUniformLocation(id(), name)).first;
    return it->second;
}

void Program::set(const char* name, int v) const
{
    glProgramUniform1i(id(), location(name), v);
}
void Program::set(const char* name, unsigned v) const
{
    glProgramUniform1ui(id(), location(name), v);
}
void Program::set(const char* name, float v) const
{
    glProgramUniform1f(id(), location(name), v);
}
void Program::set(const char* name, const glm::vec2& v) const
{
    glProgramUniform2fv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::vec3& v) const
{
    glProgramUniform3fv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::ivec3& v) const
{
    glProgramUniform3iv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::vec4& v) const
{
    glProgramUniform4fv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::mat3& v) const
{
    glProgramUniformMatrix3fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(v));
}

void Program::set(const char* name, const glm::mat4& v) const
{
    glProgramUniformMatrix4fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(const char* name, const std::vector<glm::vec4>& v) const
{
    if (!v.empty())
        glProgramUniform4fv(id(), location(name), GLsizei(v.size()), glm::value_ptr(v[0]));
}

void Program::set(const char* name, const std::vector<float>& v) const
{
    if (!v.empty())
        glProgramUniform1fv(id(), location(name), GLsizei(v.size()), v.data());
}

} // namespace vct::gl
