#include "ui/outliner.h"

#include "ui/commands/light_commands.h"
#include "ui/commands/material_commands.h"

#include <QHeaderView>

namespace lucerna {

namespace {
constexpr int kKindRole = Qt::UserRole, kIndexRole = Qt::UserRole + 1;
}  // namespace

Outliner::Outliner(Document* doc, QWidget* parent) : QTreeWidget(parent), doc_(doc) {
    setColumnCount(2);
    setHeaderLabels({tr("Name"), tr("Type")});
    header()->setSectionResizeMode(0, QHeaderView::Stretch);
    header()->setStretchLastSection(false);
    setSelectionMode(QAbstractItemView::SingleSelection);
    connect(doc_, &Document::structureChanged, this, &Outliner::rebuild);
    connect(this, &QTreeWidget::itemSelectionChanged, this, [this] { emit selectionChangedTo(selection()); });
    rebuild();
}

QTreeWidgetItem* Outliner::heading(Kind kind) const {
    switch (kind) {
    case Kind::Object: return objects_;
    case Kind::Light: return lights_;
    case Kind::Material: return materials_;
    case Kind::None: break;
    }
    return nullptr;
}

Outliner::Selection Outliner::selection() const {
    const auto items = selectedItems();
    if (items.isEmpty() || !items.front()->data(0, kKindRole).isValid()) return {};
    return {Kind(items.front()->data(0, kKindRole).toInt()), items.front()->data(0, kIndexRole).toInt()};
}

void Outliner::select(Kind kind, int index) {
    QTreeWidgetItem* parent = heading(kind);
    if (!parent || index < 0 || index >= parent->childCount()) {
        clearSelection();
        return;
    }
    setCurrentItem(parent->child(index));
}

void Outliner::rebuild() {
    const Selection keep = selection();
    {
        // Clearing would announce an empty selection in passing; the caller hears the final one.
        const QSignalBlocker block(this);
        clear();
        const Scene& scene = doc_->scene();
        const auto addHeading = [this](const QString& title) {
            auto* item = new QTreeWidgetItem(this, {title});
            item->setFlags(Qt::ItemIsEnabled);
            QFont f = item->font(0);
            f.setBold(true);
            item->setFont(0, f);
            item->setExpanded(true);
            return item;
        };
        const auto addChild = [](QTreeWidgetItem* parent, Kind kind, int index, const std::string& name,
                                 const QString& type) {
            auto* item = new QTreeWidgetItem(parent, {QString::fromStdString(name), type});
            item->setData(0, kKindRole, int(kind));
            item->setData(0, kIndexRole, index);
        };
        objects_ = addHeading(tr("Objects"));
        for (size_t i = 0; i < scene.objects.size(); ++i)
            addChild(objects_, Kind::Object, int(i), scene.objects[i].name, QString::fromStdString(scene.objects[i].material));
        lights_ = addHeading(tr("Lights"));
        for (size_t i = 0; i < scene.lights.size(); ++i)
            addChild(lights_, Kind::Light, int(i), scene.lights[i].name, lightTypeName(scene.lights[i].type));
        materials_ = addHeading(tr("Materials"));
        for (size_t i = 0; i < scene.materials.size(); ++i)
            addChild(materials_, Kind::Material, int(i), scene.materials[i].name, materialTypeName(scene.materials[i].type));
        for (auto* h : {objects_, lights_, materials_}) h->setExpanded(true);
        if (keep.kind != Kind::None) select(keep.kind, keep.index);
    }
    emit selectionChangedTo(selection());
}

}  // namespace lucerna
