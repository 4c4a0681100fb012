#pragma once
// File > Open Recent: the scenes last opened or saved, most recent first, kept with QSettings.

#include <QMenu>
#include <QStringList>

#include <functional>

namespace lucerna {

class RecentFilesMenu : public QMenu {
    Q_OBJECT
public:
    static constexpr int kMaxFiles = 8;

    // `open` is called with the chosen path.
    RecentFilesMenu(std::function<void(const QString&)> open, QWidget* parent = nullptr);

    // Puts an absolute path first (removing it further down) and rebuilds the menu.
    void add(const QString& path);
    QStringList files() const;

private:
    void rebuild();

    std::function<void(const QString&)> open_;
};

}  // namespace lucerna
