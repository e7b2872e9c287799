#include "cli/RenderCommand.h"

#include "cli/BlackImageCheck.h"

#include "Renderer.h"
#include "cli/SceneInput.h"
#include "cli/StatsJson.h"
#include "cli/TerminalProgress.h"
#include "context/HeadlessContext.h"
#include "core/BrickPool.h"
#include "document/CameraFile.h"
#include "document/LightsFile.h"
#include "document/ProjectFile.h"
#include "document/SceneLoader.h"
#include "files/AtomicFile.h"
#include "imageio/ImageFile.h"
#include "imageio/ImageMetrics.h"
#include "reference/ReferenceRenderer.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <limits>

namespace vct::cli {

namespace {

int fail(int code, const QString& message)
{
    std::fprintf(stderr, "vct-render: %s\n", qPrintable(message));
    return code;
}

QString settingsHelp()
{
    QString text = QStringLiteral("\nSettings for --set key=value (defaults shown):\n");
    for (const auto& row : render::RenderSettings().describe())
        text += QStringLiteral("  %1=%2  %3\n")
                    .arg(QString::fromStdString(row[0]), QString::fromStdString(row[1]),
                        QString::fromStdString(row[2]));
    return text;
}

/** What --reference renders with, from --spp, --max-bounces, --seed and --threads. */
struct ReferenceRequest {
    int samplesPerPixel = 256;
    render::ReferenceSettings settings;
};

/**
 * The ground truth instead of the GL frame: the CPU path tracer, no GL context. Writes the same image formats
 * and, with --stats, what the run cost. Returns the process exit code.
 */
int renderReference(const ReferenceRequest& request, const render::Scene& scene, const render::Camera& camera,
    int width, int height, const QString& outPath, float exposure, const QString& statsPath, bool checkFinite)
{
    render::RadianceImage image;
    render::ReferenceStats stats;
    try {
        render::ReferenceRenderer renderer(scene, camera, width, height, request.settings);
        if (renderer.droppedTriangles() > 0)
            std::fprintf(stderr,
                "vct-render: warning: %zu triangles left out of the path tracer's scene: zero area or "
                "non-finite once placed in the world\n",
                renderer.droppedTriangles());
        TerminalProgress progress("vct-render: reference");
        const bool done
            = renderer.render(request.samplesPerPixel, [&](double fraction) { progress(fraction); });
        progress.finish();
        if (!done)
            return fail(3, QStringLiteral("the reference render stopped before it finished"));
        image = renderer.image();
        stats = renderer.stats();
    } catch (const std::exception& e) {
        return fail(3, QString::fromUtf8(e.what()));
    }
    std::uint64_t nonFinite = 0;
    if (checkFinite) {
        nonFinite = io::ImageMetrics::nonFiniteCount(image);
        std::printf(
            "check-finite: %llu non-finite channel values in the image (%llu non-finite paths dropped)\n",
            static_cast<unsigned long long>(nonFinite),
            static_cast<unsigned long long>(stats.nonFiniteSamples));
    }
    if (const std::string warning = blackImageWarning(image, scene, camera); !warning.empty())
        std::fprintf(stderr, "vct-render: warning: %s\n", warning.c_str());
    std::string writeError;
    if (!io::ImageFile::write(outPath.toStdString(), image, exposure, &writeError))
        return fail(3, QString::fromStdString(writeError));
    const double seconds = std::max(stats.seconds, std::numeric_limits<double>::min());
    std::printf(
        "wrote %s (%dx%d) with the reference path tracer: %d spp, max %d bounces, seed %llu, %d threads\n",
        qPrintable(outPath), width, height, request.samplesPerPixel, request.settings.maxBounces,
        static_cast<unsigned long long>(request.settings.seed), request.settings.threads);
    std::printf("  %.2f s, %.3f M samples/s, %.2f M rays/s (%.2f rays per sample)\n", stats.seconds,
        double(stats.samples) / seconds * 1e-6, double(stats.rays) / seconds * 1e-6,
        double(stats.rays) / double(std::max<std::uint64_t>(stats.samples, 1)));
    if (!statsPath.isEmpty()) {
        QJsonObject json;
        json["renderer"] = QStringLiteral("reference");
        json["width"] = width;
        json["height"] = height;
        json["spp"] = request.samplesPerPixel;
        json["max_bounces"] = request.settings.maxBounces;
        json["seed"] = QString::number(request.settings.seed);
        json["threads"] = request.settings.threads;
        json["seconds"] = stats.seconds;
        json["samples"] = double(stats.samples);
        json["rays"] = double(stats.rays);
        json["non_finite_samples"] = double(stats.nonFiniteSamples);
        if (const QString problem = files::AtomicFile::write(statsPath, QJsonDocument(json).toJson());
            !problem.isEmpty())
            return fail(3, QStringLiteral("cannot write stats to '%1': %2").arg(statsPath, problem));
    }
    return nonFinite ? 4 : 0;
}

/** Reads an integer option in [lo, hi] into @p target; returns an error message or an empty string. */
QString readIntOption(const QCommandLineParser& parser, const QCommandLineOption& option, long long lo,
    long long hi, long long& target)
{
    if (!parser.isSet(option))
        return {};
    bool ok = false;
    target = parser.value(option).toLongLong(&ok);
    if (!ok || target < lo || target > hi)
        return QStringLiteral("--%1 must be %2..%3").arg(option.names().front()).arg(lo).arg(hi);
    return {};
}

} // namespace

int RenderCommand::run(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("vct-render"));
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral(
            "Renders a scene with voxel cone tracing, headless; with --reference, with the CPU path tracer "
            "instead.\n"
            "SCENE is a project (.vctproj), builtin:NAME (cornell, cornell_point, atrium, bunny, default) or "
            "a model\nfile Assimp reads "
            "(OBJ+MTL, glTF/GLB, PLY, FBX, ...); NAME.lights.json and NAME.camera.json beside a model are "
            "read too.\n"
            "Units: point lights W/sr, directional lights W/m^2, emission and output radiance W/(m^2 sr).\n"
            ".png output is tone-mapped sRGB (exposure + filmic curve); .pfm/.exr hold linear radiance.")
        + settingsHelp());
    parser.addHelpOption();
    parser.addPositionalArgument(
        QStringLiteral("SCENE"), QStringLiteral("a .vctproj project, builtin:NAME or a model file"));
    const QCommandLineOption cameraOption(QStringLiteral("camera"),
        QStringLiteral("Camera JSON (the format of tests/data/reference)."), QStringLiteral("cam.json"));
    const QCommandLineOption lightsOption(QStringLiteral("lights"),
        QStringLiteral("Lights JSON replacing the scene's lights."), QStringLiteral("lights.json"));
    const QCommandLineOption widthOption(QStringLiteral("width"),
        QStringLiteral("Image width in pixels (default: camera file or 640)."), QStringLiteral("W"));
    const QCommandLineOption heightOption(QStringLiteral("height"),
        QStringLiteral("Image height in pixels (default: camera file or 360)."), QStringLiteral("H"));
    const QCommandLineOption outOption(QStringLiteral("out"),
        QStringLiteral("Output image: .png, .pfm or .exr (default out.png)."), QStringLiteral("FILE"),
        QStringLiteral("out.png"));
    const QCommandLineOption voxelOption(QStringLiteral("voxel-res"),
        QStringLiteral("Voxel grid resolution, power of two 8..512 (same as --set voxel_res=N)."),
        QStringLiteral("N"));
    const QCommandLineOption setOption(QStringLiteral("set"),
        QStringLiteral("Render setting, repeatable; see the list below."), QStringLiteral("key=value"));
    const QCommandLineOption statsOption(QStringLiteral("stats"),
        QStringLiteral("Write per-pass GPU ms, voxel memory and settings as JSON."),
        QStringLiteral("stats.json"));
    const QCommandLineOption framesOption(QStringLiteral("frames"),
        QStringLiteral("Render N full frames (every pass re-run); --stats gives the median of frames 2..N, "
                       "leaving out the first, which compiles shaders. Default 1."),
        QStringLiteral("N"), QStringLiteral("1"));
    const QCommandLineOption checkFiniteOption(QStringLiteral("check-finite"),
        QStringLiteral("Count NaN/Inf texels in every float render target and voxel level; exit 4 if any."));
    const QCommandLineOption glOption(QStringLiteral("gl"),
        QStringLiteral(
            "Headless GL backend: egl (default; falls back to osmesa when --gl is not given) or osmesa."),
        QStringLiteral("egl|osmesa"), QStringLiteral("egl"));
    const QCommandLineOption referenceOption(QStringLiteral("reference"),
        QStringLiteral("Render the ground truth with the CPU path tracer (Embree) instead of the GL "
                       "renderer; no GL context is needed."));
    const QCommandLineOption sppOption(QStringLiteral("spp"),
        QStringLiteral("--reference: samples per pixel (default 256)."), QStringLiteral("N"));
    const QCommandLineOption maxBouncesOption(QStringLiteral("max-bounces"),
        QStringLiteral(
            "--reference: longest path in reflections, 0 = emitters only, 1 = direct light (default 64)."),
        QStringLiteral("K"));
    const QCommandLineOption seedOption(QStringLiteral("seed"),
        QStringLiteral("--reference: random seed (default 0); same seed, same image."), QStringLiteral("S"));
    const QCommandLineOption threadsOption(QStringLiteral("threads"),
        QStringLiteral("--reference: worker threads (default: all cores)."), QStringLiteral("T"));
    const QCommandLineOption unitScaleOption(QStringLiteral("unit-scale"),
        QStringLiteral("Metres per unit of a model file SCENE (0.01 for centimetres, 0.001 for millimetres); "
                       "its NAME.lights.json and NAME.camera.json are in its units too; --camera and "
                       "--lights files stay in metres. Default 1."),
        QStringLiteral("S"));
    const QCommandLineOption upAxisOption(QStringLiteral("up-axis"),
        QStringLiteral(
            "The axis that points up in a model file SCENE: y (default) or z (CAD tools, 3ds Max and "
            "many exports); its lights and camera files are in its axes too."),
        QStringLiteral("AXIS"));
    const QCommandLineOption sceneRootOption(QStringLiteral("scene-root"),
        QStringLiteral("The folder a project's relative model paths resolve against, instead of the "
                       "project's (default: $%1 when set).")
            .arg(QLatin1String(doc::ProjectFile::kModelRootVariable)),
        QStringLiteral("DIR"));
    parser.addOptions({ cameraOption, lightsOption, widthOption, heightOption, outOption, voxelOption,
        setOption, statsOption, framesOption, checkFiniteOption, glOption, referenceOption, sppOption,
        maxBouncesOption, seedOption, threadsOption, unitScaleOption, upAxisOption, sceneRootOption });
    parser.process(app);

    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1)
        return fail(1, QStringLiteral("expected exactly one SCENE argument (see --help)"));
    const QString sceneSpec = positional.front();
    const bool isProject = sceneSpec.endsWith(QStringLiteral(".vctproj"), Qt::CaseInsensitive);
    float unitScale = 1.0f;
    if (parser.isSet(unitScaleOption)) {
        if (isProject)
            return fail(1,
                QStringLiteral("--unit-scale applies to a model file; a project gives each of its sources "
                               "its own \"unit_scale\""));
        if (sceneSpec.startsWith(QStringLiteral("builtin:")))
            return fail(
                1, QStringLiteral("--unit-scale applies to a model file; built-in scenes are in metres"));
        if (const QString problem
            = doc::SceneLoader::parseUnitScale(parser.value(unitScaleOption), &unitScale);
            !problem.isEmpty())
            return fail(1, QStringLiteral("--unit-scale: %1").arg(problem));
    }
    doc::SceneLoader::UpAxis upAxis = doc::SceneLoader::UpAxis::Y;
    if (parser.isSet(upAxisOption)) {
        if (isProject || sceneSpec.startsWith(QStringLiteral("builtin:")))
            return fail(1, QStringLiteral("--up-axis applies to a model file"));
        if (const QString problem = doc::SceneLoader::parseUpAxis(parser.value(upAxisOption), &upAxis);
            !problem.isEmpty())
            return fail(1, QStringLiteral("--up-axis: %1").arg(problem));
    }
    if (parser.isSet(sceneRootOption) && !isProject)
        std::fprintf(
            stderr, "vct-render: warning: --scene-root is ignored: only a project's model paths use it\n");

    render::Scene scene;
    QString error;
    doc::SceneLoadInfo info;
    render::RenderSettings settings;
    // A project brings its own settings and camera; --set and --camera still override them.
    if (!loadSceneInput(sceneSpec, scene, settings, info, &error, unitScale, parser.value(sceneRootOption)))
        return fail(1, error);
    if (upAxis != doc::SceneLoader::UpAxis::Y) {
        scene = doc::SceneLoader::uprightScene(std::move(scene), upAxis);
        // A camera of the loader's own framed the model lying on its side: frame it upright.
        if (!info.hasCameraFile)
            scene.camera = doc::SceneLoader::frameScene(scene);
    }
    if (scene.origin != glm::dvec3(0.0))
        std::printf(
            "%s lies far from the world's origin: rendered about a local origin at (%.3f, %.3f, %.3f) m\n",
            qPrintable(sceneSpec), scene.origin.x, scene.origin.y, scene.origin.z);
    QStringList assignments = parser.values(setOption);
    if (parser.isSet(voxelOption))
        assignments.prepend(QStringLiteral("voxel_res=") + parser.value(voxelOption));
    if (const QString problem = applySettingAssignments(assignments, settings); !problem.isEmpty())
        return fail(1, problem);
    bool framesOk = false;
    const int frames = parser.value(framesOption).toInt(&framesOk);
    if (!framesOk || frames < 1 || frames > 1000)
        return fail(1, QStringLiteral("--frames must be 1..1000"));

    ViewInput view;
    if (!resolveViewInput(parser.value(lightsOption), parser.value(cameraOption), info, scene, view, &error))
        return fail(1, error);
    render::Camera camera = view.camera;
    int width = view.width;
    int height = view.height;
    for (const auto& [option, target] :
        { std::pair { &widthOption, &width }, std::pair { &heightOption, &height } })
        if (parser.isSet(*option)) {
            bool ok = false;
            *target = parser.value(*option).toInt(&ok);
            if (!ok || *target < 1 || *target > 16384)
                return fail(1, QStringLiteral("--%1 must be 1..16384").arg(option->names().front()));
        }
    const QString outPath = parser.value(outOption);
    if (io::ImageFile::formatFor(outPath.toStdString()) == io::ImageFile::Format::Unknown)
        return fail(
            1, QStringLiteral("cannot tell the image format of '%1' (use .png, .pfm or .exr)").arg(outPath));

    if (parser.isSet(referenceOption)) {
        ReferenceRequest request;
        long long spp = request.samplesPerPixel, maxBounces = request.settings.maxBounces,
                  threads = std::max(1, request.settings.threads), seed = 0;
        for (const QString& problem : { readIntOption(parser, sppOption, 1, 1 << 20, spp),
                 readIntOption(parser, maxBouncesOption, 0, 100000, maxBounces),
                 readIntOption(parser, threadsOption, 1, 1024, threads),
                 readIntOption(parser, seedOption, 0, std::numeric_limits<long long>::max(), seed) })
            if (!problem.isEmpty())
                return fail(1, problem);
        request.samplesPerPixel = int(spp);
        request.settings.maxBounces = int(maxBounces);
        request.settings.threads = int(threads);
        request.settings.seed = std::uint64_t(seed);
        for (const QCommandLineOption* glOnly : { &framesOption, &glOption, &voxelOption })
            if (parser.isSet(*glOnly))
                std::fprintf(stderr, "vct-render: warning: --%s is ignored with --reference\n",
                    qPrintable(glOnly->names().front()));
        return renderReference(request, scene, camera, width, height, outPath, settings.exposure,
            parser.isSet(statsOption) ? parser.value(statsOption) : QString(),
            parser.isSet(checkFiniteOption));
    }
    for (const QCommandLineOption* referenceOnly :
        { &sppOption, &maxBouncesOption, &seedOption, &threadsOption })
        if (parser.isSet(*referenceOnly))
            return fail(1, QStringLiteral("--%1 needs --reference").arg(referenceOnly->names().front()));

    std::string contextError;
    auto context = render::HeadlessContext::createPreferring(
        parser.value(glOption).toStdString(), parser.isSet(glOption), contextError);
    if (!context)
        return fail(2, QString::fromStdString(contextError));

    std::vector<render::FrameStats> timed;
    std::vector<render::BrickOccupancy> bricks;
    render::RadianceImage image;
    std::uint64_t nonFinite = 0;
    try {
        render::Renderer renderer(context->procAddressFunction());
        renderer.setSettings(settings);
        renderer.setScene(scene);
        // The stats say where the bounce solve's time went; a run without them does not wait for it.
        renderer.setPhaseTimes(parser.isSet(statsOption));
        for (int i = 0; i < frames; ++i) {
            if (i > 0)
                renderer.invalidate();
            render::FrameStats stats = renderer.renderFrame(camera, width, height);
            if (frames == 1 || i > 0)
                timed.push_back(stats);
        }
        // The light is written as far as it got: say so where the solve ran out of iterations, not silently.
        if (!timed.empty() && timed.back().bounceStoppedAtLimit)
            std::fprintf(stderr,
                "vct-render: warning: the bounced light stopped at its limit of %d iterations, "
                "still changing by %.2g per iteration (a closed room of albedo near 1 keeps its light "
                "for long); the image is darker than its limit\n",
                timed.back().bounceIterations, timed.back().bounceResidual);
        image = renderer.readFrame();
        if (parser.isSet(statsOption))
            for (const int brickSize : { 4, 8 }) {
                const std::vector<render::BrickOccupancy> grids = renderer.brickOccupancy(brickSize);
                bricks.insert(bricks.end(), grids.begin(), grids.end());
            }
        if (parser.isSet(checkFiniteOption)) {
            for (const render::NonFiniteCount& c : renderer.countNonFinite()) {
                nonFinite += c.count;
                if (c.count)
                    std::fprintf(stderr, "vct-render: %llu non-finite texels in %s\n",
                        static_cast<unsigned long long>(c.count), c.resource.c_str());
            }
            std::printf("check-finite: %llu non-finite texels in all render targets and voxel levels\n",
                static_cast<unsigned long long>(nonFinite));
        }
        for (const std::string& message : renderer.takeGlErrors())
            std::fprintf(stderr, "vct-render: warning: %s\n", message.c_str());
    } catch (const std::exception& e) {
        return fail(3, QString::fromUtf8(e.what()));
    }

    if (const std::string warning = blackImageWarning(image, scene, camera); !warning.empty())
        std::fprintf(stderr, "vct-render: warning: %s\n", warning.c_str());
    std::string writeError;
    if (!io::ImageFile::write(outPath.toStdString(), image, settings.exposure, &writeError))
        return fail(3, QString::fromStdString(writeError));
    std::printf(
        "wrote %s (%dx%d) with %s\n", qPrintable(outPath), width, height, context->description().c_str());

    if (parser.isSet(statsOption)) {
        QJsonObject json
            = statsToJson(timed, settings, sceneSpec, QString::fromStdString(context->description()));
        json["brick_occupancy"] = bricksToJson(bricks);
        if (const QString problem
            = files::AtomicFile::write(parser.value(statsOption), QJsonDocument(json).toJson());
            !problem.isEmpty())
            return fail(
                3, QStringLiteral("cannot write stats to '%1': %2").arg(parser.value(statsOption), problem));
        for (const QJsonValue& pass : json["passes"].toArray()) {
            const QJsonObject p = pass.toObject();
            std::printf("  %-13s %-7s %8.2f ms  (%s)\n", qPrintable(p["name"].toString()),
                qPrintable(p["action"].toString()), p["gpu_ms"].toDouble(),
                qPrintable(p["reason"].toString()));
        }
        std::printf(
            "  total %.2f ms GPU, voxel memory %.1f MiB (%.1f bytes per cell, %.0f per occupied voxel)\n",
            json["total_gpu_ms"].toDouble(), json["voxel_memory_bytes"].toDouble() / (1024.0 * 1024.0),
            json["voxel_bytes_per_cell"].toDouble(), json["voxel_bytes_per_occupied_voxel"].toDouble());
        for (const render::BrickOccupancy& b : bricks) {
            std::printf(
                "  grid %d (%d^3): %zu of %zu bricks of %d^3 hold a surface (%.1f%%); a pool of them with "
                "a one-voxel border would take %.1f%% of level 0\n",
                b.grid, b.resolution, b.occupiedBricks, b.totalBricks, b.brickSize, 100.0 * b.share(),
                100.0 * b.borderedPoolShare());
            if (b.poolSlots > 0)
                std::printf(
                    "  grid %d is sparse: its pools store %zu bricks (%.1f%% of the grid's) in %zu slots, "
                    "%.1f%% of a dense level 0\n",
                    b.grid, b.storedBricks, 100.0 * double(b.storedBricks) / double(b.totalBricks),
                    b.poolSlots,
                    100.0 * double(b.poolSlots) * double(render::BrickPool::kTexelsPerBrick)
                        / (double(b.totalBricks) * double(render::BrickPool::kVoxelsPerBrick)));
        }
    }
    return nonFinite ? 4 : 0;
}

} // namespace vct::cli
