#pragma once

#include <QString>
#include <QUndoCommand>

namespace vct::doc {

class Document;

/**
 * Changes a node's name, visibility or dynamic flag. Showing or hiding announces Structure (the renderer's
 * mesh list changes); a name or dynamic change announces NodeProperty.
 */
class SetNodePropertiesCommand : public QUndoCommand {
public:
    /** The user-editable properties of a node besides its transform. */
    struct Properties {
        QString name;
        bool visible = true;
        bool dynamic = false;
        bool operator==(const Properties& other) const = default;
    };

    SetNodePropertiesCommand(Document* document, int node, const Properties& properties);

    /** The current properties of node `node`. */
    static Properties propertiesOf(const Document& document, int node);

    void redo() override;
    void undo() override;

private:
    void apply(const Properties& properties);

    Document* m_document;
    quint64 m_nodeId;
    Properties m_before;
    Properties m_after;
};

} // namespace vct::doc
