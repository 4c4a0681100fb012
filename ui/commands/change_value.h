#pragma once
// The one undo command of every edit that replaces a value of the scene by another (a light, a
// material, the camera, the site, ...), after Tiled's ChangeValue: it reads the value before
// through a getter of the Document and sets the value after or before through the matching
// setter, so the document's signals are the setter's. Consecutive changes of the same kind and
// target with the same merge key fold into one undo step (a gizmo drag, a slider drag, a field's
// arrow steps).

#include "ui/document/document.h"

#include <QUndoCommand>

#include <type_traits>
#include <utility>
#include <variant>

namespace lucerna {

// The kinds of value a ChangeValue changes, each its own undo id: QUndoStack offers a command to
// merge only with the previous one of the same id.
enum class ValueKind { Light, Lights, LightList, Material, Object, Camera, Site, Sky, TaskArea, Project };

namespace detail {
// What a Document getter says about the value: `Value get(Target) const`, or `Value get() const`
// for a value of the whole scene (Target is then std::monostate).
template <class Get> struct GetterOf;
template <class V, class T> struct GetterOf<V (Document::*)(T) const> {
    using Target = std::remove_cvref_t<T>;
    using Value = std::remove_cvref_t<V>;
};
template <class V> struct GetterOf<V (Document::*)() const> {
    using Target = std::monostate;
    using Value = std::remove_cvref_t<V>;
};
}  // namespace detail

// `get` and `set` are a pair of Document members, e.g. &Document::light and &Document::setLight.
template <ValueKind kind, auto get, auto set>
class ChangeValue : public QUndoCommand {
public:
    using Target = typename detail::GetterOf<decltype(get)>::Target;
    using Value = typename detail::GetterOf<decltype(get)>::Value;
    static constexpr bool kWhole = std::is_same_v<Target, std::monostate>;

    // The value at `target` becomes `after`. mergeKey 0: never merges; otherwise merges into the
    // previous change of the same target with the same key (one key per drag or per field).
    ChangeValue(Document* doc, Target target, Value after, int mergeKey, const QString& text)
        requires(!kWhole)
        : QUndoCommand(text), doc_(doc), target_(std::move(target)), before_((doc->*get)(target_)),
          after_(std::move(after)), mergeKey_(mergeKey) {}
    // The same for a value of the whole scene (the camera, the site, the sky).
    ChangeValue(Document* doc, Value after, int mergeKey, const QString& text)
        requires kWhole
        : QUndoCommand(text), doc_(doc), before_((doc->*get)()), after_(std::move(after)), mergeKey_(mergeKey) {}

    void redo() override { apply(after_); }
    void undo() override { apply(before_); }
    int id() const override { return int(kind); }
    bool mergeWith(const QUndoCommand* other) override {
        // Same id, so same kind and so same class.
        const auto* o = static_cast<const ChangeValue*>(other);
        if (mergeKey_ == 0 || o->mergeKey_ != mergeKey_ || o->target_ != target_) return false;
        after_ = o->after_;
        return true;
    }

private:
    void apply(const Value& value) {
        if constexpr (kWhole) (doc_->*set)(value);
        else (doc_->*set)(target_, value);
    }

    Document* doc_;
    Target target_{};
    Value before_, after_;
    int mergeKey_;
};

}  // namespace lucerna
