#include "document/Document.h"
#include "document/ProjectFile.h"
#include "document/SceneLoader.h"
#include "ui/MainWindow.h"
#include "ui/ViewportWidget.h"
#include "ui/VoxelInspectorDock.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QSurfaceFormat>
#include <QTimer>

#include <cstdio>

namespace {

int fail(const QString& message)
{
    std::fprintf(stderr, "vct-editor: %s\n", qPrintable(message));
    return 1;
}

} // namespace

int main(int argc, char** argv)
{
    // The renderer needs 4.5 core; the default format must be set before the application exists.
    QSurfaceFormat format;
    format.setVersion(4, 5);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QSurfaceFormat::setDefaultFormat(format);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("VCT Studio"));
    QApplication::setApplicationName(QStringLiteral("VCT Studio"));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("VCT Studio: real-time global illumination by voxel cone tracing."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("SCENE"),
        QStringLiteral("A .vctproj project, builtin:NAME or a model file (default builtin:default)."),
        QStringLiteral("[SCENE]"));
    const QCommandLineOption screenshot(QStringLiteral("screenshot"),
        QStringLiteral(
            "Save a screenshot of the window once the first full-resolution frame is drawn, then quit."),
        QStringLiteral("FILE.png"));
    const QCommandLineOption inspect(QStringLiteral("inspect-level"),
        QStringLiteral("Open with the voxel inspector showing this mip level of the radiance."),
        QStringLiteral("N"));
    const QCommandLineOption unitScaleOption(QStringLiteral("unit-scale"),
        QStringLiteral("Metres per unit of a model file SCENE (0.01 for centimetres). Default 1."),
        QStringLiteral("S"));
    const QCommandLineOption sceneRootOption(QStringLiteral("scene-root"),
        QStringLiteral("The folder projects' relative model paths resolve against and are saved relative to, "
                       "instead of each project's (default: $%1 when set).")
            .arg(QLatin1String(vct::doc::ProjectFile::kModelRootVariable)),
        QStringLiteral("DIR"));
    const QCommandLineOption upAxisOption(QStringLiteral("up-axis"),
        QStringLiteral("The axis that points up in a model file: y (default) or z (CAD tools, 3ds Max)."),
        QStringLiteral("AXIS"));
    const QCommandLineOption sizeOption(QStringLiteral("size"),
        QStringLiteral("The window's size in pixels, as WIDTHxHEIGHT (for screenshots)."),
        QStringLiteral("WxH"));
    const QCommandLineOption inspectGrid(QStringLiteral("inspect-grid"),
        QStringLiteral("With a clipmap (voxel_mode=clipmap), the voxel inspector shows its level N (0 = the "
                       "finest, around the camera)."),
        QStringLiteral("N"));
    parser.addOptions(
        { screenshot, inspect, inspectGrid, unitScaleOption, upAxisOption, sceneRootOption, sizeOption });
    parser.process(app);

    const QStringList scenes = parser.positionalArguments();
    const QString scene = scenes.isEmpty() ? QStringLiteral("builtin:default") : scenes.front();
    float unitScale = 1.0f;
    if (parser.isSet(unitScaleOption)) {
        if (scene.endsWith(QStringLiteral(".vctproj"), Qt::CaseInsensitive))
            return fail(QStringLiteral("--unit-scale applies to a model file; a project gives each of its "
                                       "sources its own \"unit_scale\""));
        if (scene.startsWith(QStringLiteral("builtin:")))
            return fail(
                QStringLiteral("--unit-scale applies to a model file; built-in scenes are in metres"));
        if (const QString problem
            = vct::doc::SceneLoader::parseUnitScale(parser.value(unitScaleOption), &unitScale);
            !problem.isEmpty())
            return fail(QStringLiteral("--unit-scale: %1").arg(problem));
    }
    vct::doc::SceneLoader::UpAxis upAxis = vct::doc::SceneLoader::UpAxis::Y;
    if (parser.isSet(upAxisOption)) {
        if (scene.endsWith(QStringLiteral(".vctproj"), Qt::CaseInsensitive)
            || scene.startsWith(QStringLiteral("builtin:")))
            return fail(QStringLiteral("--up-axis applies to a model file"));
        if (const QString problem = vct::doc::SceneLoader::parseUpAxis(parser.value(upAxisOption), &upAxis);
            !problem.isEmpty())
            return fail(QStringLiteral("--up-axis: %1").arg(problem));
    }
    const bool rootFromOption = parser.isSet(sceneRootOption);
    const QString sceneRoot = rootFromOption
        ? parser.value(sceneRootOption)
        : qEnvironmentVariable(vct::doc::ProjectFile::kModelRootVariable);
    if (!sceneRoot.isEmpty() && !QFileInfo(sceneRoot).isDir())
        return fail(QStringLiteral("the scene root '%1' (from %2) is not a folder")
                        .arg(sceneRoot,
                            rootFromOption ? QStringLiteral("--scene-root")
                                           : QLatin1String(vct::doc::ProjectFile::kModelRootVariable)));

    QSize windowSize;
    if (parser.isSet(sizeOption)) {
        const QStringList parts = parser.value(sizeOption).split(QLatin1Char('x'));
        bool okWidth = false, okHeight = false;
        if (parts.size() == 2)
            windowSize = QSize(parts[0].toInt(&okWidth), parts[1].toInt(&okHeight));
        if (!okWidth || !okHeight || windowSize.width() < 320 || windowSize.height() < 240
            || windowSize.width() > 8192 || windowSize.height() > 8192)
            return fail(QStringLiteral("--size: '%1' is not WIDTHxHEIGHT between 320x240 and 8192x8192")
                            .arg(parser.value(sizeOption)));
    }

    vct::ui::MainWindow window;
    window.document()->setModelRoot(sceneRoot);
    window.openInitial(scene, unitScale, upAxis);
    if (parser.isSet(inspect) || parser.isSet(inspectGrid))
        window.inspectorDock()->setSettings({ true, parser.value(inspect).toInt(),
            vct::render::VoxelChannel::Radiance, parser.value(inspectGrid).toInt() });
    if (windowSize.isValid())
        window.resize(windowSize);
    window.show();
    if (parser.isSet(screenshot)) {
        const QString path = parser.value(screenshot);
        QObject::connect(window.viewport(), &vct::ui::ViewportWidget::frameRendered, &window,
            [&window, path, taken = false](const vct::render::FrameStats& stats) mutable {
                // The picture a user waits for: full resolution, complete, the bounces converged, taken once.
                if (taken || window.viewport()->isInteractive() || !stats.lightConverged || stats.deferred)
                    return;
                taken = true;
                // Let the docks show this frame's figures before grabbing.
                QTimer::singleShot(200, &window, [&window, path] {
                    const bool ok = window.grab().save(path);
                    std::printf("%s %s\n", ok ? "saved" : "could not save", qPrintable(path));
                    QApplication::exit(ok ? 0 : 1);
                });
            });
    }
    return QApplication::exec();
}
