#pragma once
// Crash recovery: while the document has unsaved changes, it is written to a recovery file every
// interval (a minute by default), so that a crash loses at most that much work; a clean save or
// close removes the file. A recovery file found at the next start was left by a session that did
// not end cleanly, and is offered back.

#include "ui/document.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <optional>

namespace lucerna {

class Autosave : public QObject {
    Q_OBJECT
public:
    // Recovery files live in `directory` (created when needed).
    Autosave(Document& document, QString directory, int intervalMs = 60000, QObject* parent = nullptr);

    // Writes the recovery file when the document has unsaved changes; true when it wrote one.
    bool writeNow();
    // The document was saved or closed cleanly: nothing to recover.
    void discard();

    struct Recovery {
        Scene scene;               // as it was at the last autosave, meshes resolved
        std::string documentPath;  // the file it belongs to ("" for an untitled scene)
    };
    // The recovery file a previous session left in `directory`, if any. An unreadable one is
    // reported in `error` and removed.
    static std::optional<Recovery> pending(const QString& directory, QString* error = nullptr);
    static void discard(const QString& directory);
    // <application data>/recovery.
    static QString defaultDirectory();

private:
    Document& document_;
    QString directory_;
    QTimer timer_;
};

}  // namespace lucerna
