#include "cli/PerfReport.h"
#include "cli/ReportText.h"

#include "plot/ChartPainter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace vct::cli {

namespace {

using report_text::csvField;
using report_text::format;

/** Milliseconds with precision that suits their size. */
std::string ms(double v)
{
    return format(v < 10.0 ? "%.2f" : "%.1f", v);
}

std::string withSeparators(std::uint64_t v)
{
    const std::string digits = std::to_string(v);
    std::string out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0)
            out += ',';
        out += digits[i];
    }
    return out;
}

std::string mib(std::size_t bytes)
{
    return format("%.1f", double(bytes) / (1024.0 * 1024.0));
}

std::string sweepNames(unsigned sweeps)
{
    std::string names;
    for (const auto& [bit, name] : { std::pair(kSizeSweep, "size"), std::pair(kGridSweep, "grid"),
             std::pair(kTriangleSweep, "triangles") })
        if (sweeps & bit) {
            if (!names.empty())
                names += '+';
            names += name;
        }
    return names;
}

std::string sizeText(const PerfConfig& c)
{
    return format("%d×%d", c.width, c.height);
}

std::string configColumns(const PerfResult& r)
{
    return "| " + sizeText(r.config) + " | " + format("%d³", r.config.grid) + " | "
        + withSeparators(r.triangles) + format(" (×%d) ", r.config.triangleFactor);
}

const PassTiming* findPass(const ModeTiming& mode, const std::string& name)
{
    for (const PassTiming& p : mode.passes)
        if (p.pass == name)
            return &p;
    return nullptr;
}

/** x value of a result on one sweep's curve. */
double sweepX(const PerfResult& r, unsigned sweep)
{
    if (sweep == kSizeSweep)
        return double(r.config.width) * double(r.config.height);
    if (sweep == kGridSweep)
        return double(r.config.grid);
    return double(r.triangles);
}

} // namespace

PerfReport::PerfReport(std::string scene, std::string header, std::vector<PerfResult> results)
    : m_scene(std::move(scene))
    , m_header(std::move(header))
    , m_results(std::move(results))
{
}

std::vector<std::string> PerfReport::passNames() const
{
    std::vector<std::string> names;
    for (const PerfResult& r : m_results)
        for (const PassTiming& p : r.full.passes)
            if (std::find(names.begin(), names.end(), p.pass) == names.end())
                names.push_back(p.pass);
    return names;
}

std::string PerfReport::resultsCsv() const
{
    std::ostringstream out;
    out << "scene,sweeps,width,height,pixels,grid,triangle_factor,triangles,mode,pass,action,median_ms,min_"
           "ms,max_ms,frames\n";
    for (const PerfResult& r : m_results) {
        const PerfConfig& c = r.config;
        const std::string prefix = csvField(m_scene) + "," + sweepNames(c.sweeps)
            + format(",%d,%d,%lld,%d,%d,%zu,", c.width, c.height, (long long)c.width * c.height, c.grid,
                c.triangleFactor, r.triangles);
        for (const auto& [mode, timing] :
            { std::pair("full", &r.full), std::pair("camera", &r.cameraOnly) }) {
            const auto row = [&](const std::string& pass, const std::string& action, const TimingSpread& t) {
                out << prefix << mode << "," << csvField(pass) << "," << action
                    << format(",%.3f,%.3f,%.3f,%d\n", t.median, t.min, t.max, r.frames);
            };
            for (const PassTiming& p : timing->passes)
                row(p.pass, p.action, p.ms);
            row("frame_gpu", "sum", timing->frameGpuMs);
            row("frame_wall", "cpu_clock", timing->frameWallMs);
        }
    }
    return out.str();
}

std::string PerfReport::efficiencyCsv() const
{
    std::ostringstream out;
    out << "width,height,traced_width,traced_height,grid,triangle_factor,triangles,cone_samples,cone_ms,"
           "cone_samples_per_s,peak_samples_per_s,peak_ms,peak_samples_per_pixel,efficiency\n";
    for (const PerfResult& r : m_results)
        out << format("%d,%d,%d,%d,%d,%d,%zu,%llu,%.3f,%.6g,%.6g,%.3f,%d,%.4f\n", r.config.width,
            r.config.height, r.tracedWidth, r.tracedHeight, r.config.grid, r.config.triangleFactor,
            r.triangles, (unsigned long long)r.coneSamples, r.coneMs, r.coneSamplesPerSecond(),
            r.peak.samplesPerSecond, r.peak.medianMs, r.peak.samplesPerPixel, r.coneEfficiency());
    return out.str();
}

