#include "ShaderFolder.h"

#include <QDir>
#include <QFileInfo>

namespace vct::ui {

QString ShaderFolder::forReload()
{
    const QString fromEnvironment = qEnvironmentVariable("VCT_SHADER_DIR");
    if (!fromEnvironment.isEmpty())
        return fromEnvironment;
    const QString tree = QStringLiteral(VCT_STUDIO_SOURCE_DIR) + QStringLiteral("/shaders");
    return QFileInfo(tree).isDir() ? QDir::cleanPath(tree) : QString();
}

} // namespace vct::ui
