#pragma once
// The undo command that adds an item to one of the scene's lists (the lights, the objects) or
// deletes one: the two are each other's undo, through the Document's getter, insert and remove
// members of that list (e.g. &Document::light, &Document::insertLight, &Document::removeLight).

#include "ui/document/document.h"

#include <QObject>
#include <QUndoCommand>

#include <type_traits>
#include <utility>

namespace lucerna {

template <auto get, auto insert, auto remove>
class AddOrDelete : public QUndoCommand {
public:
    using Item = std::remove_cvref_t<decltype((std::declval<const Document&>().*get)(0))>;

    // Adds `item` at `index` (at most the list's size).
    AddOrDelete(Document* doc, int index, Item item, const QString& text)
        : QUndoCommand(text), doc_(doc), index_(index), item_(std::move(item)), adds_(true) {}
    // Deletes the item at `index`, an undo step named "Delete NAME".
    AddOrDelete(Document* doc, int index)
        : QUndoCommand(QObject::tr("Delete %1").arg(QString::fromStdString((doc->*get)(index).name))), doc_(doc),
          index_(index), item_((doc->*get)(index)), adds_(false) {}

    void redo() override { adds_ ? add() : take(); }
    void undo() override { adds_ ? take() : add(); }

private:
    void add() { (doc_->*insert)(index_, item_); }
    void take() { (doc_->*remove)(index_); }

    Document* doc_;
    int index_;
    Item item_;
    bool adds_;
};

}  // namespace lucerna
