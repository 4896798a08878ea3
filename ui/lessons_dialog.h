#pragma once
// LessonsDialog (Help > Experiments): the guided experiments in a list, the chosen one's text
// beside it, and "Set up this experiment", which asks the window to load the lesson's preset
// (scene, parameters, integrator or side-by-side views) and open its docks.

#include <QDialog>

class QListWidget;
class QPushButton;
class QTextBrowser;

namespace elui {

struct Lesson;

class LessonsDialog : public QDialog {
    Q_OBJECT
public:
    explicit LessonsDialog(QWidget* parent = nullptr);
    QString currentId() const;
    void selectLesson(const QString& id);  // unknown id: no change
    QTextBrowser* browser() const { return m_text; }
    QPushButton* setUpButton() const { return m_setUp; }
    // A lesson text with its links to docs/ made absolute (the source tree's files).
    static QString displayHtml(const Lesson& lesson);

signals:
    void setUpRequested(const QString& id);

private:
    void showCurrent();

    QListWidget* m_list = nullptr;
    QTextBrowser* m_text = nullptr;
    QPushButton* m_setUp = nullptr;
};

}  // namespace elui
