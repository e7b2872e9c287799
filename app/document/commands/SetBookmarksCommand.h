#pragma once

#include "CameraBookmark.h"

#include <QUndoCommand>

#include <vector>

namespace vct::doc {

class Document;

/** Replaces the document's camera bookmarks (adding or removing one); undo puts the old list back. */
class SetBookmarksCommand : public QUndoCommand {
public:
    SetBookmarksCommand(Document* document, std::vector<CameraBookmark> bookmarks, const QString& text);

    void redo() override;
    void undo() override;

private:
    void apply(const std::vector<CameraBookmark>& bookmarks);

    Document* m_document;
    std::vector<CameraBookmark> m_before;
    std::vector<CameraBookmark> m_after;
};

} // namespace vct::doc
