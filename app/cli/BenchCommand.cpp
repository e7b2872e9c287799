#include "cli/BenchCommand.h"

#include "Renderer.h"
#include "cli/AccuracyCommand.h"
#include "cli/PerfCommand.h"
#include "cli/PlanBenchmark.h"
#include "cli/SceneInput.h"
#include "cli/TargetsBenchmark.h"
#include "context/HeadlessContext.h"
#include "files/AtomicFile.h"
#include "imageio/ImageFile.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <optional>

namespace vct::cli {

namespace {

int fail(int code, const QString& message)
{
    std::fprintf(stderr, "vct-bench: %s\n", qPrintable(message));
    return code;
}

} // namespace

int BenchCommand::run(int argc, char** argv)
{
    // perf draws PNG charts, whose text needs a QGuiApplication: it makes its own application object.
    if (argc > 1 && std::strcmp(argv[1], "perf") == 0)
        return PerfCommand::run(argc, argv);
    if (argc > 1 && std::strcmp(argv[1], "accuracy") == 0)
        return AccuracyCommand::run(argc, argv);
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("vct-bench"));
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Measures the renderer; GPU times come from GL timestamp queries (medians over frames).\n"
        "  plan SCENE   replays edit sequences with the render plan and with every pass forced, and reports\n"
        "               GPU ms per frame for both (docs/BENCHMARKS.md).\n"
        "  perf SCENE   per-pass cost, voxel memory, cone-pass sampling efficiency and scaling curves (CSV,\n"
        "               Markdown, SVG/PNG charts); see vct-bench perf --help.\n"
        "  accuracy SCENE  error against a reference and GPU time over a sweep of settings, with the path "
        "tracer's\n"
        "               own curve (CSV, Markdown, SVG/PNG chart); see vct-bench accuracy --help.\n"
        "  targets SCENE   the naive path (--naive-set) against the settings given (--set), frames "
        "interleaved in\n"
        "               one run: full-frame and camera-only speed-ups, the interactive preview's frame rate "
        "and,\n"
        "               with --reference, both paths' relative MSE (docs/BENCHMARKS.md)."));
    parser.addHelpOption();
    parser.addPositionalArgument(
        QStringLiteral("COMMAND"), QStringLiteral("plan, perf, accuracy or targets"));
    parser.addPositionalArgument(
        QStringLiteral("SCENE"), QStringLiteral("a .vctproj project, builtin:NAME or a model file"));
    const QCommandLineOption widthOption(QStringLiteral("width"),
        QStringLiteral("Frame width (default 640)."), QStringLiteral("W"), QStringLiteral("640"));
    const QCommandLineOption heightOption(QStringLiteral("height"),
        QStringLiteral("Frame height (default 360)."), QStringLiteral("H"), QStringLiteral("360"));
    const QCommandLineOption voxelOption(QStringLiteral("voxel-res"),
        QStringLiteral("Voxel grid resolution (default 128)."), QStringLiteral("N"), QStringLiteral("128"));
    const QCommandLineOption framesOption(QStringLiteral("frames"),
        QStringLiteral("Timed frames per sequence and mode (default 5)."), QStringLiteral("N"),
        QStringLiteral("5"));
    const QCommandLineOption setOption(QStringLiteral("set"),
        QStringLiteral("Render setting, repeatable (see vct-render --help)."), QStringLiteral("key=value"));
    const QCommandLineOption outOption(QStringLiteral("out"),
        QStringLiteral("Also write the Markdown tables to this file."), QStringLiteral("FILE.md"));
    const QCommandLineOption glOption(QStringLiteral("gl"),
        QStringLiteral(
            "Headless GL backend: egl (default; falls back to osmesa when --gl is not given) or osmesa."),
        QStringLiteral("egl|osmesa"), QStringLiteral("egl"));
    const QCommandLineOption naiveSetOption(QStringLiteral("naive-set"),
        QStringLiteral(
            "targets: a setting of the naive path on top of --set, repeatable (default: indirect_res=1, "
            "specular_res=1 and irradiance_cache=off, every pixel traced with the full cone set)."),
        QStringLiteral("key=value"));
    const QCommandLineOption referenceOption(QStringLiteral("reference"),
        QStringLiteral("targets: a linear reference image (PFM/EXR) of the scene's camera; frames are "
                       "box-downsampled to its size."),
        QStringLiteral("FILE"));
    // The editor's viewport renders at this share of its size while the view moves
    // (ViewportWidget::kInteractiveScale).
    const QCommandLineOption previewScaleOption(QStringLiteral("preview-scale"),
        QStringLiteral(
            "targets: the interactive preview's share of --width/--height (default 0.35, as the editor)."),
        QStringLiteral("S"), QStringLiteral("0.35"));
    const QCommandLineOption sequenceOption(QStringLiteral("sequence"),
        QStringLiteral("plan: only the edit sequences whose name contains TEXT (say, \"fly\"), and no full "
                       "rebuild."),
        QStringLiteral("TEXT"));
    const QCommandLineOption iterationsOption(QStringLiteral("iterations-per-frame"),
        QStringLiteral(
            "plan: bounce iterations a frame runs, each solve going on from the last, as the editor "
            "does with 2 (default 0: every frame solves its bounces in full, as vct-render)."),
        QStringLiteral("N"), QStringLiteral("0"));
    parser.addOptions({ widthOption, heightOption, voxelOption, framesOption, setOption, outOption, glOption,
        naiveSetOption, referenceOption, previewScaleOption, sequenceOption, iterationsOption });
    parser.process(app);

    const QStringList args = parser.positionalArguments();
    if (args.size() != 2 || (args[0] != QStringLiteral("plan") && args[0] != QStringLiteral("targets")))
        return fail(1, QStringLiteral("usage: vct-bench plan|targets SCENE [options] (see --help)"));
    const bool targets = args[0] == QStringLiteral("targets");
    bool ok = false;
    const int width = parser.value(widthOption).toInt(&ok);
    const int height = ok ? parser.value(heightOption).toInt(&ok) : 0;
    const int frames = ok ? parser.value(framesOption).toInt(&ok) : 0;
    if (!ok || width < 1 || height < 1 || width > 16384 || height > 16384 || frames < 1 || frames > 1000)
        return fail(1, QStringLiteral("--width/--height must be 1..16384 and --frames 1..1000"));

    render::Scene scene;
    render::RenderSettings settings;
    doc::SceneLoadInfo info;
    QString error;
    if (!loadSceneInput(args[1], scene, settings, info, &error))
        return fail(1, error);
    QStringList assignments = parser.values(setOption);
    assignments.prepend(QStringLiteral("voxel_res=") + parser.value(voxelOption));
    if (const QString problem = applySettingAssignments(assignments, settings); !problem.isEmpty())
        return fail(1, problem);
    render::RenderSettings naiveSettings = settings;
    QStringList naiveAssignments = parser.values(naiveSetOption);
    if (naiveAssignments.isEmpty())
        naiveAssignments = { QStringLiteral("indirect_res=1"), QStringLiteral("specular_res=1"),
            QStringLiteral("irradiance_cache=off") };
    if (const QString problem = applySettingAssignments(naiveAssignments, naiveSettings); !problem.isEmpty())
        return fail(1, problem);
    const int iterationsPerFrame = parser.value(iterationsOption).toInt(&ok);
    if (!ok || iterationsPerFrame < 0 || iterationsPerFrame > 64)
        return fail(1, QStringLiteral("--iterations-per-frame must be 0 to 64"));
    const double previewScale = parser.value(previewScaleOption).toDouble(&ok);
    if (!ok || !(previewScale > 0.0 && previewScale <= 1.0))
        return fail(1, QStringLiteral("--preview-scale must be in (0, 1]"));
    std::optional<render::RadianceImage> reference;
    if (parser.isSet(referenceOption)) {
        std::string readError;
        reference = io::ImageFile::read(parser.value(referenceOption).toStdString(), &readError);
        if (!reference)
            return fail(1, QString::fromStdString(readError));
        const int factor = width / reference->width;
        if (factor < 1 || reference->width * factor != width || reference->height * factor != height)
            return fail(1,
                QStringLiteral(
                    "the reference is %1x%2: --width/--height must be the same integer multiple of it")
                    .arg(reference->width)
                    .arg(reference->height));
    }

    std::string contextError;
    auto context = render::HeadlessContext::createPreferring(
        parser.value(glOption).toStdString(), parser.isSet(glOption), contextError);
    if (!context)
        return fail(2, QString::fromStdString(contextError));
    std::string report;
    try {
        if (targets) {
            render::Renderer naive(context->procAddressFunction());
            render::Renderer fast(context->procAddressFunction());
            naive.setSettings(naiveSettings);
            fast.setSettings(settings);
            naive.setScene(scene);
            fast.setScene(scene);
            const int previewWidth = std::max(1, int(width * previewScale + 0.5));
            const int previewHeight = std::max(1, int(height * previewScale + 0.5));
            const TargetsResult result = TargetsBenchmark::run(naive, fast, scene.camera, width, height,
                previewWidth, previewHeight, frames, reference ? &*reference : nullptr);
            std::string command = "`vct-bench targets " + args[1].toStdString() + " --width "
                + std::to_string(width) + " --height " + std::to_string(height) + " --voxel-res "
                + std::to_string(settings.voxelResolution) + " --frames " + std::to_string(frames);
            for (const QString& a : parser.values(setOption))
                command += " --set " + a.toStdString();
            for (const QString& a : parser.values(naiveSetOption))
                command += " --naive-set " + a.toStdString();
            if (reference)
                command += " --reference " + parser.value(referenceOption).toStdString();
            report = command + "` on " + context->description() + "\n\n" + TargetsBenchmark::markdown(result);
        } else {
            render::Renderer renderer(context->procAddressFunction());
            renderer.setSettings(settings);
            renderer.setBounceIterationsPerFrame(iterationsPerFrame);
            std::vector<SequenceResult> results;
            const std::string only = parser.value(sequenceOption).toStdString();
            for (const EditSequence& sequence : PlanBenchmark::standardSequences(scene)) {
                if (!only.empty() && sequence.name.find(only) == std::string::npos)
                    continue;
                results.push_back(PlanBenchmark::run(renderer, scene, sequence, width, height, frames));
                std::fprintf(stderr, "  %-40s planned %8.1f ms (worst %.1f)  forced %8.1f ms\n",
                    sequence.name.c_str(), results.back().plannedMs, results.back().plannedWorstMs,
                    results.back().forcedMs);
            }
            std::string command = "`vct-bench plan " + args[1].toStdString() + " --width "
                + std::to_string(width) + " --height " + std::to_string(height) + " --voxel-res "
                + std::to_string(settings.voxelResolution) + " --frames " + std::to_string(frames);
            for (const QString& a : parser.values(setOption))
                command += " --set " + a.toStdString();
            if (!only.empty())
                command += " --sequence \"" + only + "\"";
            if (iterationsPerFrame > 0)
                command += " --iterations-per-frame " + std::to_string(iterationsPerFrame);
            const std::string header = command + "` on " + context->description() + "\n\n";
            // The editor spreads bounce iterations over frames two at a time (ui/ViewportWidget).
            constexpr int kEditorIterationsPerFrame = 2;
            report = header + PlanBenchmark::markdown(results);
            if (only.empty())
                report
                    += PlanBenchmark::markdown(PlanBenchmark::rebuilds(renderer, scene.camera, width, height,
                                                   kEditorIterationsPerFrame, std::max(1, frames / 2)),
                        kEditorIterationsPerFrame);
        }
    } catch (const std::exception& e) {
        return fail(3, QString::fromUtf8(e.what()));
    }
    std::fputs(report.c_str(), stdout);
    if (parser.isSet(outOption)) {
        QString error;
        if (!files::AtomicFile::write(parser.value(outOption), std::string_view(report), &error))
            return fail(3, error);
    }
    return 0;
}

} // namespace vct::cli
