#pragma once
// RecentFiles: the scene files opened or saved lately, most recent first, at most kMax, kept
// in QSettings (key "recentScenes") so the File menu's "Open recent" survives a restart.
// Paths are stored absolute; a file that has gone is dropped when chosen (MainWindow says so).

#include <QStringList>

class QSettings;

namespace elui {

class RecentFiles {
public:
    static constexpr int kMax = 8;

    // settings = nullptr: kept in memory only (tests, screenshots). Not owned.
    explicit RecentFiles(QSettings* settings = nullptr);

    QStringList paths() const { return m_paths; }
    // To the front (once), the oldest beyond kMax dropped.
    void add(const QString& path);
    void remove(const QString& path);
    void clear();

private:
    void store();

    QSettings* m_settings = nullptr;
    QStringList m_paths;
};

}  // namespace elui