std::string PerfReport::memoryCsv() const
{
    std::ostringstream out;
    out << "grid,texture,format,width,height,depth,level,bytes\n";
    std::vector<int> done;
    for (const PerfResult& r : m_results) {
        if (std::find(done.begin(), done.end(), r.config.grid) != done.end())
            continue;
        done.push_back(r.config.grid);
        for (const render::VoxelTextureMemory& m : r.memory)
            for (std::size_t level = 0; level < m.levelBytes.size(); ++level)
                out << r.config.grid << "," << csvField(m.name) << "," << m.format
                    << format(",%d,%d,%d,%zu,%zu\n", m.width, m.height, m.depth, level, m.levelBytes[level]);
    }
    return out.str();
}

std::string PerfReport::wholeFrameTable() const
{
    std::ostringstream out;
    out << "| output | grid | triangles | curves | full frame GPU ms | camera-only GPU ms | full / camera | "
           "full frame wall ms | voxel MiB |\n|---|---|---|---|---|---|---|---|---|\n";
    for (const PerfResult& r : m_results) {
        const TimingSpread& f = r.full.frameGpuMs;
        const TimingSpread& c = r.cameraOnly.frameGpuMs;
        out << configColumns(r) << "| " << sweepNames(r.config.sweeps) << " | **" << ms(f.median) << "** ("
            << ms(f.min) << "–" << ms(f.max) << ") | **" << ms(c.median) << "** (" << ms(c.min) << "–"
            << ms(c.max) << ") | "
            << (c.median > 0.0 ? format("%.1f×", f.median / c.median) : std::string("–")) << " | "
            << ms(r.full.frameWallMs.median) << " | " << mib(r.voxelBytes()) << " |\n";
    }
    return out.str();
}

std::string PerfReport::passTable(bool cameraOnly) const
{
    const std::vector<std::string> names = passNames();
    std::ostringstream out;
    out << "| output | grid | triangles |";
    for (const std::string& name : names)
        out << " " << name << " |";
    out << " frame |\n|---|---|---|";
    for (std::size_t i = 0; i <= names.size(); ++i)
        out << "---|";
    out << "\n";
    for (const PerfResult& r : m_results) {
        const ModeTiming& mode = cameraOnly ? r.cameraOnly : r.full;
        out << configColumns(r) << "|";
        for (const std::string& name : names) {
            const PassTiming* p = findPass(mode, name);
            if (!p)
                out << " |";
            else if (p->action != "run")
                out << " " << p->action << " |";
            else
                out << " " << ms(p->ms.median) << " |";
        }
        out << " **" << ms(mode.frameGpuMs.median) << "** |\n";
    }
    return out.str();
}

std::string PerfReport::efficiencyTable() const
{
    std::ostringstream out;
    out << "| output | grid | triangles | traced pixels | cone samples / frame | samples / pixel | cone ms | "
           "cone Msamples/s | peak Msamples/s | efficiency |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const PerfResult& r : m_results) {
        const double pixels = double(r.tracedWidth) * double(r.tracedHeight);
        out << configColumns(r) << format("| %d×%d ", r.tracedWidth, r.tracedHeight) << "| "
            << withSeparators(r.coneSamples) << " | "
            << format("%.1f", pixels > 0 ? double(r.coneSamples) / pixels : 0.0) << " | " << ms(r.coneMs)
            << " | " << format("%.1f", r.coneSamplesPerSecond() * 1e-6) << " | "
            << format("%.1f", r.peak.samplesPerSecond * 1e-6) << " | "
            << (r.coneEfficiency() > 0.0 ? format("%.0f %%", 100.0 * r.coneEfficiency()) : std::string("n/a"))
            << " |\n";
    }
    return out.str();
}

