#include "ui/field_keys.h"

#include <QKeyEvent>
#include <QLineEdit>

namespace elui {

namespace {
class FieldKeys : public QObject {
public:
    FieldKeys(QLineEdit* edit, std::function<bool()> commit, std::function<void()> restore)
        : QObject(edit), m_edit(edit), m_commit(std::move(commit)), m_restore(std::move(restore)) {}

protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (watched != m_edit || event->type() != QEvent::KeyPress) return false;
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {
            if (m_commit()) leave();
            return true;
        }
        if (key == Qt::Key_Escape) {
            m_restore();
            leave();
            return true;
        }
        return false;
    }

private:
    void leave() {
        // Nothing else takes the keyboard: the window's shortcuts (Space, S) act again.
        if (QWidget* w = m_edit->window()) w->setFocus(Qt::OtherFocusReason);
        m_edit->clearFocus();
    }
    QLineEdit* m_edit;
    std::function<bool()> m_commit;
    std::function<void()> m_restore;
};
}  // namespace

void installFieldKeys(QLineEdit* edit, std::function<bool()> commit, std::function<void()> restore) {
    edit->installEventFilter(new FieldKeys(edit, std::move(commit), std::move(restore)));
}

void markField(QLineEdit* edit, const QString& error, const QString& normalTip) {
    edit->setStyleSheet(error.isEmpty() ? QString() : QStringLiteral("background: #ffd6d6"));
    edit->setToolTip(error.isEmpty() ? normalTip : error);
    edit->setProperty("refused", !error.isEmpty());
}

}  // namespace elui
