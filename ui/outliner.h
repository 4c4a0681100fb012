#pragma once
// The outliner: the scene's objects, lights and materials under three headings. It rebuilds
// itself when the document's structure changes (add, delete, rename) and keeps the selection
// where it can.

#include "ui/document.h"

#include <QTreeWidget>

namespace lucerna {

class Outliner : public QTreeWidget {
    Q_OBJECT
public:
    enum class Kind { None, Object, Light, Material };
    struct Selection {
        Kind kind = Kind::None;
        int index = -1;
        bool operator==(const Selection&) const = default;
    };

    explicit Outliner(Document* doc, QWidget* parent = nullptr);

    Selection selection() const;
    void select(Kind kind, int index);
    // The heading item of a kind (tests walk its children).
    QTreeWidgetItem* heading(Kind kind) const;
    QSize sizeHint() const override { return {280, 300}; }

signals:
    void selectionChangedTo(lucerna::Outliner::Selection selection);

private:
    void rebuild();

    Document* doc_;
    QTreeWidgetItem *objects_ = nullptr, *lights_ = nullptr, *materials_ = nullptr;
};

}  // namespace lucerna
