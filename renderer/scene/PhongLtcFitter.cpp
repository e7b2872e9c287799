#include "scene/PhongLtcFitter.h"

#include "scene/PhongLobe.h"

#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <thread>

namespace vct::render {

namespace {

constexpr int kMaxIterations = 600;
constexpr int kRegionCorners = 8;
constexpr int kLobeSamples = 256; // per axis, stratified over the lobe
using Region = std::array<glm::dvec3, kRegionCorners>;

/**
 * What a fit is judged on: the lobe's integral over spherical octagons of several sizes around and beside its
 * peak (as lights of several sizes and places would see it), against the fit's, which Lambert's formula gives
 * exactly. Matching integrals rather than densities is what the renderer needs: a linearly transformed cosine
 * has heavier tails than cos^n, and a fit to the densities' peak (Heitz et al.'s cubed difference) left
 * lights a lobe-width wide 10-15% short.
 */
struct FitTarget {
    std::vector<Region> regions;
    std::vector<double> lobeShares; ///< the normalised lobe's integral over each region
};

/** The spherical octagon inscribed in the cap of angular @p radius about @p centre, counter-clockwise about
 * it. */
Region capPolygon(const glm::dvec3& centre, double radius)
{
    const glm::dvec3 helper = std::abs(centre.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(helper, centre));
    const glm::dvec3 v = glm::cross(centre, u);
    Region region;
    for (int i = 0; i < kRegionCorners; ++i) {
        const double phi = 2.0 * 3.14159265358979323846 * i / kRegionCorners;
        region[std::size_t(i)]
            = std::cos(radius) * centre + std::sin(radius) * (std::cos(phi) * u + std::sin(phi) * v);
    }
    return region;
}

bool insideRegion(const Region& region, const glm::dvec3& direction)
{
    for (int i = 0; i < kRegionCorners; ++i)
        if (glm::dot(
                direction, glm::cross(region[std::size_t(i)], region[std::size_t((i + 1) % kRegionCorners)]))
            < 0.0)
            return false;
    return true;
}

FitTarget targetFor(const PhongLobe& lobe)
{
    FitTarget target;
    const double width = std::sqrt(2.0 / (lobe.shininess() + 2.0));
    const glm::dvec3 mirror = lobe.mirror();
    const glm::dvec3 inPlane { mirror.z, 0.0, -mirror.x }; // toward the normal side, in the plane of view
    const glm::dvec3 across { 0.0, 1.0, 0.0 };
    const std::array<glm::dvec2, 7> offsets { glm::dvec2(0, 0), glm::dvec2(-1, 0), glm::dvec2(1, 0),
        glm::dvec2(-2, 0), glm::dvec2(2, 0), glm::dvec2(0, 1), glm::dvec2(0, 2) };
    for (const glm::dvec2& offset : offsets) {
        const glm::dvec2 angle = glm::min(glm::abs(offset * width), glm::dvec2(1.2)) * glm::sign(offset);
        const glm::dvec3 centre
            = glm::normalize(mirror + std::tan(angle.x) * inPlane + std::tan(angle.y) * across);
        for (const double radius : { 0.25, 0.5, 1.0, 2.0, 4.0 })
            target.regions.push_back(capPolygon(centre, std::min(radius * width, 1.4)));
    }
    target.lobeShares.assign(target.regions.size(), 0.0);
    for (int i = 0; i < kLobeSamples; ++i)
        for (int j = 0; j < kLobeSamples; ++j) {
            const glm::dvec3 d = lobe.sample((i + 0.5) / kLobeSamples, (j + 0.5) / kLobeSamples);
            const double density = lobe.samplingDensity(d);
            const double weight = density > 0.0 ? lobe.value(d) / density : 0.0;
            if (weight <= 0.0)
                continue;
            for (std::size_t r = 0; r < target.regions.size(); ++r)
                if (insideRegion(target.regions[r], d))
                    target.lobeShares[r] += weight;
        }
    for (double& share : target.lobeShares)
        share /= double(kLobeSamples) * kLobeSamples * lobe.albedo();
    return target;
}

double targetError(const FitTarget& target, const PhongLtcFitter::Parameters& parameters)
{
    const LinearlyTransformedCosine ltc(PhongLtcFitter::matrixOf(parameters), PhongLtcTable::kPower);
    double sum = 0.0;
    for (std::size_t r = 0; r < target.regions.size(); ++r) {
        const double difference = ltc.polygonIntegral(target.regions[r]) - target.lobeShares[r];
        // Relative for small shares, absolute for large ones.
        sum += difference * difference / (target.lobeShares[r] + 0.02);
    }
    return sum / double(target.regions.size());
}

/** Nelder-Mead with the usual coefficients (reflection 1, expansion 2, contraction and shrink 1/2). */
template <typename Objective>
PhongLtcFitter::Parameters minimise(Objective objective, const PhongLtcFitter::Parameters& start)
{
    constexpr int kDimensions = 4;
    const PhongLtcFitter::Parameters steps { 0.1, 0.1, 0.05, 0.05 };
    std::array<PhongLtcFitter::Parameters, kDimensions + 1> points;
    std::array<double, kDimensions + 1> values;
    for (int i = 0; i <= kDimensions; ++i) {
        points[i] = start;
        if (i > 0)
            points[i][i - 1] += steps[i - 1];
        values[i] = objective(points[i]);
    }
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        std::array<int, kDimensions + 1> order;
        for (int i = 0; i <= kDimensions; ++i)
            order[i] = i;
        std::sort(order.begin(), order.end(), [&](int a, int b) { return values[a] < values[b]; });
        const int best = order[0], worst = order[kDimensions], secondWorst = order[kDimensions - 1];
        double spread = 0.0;
        for (int i = 1; i <= kDimensions; ++i)
            spread = std::max(spread, glm::length(points[order[i]] - points[best]));
        if (spread < 1e-6 || values[worst] - values[best] <= 1e-9 * std::abs(values[best]))
            break;
        PhongLtcFitter::Parameters centroid(0.0);
        for (int i = 0; i < kDimensions; ++i)
            centroid += points[order[i]] / double(kDimensions);
        const PhongLtcFitter::Parameters reflected = centroid + (centroid - points[worst]);
        const double reflectedValue = objective(reflected);
        if (reflectedValue < values[best]) {
            const PhongLtcFitter::Parameters expanded = centroid + 2.0 * (centroid - points[worst]);
            const double expandedValue = objective(expanded);
            if (expandedValue < reflectedValue) {
                points[worst] = expanded;
                values[worst] = expandedValue;
            } else {
                points[worst] = reflected;
                values[worst] = reflectedValue;
            }
            continue;
        }
        if (reflectedValue < values[secondWorst]) {
            points[worst] = reflected;
            values[worst] = reflectedValue;
            continue;
        }
        const bool outside = reflectedValue < values[worst];
        const PhongLtcFitter::Parameters contracted
            = outside ? centroid + 0.5 * (reflected - centroid) : centroid + 0.5 * (points[worst] - centroid);
        const double contractedValue = objective(contracted);
        if (contractedValue < std::min(values[worst], outside ? reflectedValue : values[worst])) {
            points[worst] = contracted;
            values[worst] = contractedValue;
            continue;
        }
        for (int i = 0; i <= kDimensions; ++i)
            if (i != best) {
                points[i] = points[best] + 0.5 * (points[i] - points[best]);
                values[i] = objective(points[i]);
            }
    }
    return points[std::size_t(std::min_element(values.begin(), values.end()) - values.begin())];
}

} // namespace

