#include "ui/accessibility.h"

#include <algorithm>
#include <cmath>

#include <QAccessible>
#include <QAccessibleWidget>
#include <QCoreApplication>
#include <QEvent>
#include <QElapsedTimer>
#include <QLabel>
#include <QRegularExpression>
#include <QTextDocumentFragment>
#include <QTimer>

namespace elui {

namespace {

const char* const kAlertProperty = "elasticLabAlert";

// The failure banner's interface: a widget with the alert role, named by its text.
class AlertInterface : public QAccessibleWidget {
public:
    explicit AlertInterface(QWidget* w) : QAccessibleWidget(w, QAccessible::AlertMessage) {}
    QString text(QAccessible::Text t) const override {
        QString s = QAccessibleWidget::text(t);
        if (t == QAccessible::Name && s.isEmpty()) {
            // The banner's labels, read as one sentence.
            QStringList parts;
            for (const QLabel* label : widget()->findChildren<QLabel*>())
                if (label->isVisible() || !widget()->isVisible()) parts << plainText(label->text());
            s = parts.join(QLatin1Char(' '));
        }
        return s;
    }
};

QAccessibleInterface* alertFactory(const QString&, QObject* object) {
    auto* w = qobject_cast<QWidget*>(object);
    if (w && w->property(kAlertProperty).toBool()) return new AlertInterface(w);
    return nullptr;
}

double luminance(const QColor& c) {
    auto channel = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    return 0.2126 * channel(c.redF()) + 0.7152 * channel(c.greenF()) + 0.0722 * channel(c.blueF());
}

}  // namespace

QString plainText(const QString& richText) {
    if (!Qt::mightBeRichText(richText)) return richText.simplified();
    QString text = richText;
    // A line break between two phrases reads as a pause.
    text.replace(QRegularExpression(QStringLiteral("<br\\s*/?>"), QRegularExpression::CaseInsensitiveOption),
                 QStringLiteral(". "));
    text = QTextDocumentFragment::fromHtml(text).toPlainText().simplified();
    text.replace(QStringLiteral(". . "), QStringLiteral(". "));
    text.replace(QStringLiteral(".. "), QStringLiteral(". "));
    return text;
}

void describeFromToolTips(QWidget* root) {
    QList<QWidget*> widgets = root->findChildren<QWidget*>();
    widgets.prepend(root);
    for (QWidget* w : widgets)
        if (w->accessibleDescription().isEmpty() && !w->toolTip().isEmpty())
            w->setAccessibleDescription(plainText(w->toolTip()));
}

namespace {
class ToolTipDescriptions : public QObject {
protected:
    bool eventFilter(QObject* object, QEvent* event) override {
        // Every widget gets a show event as it (or its window) appears.
        if (event->type() == QEvent::Show)
            if (auto* w = qobject_cast<QWidget*>(object);
                w && w->accessibleDescription().isEmpty() && !w->toolTip().isEmpty())
                w->setAccessibleDescription(plainText(w->toolTip()));
        return false;
    }
};
}  // namespace

void installToolTipDescriptions() {
    static ToolTipDescriptions* filter = [] {
        auto* f = new ToolTipDescriptions;
        f->setParent(QCoreApplication::instance());
        QCoreApplication::instance()->installEventFilter(f);
        return f;
    }();
    (void)filter;
}

void setAccessibleText(QWidget* widget, const QString& name, const QString& description) {
    widget->setAccessibleName(name);
    widget->setAccessibleDescription(plainText(description));
}

void markAsAlert(QWidget* widget) {
    static const bool installed = [] {
        QAccessible::installFactory(alertFactory);
        return true;
    }();
    (void)installed;
    widget->setProperty(kAlertProperty, true);
}

Announcements* announcements() {
    static auto* instance = new Announcements;  // lives as long as the program
    return instance;
}

void sendAccessibleEvent(QObject* object, QAccessible::Event type) {
    QAccessibleEvent event(object, type);
    QAccessible::updateAccessibility(&event);
    emit announcements()->sent(object, int(type));
}

void announceAlert(QWidget* widget) { sendAccessibleEvent(widget, QAccessible::Alert); }

// The readout's name follows its text, throttled: a change within minimumMs of the last one is
// sent when that time has passed (the newest text then).
class LiveLabel : public QObject {
public:
    LiveLabel(QLabel* label, const QString& emptyName, int minimumMs)
        : QObject(label), m_label(label), m_emptyName(emptyName), m_minimumMs(minimumMs) {
        m_timer.setSingleShot(true);
        connect(&m_timer, &QTimer::timeout, this, &LiveLabel::publish);
        label->setFocusPolicy(Qt::TabFocus);
        label->installEventFilter(this);
        publish();
    }

protected:
    bool eventFilter(QObject*, QEvent* event) override {
        // QLabel has no text-changed signal: a repaint follows every setText.
        if (event->type() == QEvent::Paint || event->type() == QEvent::Show) changed();
        return false;
    }

private:
    void changed() {
        if (plainText(m_label->text()) == m_published || m_timer.isActive()) return;
        const qint64 since = m_clock.isValid() ? m_clock.elapsed() : m_minimumMs;
        if (since >= m_minimumMs) publish();
        else m_timer.start(int(m_minimumMs - since));
    }
    void publish() {
        const QString text = plainText(m_label->text());
        if (text == m_published && m_clock.isValid()) return;
        m_published = text;
        m_clock.restart();
        m_label->setAccessibleName(text.isEmpty() ? m_emptyName : text);
        // Qt 6.4 sends no event for a new accessible name: this is what a reader hears.
        sendAccessibleEvent(m_label, QAccessible::NameChanged);
    }

