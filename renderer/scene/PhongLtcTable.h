#pragma once

#include <array>

namespace vct::render {

/**
 * The linearly transformed cosines that stand for the Phong lobe (PhongLobe) in the composite's area lights,
 * fitted offline by PhongLtcFitter (`vct-fit-ltc`) and compiled in from PhongLtcTable.inc. A kSize x kSize
 * grid: across, x = sqrt(1 - cos(view angle)) from 0 (normal view) to 1 (grazing); down, the lobe's width
 * r = sqrt(2 / (shininess + 2)) from kMinWidth (shininess kMaxShininess) to 1 (shininess 0), linearly.
 * Shininesses above kMaxShininess use the narrowest fit. The shader (common/AreaLights.glsl) samples the same
 * grid from two textures with linear filtering, texel centres on the grid points.
 */
class PhongLtcTable {
public:
    static constexpr int kSize = 32;
    static constexpr double kMaxShininess = 10000.0;
    /// The fitted distribution is cos^kPower transformed (LinearlyTransformedCosine): the cube's lighter
    /// tails fit cos^n lobes better than the cosine's.
    static constexpr int kPower = 3;

    /** M^-1 in the lobe's frame with its (1, 1) element scaled to 1 (row, column), and the lobe's albedo. */
    struct Cell {
        float m00 = 1.0f, m02 = 0.0f, m20 = 0.0f, m22 = 1.0f;
        float albedo = 1.0f;
    };

    static double minWidth();
    static double cosViewAt(int column);
    static double shininessAt(int row);
    /** Grid coordinates in [0, kSize - 1] of a view cosine and a shininess (clamped to the grid). */
    static double columnOf(double cosView);
    static double rowOf(double shininess);

    /** The compiled-in table, row by row (row-major: cell (row, column) at row * kSize + column). */
    static const std::array<Cell, kSize * kSize>& cells();
    /** Bilinear between grid points, as the shader's texture lookup. */
    static Cell lookup(double cosView, double shininess);
};

} // namespace vct::render
