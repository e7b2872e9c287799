#include "ui/MainWindow.h"

#include <QApplication>
#include <QSurfaceFormat>

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
    vct::ui::MainWindow window;
    const QStringList args = QApplication::arguments();
    window.openInitial(args.size() > 1 ? args.at(1) : QStringLiteral("builtin:default"));
    window.show();
    return QApplication::exec();
}
