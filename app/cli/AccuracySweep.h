#pragma once

#include "scene/RenderSettings.h"

#include <string>
#include <utility>
#include <vector>

namespace vct::cli {

/** `key=value` render-setting assignments, applied in order. */
using SettingAssignments = std::vector<std::pair<std::string, std::string>>;

/** One VCT configuration of an accuracy sweep. */
struct SweepPoint {
    std::string label; ///< "base", "voxel_res=32" or a preset's label; aliases joined by " = "
    std::string setting; ///< the varied key, "base" or "preset"
    std::string value; ///< the varied value, or the preset's assignments joined by spaces
    SettingAssignments assignments; ///< on top of the sweep's base
    render::RenderSettings settings; ///< the scene's settings + --set + base + assignments
};

/**
 * The sweep spec of `vct-bench accuracy` (docs/ACCURACY.md, "Sweep spec"):
 *
 *     {"base": {"voxel_res": "128"},
 *      "axes": [{"key": "voxel_res", "values": ["32", "64", "256"]}, ...],
 *      "presets": [{"label": "fast", "set": {"voxel_res": "64", "step": "1.5"}}, ...]}
 *
 * Points: the base, then each axis value varied alone around the base (one at a time, not a Cartesian
 * product), then each preset applied on top of the base (its keys in alphabetical order: JSON objects have
 * no order). Values are strings as `--set` takes them; JSON
 * numbers and booleans are accepted too. Points whose settings come out identical are measured once, their
 * labels joined ("base = balanced").
 */
class AccuracySweep {
public:
    /**
     * Parses @p json and applies every point to @p sceneSettings; false with a message naming the point and
     * the problem when the JSON is malformed or a setting is unknown or out of range.
     */
    static bool parse(const std::string& json, const render::RenderSettings& sceneSettings,
        AccuracySweep& sweep, std::string* error);

    const std::vector<SweepPoint>& points() const { return m_points; }

private:
    std::vector<SweepPoint> m_points;
};

} // namespace vct::cli