glm::dmat3 PhongLtcFitter::matrixOf(const Parameters& p)
{
    const double a = std::exp(p.x), c = std::exp(p.y), b = p.z;
    const double cosPhi = std::cos(p.w), sinPhi = std::sin(p.w);
    glm::dmat3 m(0.0); // m[column][row]: R_y(phi) [[a, 0, b], [0, c, 0], [0, 0, 1]]
    m[0][0] = cosPhi * a;
    m[2][0] = cosPhi * b + sinPhi;
    m[1][1] = c;
    m[0][2] = -sinPhi * a;
    m[2][2] = -sinPhi * b + cosPhi;
    return m;
}

PhongLtcFitter::Parameters PhongLtcFitter::parametersOf(const glm::dmat3& m)
{
    const double phi = std::atan2(-m[0][2], m[0][0]);
    const double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    // R_y(phi)^T m = s [[a, 0, b], [0, c, 0], [0, 0, 1]]
    const double scale = sinPhi * m[2][0] + cosPhi * m[2][2];
    const double a = (cosPhi * m[0][0] - sinPhi * m[0][2]) / scale;
    const double b = (cosPhi * m[2][0] - sinPhi * m[2][2]) / scale;
    return { std::log(a), std::log(m[1][1] / scale), b, phi };
}

