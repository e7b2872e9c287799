#include "gl/DebugOutput.h"

#include <glad/gl.h>

#include <mutex>
#include <sstream>

namespace vct::gl {

namespace {

std::mutex g_mutex;
std::vector<std::string> g_errors;

void GLAPIENTRY onMessage(
    GLenum, GLenum type, GLuint id, GLenum severity, GLsizei, const GLchar* message, const void*)
{
    if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH)
        return;
    std::ostringstream text;
    text << "GL debug (id " << id << "): " << message;
    std::lock_guard lock(g_mutex);
    g_errors.push_back(text.str());
}

} // namespace

void DebugOutput::enable()
{
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onMessage, nullptr);
}

std::vector<std::string> DebugOutput::takeErrors()
{
    std::vector<std::string> errors;
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
        std::ostringstream text;
        text << "glGetError 0x" << std::hex << e;
        errors.push_back(text.str());
    }
    std::lock_guard lock(g_mutex);
    errors.insert(errors.end(), g_errors.begin(), g_errors.end());
    g_errors.clear();
    return errors;
}

} // namespace vct::gl
