#include "cli/AccuracyCommand.h"

#include "Renderer.h"
#include "cli/AccuracyBenchmark.h"
#include "cli/AccuracyCsv.h"
#include "cli/AccuracyReport.h"
#include "cli/AccuracySweep.h"
#include "cli/SceneInput.h"
#include "cli/TerminalProgress.h"
#include "context/HeadlessContext.h"
#include "document/CameraFile.h"
#include "document/LightsFile.h"
#include "files/AtomicFile.h"
#include "imageio/ImageFile.h"
#include "plot/ChartWriter.h"
#include "reference/ReferenceRenderer.h"

#include <QCommandLineParser>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QGuiApplication>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <set>

namespace vct::cli {

namespace {

constexpr QSize kChartSize(1200, 760);
const QString kPointsDir = QStringLiteral("points");
const QString kStudyFile = QStringLiteral("study.json");

int fail(int code, const QString& message)
{
    std::fprintf(stderr, "vct-bench accuracy: %s\n", qPrintable(message));
    return code;
}

bool readText(const QString& path, std::string& text, QString* error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("cannot read '%1': %2").arg(path, file.errorString());
        return false;
    }
    text = file.readAll().toStdString();
    return true;
}

/** Single-quoted for a POSIX shell when it holds anything but plain word characters. */
QString shellQuote(const QString& word)
{
    static const QString plain = QStringLiteral("-_./=:,+@%");
    if (!word.isEmpty() && std::all_of(word.begin(), word.end(), [](QChar c) {
            return c.isLetterOrNumber() || plain.contains(c);
        }))
        return word;
    QString quoted = word;
    quoted.replace(QLatin1Char('\''), QStringLiteral("'\\''"));
    return QLatin1Char('\'') + quoted + QLatin1Char('\'');
}

/** Emitted jobs may run in another directory: files are named absolutely, builtin:NAME stays as it is. */
QString absoluteIfFile(const QString& spec)
{
    const QFileInfo info(spec);
    return info.exists() ? info.absoluteFilePath() : spec;
}

QString pointFileName(int point)
{
    return QStringLiteral("point-%1.csv").arg(point, 3, 10, QLatin1Char('0'));
}

/** The 1-minute load average from /proc/loadavg; NaN where there is none. */
double loadAverage()
{
    QFile file(QStringLiteral("/proc/loadavg"));
    bool ok = false;
    const double load
        = file.open(QIODevice::ReadOnly) ? file.readLine().split(' ').value(0).toDouble(&ok) : 0.0;
    return ok ? load : AccuracyRow::kNone;
}

/** "1,2,4,16" into samples per pixel; "none" is an empty curve. */
bool parseSppList(const QString& text, std::vector<int>& spp)
{
    spp.clear();
    if (text.trimmed() == QStringLiteral("none"))
        return true;
    for (const QString& item : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        bool ok = false;
        const int value = item.trimmed().toInt(&ok);
        if (!ok || value < 1 || value > (1 << 20))
            return false;
        spp.push_back(value);
    }
    return !spp.empty();
}

QString sppListText(const std::vector<int>& spp)
{
    QStringList items;
    for (int s : spp)
        items << QString::number(s);
    return items.isEmpty() ? QStringLiteral("none") : items.join(QLatin1Char(','));
}

/** 1, 2, 4, ... up to @p most. */
std::vector<int> powersOfTwoUpTo(int most)
{
    std::vector<int> spp;
    for (int s = 1; s <= most; s *= 2)
        spp.push_back(s);
    return spp;
}

QString vec3Text(const glm::vec3& v)
{
    return QStringLiteral("%1 %2 %3")
        .arg(double(v.x), 0, 'g', 9)
        .arg(double(v.y), 0, 'g', 9)
        .arg(double(v.z), 0, 'g', 9);
}

/**
 * Reads DIR/points/point-*.csv and DIR/points/study.json, and writes results.csv, results.md and
 * accuracy.svg/.png into @p outDir. @p title replaces the study's scene name when not empty.
 */
int merge(const QString& studyDir, const QString& outDir, const QString& title)
{
    const QDir points(QDir(studyDir).filePath(kPointsDir));
    const QStringList files = points.entryList({ QStringLiteral("point-*.csv") }, QDir::Files, QDir::Name);
    if (files.isEmpty())
        return fail(1, QStringLiteral("no point-*.csv files in '%1'").arg(points.path()));
    std::vector<AccuracyRow> rows;
    QString error;
    for (const QString& name : files) {
        std::string text, readError;
        if (!readText(points.filePath(name), text, &error))
            return fail(3, error);
        if (!AccuracyCsv::read(text, points.filePath(name).toStdString(), rows, &readError))
            return fail(1, QString::fromStdString(readError));
    }
    std::set<int> seen;
    int jobs = 0;
    for (const AccuracyRow& row : rows) {
        if (!seen.insert(row.point).second)
            return fail(
                1, QStringLiteral("point %1 appears twice in '%2'").arg(row.point).arg(points.path()));
        if (jobs != 0 && row.jobs != jobs)
            return fail(1,
                QStringLiteral("'%1' mixes studies of %2 and %3 points: clear it and run the jobs again")
                    .arg(points.path())
                    .arg(jobs)
                    .arg(row.jobs));
        jobs = row.jobs;
    }
    std::vector<int> missing;
    for (int k = 0; k < jobs; ++k)
        if (!seen.count(k))
            missing.push_back(k);

    std::string scene = QDir(studyDir).dirName().toStdString(), header;
    std::string studyText;
    if (QFile::exists(points.filePath(kStudyFile))
        && readText(points.filePath(kStudyFile), studyText, &error)) {
        const QJsonObject study = QJsonDocument::fromJson(QByteArray::fromStdString(studyText)).object();
        scene = study[QStringLiteral("scene")].toString(QString::fromStdString(scene)).toStdString();
        header = study[QStringLiteral("header")].toString().toStdString();
    }
    if (!title.isEmpty())
        scene = title.toStdString();
    std::set<std::string> machines;
    for (const AccuracyRow& row : rows)
        if (!row.machine.empty())
            machines.insert((row.isVct() ? "VCT on " : "path tracer on ") + row.machine);
    if (!machines.empty()) {
        header += header.empty() ? "Measured with " : "\n\nMeasured with ";
        for (auto it = machines.begin(); it != machines.end(); ++it)
            header += (it == machines.begin() ? "" : "; ") + *it;
        header += ".";
    }

    const AccuracyReport report(scene, header, rows, missing);
    const QDir out(outDir);
    if (!QDir().mkpath(outDir))
        return fail(3, QStringLiteral("cannot create '%1'").arg(outDir));
    if (!files::AtomicFile::write(
            out.filePath(QStringLiteral("results.csv")), AccuracyCsv::write(report.rows()), &error)
        || !files::AtomicFile::write(out.filePath(QStringLiteral("results.md")), report.markdown(), &error)
        || !plot::ChartWriter::write(
            report.chart(), out.filePath(QStringLiteral("accuracy")), kChartSize, &error)
        || !plot::ChartWriter::write(
            report.vctChart(), out.filePath(QStringLiteral("accuracy-vct")), kChartSize, &error))
        return fail(3, error);
    std::fputs(report.summary().c_str(), stdout);
    std::printf("written to %s: results.csv results.md accuracy.svg/.png accuracy-vct.svg/.png (%zu points",
        qPrintable(outDir), rows.size());
    if (!missing.empty())
        std::printf(", %zu missing", missing.size());
    std::printf(")\n");
    return missing.empty() ? 0 : 5;
}

/** One accuracy study as its options and inputs resolve it, shared by the steps of AccuracyCommand::run. */
struct Study {
    QString sceneSpec, sweepPath, cameraPath, lightsPath;
    QStringList settingAssignments; ///< --set, as given
    QStringList typed; ///< the command line, for the report's header
    render::Scene scene;
    render::Camera camera;
    int width = 0, height = 0;
    bool explicitSize = false; ///< --width or --height given
    int frames = 5;
    AccuracySweep sweep;
    std::vector<int> curveSpp;
    qulonglong seed = 0;
    int maxBounces = 64;
    render::ReferenceSettings tracerSettings;
    bool threadsGiven = false;
    QString glBackend;
    bool glExplicit = false;
    QString referenceFile; ///< --reference, or empty with --reference-spp
    int referenceSpp = 0;
    int vctJobs = 0, jobs = 0, onlyPoint = -1;
    QString outDir, pointsDir;
    // Set by loadReference.
    render::RadianceImage reference;
    QString referencePath, referenceDescription;
};

/** The reference: a file, or the path tracer's image cached in the output folder with what it was rendered
 * from. Sets study.reference, referencePath and referenceDescription; 0, or the exit code. */
int loadReference(Study& study)
{
    if (!study.referenceFile.isEmpty()) {
        study.referencePath = study.referenceFile;
        std::string readError;
        auto image = io::ImageFile::read(study.referencePath.toStdString(), &readError);
        if (!image)
            return fail(1, QString::fromStdString(readError));
        study.reference = std::move(*image);
        if (study.explicitSize
            && (study.width != study.reference.width || study.height != study.reference.height))
            return fail(1,
                QStringLiteral("--width/--height %1x%2 differ from the reference's %3x%4: errors are "
                               "measured at the reference's size")
                    .arg(study.width)
                    .arg(study.height)
                    .arg(study.reference.width)
                    .arg(study.reference.height));
        if (std::abs(
                double(study.width) / study.height - double(study.reference.width) / study.reference.height)
            > 1e-3)
            std::fprintf(stderr,
                "vct-bench accuracy: warning: the camera is framed for %dx%d, the reference is %dx%d\n",
                study.width, study.height, study.reference.width, study.reference.height);
        study.width = study.reference.width;
        study.height = study.reference.height;
        study.referenceDescription
            = QStringLiteral("`%1` (%2×%3)").arg(study.referenceFile).arg(study.width).arg(study.height);
    } else {
        study.referencePath = QDir(study.outDir).filePath(QStringLiteral("reference.pfm"));
        const QString keyPath = QDir(study.outDir).filePath(QStringLiteral("reference.json"));
        const QString key = QStringLiteral(
            "%1 | %2x%3 | %4 spp | seed %5 | max bounces %6 | camera %7 -> %8 up %9 fov %10 | lights %11")
                                .arg(absoluteIfFile(study.sceneSpec))
                                .arg(study.width)
                                .arg(study.height)
                                .arg(study.referenceSpp)
                                .arg(study.seed)
                                .arg(study.maxBounces)
                                .arg(vec3Text(study.camera.position), vec3Text(study.camera.lookAt),
                                    vec3Text(study.camera.up))
                                .arg(double(study.camera.fovYDeg))
                                .arg(!study.lightsPath.isEmpty() ? absoluteIfFile(study.lightsPath)
                                                                 : QStringLiteral("scene"));
        std::string cachedKey;
        QString ignored;
        if (QFile::exists(study.referencePath) && QFile::exists(keyPath)
            && readText(keyPath, cachedKey, &ignored)
            && QJsonDocument::fromJson(QByteArray::fromStdString(cachedKey))
                    .object()[QStringLiteral("key")]
                    .toString()
                == key) {
            if (auto image = io::ImageFile::read(study.referencePath.toStdString()))
                study.reference = std::move(*image);
        }
        if (study.reference.isEmpty()) {
            std::fprintf(stderr, "vct-bench accuracy: rendering the reference, %dx%d at %d spp\n",
                study.width, study.height, study.referenceSpp);
            try {
                render::ReferenceRenderer tracer(
                    study.scene, study.camera, study.width, study.height, study.tracerSettings);
                TerminalProgress progress("  reference");
                tracer.render(study.referenceSpp, [&](double fraction) { progress(fraction); });
                progress.finish();
                study.reference = tracer.image();
                std::fprintf(stderr, "  %.2f s\n", tracer.stats().seconds);
            } catch (const std::exception& e) {
                return fail(3, QString::fromUtf8(e.what()));
            }
            std::string writeError;
            if (!io::ImageFile::write(study.referencePath.toStdString(), study.reference, 1.0f, &writeError))
                return fail(3, QString::fromStdString(writeError));
            QJsonObject json;
            json[QStringLiteral("key")] = key;
            QString error;
            if (!files::AtomicFile::write(keyPath, QJsonDocument(json).toJson().toStdString(), &error))
                return fail(3, error);
        }
        study.referenceDescription = QStringLiteral(
            "the path tracer at %1 spp (seed %2, up to %3 bounces), %4×%5, cached as `reference.pfm`")
                                         .arg(study.referenceSpp)
                                         .arg(study.seed)
                                         .arg(study.maxBounces)
                                         .arg(study.width)
                                         .arg(study.height);
    }

    return 0;
}

/** The study's description beside its points, for --merge to head its report with. */
bool writeStudy(const Study& study, QString* problem)
{
    QString header = QStringLiteral(
        "`%1`\n\nReference: %2. VCT: %3 point(s) of `%4`, median of %5 full frame(s) after a warm-up, at "
        "%6×%7. Path tracer: %8 spp, up to %9 bounces, seeds from %10.")
                         .arg(study.typed.join(QLatin1Char(' ')), study.referenceDescription)
                         .arg(study.vctJobs)
                         .arg(study.sweepPath)
                         .arg(study.frames)
                         .arg(study.width)
                         .arg(study.height)
                         .arg(sppListText(study.curveSpp))
                         .arg(study.maxBounces)
                         .arg(study.seed + 1);
    QJsonObject json;
    json[QStringLiteral("scene")] = study.sceneSpec;
    json[QStringLiteral("header")] = header;
    return files::AtomicFile::write(
        QDir(study.pointsDir).filePath(kStudyFile), QJsonDocument(json).toJson().toStdString(), problem);
}

/** --emit-jobs: one command per point on stdout, each measuring that point alone (--only-point). */
int emitJobs(const Study& study)
{
    QStringList common { QCoreApplication::applicationFilePath(), QStringLiteral("accuracy"),
        absoluteIfFile(study.sceneSpec) };
    if (!study.cameraPath.isEmpty())
        common << QStringLiteral("--camera") << absoluteIfFile(study.cameraPath);
    if (!study.lightsPath.isEmpty())
        common << QStringLiteral("--lights") << absoluteIfFile(study.lightsPath);
    common << QStringLiteral("--width") << QString::number(study.width) << QStringLiteral("--height")
           << QString::number(study.height) << QStringLiteral("--sweep") << absoluteIfFile(study.sweepPath)
           << QStringLiteral("--reference") << absoluteIfFile(study.referencePath)
           << QStringLiteral("--frames") << QString::number(study.frames);
    for (const QString& assignment : study.settingAssignments)
        common << QStringLiteral("--set") << assignment;
    if (study.glExplicit)
        common << QStringLiteral("--gl") << study.glBackend;
    common << QStringLiteral("--curve-spp") << sppListText(study.curveSpp) << QStringLiteral("--seed")
           << QString::number(study.seed) << QStringLiteral("--max-bounces")
           << QString::number(study.maxBounces);
    if (study.threadsGiven)
        common << QStringLiteral("--threads") << QString::number(study.tracerSettings.threads);
    QStringList quoted;
    for (const QString& word : common)
        quoted << shellQuote(word);
    const QString prefix = quoted.join(QLatin1Char(' '));
    const QString pointsOut = shellQuote(QFileInfo(study.pointsDir).absoluteFilePath());
    for (int k = 0; k < study.jobs; ++k)
        std::printf("%s --only-point %d --out %s\n", qPrintable(prefix), k, qPrintable(pointsOut));
    QString error;
    if (!writeStudy(study, &error))
        return fail(3, error);
    std::fprintf(stderr,
        "vct-bench accuracy: %d jobs (%d VCT points, %zu path-tracer points); when they are done:\n  %s "
        "accuracy %s --merge %s\n",
        study.jobs, study.vctJobs, study.curveSpp.size(),
        qPrintable(shellQuote(QCoreApplication::applicationFilePath())),
        qPrintable(shellQuote(study.sceneSpec)),
        qPrintable(shellQuote(QFileInfo(study.outDir).absoluteFilePath())));
    return 0;
}

/** Measures the study's points (all of them and merges, or the one --only-point names). */
int measure(const Study& study)
{
    std::vector<int> toRun;
    if (study.onlyPoint >= 0) {
        toRun.push_back(study.onlyPoint);
    } else {
        for (const QString& stale :
            QDir(study.pointsDir).entryList({ QStringLiteral("point-*.csv") }, QDir::Files))
            QFile::remove(QDir(study.pointsDir).filePath(stale));
        for (int k = 0; k < study.jobs; ++k)
            toRun.push_back(k);
        QString error;
        if (!writeStudy(study, &error))
            return fail(3, error);
    }

    std::unique_ptr<render::HeadlessContext> context;
    std::unique_ptr<render::Renderer> renderer;
    const AccuracyBenchmark benchmark(study.reference);
    for (int k : toRun) {
        std::vector<std::string> warnings;
        AccuracyRow row;
        try {
            if (k < study.vctJobs) {
                if (!renderer) {
                    std::string contextError;
                    context = render::HeadlessContext::createPreferring(
                        study.glBackend.toStdString(), study.glExplicit, contextError);
                    if (!context)
                        return fail(2, QString::fromStdString(contextError));
                    renderer = std::make_unique<render::Renderer>(context->procAddressFunction());
                    renderer->setSettings(study.sweep.points()[std::size_t(k)].settings);
                    renderer->setScene(study.scene);
                }
                row = benchmark.measureVct(
                    *renderer, study.camera, study.sweep.points()[std::size_t(k)], study.frames, warnings);
                row.machine = context->description();
            } else {
                const std::size_t c = std::size_t(k - study.vctJobs);
                render::ReferenceSettings settings = study.tracerSettings;
                settings.seed = study.seed + 1
                    + c; // independent of the reference's noise and of the other curve points
                row = benchmark.measurePathTracer(
                    study.scene, study.camera, study.curveSpp[c], settings, warnings);
            }
        } catch (const std::exception& e) {
            return fail(3, QStringLiteral("point %1: %2").arg(k).arg(QString::fromUtf8(e.what())));
        }
        row.point = k;
        row.jobs = study.jobs;
        row.loadAverage = loadAverage();
        for (const std::string& warning : warnings)
            std::fprintf(stderr, "vct-bench accuracy: warning: %s\n", warning.c_str());
        std::fprintf(stderr, "  [%d/%d] %-36s %9.1f ms  rel. MSE %.4f  PSNR %.2f dB  (load %.1f)\n", k + 1,
            study.jobs, row.label.c_str(), row.timeMs(), row.relMse, row.psnr, row.loadAverage);
        QString error;
        if (!files::AtomicFile::write(
                QDir(study.pointsDir).filePath(pointFileName(k)), AccuracyCsv::write({ row }), &error))
            return fail(3, error);
    }
    if (study.onlyPoint >= 0)
        return 0;
    return merge(study.outDir, study.outDir, QString());
}

} // namespace

