#include "cli/AccuracyReport.h"
#include "cli/ReportText.h"

#include "plot/ParetoFrontier.h"

#include <QColor>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace vct::cli {

namespace {

using report_text::format;

std::string ms(double v)
{
    if (!std::isfinite(v))
        return "–";
    return format(v < 10.0 ? "%.2f" : "%.0f", v);
}

std::string fixed(const char* pattern, double v)
{
    return std::isfinite(v) ? format(pattern, v) : std::string(std::isnan(v) ? "–" : (v > 0 ? "∞" : "−∞"));
}

std::string pathTracerTime(const PathTracerTime& t)
{
    const std::string cpu = std::isfinite(t.cpuMs) ? " / " + ms(t.cpuMs) + " CPU" : std::string();
    switch (t.kind) {
    case PathTracerTime::Kind::None:
        return "–";
    case PathTracerTime::Kind::Interpolated:
        return ms(t.ms) + cpu + format(" ms (%.3g spp)", t.spp);
    case PathTracerTime::Kind::AtMost:
        return "≤ " + ms(t.ms) + cpu + format(" ms (%.0f spp)", t.spp);
    case PathTracerTime::Kind::Beyond:
        return "> " + ms(t.ms) + cpu + format(" ms (%.0f spp)", t.spp);
    }
    return "–";
}

std::vector<AccuracyRow> sortedByPoint(std::vector<AccuracyRow> rows)
{
    std::stable_sort(rows.begin(), rows.end(),
        [](const AccuracyRow& a, const AccuracyRow& b) { return a.point < b.point; });
    return rows;
}

std::string markdownCell(std::string text)
{
    for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2))
        text.replace(at, 1, "\\|");
    return text;
}

} // namespace

AccuracyReport::AccuracyReport(
    std::string scene, std::string header, std::vector<AccuracyRow> rows, std::vector<int> missing)
    : m_scene(std::move(scene))
    , m_header(std::move(header))
    , m_rows(sortedByPoint(std::move(rows)))
    , m_missing(std::move(missing))
    , m_curve(m_rows)
{
    std::vector<plot::TimeError> points;
    std::vector<std::size_t> vctIndex;
    for (std::size_t i = 0; i < m_rows.size(); ++i)
        if (m_rows[i].isVct()) {
            points.push_back({ m_rows[i].gpuMs, m_rows[i].relMse });
            vctIndex.push_back(i);
        }
    for (std::size_t k : plot::ParetoFrontier::of(points))
        m_frontier.push_back(vctIndex[k]);
}

plot::Chart AccuracyReport::chart() const
{
    plot::Chart chart;
    int width = 0, height = 0;
    for (const AccuracyRow& row : m_rows)
        if (row.width > 0) {
            width = row.width;
            height = row.height;
            break;
        }
    chart.title = QString::fromStdString(m_scene) + QStringLiteral(": error against time per image")
        + (width > 0 ? QStringLiteral(", %1×%2").arg(width).arg(height) : QString());
    chart.x.label = QStringLiteral("ms per image (VCT: GPU, full frame; path tracer: wall clock)");
    chart.x.scale = plot::AxisScale::Log10;
    chart.y.label = QStringLiteral("relative MSE");
    chart.y.scale = plot::AxisScale::Log10;

    plot::ChartSeries& vct = chart.addSeries(QStringLiteral("VCT settings"));
    vct.line = false;
    vct.color = QColor(0x1f, 0x77, 0xb4);
    vct.highlightName = QStringLiteral("Pareto frontier");
    for (std::size_t i = 0; i < m_rows.size(); ++i) {
        if (!m_rows[i].isVct())
            continue;
        if (std::find(m_frontier.begin(), m_frontier.end(), i) != m_frontier.end())
            vct.highlighted.push_back(vct.points.size());
        vct.points.push_back({ m_rows[i].gpuMs, m_rows[i].relMse, QString::fromStdString(m_rows[i].label) });
    }
    // The same settings when only the camera moves: what orbiting a static scene costs per frame.
    plot::ChartSeries& cameraOnly = chart.addSeries(QStringLiteral("VCT, camera-only frames"));
    cameraOnly.line = false;
    cameraOnly.color = QColor(0x9e, 0xca, 0xe1);
    for (const AccuracyRow& row : m_rows)
        if (row.isVct())
            cameraOnly.points.push_back({ row.cameraMs, row.relMse, QString() });
    if (!m_curve.empty()) {
        plot::ChartSeries& tracer = chart.addSeries(QStringLiteral("path tracer (spp)"));
        tracer.color = QColor(0xd6, 0x27, 0x28);
        tracer.dashed = true;
        for (const AccuracyRow& row : m_curve.points())
            tracer.points.push_back({ row.wallMs, row.relMse, QString::number(row.spp) });
    }
    return chart;
}

