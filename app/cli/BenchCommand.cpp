#include "cli/BenchCommand.h"

#include "cli/AccuracyCommand.h"
#include "cli/PerfCommand.h"
#include "cli/PlanBenchmark.h"
#include "cli/SceneInput.h"
#include "context/HeadlessContext.h"
#include "core/Renderer.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QSaveFile>

#include <cstdio>
#include <cstring>

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
        "  accuracy SCENE  error against a reference and GPU time over a sweep of settings, with the path tracer's\n"
        "               own curve (CSV, Markdown, SVG/PNG chart); see vct-bench accuracy --help."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("COMMAND"), QStringLiteral("plan, perf or accuracy"));
    parser.addPositionalArgument(QStringLiteral("SCENE"), QStringLiteral("a .vctproj project, builtin:NAME or a model file"));
    const QCommandLineOption widthOption(QStringLiteral("width"), QStringLiteral("Frame width (default 640)."), QStringLiteral("W"), QStringLiteral("640"));
    const QCommandLineOption heightOption(QStringLiteral("height"), QStringLiteral("Frame height (default 360)."), QStringLiteral("H"), QStringLiteral("360"));
    const QCommandLineOption voxelOption(QStringLiteral("voxel-res"), QStringLiteral("Voxel grid resolution (default 128)."), QStringLiteral("N"), QStringLiteral("128"));
    const QCommandLineOption framesOption(QStringLiteral("frames"), QStringLiteral("Timed frames per sequence and mode (default 5)."), QStringLiteral("N"), QStringLiteral("5"));
    const QCommandLineOption setOption(QStringLiteral("set"), QStringLiteral("Render setting, repeatable (see vct-render --help)."), QStringLiteral("key=value"));
    const QCommandLineOption outOption(QStringLiteral("out"), QStringLiteral("Also write the Markdown tables to this file."), QStringLiteral("FILE.md"));
    const QCommandLineOption glOption(QStringLiteral("gl"), QStringLiteral("Headless GL backend: egl (default; falls back to osmesa when --gl is not given) or osmesa."), QStringLiteral("egl|osmesa"), QStringLiteral("egl"));
    parser.addOptions({widthOption, heightOption, voxelOption, framesOption, setOption, outOption, glOption});
    parser.process(app);

    const QStringList args = parser.positionalArguments();
    if (args.size() != 2 || args[0] != QStringLiteral("plan"))
        return fail(1, QStringLiteral("usage: vct-bench plan SCENE [options] (see --help)"));
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

    std::string contextError;
    auto context = render::HeadlessContext::createPreferring(
        parser.value(glOption).toStdString(), parser.isSet(glOption), contextError);
    if (!context)
        return fail(2, QString::fromStdString(contextError));
    std::string report;
    try {
        render::Renderer renderer(context->procAddressFunction());
        renderer.setSettings(settings);
        std::vector<SequenceResult> results;
        for (const EditSequence& sequence : PlanBenchmark::standardSequences(scene)) {
            results.push_back(PlanBenchmark::run(renderer, scene, sequence, width, height, frames));
            std::fprintf(stderr, "  %-40s planned %8.1f ms  forced %8.1f ms\n", sequence.name.c_str(),
                results.back().plannedMs, results.back().forcedMs);
        }
        char header[512];
        std::snprintf(header, sizeof header, "`vct-bench plan %s --width %d --height %d --voxel-res %d --frames %d` on %s\n\n",
            qPrintable(args[1]), width, height, settings.voxelResolution, frames, context->description().c_str());
        report = header + PlanBenchmark::markdown(results);
    } catch (const std::exception& e) {
        return fail(3, QString::fromUtf8(e.what()));
    }
    std::fputs(report.c_str(), stdout);
    if (parser.isSet(outOption)) {
        QSaveFile file(parser.value(outOption));
        if (!file.open(QIODevice::WriteOnly) || file.write(report.c_str(), qint64(report.size())) < 0 || !file.commit())
            return fail(3, QStringLiteral("cannot write '%1': %2").arg(parser.value(outOption), file.errorString()));
    }
    return 0;
}

} // namespace vct::cli