double PhongLtcFitter::error(const PhongLobe& lobe, const Parameters& parameters)
{
    return targetError(targetFor(lobe), parameters);
}

PhongLtcFitter::Fit PhongLtcFitter::fit(const PhongLobe& lobe, const Parameters& start)
{
    const FitTarget target = targetFor(lobe);
    const auto objective = [&target](const Parameters& p) { return targetError(target, p); };
    Fit result;
    result.parameters = minimise(objective, start);
    // A second start from the first one's end: Nelder-Mead's simplex may have collapsed along a valley.
    result.parameters = minimise(objective, result.parameters);
    result.matrix = matrixOf(result.parameters);
    result.error = objective(result.parameters);
    return result;
}

PhongLtcTable::Cell PhongLtcFitter::cellOf(const PhongLobe& lobe, const Fit& fit)
{
    const glm::dmat3 inverse = glm::inverse(fit.matrix);
    const double scale = 1.0 / inverse[1][1];
    return { float(inverse[0][0] * scale), float(inverse[2][0] * scale), float(inverse[0][2] * scale),
        float(inverse[2][2] * scale), float(lobe.albedo()) };
}

std::vector<PhongLtcTable::Cell> PhongLtcFitter::fitTable(int threads)
{
    constexpr int n = PhongLtcTable::kSize;
    std::vector<PhongLtcTable::Cell> cells(std::size_t(n * n));
    // Normal view, from the roughest lobe (shininess 0 at normal view is the cosine itself) to the sharpest.
    std::vector<Parameters> rowStarts(static_cast<std::size_t>(n));
    Parameters previous(0.0);
    for (int row = n - 1; row >= 0; --row) {
        const PhongLobe lobe(PhongLtcTable::cosViewAt(0), PhongLtcTable::shininessAt(row));
        const Fit f = fit(lobe, previous);
        cells[std::size_t(row * n)] = cellOf(lobe, f);
        rowStarts[std::size_t(row)] = previous = f.parameters;
    }
    // Then each row toward grazing views, each cell from its neighbour turned by the mirror's own turn.
    const auto fitRow = [&](int row) {
        Parameters p = rowStarts[std::size_t(row)];
        for (int column = 1; column < n; ++column) {
            const double turn = std::acos(PhongLtcTable::cosViewAt(column))
                - std::acos(PhongLtcTable::cosViewAt(column - 1));
            p.w -= turn;
            const PhongLobe lobe(
                std::max(PhongLtcTable::cosViewAt(column), 1e-3), PhongLtcTable::shininessAt(row));
            const Fit f = fit(lobe, p);
            cells[std::size_t(row * n + column)] = cellOf(lobe, f);
            p = f.parameters;
        }
    };
    std::vector<std::thread> workers;
    const int count = std::max(threads, 1);
    for (int t = 0; t < count; ++t)
        workers.emplace_back([&, t] {
            for (int row = t; row < n; row += count)
                fitRow(row);
        });
    for (std::thread& worker : workers)
        worker.join();
    return cells;
}

} // namespace vct::render