int AccuracyCommand::run(int argc, char** argv)
{
    // PNG charts draw text, which needs a QGuiApplication; the offscreen platform needs no display, and GL
    // comes from our own EGL/OSMesa context, not from Qt.
    if (!qEnvironmentVariableIsSet("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("vct-bench"));
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "vct-bench accuracy: renders SCENE under every point of a sweep spec (docs/ACCURACY.md, "
        "\"Sweep\nspec\"), measures the GPU time of full frames (median over --frames, after a warm-up) and "
        "the error\nagainst a reference image, and the path tracer's own error against time at increasing "
        "samples per\npixel. Writes DIR/points/point-K.csv per point, then DIR/results.csv, results.md, "
        "accuracy.svg/.png\nand accuracy-vct.svg/.png.\nLarge sweeps: --emit-jobs prints one independent "
        "command per point (GNU parallel, a job array),\nthen --merge DIR collects the results."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("accuracy"), QStringLiteral("the subcommand"));
    parser.addPositionalArgument(QStringLiteral("SCENE"),
        QStringLiteral("a .vctproj project, builtin:NAME or a model file (optional with --merge)"));
    const QCommandLineOption sweepOption(QStringLiteral("sweep"),
        QStringLiteral("Sweep spec JSON: base, one-at-a-time axes, presets."), QStringLiteral("spec.json"));
    const QCommandLineOption referenceOption(QStringLiteral("reference"),
        QStringLiteral("Reference image, linear radiance (.pfm or .exr); sets the image size."),
        QStringLiteral("ref.pfm"));
    const QCommandLineOption referenceSppOption(QStringLiteral("reference-spp"),
        QStringLiteral(
            "Render the reference with the path tracer at N spp instead, cached as DIR/reference.pfm."),
        QStringLiteral("N"));
    const QCommandLineOption cameraOption(QStringLiteral("camera"),
        QStringLiteral("Camera JSON (the format of tests/data/reference); sets the image size."),
        QStringLiteral("cam.json"));
    const QCommandLineOption lightsOption(QStringLiteral("lights"),
        QStringLiteral("Lights JSON replacing the scene's lights."), QStringLiteral("lights.json"));
    const QCommandLineOption widthOption(QStringLiteral("width"),
        QStringLiteral("Image width (default: reference, camera file or 640)."), QStringLiteral("W"));
    const QCommandLineOption heightOption(QStringLiteral("height"),
        QStringLiteral("Image height (default: reference, camera file or 360)."), QStringLiteral("H"));
    const QCommandLineOption framesOption(QStringLiteral("frames"),
        QStringLiteral("Timed frames per point and mode (default 5)."), QStringLiteral("N"),
        QStringLiteral("5"));
    const QCommandLineOption setOption(QStringLiteral("set"),
        QStringLiteral("Render setting under the sweep's base, repeatable (see vct-render --help)."),
        QStringLiteral("key=value"));
    const QCommandLineOption curveOption(QStringLiteral("curve-spp"),
        QStringLiteral("Samples per pixel of the path tracer's curve, or none (default 1,2,4,... up to N/4 "
                       "with --reference-spp N, up to 256 with --reference)."),
        QStringLiteral("S,..."));
    const QCommandLineOption seedOption(QStringLiteral("seed"),
        QStringLiteral("Seed of the rendered reference (default 0); curve point i uses seed+1+i."),
        QStringLiteral("S"), QStringLiteral("0"));
    const QCommandLineOption bouncesOption(QStringLiteral("max-bounces"),
        QStringLiteral("Path tracer: longest path in reflections (default 64)."), QStringLiteral("K"),
        QStringLiteral("64"));
    const QCommandLineOption threadsOption(QStringLiteral("threads"),
        QStringLiteral("Path tracer worker threads (default: all cores)."), QStringLiteral("T"));
    const QCommandLineOption outOption(QStringLiteral("out"),
        QStringLiteral(
            "Output directory (default accuracy-results); with --only-point, where point-K.csv goes."),
        QStringLiteral("DIR"), QStringLiteral("accuracy-results"));
    const QCommandLineOption emitOption(QStringLiteral("emit-jobs"),
        QStringLiteral("Print one command per point (and render a --reference-spp reference first) instead "
                       "of measuring."));
    const QCommandLineOption onlyOption(QStringLiteral("only-point"),
        QStringLiteral("Measure job K only and write OUT/point-K.csv."), QStringLiteral("K"));
    const QCommandLineOption mergeOption(QStringLiteral("merge"),
        QStringLiteral("Collect DIR/points/*.csv into results.csv, results.md and the chart (into --out if "
                       "given, else DIR)."),
        QStringLiteral("DIR"));
    const QCommandLineOption glOption(QStringLiteral("gl"),
        QStringLiteral(
            "Headless GL backend: egl (default; falls back to osmesa when --gl is not given) or osmesa."),
        QStringLiteral("egl|osmesa"), QStringLiteral("egl"));
    parser.addOptions({ sweepOption, referenceOption, referenceSppOption, cameraOption, lightsOption,
        widthOption, heightOption, framesOption, setOption, curveOption, seedOption, bouncesOption,
        threadsOption, outOption, emitOption, onlyOption, mergeOption, glOption });
    parser.process(app);

    const QStringList args = parser.positionalArguments();
    if (args.isEmpty() || args[0] != QStringLiteral("accuracy") || args.size() > 2)
        return fail(1,
            QStringLiteral("usage: vct-bench accuracy SCENE --sweep spec.json (--reference ref.pfm | "
                           "--reference-spp N) [options]"));
    if (parser.isSet(mergeOption)) {
        const QString dir = parser.value(mergeOption);
        return merge(dir, parser.isSet(outOption) ? parser.value(outOption) : dir,
            args.size() == 2 ? args[1] : QString());
    }
    if (args.size() != 2)
        return fail(1, QStringLiteral("expected a SCENE (see vct-bench accuracy --help)"));
    if (!parser.isSet(sweepOption))
        return fail(1, QStringLiteral("--sweep spec.json is required"));
    if (parser.isSet(referenceOption) == parser.isSet(referenceSppOption))
        return fail(1, QStringLiteral("give exactly one of --reference ref.pfm and --reference-spp N"));
    if (parser.isSet(emitOption) && parser.isSet(onlyOption))
        return fail(1, QStringLiteral("--emit-jobs and --only-point do not go together"));

    bool ok = false;
    const int frames = parser.value(framesOption).toInt(&ok);
    if (!ok || frames < 1 || frames > 1000)
        return fail(1, QStringLiteral("--frames must be 1..1000"));
    const qulonglong seed = parser.value(seedOption).toULongLong(&ok);
    if (!ok)
        return fail(1, QStringLiteral("--seed must be a non-negative integer"));
    const int maxBounces = parser.value(bouncesOption).toInt(&ok);
    if (!ok || maxBounces < 0 || maxBounces > 100000)
        return fail(1, QStringLiteral("--max-bounces must be 0..100000"));
    render::ReferenceSettings tracerSettings;
    tracerSettings.maxBounces = maxBounces;
    tracerSettings.seed = seed;
    if (parser.isSet(threadsOption)) {
        tracerSettings.threads = parser.value(threadsOption).toInt(&ok);
        if (!ok || tracerSettings.threads < 1 || tracerSettings.threads > 1024)
            return fail(1, QStringLiteral("--threads must be 1..1024"));
    }
    int referenceSpp = 0;
    if (parser.isSet(referenceSppOption)) {
        referenceSpp = parser.value(referenceSppOption).toInt(&ok);
        if (!ok || referenceSpp < 1 || referenceSpp > (1 << 20))
            return fail(1, QStringLiteral("--reference-spp must be 1..1048576"));
    }
    std::vector<int> curveSpp = powersOfTwoUpTo(referenceSpp > 0 ? referenceSpp / 4 : 256);
    if (parser.isSet(curveOption) && !parseSppList(parser.value(curveOption), curveSpp))
        return fail(1, QStringLiteral("--curve-spp takes samples per pixel, e.g. 1,2,4,8, or none"));

    // The scene, its camera and lights, as vct-render reads them.
    const QString sceneSpec = args[1];
    render::Scene scene;
    render::RenderSettings sceneSettings;
    doc::SceneLoadInfo info;
    QString error;
    if (!loadSceneInput(sceneSpec, scene, sceneSettings, info, &error))
        return fail(1, error);
    if (const QString problem = applySettingAssignments(parser.values(setOption), sceneSettings);
        !problem.isEmpty())
        return fail(1, problem);
    ViewInput view;
    if (!resolveViewInput(parser.value(lightsOption), parser.value(cameraOption), info, scene, view, &error))
        return fail(1, error);
    render::Camera camera = view.camera;
    int width = view.width;
    int height = view.height;
    const bool explicitSize = parser.isSet(widthOption) || parser.isSet(heightOption);
    for (const auto& [option, target] :
        { std::pair { &widthOption, &width }, std::pair { &heightOption, &height } })
        if (parser.isSet(*option)) {
            *target = parser.value(*option).toInt(&ok);
            if (!ok || *target < 1 || *target > 16384)
                return fail(1, QStringLiteral("--%1 must be 1..16384").arg(option->names().front()));
        }

    std::string sweepText;
    if (!readText(parser.value(sweepOption), sweepText, &error))
        return fail(1, error);
    AccuracySweep sweep;
    std::string sweepError;
    if (!AccuracySweep::parse(sweepText, sceneSettings, sweep, &sweepError))
        return fail(1, parser.value(sweepOption) + QStringLiteral(": ") + QString::fromStdString(sweepError));
    const int vctJobs = int(sweep.points().size());
    const int jobs = vctJobs + int(curveSpp.size());
    int onlyPoint = -1;
    if (parser.isSet(onlyOption)) {
        onlyPoint = parser.value(onlyOption).toInt(&ok);
        if (!ok || onlyPoint < 0 || onlyPoint >= jobs)
            return fail(
                1, QStringLiteral("--only-point must be 0..%1 for this sweep and curve").arg(jobs - 1));
    }

    const QString outDir = parser.value(outOption);
    // --only-point writes where it is told (the emitted jobs say DIR/points); the other modes own DIR.
    const QString pointsDir = onlyPoint >= 0 ? outDir : QDir(outDir).filePath(kPointsDir);
    if (!QDir().mkpath(pointsDir))
        return fail(3, QStringLiteral("cannot create '%1'").arg(pointsDir));

    Study study;
    study.sceneSpec = sceneSpec;
    study.sweepPath = parser.value(sweepOption);
    study.cameraPath = parser.value(cameraOption);
    study.lightsPath = parser.value(lightsOption);
    study.settingAssignments = parser.values(setOption);
    study.typed << QStringLiteral("vct-bench");
    for (int i = 1; i < argc; ++i)
        study.typed << shellQuote(QString::fromLocal8Bit(argv[i]));
    study.scene = std::move(scene);
    study.camera = camera;
    study.width = width;
    study.height = height;
    study.explicitSize = explicitSize;
    study.frames = frames;
    study.sweep = std::move(sweep);
    study.curveSpp = curveSpp;
    study.seed = seed;
    study.maxBounces = maxBounces;
    study.tracerSettings = tracerSettings;
    study.threadsGiven = parser.isSet(threadsOption);
    study.glBackend = parser.value(glOption);
    study.glExplicit = parser.isSet(glOption);
    study.referenceFile = parser.isSet(referenceOption) ? parser.value(referenceOption) : QString();
    study.referenceSpp = referenceSpp;
    study.vctJobs = vctJobs;
    study.jobs = jobs;
    study.onlyPoint = onlyPoint;
    study.outDir = outDir;
    study.pointsDir = pointsDir;
    if (const int failed = loadReference(study))
        return failed;
    return parser.isSet(emitOption) ? emitJobs(study) : measure(study);
}

} // namespace vct::cli
