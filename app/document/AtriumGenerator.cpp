#include "AtriumGenerator.h"

#include "MeshBuilder.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace vct::doc {

namespace {

constexpr float kPi = glm::pi<float>();

constexpr float kHalfLength = AtriumGenerator::kLength * 0.5f;
constexpr float kHalfWidth = AtriumGenerator::kWidth * 0.5f;
constexpr float kWallThickness = 0.6f;
constexpr int kBays = 8;
constexpr float kBayWidth = AtriumGenerator::kLength / kBays;
constexpr float kFacadeHalfThickness = 0.3f;

// Column profile, bottom to top: square plinth, base moulding, tapering shaft, flaring echinus, square
// abacus.
constexpr float kPlinthHalf = 0.45f;
constexpr float kPlinthHeight = 0.25f;
constexpr float kMouldingHeight = 0.2f;
constexpr float kMouldingRadius = 0.38f;
constexpr float kShaftBottomRadius = 0.3f;
constexpr float kShaftTopRadius = 0.27f;
constexpr float kEchinusHeight = 0.3f;
constexpr float kEchinusTopRadius = 0.42f;
constexpr float kAbacusHalf = 0.45f;
constexpr float kAbacusHeight = 0.2f;
constexpr int kColumnSegments = 32;
constexpr int kShaftRings = 8;

// The arch springs 0.1 m inside the abacus, which leaves a 0.35 m pier at the end walls.
constexpr float kArchRadius = kBayWidth * 0.5f - 0.35f;
constexpr int kArchSegments = 32;

/** One storey of an arcade: columns from `floorY` up to `springY`, arches and wall up to `topY`. */
struct Storey {
    float floorY;
    float springY;
    float topY;
    bool parapet;
};

constexpr float kGalleryFloorBottom = 5.6f;
constexpr float kGalleryFloorTop = 5.9f;
constexpr float kUpperCeiling = 10.8f;
constexpr std::array<Storey, 2> kStoreys { {
    { AtriumGenerator::kFloorY, 3.5f, kGalleryFloorTop, false },
    { kGalleryFloorTop, 8.9f, AtriumGenerator::kHeight, true },
} };
constexpr float kParapetHeight = 1.0f;
constexpr float kParapetHalfThickness = 0.15f;

constexpr int kClothColumns = 12;
constexpr int kClothRows = 28;
constexpr float kClothWidth = 2.0f;
constexpr float kClothLength = 4.4f;
constexpr float kClothOffset = 0.5f; // In front of the arcade's centre line, metres.
constexpr float kClothFold = 0.08f; // Amplitude of the vertical folds, metres.
constexpr float kClothBillow = 0.15f; // How far the hem swings out into the courtyard, metres.
constexpr float kClothThickness = 0.01f;

float columnX(int i)
{
    return -kHalfLength + kBayWidth * float(i);
}

void addColumn(MeshBuilder& b, const glm::vec3& foot, float springY)
{
    const float shaftBottom = foot.y + kPlinthHeight + kMouldingHeight;
    const float shaftTop = springY - kAbacusHeight - kEchinusHeight;
    const glm::vec3 plinth(kPlinthHalf, 0.0f, kPlinthHalf);
    b.addBox(foot - plinth, foot + plinth + glm::vec3(0.0f, kPlinthHeight, 0.0f), 1.0f);
    b.addFrustum({ foot.x, foot.y + kPlinthHeight, foot.z }, kMouldingRadius, kShaftBottomRadius,
        kMouldingHeight, kColumnSegments, 2);
    b.addFrustum({ foot.x, shaftBottom, foot.z }, kShaftBottomRadius, kShaftTopRadius, shaftTop - shaftBottom,
        kColumnSegments, kShaftRings);
    b.addFrustum(
        { foot.x, shaftTop, foot.z }, kShaftTopRadius, kEchinusTopRadius, kEchinusHeight, kColumnSegments, 3);
    const glm::vec3 abacus(kAbacusHalf, 0.0f, kAbacusHalf);
    b.addBox(glm::vec3(foot.x, springY - kAbacusHeight, foot.z) - abacus,
        glm::vec3(foot.x, springY, foot.z) + abacus, 1.0f);
}

/** Angles from pi down to 0 along the arch, including the directions of the panel's two upper corners. */
std::vector<float> archAngles(float halfWidth, float height)
{
    std::vector<float> angles;
    for (int k = 0; k <= kArchSegments; ++k)
        angles.push_back(kPi * (1.0f - float(k) / kArchSegments));
    angles.push_back(std::atan2(height, -halfWidth));
    angles.push_back(std::atan2(height, halfWidth));
    std::sort(angles.begin(), angles.end(), std::greater<>());
    angles.erase(std::unique(angles.begin(), angles.end(), [](float a, float b) { return a - b < 1e-4f; }),
        angles.end());
    return angles;
}

/**
 * The wall of one bay above the springing line: a rectangle x0..x1, springY..topY with a semicircular
 * opening, its two faces, the arch's underside (intrados) and the flat undersides beside the arch. `facadeZ`
 * is the arcade's centre line.
 */
void addArchBay(MeshBuilder& b, float x0, float x1, const Storey& storey, float facadeZ)
{
    const float xm = 0.5f * (x0 + x1);
    const float zMin = facadeZ - kFacadeHalfThickness;
    const float zMax = facadeZ + kFacadeHalfThickness;
    const glm::vec2 centre(xm, storey.springY);
    const float height = storey.topY - storey.springY;
    auto inner = [&](float a) { return centre + kArchRadius * glm::vec2(std::cos(a), std::sin(a)); };
    // Where the ray from the arch centre meets the panel's left, top or right edge.
    auto outer = [&](float a) {
        const glm::vec2 dir(std::cos(a), std::sin(a));
        float t = 1e9f;
        if (dir.x > 1e-6f)
            t = std::min(t, (x1 - xm) / dir.x);
        if (dir.x < -1e-6f)
            t = std::min(t, (x0 - xm) / dir.x);
        if (dir.y > 1e-6f)
            t = std::min(t, height / dir.y);
        return centre + t * dir;
    };
    auto at = [](const glm::vec2& p, float z) { return glm::vec3(p.x, p.y, z); };

    const std::vector<float> angles = archAngles(0.5f * (x1 - x0), height);
    for (size_t k = 0; k + 1 < angles.size(); ++k) {
        const float a = angles[k];
        const float c = angles[k + 1];
        for (const float z : { zMin, zMax }) {
            const glm::vec3 facing(0.0f, 0.0f, z < facadeZ ? -1.0f : 1.0f);
            b.addQuad(at(inner(a), z), at(inner(c), z), at(outer(c), z), at(outer(a), z), facing);
        }
        const glm::vec3 na(-std::cos(a), -std::sin(a), 0.0f);
        const glm::vec3 nc(-std::cos(c), -std::sin(c), 0.0f);
        b.addQuad(
            at(inner(a), zMin), at(inner(c), zMin), at(inner(c), zMax), at(inner(a), zMax), na, nc, nc, na);
    }
    const glm::vec3 down(0.0f, -1.0f, 0.0f);
    const float y0 = storey.springY;
    b.addQuad({ x0, y0, zMin }, { xm - kArchRadius, y0, zMin }, { xm - kArchRadius, y0, zMax },
        { x0, y0, zMax }, down);
    b.addQuad({ xm + kArchRadius, y0, zMin }, { x1, y0, zMin }, { x1, y0, zMax },
        { xm + kArchRadius, y0, zMax }, down);
    const float y1 = storey.topY;
    b.addQuad(
        { x0, y1, zMin }, { x1, y1, zMin }, { x1, y1, zMax }, { x0, y1, zMax }, glm::vec3(0.0f, 1.0f, 0.0f));
}

/** Columns, end piers, arches and (upper storey) parapets of one storey along the line z = facadeZ. */
void addArcadeStorey(MeshBuilder& columns, MeshBuilder& stone, const Storey& storey, float facadeZ)
{
    const float pierWidth = kBayWidth * 0.5f - kArchRadius;
    const float zMin = facadeZ - kFacadeHalfThickness;
    const float zMax = facadeZ + kFacadeHalfThickness;
    for (int i = 1; i < kBays; ++i)
        addColumn(columns, { columnX(i), storey.floorY, facadeZ }, storey.springY);
    stone.addBox(
        { -kHalfLength, storey.floorY, zMin }, { -kHalfLength + pierWidth, storey.springY, zMax }, 1.0f);
    stone.addBox(
        { kHalfLength - pierWidth, storey.floorY, zMin }, { kHalfLength, storey.springY, zMax }, 1.0f);
    for (int i = 0; i < kBays; ++i) {
        addArchBay(stone, columnX(i), columnX(i + 1), storey, facadeZ);
        if (storey.parapet) {
            // Parapets run into the columns; the ends hide inside the shafts.
            const float x0 = i == 0 ? -kHalfLength : columnX(i) + 0.2f;
            const float x1 = i == kBays - 1 ? kHalfLength : columnX(i + 1) - 0.2f;
            stone.addBox({ x0, storey.floorY, facadeZ - kParapetHalfThickness },
                { x1, storey.floorY + kParapetHeight, facadeZ + kParapetHalfThickness }, 1.0f);
        }
    }
}

/** Outer walls, galleries' floor slab and ceilings, both arcades. */
void addBuilding(MeshBuilder& stone, MeshBuilder& columns)
{
    const float top = AtriumGenerator::kHeight;
    const float outerX = kHalfLength + kWallThickness;
    const float outerZ = kHalfWidth + kWallThickness;
    for (const float side : { -1.0f, 1.0f }) {
        // Long walls (the galleries' back walls) and end walls.
        stone.addBox({ -outerX, AtriumGenerator::kFloorY, side > 0 ? kHalfWidth : -outerZ },
            { outerX, top, side > 0 ? outerZ : -kHalfWidth }, 1.0f);
        stone.addBox({ side > 0 ? kHalfLength : -outerX, AtriumGenerator::kFloorY, -kHalfWidth },
            { side > 0 ? outerX : -kHalfLength, top, kHalfWidth }, 1.0f);

        const float facadeZ = side * AtriumGenerator::kArcadeZ;
        const float galleryNear = AtriumGenerator::kArcadeZ + kFacadeHalfThickness;
        const float zLow = side > 0 ? galleryNear : -kHalfWidth;
        const float zHigh = side > 0 ? kHalfWidth : -galleryNear;
        stone.addBox(
            { -kHalfLength, kGalleryFloorBottom, zLow }, { kHalfLength, kGalleryFloorTop, zHigh }, 1.0f);
        stone.addBox({ -kHalfLength, kUpperCeiling, zLow }, { kHalfLength, top, zHigh }, 1.0f);
        for (const Storey& storey : kStoreys)
            addArcadeStorey(columns, stone, storey, facadeZ);
    }
}

/**
 * A cloth hanging from the upper parapet at x = centreX in front of the arcade z = facadeZ, with vertical
 * folds and a hem that swings out into the courtyard. Both faces are modelled, kClothThickness apart.
 */
void addCloth(MeshBuilder& b, float centreX, float facadeZ, float phase)
{
    const float toCourtyard = facadeZ > 0.0f ? -1.0f : 1.0f;
    const float topY = kGalleryFloorTop + kParapetHeight;
    const float planeZ = facadeZ + toCourtyard * kClothOffset;
    // s runs across, t down; x runs so that cross(dP/ds, dP/dt) faces the courtyard.
    auto surface = [=](float s, float t, float offset) {
        const float x = centreX - toCourtyard * (s - 0.5f) * kClothWidth;
        const float folds = kClothFold * std::sin(2.0f * kPi * 3.0f * s + phase) * (0.3f + 0.7f * t);
        const float z = planeZ + toCourtyard * (folds + kClothBillow * t * t + offset);
        return glm::vec3(x, topY - kClothLength * t, z);
    };
    b.addSurface(kClothColumns, kClothRows, [=](float s, float t) { return surface(s, t, 0.0f); });
    // The back: mirrored in s to turn the winding around.
    b.addSurface(
        kClothColumns, kClothRows, [=](float s, float t) { return surface(1.0f - s, t, -kClothThickness); });
}

void addFloor(MeshBuilder& b)
{
    constexpr float kCell = 0.5f;
    b.addGrid({ -kHalfLength, AtriumGenerator::kFloorY, -kHalfWidth },
        { 0.0f, 0.0f, AtriumGenerator::kWidth }, { AtriumGenerator::kLength, 0.0f, 0.0f },
        int(AtriumGenerator::kWidth / kCell), int(AtriumGenerator::kLength / kCell));
}

int addMaterial(render::Scene& scene, const std::string& name, const glm::vec3& albedo)
{
    render::Material material;
    material.name = name;
    material.albedo = albedo;
    scene.materials.push_back(material);
    return int(scene.materials.size()) - 1;
}

} // namespace

