#include "cli/PathTracerCurve.h"

#include <algorithm>
#include <cmath>

namespace vct::cli {

PathTracerCurve::PathTracerCurve(const std::vector<AccuracyRow>& rows)
{
    for (const AccuracyRow& row : rows)
        if (!row.isVct() && std::isfinite(row.wallMs) && std::isfinite(row.relMse))
            m_points.push_back(row);
    std::stable_sort(m_points.begin(), m_points.end(),
        [](const AccuracyRow& a, const AccuracyRow& b) { return a.spp < b.spp; });
}

PathTracerTime PathTracerCurve::timeToReach(double relMse) const
{
    PathTracerTime result;
    if (m_points.empty() || !std::isfinite(relMse))
        return result;
    for (std::size_t i = 0; i < m_points.size(); ++i) {
        if (m_points[i].relMse > relMse)
            continue;
        if (i == 0) {
            result.kind = PathTracerTime::Kind::AtMost;
            result.ms = m_points[0].wallMs;
            result.cpuMs = m_points[0].cpuMs;
            result.spp = m_points[0].spp;
            return result;
        }
        const AccuracyRow& a = m_points[i - 1];
        const AccuracyRow& b = m_points[i];
        result.kind = PathTracerTime::Kind::Interpolated;
        // Error falls as a power of the samples, so straight lines in log-log space.
        const double la = std::log(a.relMse), lb = std::log(b.relMse);
        const double t = la > lb && relMse > 0.0 ? (la - std::log(relMse)) / (la - lb) : 1.0;
        const auto lerpLog = [t](double x, double y) {
            return x > 0.0 && y > 0.0 ? std::exp(std::log(x) + t * (std::log(y) - std::log(x))) : y;
        };
        result.ms = lerpLog(a.wallMs, b.wallMs);
        result.cpuMs = lerpLog(a.cpuMs, b.cpuMs);
        result.spp = lerpLog(double(a.spp), double(b.spp));
        return result;
    }
    result.kind = PathTracerTime::Kind::Beyond;
    result.ms = m_points.back().wallMs;
    result.cpuMs = m_points.back().cpuMs;
    result.spp = m_points.back().spp;
    return result;
}

} // namespace vct::cli
