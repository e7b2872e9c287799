#pragma once

#include "scene/RenderSettings.h"

#include <QStringList>
#include <QUndoCommand>

namespace vct::doc {

class Document;

/**
 * Replaces the render settings. Consecutive commands that change the same keys merge (a slider drag is one
 * step), while changing a different setting starts a new step.
 */
class SetRenderSettingsCommand : public QUndoCommand {
public:
    SetRenderSettingsCommand(Document* document, const render::RenderSettings& settings);

    /** The keys (as RenderSettings::set names them) whose values differ between `a` and `b`. */
    static QStringList changedKeys(const render::RenderSettings& a, const render::RenderSettings& b);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    void apply(const render::RenderSettings& settings);

    Document* m_document;
    render::RenderSettings m_before;
    render::RenderSettings m_after;
    QStringList m_keys; ///< What the first command of a merged run changed.
};

} // namespace vct::doc
