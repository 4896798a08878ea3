#include "ui/recent_files.h"

#include <QFileInfo>
#include <QSettings>

namespace elui {

namespace {
const QString kKey = QStringLiteral("recentScenes");
QString absolute(const QString& path) { return QFileInfo(path).absoluteFilePath(); }
}  // namespace

RecentFiles::RecentFiles(QSettings* settings) : m_settings(settings) {
    if (!m_settings) return;
    for (const QString& path : m_settings->value(kKey).toStringList())
        if (!path.isEmpty() && !m_paths.contains(path) && m_paths.size() < kMax) m_paths << path;
}

void RecentFiles::add(const QString& path) {
    const QString a = absolute(path);
    m_paths.removeAll(a);
    m_paths.prepend(a);
    while (m_paths.size() > kMax) m_paths.removeLast();
    store();
}

void RecentFiles::remove(const QString& path) {
    m_paths.removeAll(absolute(path));
    store();
}

void RecentFiles::clear() {
    m_paths.clear();
    store();
}

void RecentFiles::store() {
    if (m_settings) m_settings->setValue(kKey, m_paths);
}

}  // namespace elui
