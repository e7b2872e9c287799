#include "cli/PerfCommand.h"

#include "Renderer.h"
#include "cli/PerfBenchmark.h"
#include "cli/PerfReport.h"
#include "cli/SceneInput.h"
#include "context/HeadlessContext.h"
#include "files/AtomicFile.h"
#include "plot/ChartWriter.h"

#include <QCommandLineParser>
#include <QDir>
#include <QGuiApplication>

#include <algorithm>
#include <cstdio>

namespace vct::cli {

namespace {

constexpr QSize kChartSize(960, 600);

int fail(int code, const QString& message)
{
    std::fprintf(stderr, "vct-bench perf: %s\n", qPrintable(message));
    return code;
}

bool parseSize(const QString& text, std::pair<int, int>& size)
{
    const QStringList parts = text.trimmed().split(QLatin1Char('x'));
    bool okW = false, okH = false;
    if (parts.size() == 2)
        size = { parts[0].toInt(&okW), parts[1].toInt(&okH) };
    return okW && okH && size.first >= 1 && size.second >= 1 && size.first <= 16384 && size.second <= 16384;
}

bool parseSizes(const QString& text, std::vector<std::pair<int, int>>& sizes)
{
    sizes.clear();
    for (const QString& item : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        std::pair<int, int> size;
        if (!parseSize(item, size))
            return false;
        sizes.push_back(size);
    }
    return !sizes.empty();
}

bool parseInts(const QString& text, std::vector<int>& values)
{
    values.clear();
    for (const QString& item : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        bool ok = false;
        values.push_back(item.trimmed().toInt(&ok));
        if (!ok)
            return false;
    }
    return !values.empty();
}

bool isPowerOfTwo(int v)
{
    return v >= 1 && (v & (v - 1)) == 0;
}

} // namespace

int PerfCommand::run(int argc, char** argv)
{
    // PNG charts draw text, which needs a QGuiApplication; the offscreen platform needs no display. GL does
    // not come from Qt here (our own EGL/OSMesa context), so Qt's offscreen lack of GL does not matter.
    if (!qEnvironmentVariableIsSet("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("vct-bench"));
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "vct-bench perf: per-pass GPU ms of full frames (every pass re-run) and camera-only frames (the plan "
        "reuses "
        "voxels), voxel memory per 3D texture level, and the cone pass's 3D samples per second against the "
        "peak "
        "trilinear rate measured in the same run. Three scaling curves: output size (at --base-grid), grid "
        "resolution and triangle count (at --base-size)."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("perf"), QStringLiteral("the subcommand"));
    parser.addPositionalArgument(
        QStringLiteral("SCENE"), QStringLiteral("a .vctproj project, builtin:NAME or a model file"));
    const QCommandLineOption sizesOption(QStringLiteral("sizes"),
        QStringLiteral("Output sizes of the size curve (default 320x180,640x360,1280x720)."),
        QStringLiteral("WxH,..."), QStringLiteral("320x180,640x360,1280x720"));
    const QCommandLineOption gridsOption(QStringLiteral("grids"),
        QStringLiteral("Grid resolutions of the grid curve (default 32,64,128,256)."),
        QStringLiteral("N,..."), QStringLiteral("32,64,128,256"));
    const QCommandLineOption trianglesOption(QStringLiteral("triangles"),
        QStringLiteral("Triangle multipliers of the triangle curve, powers of two (default 1,4,16)."),
        QStringLiteral("F,..."), QStringLiteral("1,4,16"));
    const QCommandLineOption baseSizeOption(QStringLiteral("base-size"),
        QStringLiteral("Output size of the grid and triangle curves (default 640x360)."),
        QStringLiteral("WxH"), QStringLiteral("640x360"));
    const QCommandLineOption baseGridOption(QStringLiteral("base-grid"),
        QStringLiteral("Grid of the size and triangle curves (default 128)."), QStringLiteral("N"),
        QStringLiteral("128"));
    const QCommandLineOption framesOption(QStringLiteral("frames"),
        QStringLiteral("Timed frames per mode and configuration (default 5)."), QStringLiteral("N"),
        QStringLiteral("5"));
    const QCommandLineOption setOption(QStringLiteral("set"),
        QStringLiteral("Render setting, repeatable (see vct-render --help)."), QStringLiteral("key=value"));
    const QCommandLineOption outOption(QStringLiteral("out"),
        QStringLiteral("Directory for the CSV, Markdown and chart files (default perf-results)."),
        QStringLiteral("DIR"), QStringLiteral("perf-results"));
    const QCommandLineOption glOption(QStringLiteral("gl"),
        QStringLiteral(
            "Headless GL backend: egl (default; falls back to osmesa when --gl is not given) or osmesa."),
        QStringLiteral("egl|osmesa"), QStringLiteral("egl"));
    parser.addOptions({ sizesOption, gridsOption, trianglesOption, baseSizeOption, baseGridOption,
        framesOption, setOption, outOption, glOption });
    parser.process(app);

    const QStringList args = parser.positionalArguments();
    if (args.size() != 2 || args[0] != QStringLiteral("perf"))
        return fail(1, QStringLiteral("usage: vct-bench perf SCENE [options] (see vct-bench perf --help)"));
    PerfOptions options;
    std::pair<int, int> baseSize;
    bool ok = false;
    options.frames = parser.value(framesOption).toInt(&ok);
    if (!ok || options.frames < 1 || options.frames > 1000)
        return fail(1, QStringLiteral("--frames must be 1..1000"));
    if (!parseSizes(parser.value(sizesOption), options.sizes)
        || !parseSize(parser.value(baseSizeOption), baseSize))
        return fail(
            1, QStringLiteral("--sizes and --base-size take WxH with 1..16384 per side, e.g. 640x360"));
    options.baseWidth = baseSize.first;
    options.baseHeight = baseSize.second;
    std::vector<int> baseGrid;
    if (!parseInts(parser.value(gridsOption), options.grids)
        || !parseInts(parser.value(baseGridOption), baseGrid) || baseGrid.size() != 1)
        return fail(1, QStringLiteral("--grids and --base-grid take grid resolutions, e.g. 32,64,128"));
    options.baseGrid = baseGrid.front();
    if (!parseInts(parser.value(trianglesOption), options.triangleFactors)
        || !std::all_of(options.triangleFactors.begin(), options.triangleFactors.end(),
            [](int f) { return isPowerOfTwo(f) && f <= 64; }))
        return fail(1, QStringLiteral("--triangles takes powers of two up to 64, e.g. 1,4,16"));

    render::Scene scene;
    render::RenderSettings settings;
    doc::SceneLoadInfo info;
    QString error;
    if (!loadSceneInput(args[1], scene, settings, info, &error))
        return fail(1, error);
    if (const QString problem = applySettingAssignments(parser.values(setOption), settings);
        !problem.isEmpty())
        return fail(1, problem);
    std::vector<int> allGrids = options.grids;
    allGrids.push_back(options.baseGrid);
    for (int grid : allGrids) {
        render::RenderSettings candidate = settings;
        if (const std::string problem = candidate.set("voxel_res", std::to_string(grid)); !problem.empty())
            return fail(1, QString::fromStdString(problem));
    }
    const QString outDir = parser.value(outOption);
    if (!QDir().mkpath(outDir))
        return fail(3, QStringLiteral("cannot create '%1'").arg(outDir));

    std::string contextError;
    auto context = render::HeadlessContext::createPreferring(
        parser.value(glOption).toStdString(), parser.isSet(glOption), contextError);
    if (!context)
        return fail(2, QString::fromStdString(contextError));
    std::vector<PerfResult> results;
    try {
        render::Renderer renderer(context->procAddressFunction());
        // Each pass's phases as rows of their own (the bounce solve's gathers, reinjections, filterings).
        renderer.setPhaseTimes(true);
        PerfBenchmark benchmark(renderer, scene, settings, options.frames);
        for (const PerfConfig& config : PerfBenchmark::configurations(options)) {
            results.push_back(benchmark.measure(config));
            const PerfResult& r = results.back();
            std::fprintf(stderr,
                "  %5d×%-5d %4d³ ×%-3d  full %8.1f ms  camera-only %7.1f ms  cone %7.1f ms  efficiency "
                "%3.0f%%\n",
                config.width, config.height, config.grid, config.triangleFactor, r.full.frameGpuMs.median,
                r.cameraOnly.frameGpuMs.median, r.coneMs, 100.0 * r.coneEfficiency());
        }
        for (const std::string& message : renderer.takeGlErrors())
            std::fprintf(stderr, "vct-bench perf: GL: %s\n", message.c_str());
    } catch (const std::exception& e) {
        return fail(3, QString::fromUtf8(e.what()));
    }

    QStringList command { QStringLiteral("vct-bench") };
    for (int i = 1; i < argc; ++i)
        command << QString::fromLocal8Bit(argv[i]);
    const std::string header
        = "`" + command.join(QLatin1Char(' ')).toStdString() + "` on " + context->description() + ".";
    const PerfReport report(args[1].toStdString(), header, results);
    const QDir dir(outDir);
    if (!files::AtomicFile::write(dir.filePath(QStringLiteral("results.csv")), report.resultsCsv(), &error)
        || !files::AtomicFile::write(
            dir.filePath(QStringLiteral("efficiency.csv")), report.efficiencyCsv(), &error)
        || !files::AtomicFile::write(dir.filePath(QStringLiteral("memory.csv")), report.memoryCsv(), &error)
        || !files::AtomicFile::write(dir.filePath(QStringLiteral("perf.md")), report.markdown(), &error))
        return fail(3, error);
    for (const NamedChart& chart : report.charts())
        if (!plot::ChartWriter::write(chart.chart, dir.filePath(chart.baseName), kChartSize, &error))
            return fail(3, error);
    std::fputs(report.summary().c_str(), stdout);
    std::printf("\nwritten to %s: results.csv efficiency.csv memory.csv perf.md",
        qPrintable(QDir::toNativeSeparators(outDir)));
    for (const NamedChart& chart : report.charts())
        std::printf(" %s.svg/.png", qPrintable(chart.baseName));
    std::printf("\n");
    return 0;
}

} // namespace vct::cli
