#pragma once

#include <assimp/IOSystem.hpp>

namespace vct::doc {

/**
 * Lets Assimp open files through QFile, so models embedded as Qt resources (":/scenes/...") load, including
 * the files they reference relative to themselves (an OBJ's mtllib, a glTF's buffers). Paths are UTF-8.
 */
class QtAssimpIOSystem final : public Assimp::IOSystem {
public:
    QtAssimpIOSystem();
    ~QtAssimpIOSystem() override;

    bool Exists(const char* path) const override;
    char getOsSeparator() const override;
    Assimp::IOStream* Open(const char* path, const char* mode = "rb") override;
    void Close(Assimp::IOStream* stream) override;
};

} // namespace vct::doc