namespace {

double bytesPerCell(const PerfResult& r)
{
    const double cells
        = double(r.config.grid) * double(r.config.grid) * double(r.config.grid) * double(r.gridLevels);
    return cells > 0.0 ? double(r.voxelBytes()) / cells : 0.0;
}

double bytesPerOccupiedVoxel(const PerfResult& r)
{
    return r.occupiedVoxels > 0 ? double(r.voxelBytes()) / double(r.occupiedVoxels) : 0.0;
}

} // namespace

std::string PerfReport::memoryTables() const
{
    std::ostringstream out;
    std::vector<int> done;
    for (const PerfResult& r : m_results) {
        if (std::find(done.begin(), done.end(), r.config.grid) != done.end() || r.memory.empty())
            continue;
        done.push_back(r.config.grid);
        std::size_t levels = 0;
        for (const render::VoxelTextureMemory& m : r.memory)
            levels = std::max(levels, m.levelBytes.size());
        out << format("\n**%d³ grid**: %s bytes (%s MiB) in total (GL reports %s), %.1f bytes per cell, %.0f "
                      "per occupied voxel (%s of them).\n\n| texture | format | level 0 texels |",
            r.config.grid, withSeparators(r.voxelBytes()).c_str(), mib(r.voxelBytes()).c_str(),
            withSeparators(r.glVoxelBytes()).c_str(), bytesPerCell(r), bytesPerOccupiedVoxel(r),
            withSeparators(r.occupiedVoxels).c_str());
        for (std::size_t l = 0; l < levels; ++l)
            out << " level " << l << " |";
        out << " total bytes |\n|---|---|---|";
        for (std::size_t l = 0; l <= levels; ++l)
            out << "---|";
        out << "\n";
        for (const render::VoxelTextureMemory& m : r.memory) {
            out << "| " << m.name << " | " << m.format << " | "
                << format("%d×%d×%d", m.width, m.height, m.depth) << " |";
            for (std::size_t l = 0; l < levels; ++l)
                out << " " << (l < m.levelBytes.size() ? withSeparators(m.levelBytes[l]) : std::string())
                    << " |";
            out << " " << withSeparators(m.totalBytes()) << " |\n";
        }
    }
    return out.str();
}

std::string PerfReport::markdown() const
{
    std::ostringstream out;
    const int frames = m_results.empty() ? 0 : m_results.front().frames;
    out << "# `vct-bench perf` on " << m_scene << "\n\n"
        << m_header << "\n\n"
        << "GPU times are GL timestamp pairs around each pass, medians over " << frames
        << " timed frames per mode after one warm-up frame, with (min–max). **Full** frames re-run every "
           "pass "
           "(`Renderer::invalidate()` before each); **camera-only** frames turn the camera 0.5° about its "
           "look-at "
           "point before each frame, so the render plan reuses shadow maps, voxels, injection and mips. "
           "Wall ms is `Renderer::renderFrame` on the CPU clock, timer readback included. A column named "
           "\"pass: phase\" is the sum of that phase's runs within the pass (`core/PhaseTimes`), a part of "
           "the pass's time, not added to the frame's again.\n\n"
        << "## Whole frame\n\n"
        << wholeFrameTable() << "\n## Per pass, full frames (GPU ms, median)\n\n"
        << passTable(false) << "\n## Per pass, camera-only frames (GPU ms, median)\n\n"
        << passTable(true)
        << "\n## Cone-trace efficiency\n\n"
           "Cone samples are the 3D texture fetches (`textureLod` calls) of the cone pass, counted in a "
           "separate, "
           "untimed frame by the shader's `COUNT_SAMPLES` variant. The peak is `TrilinearRateProbe`: a "
           "full-screen "
           "draw of the cone pass's size taking "
        << (m_results.empty() ? 0 : m_results.front().peak.samplesPerPixel)
        << " coherent `textureLod` samples per pixel (rays of steps with the level rising along each ray) "
           "from an "
           "RGBA16F volume of the same size, format and filter as the voxel radiance, timed the same way "
           "right after "
           "the configuration's frames. Efficiency = (cone samples / cone-pass seconds) / peak.\n\n"
        << efficiencyTable() << "\n## 3D texture memory (bytes per mip level)\n"
        << memoryTables() << "\n## Plots\n\n";
    for (const NamedChart& c : charts())
        out << "![" << c.chart.title.toStdString() << "](" << c.baseName.toStdString() << ".svg)\n\n";
    return out.str();
}

