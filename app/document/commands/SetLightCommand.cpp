#include "SetLightCommand.h"

#include "CommandIds.h"
#include "Document.h"

#include <QCoreApplication>

namespace vct::doc {

namespace {

/** Names the field as the Light panel labels it for this type of light. */
const char* textFor(LightField field, const LightNode& light)
{
    switch (field) {
    case LightField::Name:
        return QT_TRANSLATE_NOOP("SetLightCommand", "Rename light %1");
    case LightField::Type:
        return QT_TRANSLATE_NOOP("SetLightCommand", "Light type of %1");
    case LightField::PositionX:
        return light.isSurface() ? QT_TRANSLATE_NOOP("SetLightCommand", "Light centre X of %1")
                                 : QT_TRANSLATE_NOOP("SetLightCommand", "Light position X of %1");
    case LightField::PositionY:
        return light.isSurface() ? QT_TRANSLATE_NOOP("SetLightCommand", "Light centre Y of %1")
                                 : QT_TRANSLATE_NOOP("SetLightCommand", "Light position Y of %1");
    case LightField::PositionZ:
        return light.isSurface() ? QT_TRANSLATE_NOOP("SetLightCommand", "Light centre Z of %1")
                                 : QT_TRANSLATE_NOOP("SetLightCommand", "Light position Z of %1");
    case LightField::DirectionX:
        return QT_TRANSLATE_NOOP("SetLightCommand", "Light direction X of %1");
    case LightField::DirectionY:
        return QT_TRANSLATE_NOOP("SetLightCommand", "Light direction Y of %1");
    case LightField::DirectionZ:
        return QT_TRANSLATE_NOOP("SetLightCommand", "Light direction Z of %1");
    case LightField::Color:
        return QT_TRANSLATE_NOOP("SetLightCommand", "Light colour of %1");
    case LightField::Intensity:
        return light.isSurface() ? QT_TRANSLATE_NOOP("SetLightCommand", "Light radiance of %1")
                                 : QT_TRANSLATE_NOOP("SetLightCommand", "Light intensity of %1");
    case LightField::Shadows:
        return QT_TRANSLATE_NOOP("SetLightCommand", "Light shadows of %1");
    case LightField::SpotInner:
        return QT_TRANSLATE_NOOP("SetLightCommand", "Spot inner angle of %1");
    case LightField::SpotOuter:
        return QT_TRANSLATE_NOOP("SetLightCommand", "Spot outer angle of %1");
    case LightField::Radius:
        return QT_TRANSLATE_NOOP("SetLightCommand", "Light radius of %1");
    case LightField::AngularDiameter:
        return QT_TRANSLATE_NOOP("SetLightCommand", "Light angular diameter of %1");
    case LightField::AreaWidth:
        return light.type == LightType::Disk ? QT_TRANSLATE_NOOP("SetLightCommand", "Light diameter of %1")
                                             : QT_TRANSLATE_NOOP("SetLightCommand", "Light width of %1");
    case LightField::AreaHeight:
        return QT_TRANSLATE_NOOP("SetLightCommand", "Light height of %1");
    case LightField::AreaRotation:
        return QT_TRANSLATE_NOOP("SetLightCommand", "Light rotation of %1");
    case LightField::Whole:
        break;
    }
    return QT_TRANSLATE_NOOP("SetLightCommand", "Edit light %1");
}

/**
 * A name is committed once per edit and a type or a switch is picked in one click: merging two would make
 * a second rename or click undo the first along with itself.
 */
bool isSingleShot(LightField field)
{
    return field == LightField::Name || field == LightField::Type || field == LightField::Shadows;
}

} // namespace

SetLightCommand::SetLightCommand(Document* document, int index, const LightNode& light, LightField field)
    : m_document(document)
    , m_field(field)
    , m_gesture(document->editGesture())
    , m_before(document->state().lights.at(std::size_t(index)))
    , m_after(light)
{
    // The id is what identifies the light; an edit never changes it.
    m_after.id = m_before.id;
    setText(QCoreApplication::translate("SetLightCommand", textFor(field, m_before)).arg(m_before.name));
}

void SetLightCommand::redo()
{
    apply(m_after);
}

void SetLightCommand::undo()
{
    apply(m_before);
}

int SetLightCommand::id() const
{
    return int(CommandId::SetLight);
}

bool SetLightCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetLightCommand*>(other);
    if (next->m_before.id != m_before.id || next->m_field != m_field || next->m_gesture != m_gesture
        || isSingleShot(m_field))
        return false;
    m_after = next->m_after;
    setObsolete(m_after == m_before);
    return true;
}

void SetLightCommand::apply(const LightNode& light)
{
    const int index = m_document->lightIndex(light.id);
    if (index < 0)
        return;
    m_document->mutableState().lights[std::size_t(index)] = light;
    m_document->notify({ ChangeEvent::Kind::Lights, index });
}

} // namespace vct::doc