void AtriumGenerator::generate(render::Scene& scene)
{
    const int stoneMaterial = addMaterial(scene, "atrium_stone", { 0.68f, 0.64f, 0.58f });
    const int columnMaterial = addMaterial(scene, "atrium_column", { 0.7f, 0.67f, 0.61f });
    const int floorMaterial = addMaterial(scene, "atrium_floor", { 0.5f, 0.45f, 0.39f });
    // The building is seen from inside and lit from inside: its stone shows front faces only, which leaves
    // the faces turned away out of the g-buffer and the shadow maps (the cloths, thin sheets, keep both).
    for (const int m : { stoneMaterial, columnMaterial, floorMaterial })
        scene.materials[std::size_t(m)].doubleSided = false;
    // Polished stone, as in the paper's courtyard: a faint glossy reflection exercises the specular cone.
    scene.materials[std::size_t(floorMaterial)].specular = glm::vec3(0.08f);
    scene.materials[std::size_t(floorMaterial)].shininess = 80.0f;
    const std::array<int, 3> clothMaterials {
        addMaterial(scene, "cloth_red", { 0.75f, 0.08f, 0.06f }),
        addMaterial(scene, "cloth_green", { 0.1f, 0.55f, 0.15f }),
        addMaterial(scene, "cloth_blue", { 0.08f, 0.15f, 0.65f }),
    };

    MeshBuilder floor;
    addFloor(floor);
    MeshBuilder stone;
    MeshBuilder columns;
    addBuilding(stone, columns);
    scene.meshes.push_back(floor.build("atrium_floor", floorMaterial));
    scene.meshes.push_back(stone.build("atrium_walls_and_arches", stoneMaterial));
    scene.meshes.push_back(columns.build("atrium_columns", columnMaterial));

    std::array<MeshBuilder, 3> cloths;
    int next = 0;
    for (const float facadeZ : { kArcadeZ, -kArcadeZ }) {
        for (int bay = 1; bay < kBays; bay += 2) {
            const float centreX = columnX(bay) + 0.5f * kBayWidth;
            addCloth(cloths[size_t(next % 3)], centreX, facadeZ, 0.7f * float(next));
            ++next;
        }
    }
    const std::array<const char*, 3> clothNames { "atrium_cloths_red", "atrium_cloths_green",
        "atrium_cloths_blue" };
    for (size_t i = 0; i < cloths.size(); ++i)
        scene.meshes.push_back(cloths[i].build(clothNames[i], clothMaterials[i]));
}

} // namespace vct::doc