plot::Chart AccuracyReport::vctChart() const
{
    plot::Chart full = chart();
    plot::Chart chart;
    chart.title = QString::fromStdString(m_scene) + QStringLiteral(": VCT settings only");
    chart.x = full.x;
    chart.x.label = QStringLiteral("GPU ms per full frame");
    chart.y.label = QStringLiteral("relative MSE");
    chart.series.push_back(full.series.front());
    return chart;
}

std::string AccuracyReport::equalTimeCrossing(
    double AccuracyRow::*vctTime, double AccuracyRow::*tracerTime) const
{
    if (m_curve.empty())
        return "No path-tracer curve was measured.";
    double fastestVct = std::numeric_limits<double>::infinity();
    for (const AccuracyRow& row : m_rows)
        if (row.isVct() && std::isfinite(row.relMse) && std::isfinite(row.*vctTime))
            fastestVct = std::min(fastestVct, row.*vctTime);
    if (!std::isfinite(fastestVct))
        return "No VCT point was measured.";
    const auto bestVctWithin = [this, vctTime](double timeMs) {
        double best = std::numeric_limits<double>::infinity();
        for (const AccuracyRow& row : m_rows)
            if (row.isVct() && row.*vctTime <= timeMs && std::isfinite(row.relMse))
                best = std::min(best, row.relMse);
        return best;
    };
    // Path-tracer images that take less time than any VCT frame have nothing to be compared with.
    std::vector<AccuracyRow> compared;
    for (const AccuracyRow& row : m_curve.points())
        if (std::isfinite(row.*tracerTime) && row.*tracerTime >= fastestVct)
            compared.push_back(row);
    std::string note;
    if (compared.size() < m_curve.points().size())
        note = format(" (Path-tracer images faster than the fastest VCT frame, %s ms, are left out of this "
                      "comparison.)",
            ms(fastestVct).c_str());
    if (compared.empty())
        return format("Every path-tracer image took less time than the fastest VCT frame (%s ms); measure "
                      "more samples per pixel to see where the curves cross.",
            ms(fastestVct).c_str());
    for (std::size_t i = 0; i < compared.size(); ++i) {
        if (compared[i].relMse > bestVctWithin(compared[i].*tracerTime))
            continue;
        if (i == 0)
            return format("The path tracer is at least as accurate as the best VCT setting of equal or lower "
                          "time at every compared time: at %d spp (%s ms) its relative MSE is %.4g, against "
                          "%.4g.",
                       compared[0].spp, ms(compared[0].*tracerTime).c_str(), compared[0].relMse,
                       bestVctWithin(compared[0].*tracerTime))
                + note;
        return format("The curves cross between %d spp (%s ms, relative MSE %.4g against VCT's best %.4g in "
                      "that time) and %d spp (%s ms, %.4g against %.4g): with more time than that, samples "
                      "beat any VCT setting.",
                   compared[i - 1].spp, ms(compared[i - 1].*tracerTime).c_str(), compared[i - 1].relMse,
                   bestVctWithin(compared[i - 1].*tracerTime), compared[i].spp,
                   ms(compared[i].*tracerTime).c_str(), compared[i].relMse,
                   bestVctWithin(compared[i].*tracerTime))
            + note;
    }
    return format("Within the measured curve (up to %d spp, %s ms) the path tracer never beats the best VCT "
                  "setting of equal or lower time: at %d spp its relative MSE is %.4g against VCT's %.4g.",
               compared.back().spp, ms(compared.back().*tracerTime).c_str(), compared.back().spp,
               compared.back().relMse, bestVctWithin(compared.back().*tracerTime))
        + note;
}

