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

QString applySettingAssignments(const QStringList& assignments, render::RenderSettings& settings)
{
    for (const QString& assignment : assignments) {
        const int eq = assignment.indexOf(QLatin1Char('='));
        if (eq <= 0)
            return QStringLiteral("--set expects key=value, got '%1'").arg(assignment);
        const std::string problem = settings.set(assignment.left(eq).toStdString(), assignment.mid(eq + 1).toStdString());
        if (!problem.empty())
            return QString::fromStdString(problem);
    }
    return {};
}

} // namespace vct::cli
