#include "cli/SceneInput.h"

#include "document/Document.h"
#include "document/SceneLoader.h"

namespace vct::cli {

bool loadSceneInput(const QString& spec, render::Scene& scene, render::RenderSettings& settings,
    doc::SceneLoadInfo& info, QString* error)
{
    if (spec.endsWith(QStringLiteral(".vctproj"), Qt::CaseInsensitive)) {
        doc::Document project;
        if (!project.openProject(spec, error))
            return false;
        scene = project.buildRenderScene();
        settings = project.state().settings;
        return true;
    }
    return doc::SceneLoader::load(spec, scene, error, &info);
}

} // namespace vct::cli
