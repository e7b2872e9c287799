#pragma once

#include <QStringList>

namespace vct::doc {

/** What ModelImporter did to a file's data on the way in; counts accumulate over several imports. */
struct ImportReport {
    int meshes = 0; ///< Triangle meshes appended to the scene (one per mesh instance in the node tree).
    int triangles = 0; ///< Triangles appended.
    int droppedTriangles = 0; ///< Triangles left out: the sum of the three counts below.
    int nonFiniteTriangles = 0; ///< Left out for a NaN or infinite vertex position.
    int badIndexTriangles = 0; ///< Left out for a vertex index beyond the mesh's vertices.
    int zeroAreaTriangles = 0; ///< Left out for (nearly) zero area: collinear or repeated corners.
    int repairedNormals = 0; ///< Vertex normals that were missing, NaN or zero length and were recomputed.
    int clampedMaterials
        = 0; ///< Materials whose albedo + specular exceeded 1 in a channel and were scaled down.
    int ignoredMeshes = 0; ///< Point or line meshes, which the renderer cannot draw.
    QStringList warnings; ///< Human-readable, one line each, naming the file.
};

} // namespace vct::doc
