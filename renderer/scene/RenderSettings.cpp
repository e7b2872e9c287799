#include "scene/RenderSettings.h"
#include "scene/VoxelTextureEstimate.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <sstream>

namespace vct::render {

namespace {

constexpr DebugView kViews[]
    = { DebugView::Final, DebugView::Direct, DebugView::IndirectDiffuse, DebugView::IndirectSpecular,
          DebugView::AmbientOcclusion, DebugView::Albedo, DebugView::Normal, DebugView::Emission };

bool parseFloat(const std::string& text, float& out)
{
    try {
        std::size_t used = 0;
        const float v = std::stof(text, &used);
        if (used != text.size() || !std::isfinite(v))
            return false;
        out = v;
        return true;
    } catch (...) {
        return false;
    }
}

bool parseInt(const std::string& text, int& out)
{
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end;
}

bool parseBool(const std::string& text, bool& out)
{
    if (text == "1" || text == "true" || text == "on" || text == "yes")
        out = true;
    else if (text == "0" || text == "false" || text == "off" || text == "no")
        out = false;
    else
        return false;
    return true;
}

std::string toText(float v)
{
    std::ostringstream s;
    s << v;
    return s.str();
}

struct Field {
    std::function<bool(RenderSettings&, const std::string&)> parse;
    std::function<std::string(const RenderSettings&)> print;
    const char* meaning;
};

template <typename T> Field makeField(T RenderSettings::*member, const char* meaning)
{
    Field f;
    f.meaning = meaning;
    if constexpr (std::is_same_v<T, float>) {
        f.parse = [member](RenderSettings& s, const std::string& v) { return parseFloat(v, s.*member); };
        f.print = [member](const RenderSettings& s) { return toText(s.*member); };
    } else if constexpr (std::is_same_v<T, int>) {
        f.parse = [member](RenderSettings& s, const std::string& v) { return parseInt(v, s.*member); };
        f.print = [member](const RenderSettings& s) { return std::to_string(s.*member); };
    } else {
        f.parse = [member](RenderSettings& s, const std::string& v) { return parseBool(v, s.*member); };
        f.print = [member](const RenderSettings& s) { return std::string(s.*member ? "on" : "off"); };
    }
    return f;
}

const std::map<std::string, Field>& fields()
{
    static const std::map<std::string, Field> table = [] {
        std::map<std::string, Field> t;
        t["voxel_res"]
            = makeField(&RenderSettings::voxelResolution, "voxel grid cells per side (power of two, 8..512)");
        t["conservative"]
            = makeField(&RenderSettings::conservativeVoxelization, "conservative voxelization (on/off)");
        t["small_triangle_compute"] = makeField(&RenderSettings::smallTrianglesByCompute,
            "voxelize triangles of a few voxels in a compute shader (on/off; the voxels are the same)");
        t["anisotropic"] = makeField(&RenderSettings::anisotropicMips,
            "direction-dependent mips: six chains composited along each axis (on/off)");
        Field bounces;
        bounces.meaning
            = "light bounces carried by the voxels: converged (every bounce, until the change is under "
              "bounce_tolerance), or 1..64";
        bounces.parse = [](RenderSettings& s, const std::string& v) {
            if (v == "converged") {
                s.bounces = RenderSettings::kConvergedBounces;
                return true;
            }
            int n = 0;
            if (!parseInt(v, n) || n < 1)
                return false;
            s.bounces = n;
            return true;
        };
        bounces.print = [](const RenderSettings& s) {
            return s.bounces == RenderSettings::kConvergedBounces ? std::string("converged")
                                                                  : std::to_string(s.bounces);
        };
        t["bounces"] = bounces;
        t["bounce_cell"] = makeField(&RenderSettings::bounceCellSize,
            "cell side in voxels of the bounce iteration's gather: 2, 4 or 8");
        t["higher_bounce_cell"] = makeField(&RenderSettings::higherBounceCellSize,
            "cell side in voxels of the gathers of the third bounce on: 2, 4, 8 or 16, not below "
            "bounce_cell");
        t["bounce_tolerance"] = makeField(&RenderSettings::bounceTolerance,
            "bounces=converged stops below this relative change (0.0001..0.5)");
        t["irradiance_cache"] = makeField(&RenderSettings::irradianceCache,
            "diffuse cones gathered once per surface voxel, looked up per pixel (on/off)");
        t["irradiance_cell"] = makeField(
            &RenderSettings::irradianceCellSize, "irradiance cache cell side in voxels: 1, 2 or 4");
        t["diffuse_cones"] = makeField(&RenderSettings::diffuseConeCount, "number of diffuse cones (1..32)");
        t["diffuse_aperture"]
            = makeField(&RenderSettings::diffuseApertureDeg, "diffuse cone full angle, degrees (0..180)");
        t["specular_aperture"] = makeField(
            &RenderSettings::specularApertureDeg, "narrowest specular cone full angle, degrees (0..180)");
        t["step"]
            = makeField(&RenderSettings::stepFactor, "step factor beta: step = cone diameter * beta (>0)");
        t["bounce_step"] = makeField(
            &RenderSettings::bounceStepScale, "the bounce solve's cone steps as a multiple of step's (0..8]");
        t["drop_back_faces"] = makeField(&RenderSettings::dropBackFaces,
            "directional mips leave out surfaces facing the way a cone travels (on/off)");
        t["enclosed_space"] = makeField(&RenderSettings::enclosedSpace,
            "in space no light can leave, diffuse cones count what walls let through as the "
            "walls' light; not with max_distance set (on/off)");
        t["max_distance"]
            = makeField(&RenderSettings::maxDistance, "cone length in metres; negative = grid diagonal");
        t["indirect_res"] = makeField(
            &RenderSettings::indirectDivisor, "trace indirect light at 1/N resolution per axis: 1, 2 or 4");
        t["area_shadow_res"] = makeField(&RenderSettings::areaShadowDivisor,
            "trace the area lights' shadow cones at 1/N resolution per axis: 1, 2 or 4");
        t["specular_res"] = makeField(&RenderSettings::specularDivisor,
            "trace the specular cone at 1/N resolution per axis: 1, 2, 4 or 8");
        t["cone_offset"] = makeField(&RenderSettings::coneOffsetVoxels,
            "cone origin offset along the normal, voxels (finer grids than 128^3 keep its distance)");
        t["direct"] = makeField(&RenderSettings::direct, "direct light (on/off)");
        t["indirect_diffuse"]
            = makeField(&RenderSettings::indirectDiffuse, "indirect diffuse cones (on/off)");
        t["indirect_specular"]
            = makeField(&RenderSettings::indirectSpecular, "specular cone for glossy materials (on/off)");
        t["ao"] = makeField(
            &RenderSettings::ambientOcclusion, "ambient occlusion from the diffuse cones (on/off)");
        t["emission"] = makeField(&RenderSettings::emission, "emissive materials (on/off)");
        t["view_culling"] = makeField(&RenderSettings::viewCulling,
            "draw only what each view can see, nearest first (on/off; the image is the same)");
        t["shadow_map"] = makeField(&RenderSettings::shadowMapSize, "shadow map texels per side (64..8192)");
        t["exposure"] = makeField(&RenderSettings::exposure, "exposure multiplier for 8-bit output (>0)");
        t["voxel_budget_mb"] = makeField(
            &RenderSettings::voxelBudgetMiB, "most MiB the voxel textures may take (64..1048576)");
        Field view;
        view.meaning = "final|direct|indirect_diffuse|indirect_specular|ao|albedo|normal|emission";
        view.parse = [](RenderSettings& s, const std::string& v) {
            for (DebugView candidate : kViews)
                if (v == debugViewName(candidate)) {
                    s.view = candidate;
                    return true;
                }
            return false;
        };
        view.print = [](const RenderSettings& s) { return std::string(debugViewName(s.view)); };
        t["view"] = view;
        Field mode;
        mode.meaning = "dense (one grid around the scene), sparse (the same grid storing only the 8^3 bricks "
                       "that hold "
                       "surface) or clipmap (clip_levels nested grids, the finer ones centred on the camera)";
        mode.parse = [](RenderSettings& s, const std::string& v) {
            if (v != "dense" && v != "sparse" && v != "clipmap")
                return false;
            s.voxelMode = v == "dense" ? VoxelMode::Dense
                : v == "sparse"        ? VoxelMode::Sparse
                                       : VoxelMode::Clipmap;
            return true;
        };
        mode.print = [](const RenderSettings& s) {
            return std::string(s.voxelMode == VoxelMode::Dense ? "dense"
                    : s.voxelMode == VoxelMode::Sparse         ? "sparse"
                                                               : "clipmap");
        };
        t["voxel_mode"] = mode;
        t["clip_levels"] = makeField(&RenderSettings::clipLevels,
            "levels of voxel_mode=clipmap, each voxel_res^3 and half as wide as the one around it (2..6)");
        return t;
    }();
    return table;
}

} // namespace

const char* debugViewName(DebugView view)
{
    switch (view) {
    case DebugView::Final:
        return "final";
    case DebugView::Direct:
        return "direct";
    case DebugView::IndirectDiffuse:
        return "indirect_diffuse";
    case DebugView::IndirectSpecular:
        return "indirect_specular";
    case DebugView::AmbientOcclusion:
        return "ao";
    case DebugView::Albedo:
        return "albedo";
    case DebugView::Normal:
        return "normal";
    case DebugView::Emission:
        return "emission";
    }
    return "final";
}

std::string RenderSettings::set(const std::string& key, const std::string& value)
{
    return setAll({ { key, value } });
}

std::string RenderSettings::setAll(const std::vector<std::pair<std::string, std::string>>& assignments)
{
    RenderSettings candidate = *this;
    for (const auto& [key, value] : assignments) {
        const auto it = fields().find(key);
        if (it == fields().end()) {
            std::string known;
            for (const auto& [name, field] : fields())
                known += (known.empty() ? "" : ", ") + name;
            return "unknown setting '" + key + "' (known: " + known + ")";
        }
        if (!it->second.parse(candidate, value))
            return "setting '" + key + "': cannot read '" + value + "' (" + it->second.meaning + ")";
    }
    if (std::string problem = candidate.validate(); !problem.empty())
        return problem;
    *this = candidate;
    return {};
}

int RenderSettings::bounceCellVoxels(int resolution) const
{
    return std::min(bounceCellSize, resolution);
}

int RenderSettings::higherBounceCellVoxels(int resolution) const
{
    return std::max(bounceCellVoxels(resolution), std::min(higherBounceCellSize, resolution));
}

bool RenderSettings::splitsHigherBounces(int resolution) const
{
    const bool laterIterations = bounces == kConvergedBounces || bounces > 2;
    return higherBounceCellVoxels(resolution) > bounceCellVoxels(resolution) && laterIterations;
}

std::string RenderSettings::validate() const
{
    const bool powerOfTwo = voxelResolution > 0 && (voxelResolution & (voxelResolution - 1)) == 0;
    if (!powerOfTwo || voxelResolution < 8 || voxelResolution > 512)
        return "voxel_res must be a power of two from 8 to 512, not " + std::to_string(voxelResolution);
    if (clipLevels < 2 || clipLevels > 6)
        return "clip_levels must be 2..6, not " + std::to_string(clipLevels);
    if (voxelMode == VoxelMode::Sparse && !anisotropicMips)
        return "voxel_mode=sparse needs anisotropic=on: the box mip chain of anisotropic=off is kept in "
               "level 0's "
               "texture, which a sparse grid splits into bricks";
    if (irradianceCellSize != 1 && irradianceCellSize != 2 && irradianceCellSize != 4)
        return "irradiance_cell must be 1, 2 or 4, not " + std::to_string(irradianceCellSize);
    if (bounces != kConvergedBounces && (bounces < 1 || bounces > kMaxBounces))
        return "bounces must be converged or 1.." + std::to_string(kMaxBounces) + ", not "
            + std::to_string(bounces);
    if (bounceCellSize != 2 && bounceCellSize != 4 && bounceCellSize != 8)
        return "bounce_cell must be 2, 4 or 8, not " + std::to_string(bounceCellSize);
    if (higherBounceCellSize != 2 && higherBounceCellSize != 4 && higherBounceCellSize != 8
        && higherBounceCellSize != 16)
        return "higher_bounce_cell must be 2, 4, 8 or 16, not " + std::to_string(higherBounceCellSize);
    if (higherBounceCellSize < bounceCellSize)
        return "higher_bounce_cell (" + std::to_string(higherBounceCellSize)
            + ") must not be below bounce_cell (" + std::to_string(bounceCellSize)
            + "): the later bounces vary more slowly than the second";
    if (!(bounceTolerance >= 1e-4f && bounceTolerance <= 0.5f))
        return "bounce_tolerance must be 0.0001..0.5";
    if (diffuseConeCount < 1 || diffuseConeCount > 32)
        return "diffuse_cones must be 1..32, not " + std::to_string(diffuseConeCount);
    if (!(diffuseApertureDeg > 0.0f && diffuseApertureDeg < 180.0f))
        return "diffuse_aperture must be between 0 and 180 degrees (exclusive)";
    if (!(specularApertureDeg > 0.0f && specularApertureDeg < 180.0f))
        return "specular_aperture must be between 0 and 180 degrees (exclusive)";
    if (!(stepFactor > 0.0f))
        return "step must be greater than 0";
    if (!(bounceStepScale > 0.0f && bounceStepScale <= 8.0f))
        return "bounce_step must be greater than 0 and at most 8";
    if (indirectDivisor != 1 && indirectDivisor != 2 && indirectDivisor != 4)
        return "indirect_res must be 1, 2 or 4";
    if (areaShadowDivisor != 1 && areaShadowDivisor != 2 && areaShadowDivisor != 4)
        return "area_shadow_res must be 1, 2 or 4";
    if (specularDivisor != 1 && specularDivisor != 2 && specularDivisor != 4 && specularDivisor != 8)
        return "specular_res must be 1, 2, 4 or 8";
    if (!(coneOffsetVoxels >= 0.0f))
        return "cone_offset must be 0 or more";
    if (shadowMapSize < 64 || shadowMapSize > 8192)
        return "shadow_map must be 64..8192";
    if (!(exposure > 0.0f))
        return "exposure must be greater than 0";
    if (voxelBudgetMiB < 64 || voxelBudgetMiB > (1 << 20))
        return "voxel_budget_mb must be 64..1048576";
    if (const std::uint64_t bytes = voxelMemoryBytes(); bytes > std::uint64_t(voxelBudgetMiB) << 20) {
        char text[256];
        std::snprintf(text, sizeof text,
            "voxel_res=%d%s%s needs %.1f GiB of voxel textures, more than voxel_budget_mb=%d allows; "
            "lower voxel_res or raise voxel_budget_mb if the GL has the memory",
            voxelResolution, anisotropicMips ? " with anisotropic mips" : "",
            voxelMode == VoxelMode::Clipmap ? (" in " + std::to_string(clipLevels) + " clip levels").c_str()
                                            : "",
            double(bytes) / double(1u << 30), voxelBudgetMiB);
        return text;
    }
    return {};
}

std::uint64_t RenderSettings::voxelMemoryBytes(VoxelSceneNeeds scene) const
{
    std::uint64_t bytes = 0;
    for (const VoxelTextureEstimate& texture : VoxelTextureEstimate::of(*this, scene))
        bytes += texture.bytes;
    return bytes;
}

std::vector<std::vector<std::string>> RenderSettings::describe() const
{
    std::vector<std::vector<std::string>> rows;
    for (const auto& [name, field] : fields())
        rows.push_back({ name, field.print(*this), field.meaning });
    return rows;
}

} // namespace vct::render
