#include "ui/MainWindow.h"
#include "ui/ViewportWidget.h"
#include "ui/VoxelInspectorDock.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>
#include <QTimer>

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
    parser.addOptions({ screenshot, inspect });
    parser.process(app);

    vct::ui::MainWindow window;
    const QStringList scenes = parser.positionalArguments();
    window.openInitial(scenes.isEmpty() ? QStringLiteral("builtin:default") : scenes.front());
    if (parser.isSet(inspect))
        window.inspectorDock()->setSettings(
            { true, parser.value(inspect).toInt(), vct::render::VoxelChannel::Radiance });
    window.show();
    if (parser.isSet(screenshot)) {
        const QString path = parser.value(screenshot);
        QObject::connect(
            window.viewport(), &vct::ui::ViewportWidget::frameRendered, &window, [&window, path] {
                if (window.viewport()->isInteractive())
                    return;
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
