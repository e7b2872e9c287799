#include "cli/StatsJson.h"

#include "cli/Statistics.h"

#include <QJsonArray>

namespace vct::cli {

QJsonObject statsToJson(const std::vector<render::FrameStats>& frames, const render::RenderSettings& settings,
    const QString& scene, const QString& glDescription)
{
    QJsonObject root;
    root["scene"] = scene;
    root["gl"] = glDescription;
    root["frames_timed"] = int(frames.size());
    if (frames.empty())
        return root;
    const render::FrameStats& last = frames.back();
    root["width"] = last.width;
    root["height"] = last.height;
    root["voxel_resolution"] = last.voxelResolution;
    root["voxel_size_m"] = double(last.voxelSize);
    root["voxel_memory_bytes"] = double(last.voxelBytes);
    root["occupied_voxels"] = double(last.occupiedVoxels);
    root["voxel_bytes_per_cell"] = last.voxelBytesPerCell();
    root["voxel_bytes_per_occupied_voxel"] = last.voxelBytesPerOccupiedVoxel();
    root["bounce_iterations"] = last.bounceIterations;
    root["enclosed_cells"] = qint64(last.enclosedCells);
    root["enclosure_cells"] = qint64(last.enclosureCells);
    root["bounce_residual"] = last.bounceResidual;
    root["light_converged"] = last.lightConverged;
    root["bounce_extrapolated"] = last.bounceExtrapolated;
    root["bounce_stopped_at_limit"] = last.bounceStoppedAtLimit;
    QJsonArray passes;
    std::vector<double> totals;
    for (const render::FrameStats& f : frames)
        totals.push_back(f.totalGpuMs);
    for (std::size_t i = 0; i < last.passes.size(); ++i) {
        std::vector<double> ms;
        for (const render::FrameStats& f : frames)
            if (i < f.passes.size() && f.passes[i].action == "run")
                ms.push_back(f.passes[i].gpuMs);
        QJsonObject pass;
        pass["name"] = QString::fromStdString(last.passes[i].name);
        pass["action"] = QString::fromStdString(last.passes[i].action);
        pass["reason"] = QString::fromStdString(last.passes[i].reason);
        pass["gpu_ms"] = median(ms);
        passes.append(pass);
    }
    root["passes"] = passes;
    root["total_gpu_ms"] = median(totals);
    QJsonObject values;
    for (const auto& row : settings.describe())
        values[QString::fromStdString(row[0])] = QString::fromStdString(row[1]);
    root["settings"] = values;
    return root;
}

QJsonArray bricksToJson(const std::vector<render::BrickOccupancy>& bricks)
{
    QJsonArray list;
    for (const render::BrickOccupancy& b : bricks) {
        QJsonObject o;
        o["grid"] = b.grid;
        o["resolution"] = b.resolution;
        o["brick_size"] = b.brickSize;
        o["occupied_voxels"] = double(b.occupiedVoxels);
        o["occupied_bricks"] = double(b.occupiedBricks);
        o["total_bricks"] = double(b.totalBricks);
        o["share"] = b.share();
        o["bordered_pool_share"] = b.borderedPoolShare();
        if (b.poolSlots > 0) {
            o["stored_bricks"] = double(b.storedBricks);
            o["pool_slots"] = double(b.poolSlots);
        }
        list.append(o);
    }
    return list;
}

} // namespace vct::cli
