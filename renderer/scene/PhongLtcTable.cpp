#include "scene/PhongLtcTable.h"

#include <algorithm>
#include <cmath>

namespace vct::render {

double PhongLtcTable::minWidth()
{
    return std::sqrt(2.0 / (kMaxShininess + 2.0));
}

double PhongLtcTable::cosViewAt(int column)
{
    const double x = double(column) / (kSize - 1);
    return 1.0 - x * x;
}

double PhongLtcTable::shininessAt(int row)
{
    const double width = minWidth() + (1.0 - minWidth()) * double(row) / (kSize - 1);
    return std::max(0.0, 2.0 / (width * width) - 2.0);
}

double PhongLtcTable::columnOf(double cosView)
{
    return std::sqrt(std::clamp(1.0 - cosView, 0.0, 1.0)) * (kSize - 1);
}

double PhongLtcTable::rowOf(double shininess)
{
    const double width = std::sqrt(2.0 / (std::max(shininess, 0.0) + 2.0));
    return std::clamp((width - minWidth()) / (1.0 - minWidth()), 0.0, 1.0) * (kSize - 1);
}

const std::array<PhongLtcTable::Cell, PhongLtcTable::kSize * PhongLtcTable::kSize>& PhongLtcTable::cells()
{
    static const std::array<Cell, kSize * kSize> table { {
#include "scene/PhongLtcTable.inc"
    } };
    return table;
}

PhongLtcTable::Cell PhongLtcTable::lookup(double cosView, double shininess)
{
    const double column = columnOf(cosView), row = rowOf(shininess);
    const int c0 = std::min(int(column), kSize - 2), r0 = std::min(int(row), kSize - 2);
    const float fc = float(column - c0), fr = float(row - r0);
    const auto at = [](int r, int c) { return cells()[std::size_t(r * kSize + c)]; };
    const auto mix = [](const Cell& a, const Cell& b, float t) {
        return Cell { a.m00 + (b.m00 - a.m00) * t, a.m02 + (b.m02 - a.m02) * t, a.m20 + (b.m20 - a.m20) * t,
            a.m22 + (b.m22 - a.m22) * t, a.albedo + (b.albedo - a.albedo) * t };
    };
    return mix(mix(at(r0, c0), at(r0, c0 + 1), fc), mix(at(r0 + 1, c0), at(r0 + 1, c0 + 1), fc), fr);
}

} // namespace vct::render
