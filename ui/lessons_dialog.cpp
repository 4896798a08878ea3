#include "ui/lessons_dialog.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSplitter>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

#include "ui/lessons.h"

namespace elui {

QString LessonsDialog::displayHtml(const Lesson& lesson) {
    QString html = lesson.html();
    const QString root = QUrl::fromLocalFile(QDir(QStringLiteral(ELASTIC_LAB_SOURCE_DIR)).absolutePath()).toString();
    html.replace(QStringLiteral("href=\"docs/"), QStringLiteral("href=\"%1/docs/").arg(root));
    return html;
}

LessonsDialog::LessonsDialog(QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Experiments"));
    setObjectName(QStringLiteral("lessonsDialog"));
    resize(980, 640);
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("Short guided experiments: each sets up a scene, says what to change and what "
                                "to look at, and gives the answer measured with elastic-lab-cli."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    auto* splitter = new QSplitter(Qt::Horizontal, this);
    m_list = new QListWidget(splitter);
    m_list->setObjectName(QStringLiteral("lessonList"));
    for (const Lesson& l : lessons()) {
        auto* item = new QListWidgetItem(l.title, m_list);
        item->setData(Qt::UserRole, l.id);
    }
    m_text = new QTextBrowser(splitter);
    m_text->setObjectName(QStringLiteral("lessonText"));
    m_text->setOpenExternalLinks(true);
    // Long commands wrap instead of scrolling the page sideways.
    m_text->document()->setDefaultStyleSheet(QStringLiteral("pre { white-space: pre-wrap; }"));
    splitter->addWidget(m_list);
    splitter->addWidget(m_text);
    splitter->setStretchFactor(0, 0);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({300, 680});
    layout->addWidget(splitter, 1);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_setUp = buttons->addButton(tr("Set up this experiment"), QDialogButtonBox::ActionRole);
    m_setUp->setObjectName(QStringLiteral("setUpLesson"));
    m_setUp->setDefault(true);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_setUp, &QPushButton::clicked, this, [this] {
        if (!currentId().isEmpty()) emit setUpRequested(currentId());
    });
    layout->addWidget(buttons);

    connect(m_list, &QListWidget::currentRowChanged, this, &LessonsDialog::showCurrent);
    m_list->setCurrentRow(0);
}

QString LessonsDialog::currentId() const {
    const QListWidgetItem* item = m_list->currentItem();
    return item ? item->data(Qt::UserRole).toString() : QString();
}

void LessonsDialog::selectLesson(const QString& id) {
    for (int i = 0; i < m_list->count(); ++i)
        if (m_list->item(i)->data(Qt::UserRole).toString() == id) m_list->setCurrentRow(i);
}

void LessonsDialog::showCurrent() {
    const Lesson* lesson = findLesson(currentId());
    m_text->setHtml(lesson ? displayHtml(*lesson) : QString());
    m_setUp->setEnabled(lesson != nullptr);
}

}  // namespace elui
