#include "plot/AxisTicks.h"

#include <algorithm>
#include <cmath>

namespace vct::plot {

namespace {

// Relative slack when comparing data with tick values, so 100 computed as 10^2 still counts as 100.
constexpr double kSlack = 1e-9;

double niceStep(double raw)
{
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double normalized = raw / magnitude;
    const double nice = normalized <= 1.0 ? 1.0 : normalized <= 2.0 ? 2.0 : normalized <= 5.0 ? 5.0 : 10.0;
    return nice * magnitude;
}

} // namespace

AxisRange AxisTicks::linear(double lo, double hi, int targetCount)
{
    if (!std::isfinite(lo) || !std::isfinite(hi))
        lo = 0.0, hi = 1.0;
    if (hi < lo)
        std::swap(lo, hi);
    const double scale = std::max({ std::abs(lo), std::abs(hi), 1e-300 });
    if (hi - lo <= scale * 1e-12) {
        const double pad = lo == 0.0 ? 1.0 : std::abs(lo) * 0.1;
        lo -= pad;
        hi += pad;
    }
    const double step = niceStep((hi - lo) / double(std::max(1, targetCount - 1)));
    AxisRange range;
    const double first = std::floor(lo / step + kSlack);
    const double last = std::ceil(hi / step - kSlack);
    range.min = first * step;
    range.max = last * step;
    for (double i = first; i <= last + 0.5; i += 1.0) {
        const double tick = i * step;
        range.ticks.push_back(std::abs(tick) < step * 1e-9 ? 0.0 : tick); // no "-0"
    }
    return range;
}

AxisRange AxisTicks::log10(double lo, double hi)
{
    if (hi < lo)
        std::swap(lo, hi);
    if (!std::isfinite(hi) || hi <= 0.0)
        lo = 1.0, hi = 10.0;
    if (!std::isfinite(lo) || lo <= 0.0)
        lo = hi / 10.0;
    const int firstDecade = int(std::floor(std::log10(lo) + kSlack));
    int lastDecade = int(std::ceil(std::log10(hi) - kSlack));
    if (lastDecade <= firstDecade)
        lastDecade = firstDecade + 1;

    std::vector<double> candidates;
    if (lastDecade - firstDecade <= 2) {
        // Few decades: 1, 2 and 5 times each so the axis carries more than two or three labels.
        for (int d = firstDecade; d < lastDecade; ++d)
            for (double m : { 1.0, 2.0, 5.0 })
                candidates.push_back(m * std::pow(10.0, d));
    } else {
        const int stride = std::max(1, (lastDecade - firstDecade + 7) / 8);
        for (int d = firstDecade; d < lastDecade; d += stride)
            candidates.push_back(std::pow(10.0, d));
    }
    candidates.push_back(std::pow(10.0, lastDecade));

    AxisRange range;
    range.min = candidates.front();
    range.max = candidates.back();
    for (double c : candidates) {
        if (c <= lo * (1.0 + kSlack))
            range.min = c;
    }
    for (auto it = candidates.rbegin(); it != candidates.rend(); ++it)
        if (*it >= hi * (1.0 - kSlack))
            range.max = *it;
    for (double c : candidates)
        if (c >= range.min && c <= range.max)
            range.ticks.push_back(c);
    return range;
}

AxisRange AxisTicks::fixed(std::vector<double> ticks, double lo, double hi)
{
    std::sort(ticks.begin(), ticks.end());
    AxisRange range;
    range.ticks = std::move(ticks);
    range.min = range.ticks.empty() ? lo
        : std::isfinite(lo)         ? std::min(lo, range.ticks.front())
                                    : range.ticks.front();
    range.max = range.ticks.empty() ? hi
        : std::isfinite(hi)         ? std::max(hi, range.ticks.back())
                                    : range.ticks.back();
    return range;
}

AxisRange AxisTicks::forAxis(const ChartAxis& axis, double lo, double hi)
{
    const bool log = axis.scale == AxisScale::Log10;
    std::vector<double> ticks;
    for (double t : axis.fixedTicks)
        if (std::isfinite(t) && (!log || t > 0.0))
            ticks.push_back(t);
    if (ticks.empty())
        return log ? log10(lo, hi) : linear(lo, hi);
    AxisRange range = fixed(std::move(ticks), lo, hi);
    // Hand-picked ticks usually sit on the data: pad so the outermost markers do not straddle the frame.
    if (log) {
        const double pad = std::pow(range.max / range.min, 0.04);
        range.min /= pad;
        range.max *= pad;
    } else {
        const double pad = range.max > range.min ? 0.04 * (range.max - range.min) : 1.0;
        range.min -= pad;
        range.max += pad;
    }
    return range;
}

QString AxisTicks::label(double value)
{
    if (value == 0.0 || !std::isfinite(value))
        return QString::number(value);
    const double magnitude = std::abs(value);
    static const struct {
        double scale;
        const char* suffix;
    } kSi[] = { { 1e9, "G" }, { 1e6, "M" }, { 1e3, "k" } };
    for (const auto& si : kSi)
        if (magnitude >= si.scale * (1.0 - kSlack))
            return QString::number(value / si.scale, 'g', 4) + QLatin1String(si.suffix);
    return QString::number(value, 'g', magnitude < 1e-3 ? 3 : 6);
}

} // namespace vct::plot
