#include "SetMaterialCommand.h"

#include "CommandIds.h"
#include "Document.h"

#include <QCoreApplication>

namespace vct::doc {

namespace {

const char* textFor(MaterialField field)
{
    switch (field) {
    case MaterialField::Albedo:
        return QT_TRANSLATE_NOOP("SetMaterialCommand", "Albedo of %1");
    case MaterialField::Emissive:
        return QT_TRANSLATE_NOOP("SetMaterialCommand", "Emissive switch of %1");
    case MaterialField::EmissionColor:
        return QT_TRANSLATE_NOOP("SetMaterialCommand", "Emission colour of %1");
    case MaterialField::EmissionStrength:
        return QT_TRANSLATE_NOOP("SetMaterialCommand", "Emission strength of %1");
    case MaterialField::Specular:
        return QT_TRANSLATE_NOOP("SetMaterialCommand", "Specular of %1");
    case MaterialField::Shininess:
        return QT_TRANSLATE_NOOP("SetMaterialCommand", "Shininess of %1");
    case MaterialField::DoubleSided:
        return QT_TRANSLATE_NOOP("SetMaterialCommand", "Double-sided switch of %1");
    case MaterialField::Whole:
        break;
    }
    return QT_TRANSLATE_NOOP("SetMaterialCommand", "Edit material %1");
}

/** A switch's second click undoes its first: merged, the two would leave no step to undo at all. */
bool isSwitch(MaterialField field)
{
    return field == MaterialField::Emissive || field == MaterialField::DoubleSided;
}

} // namespace

SetMaterialCommand::SetMaterialCommand(
    Document* document, int index, const render::Material& material, MaterialField field)
    : m_document(document)
    , m_index(index)
    , m_field(field)
    , m_gesture(document->editGesture())
    , m_before(document->state().materials.at(std::size_t(index)))
    , m_after(material)
{
    setText(QCoreApplication::translate("SetMaterialCommand", textFor(field))
                .arg(QString::fromStdString(m_before.name)));
}

void SetMaterialCommand::redo()
{
    apply(m_after);
}

void SetMaterialCommand::undo()
{
    apply(m_before);
}

int SetMaterialCommand::id() const
{
    return int(CommandId::SetMaterial);
}

bool SetMaterialCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetMaterialCommand*>(other);
    if (next->m_index != m_index || next->m_field != m_field || next->m_gesture != m_gesture
        || isSwitch(m_field))
        return false;
    m_after = next->m_after;
    setObsolete(sameMaterial(m_after, m_before));
    return true;
}

void SetMaterialCommand::apply(const render::Material& material)
{
    // Materials are only ever appended or removed from the end (import and its undo), and the undo stack
    // replays in order, so the index still names the same material here.
    m_document->mutableState().materials[std::size_t(m_index)] = material;
    m_document->notify({ ChangeEvent::Kind::Material, m_index });
}

} // namespace vct::doc
