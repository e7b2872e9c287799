#pragma once

#include "ImportReport.h"
#include "scene/Scene.h"

#include <QString>

namespace vct::doc {

/**
 * Imports a model file (anything Assimp reads: OBJ, glTF/GLB, PLY, FBX, ...) into a render::Scene.
 *
 * Conventions of the result:
 * - Each mesh instance of the node tree becomes one render::Mesh with the accumulated node transform; only
 *   triangles are kept (points and lines are counted in ImportReport::ignoredMeshes and skipped).
 * - Materials: OBJ Kd -> albedo, Ke -> emission (radiance, W/(m^2 sr)), Ks -> specular, Ns -> shininess (only
 * when Ks is non-zero). glTF metallic-roughness: albedo = base * (1 - metallic), specular = mix(0.04, base,
 * metallic), shininess = 2/a^2 - 2 with a = roughness^2, capped at kMaxShininess; below shininess 1
 * (roughness above ~0.9) the lobe is as wide as a Lambertian one, so the specular part is folded into the
 * albedo and shininess is 0. emission = emissiveFactor * KHR_materials_emissive_strength. Then albedo +
 * specular is scaled to <= 1 per channel.
 * - Only materials that a mesh uses are appended. Textures: the diffuse / base-colour map, decoded to
 * RGBA8888 rows top to bottom; uvs are flipped so that v = 0 is the top row (the first row of
 * TextureImage::rgba).
 * - Mesh names: "node/mesh" from the file, said once when both are the same ("floor", not "floor/floor").
 * Names the file did not give (empty, Assimp's "defaultobject" for an OBJ without groups, bracketed loader
 * names) become the file's base name: "bunny", and "bunny 2", ... only when several meshes of one import
 * would share it.
 * - Triangles with a non-finite vertex or zero area are dropped; missing, NaN or zero normals are recomputed
 * from the adjacent faces; vertices no triangle uses are removed.
 */
class ModelImporter {
public:
    static constexpr float kMaxShininess = 10000.0f;

    /**
     * Appends the model at `path` (a file or Qt resource path) to `scene`: meshes, then the materials and
     * textures they use, with indices offset past what `scene` already holds. Lights and camera of the file
     * are ignored. On failure (file missing, Assimp error, no triangles) returns false, leaves `scene`
     * unchanged and writes a message naming the file to `error`. `report`, if given, accumulates counts and
     * warnings.
     */
    static bool importModel(
        const QString& path, render::Scene& scene, QString* error, ImportReport* report = nullptr);
};

} // namespace vct::doc
