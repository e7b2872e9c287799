#pragma once

#include <glm/glm.hpp>

// The GLSL file is the single definition; here it compiles as C++ over GLM's GLSL-like types.
namespace vct::render::conemath {
using namespace glm;
#include "common/ConeMath.glsl"
} // namespace vct::render::conemath
