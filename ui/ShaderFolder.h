#pragma once

#include <QString>

namespace vct::ui {

/** Where the editor's Render > Reload shaders (F5) reads shader text. */
class ShaderFolder {
public:
    /**
     * $VCT_SHADER_DIR when set, else the shaders/ folder of the source tree the editor was built from when it
     * still exists; empty when neither is there (an installed editor has only its built-in shaders).
     */
    static QString forReload();
};

} // namespace vct::ui
