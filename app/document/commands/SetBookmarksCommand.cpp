#include "SetBookmarksCommand.h"

#include "Document.h"

namespace vct::doc {

SetBookmarksCommand::SetBookmarksCommand(
    Document* document, std::vector<CameraBookmark> bookmarks, const QString& text)
    : m_document(document)
    , m_before(document->state().bookmarks)
    , m_after(std::move(bookmarks))
{
    setText(text);
}

void SetBookmarksCommand::redo()
{
    apply(m_after);
}

void SetBookmarksCommand::undo()
{
    apply(m_before);
}

void SetBookmarksCommand::apply(const std::vector<CameraBookmark>& bookmarks)
{
    m_document->mutableState().bookmarks = bookmarks;
    m_document->notify({ ChangeEvent::Kind::Bookmarks, -1 });
}

} // namespace vct::doc