std::string PerfReport::summary() const
{
    std::ostringstream out;
    out << m_header << "\n\n" << wholeFrameTable() << "\n" << efficiencyTable();
    std::vector<int> done;
    out << "\n";
    for (const PerfResult& r : m_results)
        if (std::find(done.begin(), done.end(), r.config.grid) == done.end()) {
            done.push_back(r.config.grid);
            out << format(
                "voxel memory at %d³: %s bytes (%s MiB), %.1f bytes per cell, %.0f per occupied voxel\n",
                r.config.grid, withSeparators(r.voxelBytes()).c_str(), mib(r.voxelBytes()).c_str(),
                bytesPerCell(r), bytesPerOccupiedVoxel(r));
        }
    return out.str();
}

std::vector<NamedChart> PerfReport::charts() const
{
    struct Curve {
        unsigned sweep;
        const char* baseName;
        const char* against;
        const char* xLabel;
    };
    const Curve curves[]
        = { { kSizeSweep, "frame_vs_pixels", "output pixels", "output pixels (width × height)" },
              { kGridSweep, "frame_vs_grid", "voxel grid resolution", "grid cells per side" },
              { kTriangleSweep, "frame_vs_triangles", "triangle count", "triangles" } };
    std::vector<NamedChart> list;
    for (const Curve& curve : curves) {
        std::vector<const PerfResult*> points;
        for (const PerfResult& r : m_results)
            if (r.config.sweeps & curve.sweep)
                points.push_back(&r);
        if (points.size() < 2)
            continue;
        std::sort(points.begin(), points.end(), [&](const PerfResult* a, const PerfResult* b) {
            return sweepX(*a, curve.sweep) < sweepX(*b, curve.sweep);
        });
        const PerfConfig& first = points.front()->config;
        std::string fixed;
        if (curve.sweep != kSizeSweep)
            fixed += format("%d×%d", first.width, first.height);
        if (curve.sweep != kGridSweep)
            fixed += (fixed.empty() ? "" : ", ") + format("%d³", first.grid);
        if (curve.sweep != kTriangleSweep)
            fixed += (fixed.empty() ? "" : ", ") + format("×%d triangles", first.triangleFactor);

        NamedChart named { QString::fromLatin1(curve.baseName), {} };
        plot::Chart& chart = named.chart;
        chart.title = QString::fromStdString(
            m_scene + ": GPU ms per frame against " + curve.against + " (" + fixed + ")");
        chart.x = { QString::fromUtf8(curve.xLabel), plot::AxisScale::Log10, {} };
        chart.y = { QStringLiteral("GPU ms (median of %1 frames)").arg(points.front()->frames),
            plot::AxisScale::Log10, {} };
        for (const PerfResult* r : points)
            chart.x.fixedTicks.push_back(sweepX(*r, curve.sweep));
        // The two frame totals in black, labelled; the passes of the full frame in colour below them.
        plot::ChartSeries full, camera;
        full.name = QStringLiteral("full frame");
        camera.name = QStringLiteral("camera-only frame");
        full.color = camera.color = QColor(0x22, 0x22, 0x22);
        camera.dashed = true;
        for (const PerfResult* r : points) {
            const double x = sweepX(*r, curve.sweep);
            full.points.push_back(
                { x, r->full.frameGpuMs.median, QString::fromStdString(ms(r->full.frameGpuMs.median)) });
            camera.points.push_back({ x, r->cameraOnly.frameGpuMs.median,
                QString::fromStdString(ms(r->cameraOnly.frameGpuMs.median)) });
        }
        chart.series.push_back(full);
        chart.series.push_back(camera);
        std::size_t palette = 0;
        for (const std::string& name : passNames()) {
            plot::ChartSeries series;
            series.name = QString::fromStdString(name) + QStringLiteral(" (full)");
            series.color = plot::ChartPainter::paletteColor(palette++);
            for (const PerfResult* r : points)
                if (const PassTiming* p = findPass(r->full, name); p && p->ms.median > 0.0)
                    series.points.push_back({ sweepX(*r, curve.sweep), p->ms.median, {} });
            if (!series.points.empty()) // a pass skipped in every frame has nothing to draw
                chart.series.push_back(series);
        }
        list.push_back(named);
    }
    return list;
}

} // namespace vct::cli
