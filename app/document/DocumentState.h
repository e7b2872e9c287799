#pragma once

#include "CameraBookmark.h"
#include "LightNode.h"
#include "SceneNode.h"

#include "scene/Camera.h"
#include "scene/Material.h"
#include "scene/RenderSettings.h"

#include <QString>

#include <vector>

namespace vct::doc {

/** Where a group of nodes' geometry comes from: "builtin:NAME" or an absolute model path. */
struct SceneSource {
    QString spec;
    /// Metres per model unit (0.01 for a model in centimetres); the geometry is cached already scaled.
    float unitScale = 1.0f;
    bool operator==(const SceneSource& other) const = default;
};

/** Everything a project saves. Plain data: comparing two states compares two documents. */
struct DocumentState {
    std::vector<SceneSource> sources;
    std::vector<SceneNode> nodes;
    /// albedoTexture indexes the textures of all sources concatenated in source order (source 0's first),
    /// which is exactly Document::buildRenderScene()'s texture list; importing offsets a model's indices.
    std::vector<render::Material> materials;
    std::vector<LightNode> lights;
    render::Camera camera;
    std::vector<CameraBookmark> bookmarks; ///< Named views, in the order they were kept.
    render::RenderSettings settings;
    quint64 nextId = 1; ///< Next free SceneNode/LightNode id.
};

/** Equality of everything a project file stores (settings by their key=value text). */
bool sameDocument(const DocumentState& a, const DocumentState& b);
/** Field-wise equality (render::Material has no operator==). */
bool sameMaterial(const render::Material& a, const render::Material& b);
/** Field-wise equality, near plane included. */
bool sameCamera(const render::Camera& a, const render::Camera& b);
/** Equality of the key=value text of every setting, as a project file stores them. */
bool sameSettings(const render::RenderSettings& a, const render::RenderSettings& b);

} // namespace vct::doc
