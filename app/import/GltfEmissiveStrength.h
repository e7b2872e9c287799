#pragma once

#include <QString>

#include <vector>

namespace vct::doc {

/**
 * Reads `KHR_materials_emissive_strength` from a glTF file's JSON, which Assimp 5.2 drops on import.
 * glTF keeps emissiveFactor in [0,1] and puts the brightness in this multiplier.
 */
class GltfEmissiveStrength {
public:
    struct Entry {
        QString name; ///< glTF material name, may be empty.
        float strength = 1.0f; ///< Multiplies emissiveFactor; 1 when the extension is absent.
    };

    /**
     * One entry per glTF material, in file order. `path` is a .gltf (JSON) or .glb (binary, JSON chunk first)
     * file, possibly a Qt resource. On failure returns false with a message naming the file in `error`.
     */
    static bool read(const QString& path, std::vector<Entry>& entries, QString* error);

    /** The entry for Assimp's material `index` named `name`: by name when unambiguous, else by index, else 1.
     */
    static float strengthFor(const std::vector<Entry>& entries, const QString& name, unsigned index);
};

} // namespace vct::doc