std::string AccuracyReport::markdown() const
{
    std::ostringstream out;
    out << "# Accuracy against time: " << m_scene << "\n\n" << m_header << "\n\n";
    if (!m_missing.empty()) {
        out << "**Incomplete:** no results for job";
        for (int k : m_missing)
            out << ' ' << k;
        out << ".\n\n";
    }
    double lowLoad = std::numeric_limits<double>::infinity(), highLoad = -lowLoad;
    for (const AccuracyRow& r : m_rows)
        if (std::isfinite(r.loadAverage)) {
            lowLoad = std::min(lowLoad, r.loadAverage);
            highLoad = std::max(highLoad, r.loadAverage);
        }
    if (std::isfinite(lowLoad))
        out << format("1-minute load average after each point: %.1f–%.1f. ", lowLoad, highLoad);
    out << "Relative MSE is the mean over pixels and channels of (x − ref)² / (ref² + 0.01); PSNR has peak "
           "radiance 1; SSIM is of the tone-mapped images; mean ratio is the image's mean luminance over the "
           "reference's. VCT times are medians of GL timer queries over full frames (every pass re-run); "
           "camera-only frames reuse voxels and mips. CPU ms is the CPU time of all the process's threads "
           "over the same frame or render (llvmpipe, too, renders on the CPU): on shared cores it is "
           "steadier than GPU or wall time, which grow with other processes' load. ★ marks the Pareto "
           "frontier (no other setting is both faster and more accurate). The last column is how long the "
           "path tracer takes to reach the same relative MSE (wall clock / CPU time of all threads), "
           "interpolated in log-log between the measured sample counts.\n\n";
    out << "![error against time](accuracy.svg)\n\n![VCT settings only](accuracy-vct.svg)\n\n";
    out << "## VCT settings, by GPU time\n\n"
        << "| setting | GPU ms | cone ms | camera-only ms | CPU ms | rel. MSE | RMSE | PSNR dB | SSIM | mean "
           "ratio | frontier | path tracer at same error "
           "|\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    std::vector<std::size_t> vct;
    for (std::size_t i = 0; i < m_rows.size(); ++i)
        if (m_rows[i].isVct())
            vct.push_back(i);
    std::stable_sort(vct.begin(), vct.end(),
        [this](std::size_t a, std::size_t b) { return m_rows[a].gpuMs < m_rows[b].gpuMs; });
    for (std::size_t i : vct) {
        const AccuracyRow& r = m_rows[i];
        const bool onFrontier = std::find(m_frontier.begin(), m_frontier.end(), i) != m_frontier.end();
        std::string label = markdownCell(r.label);
        if (r.setting == "preset" && !r.value.empty())
            label += " (" + markdownCell(r.value) + ")";
        out << "| " << (onFrontier ? "**" + label + "**" : label) << " | " << ms(r.gpuMs) << " | "
            << ms(r.coneMs) << " | " << ms(r.cameraMs) << " | " << ms(r.cpuMs) << " | "
            << fixed("%.4f", r.relMse) << " | " << fixed("%.4f", r.rmse) << " | " << fixed("%.2f", r.psnr)
            << " | " << fixed("%.4f", r.ssim) << " | " << fixed("%.3f", r.meanRatio) << " | "
            << (onFrontier ? "★" : "") << " | " << pathTracerTime(m_curve.timeToReach(r.relMse)) << " |\n";
    }
    if (!m_curve.empty()) {
        out << "\n## Path tracer, independent images at increasing samples per pixel\n\n"
            << "| spp | wall ms | CPU ms | rel. MSE | RMSE | PSNR dB | SSIM | mean ratio "
               "|\n|---|---|---|---|---|---|---|---|\n";
        for (const AccuracyRow& r : m_curve.points())
            out << "| " << r.spp << " | " << ms(r.wallMs) << " | " << ms(r.cpuMs) << " | "
                << fixed("%.4f", r.relMse) << " | " << fixed("%.4f", r.rmse) << " | " << fixed("%.2f", r.psnr)
                << " | " << fixed("%.4f", r.ssim) << " | " << fixed("%.3f", r.meanRatio) << " |\n";
    }
    out << "\n## Where the curves cross\n\n**Full frames** (every pass re-run: the first frame, or after a "
           "light or geometry edit): "
        << equalTimeCrossing(&AccuracyRow::gpuMs, &AccuracyRow::wallMs)
        << "\n\n**Camera-only frames** (voxels, injection and mips reused: orbiting a static scene, where "
           "the path tracer has to start again): "
        << equalTimeCrossing(&AccuracyRow::cameraMs, &AccuracyRow::wallMs)
        << "\n\n**CPU time** (all threads of the process, full frames; llvmpipe and the path tracer both run "
           "on the CPU, and CPU time does not grow with other processes' load on shared cores as wall time "
           "does): "
        << equalTimeCrossing(&AccuracyRow::cpuMs, &AccuracyRow::cpuMs) << "\n";
    return out.str();
}

std::string AccuracyReport::summary() const
{
    std::ostringstream out;
    out << "Pareto frontier (fastest first):\n";
    for (std::size_t i : m_frontier)
        out << format("  %-40s %9s ms  rel. MSE %.4f  path tracer at same error %s\n",
            m_rows[i].label.c_str(), ms(m_rows[i].gpuMs).c_str(), m_rows[i].relMse,
            pathTracerTime(m_curve.timeToReach(m_rows[i].relMse)).c_str());
    out << "Full frames: " << equalTimeCrossing(&AccuracyRow::gpuMs, &AccuracyRow::wallMs) << "\n";
    out << "Camera-only frames: " << equalTimeCrossing(&AccuracyRow::cameraMs, &AccuracyRow::wallMs) << "\n";
    out << "CPU time: " << equalTimeCrossing(&AccuracyRow::cpuMs, &AccuracyRow::cpuMs) << "\n";
    return out.str();
}

} // namespace vct::cli
