#pragma once

#include "scene/LinearlyTransformedCosine.h"
#include "scene/PhongLtcTable.h"

#include <glm/mat3x3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace vct::render {

class PhongLobe;

/**
 * Fits linearly transformed cosines to the Phong lobe (PhongLobe) over PhongLtcTable's grid of view angles
 * and shininesses, as Heitz et al. 2016 did for GGX: per cell, Nelder-Mead over the matrix M = R_y(phi) [[a,
 * 0, b], [0, c, 0], [0, 0, 1]] (the four degrees of freedom an isotropic lobe with the viewer in the xz-plane
 * has), minimising the cubed difference between the two densities over the sphere, estimated with a fixed set
 * of directions drawn half from each (so the objective is smooth in the parameters). Each cell starts from
 * its rougher neighbour's fit; the roughest cell at normal view is the cosine itself. Offline work:
 * `vct-fit-ltc` writes the table the renderer compiles in.
 */
class PhongLtcFitter {
public:
    /** The fit's parameters: log a, log c, b, phi. */
    using Parameters = glm::dvec4;

    struct Fit {
        Parameters parameters;
        glm::dmat3 matrix;
        double error = 0.0; ///< the objective at the fit (PhongLtcFitter.cpp, targetError)
    };

    static glm::dmat3 matrixOf(const Parameters& parameters);
    /** The parameters of a matrix of the fitted form (up to scale), for restarting a fit from a table cell.
     */
    static Parameters parametersOf(const glm::dmat3& matrix);

    /** The objective for @p lobe at @p parameters. */
    static double error(const PhongLobe& lobe, const Parameters& parameters);
    /** Nelder-Mead from @p start. */
    static Fit fit(const PhongLobe& lobe, const Parameters& start);
    /** The whole table, each cell fitted from its rougher neighbour; rows in parallel on @p threads. */
    static std::vector<PhongLtcTable::Cell> fitTable(int threads);
    /** The table cell of @p fit for @p lobe: M^-1 scaled to (1, 1) = 1, and the lobe's albedo. */
    static PhongLtcTable::Cell cellOf(const PhongLobe& lobe, const Fit& fit);
};

} // namespace vct::render
