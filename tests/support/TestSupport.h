#pragma once

#include "image/RadianceImage.h"
#include "scene/Aabb.h"
#include "scene/Camera.h"
#include "scene/Mesh.h"
#include "scene/Scene.h"

#include <QByteArray>
#include <QString>

#include <vector>

namespace vct::test {

/** The project's source tree (set by CTest), for test data. */
QString sourceDir();
/** tests/data/reference: the Cycles references of the Cornell boxes, kept in the repository. */
QString referenceDir();
/** Where tests write actual/diff images; created on demand. */
QString outputDir();

/** A mesh of unindexed triangles (three positions each) with flat normals. */
render::Mesh makeTriangles(const std::vector<glm::vec3>& positions, int material = 0);
/** A quad (two triangles) with corners a, b, c, d counter-clockwise seen from the front. */
std::vector<glm::vec3> quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d);
/**
 * A 14 m floor at y = 0.5 over x, z in [1, 15] (mesh 0), a small dynamic plate at y = 4.5 over x, z in
 * [3.2, 4.8] (mesh 1) and a point light above: the scene of the moving-object tests.
 */
render::Scene floorAndDynamicPlate();
/** The box spanning two corners. */
render::Aabb box(glm::vec3 lo, glm::vec3 hi);
/** The pixel of a size x size RadianceImage (rows top to bottom) that camera sees world in. */
glm::ivec2 pixelOf(const render::Camera& camera, glm::vec3 world, int size);
/** Where the ray through the centre of @p pixel (of a size x size image) meets the plane y = @p height. */
glm::vec3 floorPointOf(const render::Camera& camera, glm::ivec2 pixel, int size, float height = 0.0f);
/**
 * Irradiance (W/m^2) at floor point @p p from a light of @p radiance (W/(m^2 sr)) facing straight down at
 * @p height, 1 m across and centred over the origin: the square [-0.5, 0.5]^2, or with @p disk the disk of
 * diameter 1 (cells whose centre lies inside it). Brute-force quadrature of E = L * integral of cos cos / r^2
 * dA, independent of the contour integral the renderer evaluates.
 */
double floorIrradianceFromOverheadLight(
    const glm::dvec3& p, double height, double radiance, bool disk = false);
/** The red channel's mean over the 3 x 3 pixels around @p pixel: a path tracer's noise, not its edges,
 * decides. */
double meanAround(const render::RadianceImage& image, glm::ivec2 pixel);
/** The red channel's mean over the whole image. */
double meanRed(const render::RadianceImage& image);
/** "(x, y, z)", for test messages. */
QString describe(const glm::vec3& v);
/** Writes @p bytes to @p path (creating its folder) and returns the path; a test cannot go on if it fails. */
QString writeFile(const QString& path, const QByteArray& bytes);

} // namespace vct::test
