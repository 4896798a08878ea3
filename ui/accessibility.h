#pragma once
// Accessibility (issue 30; docs/accessibility.md): what a screen reader (Orca through AT-SPI, via
// Qt's accessibility bridge) reads, and what a keyboard or low-vision user gets.
//
//   names and descriptions  every focusable control has an accessible name (its label, its
//                           text) and a description (what the tooltip says, as plain text: the
//                           bridge passes rich text on unchanged and a reader would speak tags)
//   live text               the readout is a focusable label whose name follows its text at most
//                           once per second (a change of name is what a reader speaks; every
//                           frame would drown it); the failure banner has the alert role and is
//                           announced with an Alert event when it appears
//   high contrast           a palette of black, white and yellow (contrast 21:1 and 19.6:1),
//                           View > High contrast
#include <QAccessible>
#include <QObject>
#include <QPalette>
#include <QString>

class QLabel;
class QWidget;

namespace elui {

// The plain text of Qt rich text ("<b>ks</b> [N/m]<br>stiffness" -> "ks [N/m]. stiffness").
QString plainText(const QString& richText);

// Every descendant of root (and root) that has a tooltip and no accessible description gets the
// tooltip's plain text as its description.
void describeFromToolTips(QWidget* root);

// Does describeFromToolTips for every widget as it is shown, application-wide (docks rebuilt for
// a new scene, dialogs opened later). Installed once by the main window. A tooltip that changes
// after the widget is shown (an error in a field) is set as its description where it changes.
void installToolTipDescriptions();

// Sets name and description (the description made plain).
void setAccessibleText(QWidget* widget, const QString& name, const QString& description);

// The widget's accessible role is an alert (AT-SPI ALERT): for the failure banner. Installs a
// factory once; widgets are marked by a dynamic property.
void markAsAlert(QWidget* widget);
// Tells assistive technology that an alert appeared (QAccessible::Alert on the widget).
void announceAlert(QWidget* widget);

// Every event sent above (an alert, a live label's new name) is also this object's signal. Qt
// hands an event to the AT-SPI bridge only while a screen reader is active, so a test listens
// here for what was sent, and scripts/atspi-tree.py checks the bridge's side by hand.
class Announcements : public QObject {
    Q_OBJECT
signals:
    void sent(QObject* object, int event);  // event: a QAccessible::Event
};
Announcements* announcements();
void sendAccessibleEvent(QObject* object, QAccessible::Event type);

// A label read out by screen readers as its text changes: focusable (Tab reaches it), its name the
// plain text (emptyName while it has none), a NameChanged event at most once per `minimumMs` (the
// newest text wins).
class LiveLabel;
void makeLive(QLabel* label, const QString& emptyName, int minimumMs = 1000);

// Black background, white text, yellow highlight and focus; links in cyan.
QPalette highContrastPalette();
// The ratio of WCAG 2 relative luminances, (L1 + 0.05) / (L2 + 0.05), >= 1.
double contrastRatio(const QColor& a, const QColor& b);

}  // namespace elui
