#pragma once

namespace vct::doc {

/**
 * QUndoCommand::id() values of the commands that merge (slider drags, spin boxes), kept in one enum so two
 * command types can never share an id by accident. Commands that never merge return -1.
 */
enum class CommandId : int {
    SetNodeTransform = 1,
    SetMaterial,
    SetLight,
    SetRenderSettings,
};

} // namespace vct::doc
