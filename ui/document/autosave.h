#pragma once
// Crash recovery: while the document has unsaved changes, it is written to a recovery file every
// interval (a minute by default), so that a crash loses at most that much work; a clean save or
// close removes the file. A recovery file found at the next start is offered back only when the
// run that wrote it did not close cleanly (its run marker is still there: every run writes one at
// its start and removes it when it closes cleanly) and it is newer than the scene's file.

#include "ui/document/document.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <optional>

namespace lucerna {

class Autosave : public QObject {
    Q_OBJECT
public:
    // Recovery files live in `directory` (created when needed). Writes this run's marker there.
    Autosave(Document& document, QString directory, int intervalMs = 60000, QObject* parent = nullptr);

    // Writes the recovery file when the document has unsaved changes; true when it wrote one.
    bool writeNow();
    // The document was saved, or replaced by another (its changes saved or let go): nothing to
    // recover.
    void discard();
    // The designer let the unsaved changes go (Discard, before another scene replaces them): the
    // recovery file goes, and none is written again until the document changes, so that a crash
    // while the next scene is read does not offer the discarded changes back.
    void letGo();
    // The application closes cleanly: nothing to recover, and the run's marker goes.
    void closedCleanly();

    struct Recovery {
        Scene scene;               // as it was at the last autosave, meshes resolved
        std::string documentPath;  // the file it belongs to ("" for an untitled scene)
    };
    // The recovery file a previous run left in `directory`, if any and if worth offering (see
    // above); a stale one is removed, an unreadable one is reported in `error` and removed.
    static std::optional<Recovery> pending(const QString& directory, QString* error = nullptr);
    static void discard(const QString& directory);
    // <application data>/recovery.
    static QString defaultDirectory();

private:
    Document& document_;
    QString directory_;
    QByteArray runId_;  // this run's marker, also the third line of the origin file
    QTimer timer_;
    bool letGo_ = false;  // until the undo stack moves
};

}  // namespace lucerna
