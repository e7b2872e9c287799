#pragma once

#include "DocumentState.h"
#include "WholeSources.h"

#include <QByteArray>
#include <QString>

namespace vct::doc {

/**
 * The project file (*.vctproj): versioned JSON holding a DocumentState.
 *
 * `{"format": "vct-studio-project", "version": 1, "sources": [...], "nodes": [...], "materials": [...],
 *   "lights": [...], "camera": {...}, "bookmarks": [...], "settings": {"voxel_res": "128", ...}, "next_id":
 * N}`
 *
 * - sources: spec, and for a model unit_scale (metres per model unit, 0.01 for centimetres; optional, 1
 *   when absent and written only when not 1: an older reader ignores it and loads the model unscaled).
 *   `builtin:NAME` as is; model paths relative to the project file's directory (so a project and its models
 *   move together), resolved to absolute paths on load. A model root, when given, replaces that directory for
 *   reading and writing: a small project can then name a big model kept outside the repository
 *   ("sponza/sponza.obj" under the root).
 * - nodes: id, name, source, mesh, material, translation (metres), rotation_deg (XYZ Euler, degrees), scale,
 *   dynamic, visible.
 * - materials: name, albedo, emission (W/(m^2 sr)), specular, shininess, albedo_texture (index into the
 *   textures of all sources concatenated in source order, or -1).
 * - lights: id, name, type (point|spot|directional|rect|disk), position (m; rects and disks: the centre),
 *   direction, color, intensity (W/sr, W/m^2 or, for rects and disks, radiance in W/(m^2 sr)), shadows; spots
 *   also inner_deg and outer_deg, rects size ([width, height], m) and rotation_deg, disks diameter (m), as
 *   in lights files (LightsFile); point and spot lights radius (m), directional lights angular_diameter_deg,
 *   both optional (0 when absent). New light types and fields came without a new version: an older reader
 *   refuses a new type naming it and ignores the sizes, and every file it could read reads the same.
 * - camera: position, look_at, up, fov_y_deg, near_plane (m).
 * - bookmarks (optional, none when absent): name and the camera's fields, one per kept view.
 * - settings: every RenderSettings key with its value as text, read back through RenderSettings::set.
 *
 * A project may omit both nodes and materials (never just one): every source is then taken whole, one node
 * per mesh with the source's own materials, as an import makes them (Document::openProject does it, since it
 * needs the geometry). The lights are still the project's: a model's sibling NAME.lights.json is not read
 * into the document. Saving such a document writes its nodes and materials in full. A source of such a
 * project may carry "placement": {translation, rotation_deg, scale, dynamic} (all optional), given to every
 * node made from it (WholeSources); a project that lists its nodes refuses it.
 *
 * Loading validates everything and reports the first problem naming the file and the field. Index checks
 * that need the geometry (a node's mesh, a material's texture) are left to the caller (Document).
 */
class ProjectFile {
public:
    static constexpr const char* kFormat = "vct-studio-project";
    static constexpr int kVersion = 1;
    static constexpr qint64 kMaxFileBytes = 64ll * 1024 * 1024; ///< Larger files are refused unread.
    static constexpr int kMaxNodes = 1000000; ///< Also the cap for lights and materials.
    static constexpr int kMaxSources = 100000;
    static constexpr int kMaxNesting = 64; ///< Deepest [ and { nesting accepted (the format needs 4).
    /// The environment variable the command lines take the model root from when no --scene-root is given.
    static constexpr const char* kModelRootVariable = "VCT_SCENE_ROOT";

    /**
     * Reads the project at `path` into `state`. On failure returns false, leaves `state` unchanged and writes
     * a message naming the file and the field to `error`. Model files the sources name must exist; relative
     * ones are looked for under `modelRoot`, or beside the project when it is empty. `wholeSources`, if
     * given, tells whether the project omitted nodes and materials (then `state` has none: the caller makes
     * them from the geometry) and how each source's nodes are placed.
     */
    static bool load(const QString& path, DocumentState* state, QString* error,
        const QString& modelRoot = QString(), WholeSources* wholeSources = nullptr);
    /**
     * Writes `state` to `path` atomically (files::AtomicFile): on failure returns false, any old file there
     * is left byte-identical, and `error` names the file and the reason. Model paths are written relative to
     * `modelRoot`, or to the project's folder when it is empty, so that load() with the same root finds them.
     */
    static bool save(const QString& path, const DocumentState& state, QString* error,
        const QString& modelRoot = QString());
    /** The absolute folder relative model paths of the project at `projectPath` are relative to. */
    static QString modelDir(const QString& projectPath, const QString& modelRoot);

    /** The file's bytes for `state`, model paths made relative to `projectDir`. */
    static QByteArray toJson(const DocumentState& state, const QString& projectDir);
    /**
     * Parses file bytes (as load() does after reading): relative model paths resolve against `projectDir`;
     * `fileName` is used in messages only; `wholeSources` as in load().
     */
    static bool fromJson(const QByteArray& json, const QString& projectDir, const QString& fileName,
        DocumentState* state, QString* error, WholeSources* wholeSources = nullptr);
};

} // namespace vct::doc