    QLabel* m_label;
    QString m_emptyName;
    int m_minimumMs;
    QTimer m_timer;
    QElapsedTimer m_clock;
    QString m_published;
};

void makeLive(QLabel* label, const QString& emptyName, int minimumMs) { new LiveLabel(label, emptyName, minimumMs); }

QPalette highContrastPalette() {
    const QColor black(0, 0, 0), white(255, 255, 255), yellow(255, 255, 0), grey(170, 170, 170), cyan(0, 255, 255);
    QPalette p;
    for (QPalette::ColorGroup g : {QPalette::Active, QPalette::Inactive}) {
        p.setColor(g, QPalette::Window, black);
        p.setColor(g, QPalette::WindowText, white);
        p.setColor(g, QPalette::Base, black);
        p.setColor(g, QPalette::AlternateBase, QColor(30, 30, 30));
        p.setColor(g, QPalette::Text, white);
        p.setColor(g, QPalette::Button, black);
        p.setColor(g, QPalette::ButtonText, white);
        p.setColor(g, QPalette::BrightText, yellow);
        p.setColor(g, QPalette::Highlight, yellow);
        p.setColor(g, QPalette::HighlightedText, black);
        p.setColor(g, QPalette::ToolTipBase, black);
        p.setColor(g, QPalette::ToolTipText, white);
        p.setColor(g, QPalette::PlaceholderText, grey);
        p.setColor(g, QPalette::Link, cyan);
        p.setColor(g, QPalette::LinkVisited, cyan);
        p.setColor(g, QPalette::Light, white);
        p.setColor(g, QPalette::Midlight, grey);
        p.setColor(g, QPalette::Mid, grey);
        p.setColor(g, QPalette::Dark, white);
        p.setColor(g, QPalette::Shadow, white);
    }
    // Disabled: grey on black (8.8:1), still readable, clearly not active.
    for (QPalette::ColorRole r : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
        p.setColor(QPalette::Disabled, r, grey);
    for (QPalette::ColorRole r : {QPalette::Window, QPalette::Base, QPalette::Button})
        p.setColor(QPalette::Disabled, r, black);
    return p;
}

double contrastRatio(const QColor& a, const QColor& b) {
    const double la = luminance(a), lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

}  // namespace elui
