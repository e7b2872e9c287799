#include "SetRenderSettingsCommand.h"

#include "CommandIds.h"
#include "Document.h"

#include <QCoreApplication>

namespace vct::doc {

SetRenderSettingsCommand::SetRenderSettingsCommand(Document* document, const render::RenderSettings& settings)
    : m_document(document)
    , m_before(document->state().settings)
    , m_after(settings)
    , m_keys(changedKeys(m_before, m_after))
{
    setText(m_keys.size() == 1
            ? QCoreApplication::translate("SetRenderSettingsCommand", "Change %1").arg(m_keys.front())
            : QCoreApplication::translate("SetRenderSettingsCommand", "Change render settings"));
}

QStringList SetRenderSettingsCommand::changedKeys(
    const render::RenderSettings& a, const render::RenderSettings& b)
{
    const auto rowsA = a.describe();
    const auto rowsB = b.describe();
    QStringList keys;
    // describe() lists the same keys in the same order for every instance.
    for (std::size_t i = 0; i < rowsA.size() && i < rowsB.size(); ++i)
        if (rowsA[i][1] != rowsB[i][1])
            keys << QString::fromStdString(rowsA[i][0]);
    return keys;
}

void SetRenderSettingsCommand::redo()
{
    apply(m_after);
}

void SetRenderSettingsCommand::undo()
{
    apply(m_before);
}

int SetRenderSettingsCommand::id() const
{
    return int(CommandId::SetRenderSettings);
}

bool SetRenderSettingsCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetRenderSettingsCommand*>(other);
    if (next->m_keys != m_keys)
        return false;
    m_after = next->m_after;
    setObsolete(sameSettings(m_after, m_before));
    return true;
}

void SetRenderSettingsCommand::apply(const render::RenderSettings& settings)
{
    m_document->mutableState().settings = settings;
    m_document->notify({ ChangeEvent::Kind::Settings, -1 });
}

} // namespace vct::doc
