#pragma once
// What the property panels of one item of the scene (a light, an object, a material) share: the
// item's index, the column of labelled rows its fields stand in (addPropertyRow), the undo
// merging of those fields, and the renaming rule of lights and objects.

#include "ui/document/document.h"
#include "ui/properties/property_rows.h"

#include <QWidget>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSignalBlocker;
class QVBoxLayout;

namespace lucerna {

class ItemProperties : public QWidget {
    Q_OBJECT
protected:
    // Makes fields_, packed at the top, with rows_ as its layout, and empty_, the note `none`
    // shown while no item is (none empty: the panel hides itself then). The panel lays them out.
    ItemProperties(Document* doc, const QString& none, QWidget* parent);
    ~ItemProperties() override;  // disconnects its children first (ui/disconnect_children.h)

    // Shows the item as the document has it now.
    virtual void refresh() = 0;
    // Shows another item (-1: none); an edit there is a new undo step.
    void select(int index);
    // Whether the item is one of the `count` in its list: shows the fields or the note to match.
    bool showsItem(size_t count);

    // A spin box among the fields (makePropertySpin) that calls `edited` with itself when its
    // value changes; once its editing finishes, its next edit is a new undo step.
    QDoubleSpinBox* makeSpin(double lo, double hi, int decimals, std::function<void(QDoubleSpinBox*)> edited);
    // Every field's signals blocked while the result lives (refresh sets the fields' values).
    std::vector<std::unique_ptr<QSignalBlocker>> quietFields() const;
    // The item (a light or an object, edited by `Command`) renamed to the name typed in `field`,
    // one undo step. Not when the name is unchanged, empty or used by an object or a light
    // (SPEC.md: names are unique across both): the field then shows the item's name again.
    template <class Command, class Item> void rename(QLineEdit* field, Item item) {
        const std::optional<std::string> name = newName(field, item.name);
        if (!name) return;
        const QString text = renameText(item.name, *name);
        item.name = *name;
        doc_->undoStack()->push(new Command(doc_, index_, std::move(item), 0, text));
    }

    Document* doc_;
    int index_ = -1;
    QWidget* fields_;
    QVBoxLayout* rows_;
    QLabel* empty_ = nullptr;
    MergeTracker merge_;

private:
    std::optional<std::string> newName(QLineEdit* field, const std::string& current) const;
    QString renameText(const std::string& from, const std::string& to) const;
};

}  // namespace lucerna
