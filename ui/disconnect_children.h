#pragma once
// Qt removes a receiver's connections in ~QObject, which runs after ~QWidget has hidden the
// widget and moved the focus away; a focused child (a spin box, a time edit) then emits
// editingFinished into a panel whose own destructor has already run (UBSan: member access within
// an object that is no longer of the panel's type). A panel whose slots use its members calls this
// in its destructor.

#include <QObject>

namespace lucerna {

inline void disconnectChildren(QObject* panel) {
    for (QObject* child : panel->findChildren<QObject*>()) QObject::disconnect(child, nullptr, panel, nullptr);
}

}  // namespace lucerna
