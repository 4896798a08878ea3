// Keyboard and screen readers (issue 30): the accessibility tree that a screen reader (Orca,
// through AT-SPI) reads is Qt's QAccessibleInterface tree; this test walks it for the main
// window with every dock open, and for every dialog, and fails on any focusable control without
// an accessible name or without a description (what the reader says after the name: a tooltip
// or an accessibleDescription). docs/accessibility.md says what else was tried and how.
#include <functional>
#include <memory>

#include <QAccessible>
#include <QApplication>
#include <QDockWidget>
#include <QMenuBar>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

#include <QLabel>

#include "simcore/params.h"
#include "simcore/scenes.h"
#include "test_support.h"
#include "ui/accessibility.h"
#include "ui/compare_dialog.h"
#include "ui/help_dialog.h"
#include "ui/lessons_dialog.h"
#include "ui/main_window.h"
#include "ui/simulation_controller.h"
#include "ui/studies_dialog.h"

using namespace elui;

namespace {

QString describe(QAccessibleInterface* iface) {
    QString path;
    for (QObject* o = iface->object(); o; o = o->parent())
        path.prepend(QStringLiteral("/%1(%2)").arg(QString::fromLatin1(o->metaObject()->className()), o->objectName()));
    return QStringLiteral("%1 role %2").arg(path).arg(int(iface->role()));
}

// Every focusable, visible control under `root` without a name or a description.
QStringList unnamedControls(QWidget* root) {
    QStringList missing;
    std::function<void(QAccessibleInterface*)> walk = [&](QAccessibleInterface* iface) {
        for (int i = 0; i < iface->childCount(); ++i) {
            QAccessibleInterface* child = iface->child(i);
            if (!child || !child->isValid()) continue;
            const QAccessible::State state = child->state();
            if (state.invisible) continue;
            // Controls, not the parts of a view's content (cells, list items, headers: named by
            // their text, and read as such), which have no widget of their own.
            auto* widget = qobject_cast<QWidget*>(child->object());
            const bool control = widget && QAccessible::queryAccessibleInterface(widget) == child;
            if (control && state.focusable) {
                if (child->text(QAccessible::Name).trimmed().isEmpty())
                    missing << QStringLiteral("no name: ") + describe(child);
                // Qt 6.4's interface for a tab bar (the docks QMainWindow stacks) reports no
                // description whatever is set; its tabs are named by their docks.
                else if (child->role() != QAccessible::PageTabList &&
                         child->text(QAccessible::Description).trimmed().isEmpty())
                    missing << QStringLiteral("no description: '%1' ").arg(child->text(QAccessible::Name)) + describe(child);
            }
            walk(child);
        }
    };
    walk(QAccessible::queryAccessibleInterface(root));
    return missing;
}

}  // namespace

class TestAccessibility : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void everyControlOfTheMainWindowIsNamed_data() {
        QTest::addColumn<QString>("scene");
        QTest::newRow("spring1d") << QStringLiteral("spring1d");
        QTest::newRow("ring2d") << QStringLiteral("ring2d");
        QTest::newRow("sphere3d") << QStringLiteral("sphere3d");
    }
    void everyControlOfTheMainWindowIsNamed() {
        QFETCH(QString, scene);
        MainWindow window(false);
        window.startScene(simcore::ParameterSet(simcore::findScene(scene.toStdString())->kind), {QStringLiteral("rk4")});
        window.resize(1280, 800);
        window.show();
        for (const QString& dock : MainWindow::dockNames()) QVERIFY(window.openDock(dock));
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QStringList missing = unnamedControls(&window);
        QVERIFY2(missing.isEmpty(), qPrintable(missing.join('\n')));
    }

    void failureAndReadoutAreAnnounced() {
        // What a screen reader hears: the events Qt's bridge turns into AT-SPI events (captured
        // here by an update handler, as Qt's own accessibility tests do).
        // Qt passes events to the bridge only while a reader is active (never on the offscreen
        // platform): what the code sends is read from elui::announcements().
        QSignalSpy sent(announcements(), &Announcements::sent);
        auto seen = [&](QAccessible::Event type, QObject* object) {
            for (const QList<QVariant>& e : sent)
                if (e.at(0).value<QObject*>() == object && e.at(1).toInt() == int(type)) return true;
            return false;
        };
        {
            MainWindow window(false);
            simcore::ParameterSet params(simcore::SceneKind::Ring2d);
            params.set(simcore::Param::Dt, 0.3);  // explicit Euler blows up at once
            window.startScene(params, {QStringLiteral("euler")});
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            auto* readout = window.findChild<QLabel*>(QStringLiteral("readout"));
            QVERIFY(readout);
            // The readout: reached by Tab, named by its text (plain), a name change when it changes.
            QVERIFY(readout->focusPolicy() & Qt::TabFocus);
            QVERIFY(testsupport::waitUntil([&] { return !readout->text().isEmpty(); }));
            QVERIFY(testsupport::waitUntil([&] { return readout->accessibleName() == plainText(readout->text()); }));
            QVERIFY(!readout->accessibleName().contains('<'));
            QVERIFY(testsupport::waitUntil([&] { return seen(QAccessible::NameChanged, readout); }));
            // The failure banner: an alert, announced when it appears, read as its text.
            window.controller()->setSpeed(Speed::AsFastAsPossible);
            window.controller()->run();
            QVERIFY(testsupport::waitUntil([&] { return !window.failureText().isEmpty(); }));
            QWidget* banner = window.findChild<QWidget*>(QStringLiteral("failureBanner"));
            QVERIFY(testsupport::waitUntil([&] { return seen(QAccessible::Alert, banner); }));
            QAccessibleInterface* iface = QAccessible::queryAccessibleInterface(banner);
            QCOMPARE(iface->role(), QAccessible::AlertMessage);
            QVERIFY2(iface->text(QAccessible::Name).startsWith("The simulation blew up at t = "),
                     qPrintable(iface->text(QAccessible::Name)));
            window.controller()->pause();
        }
    }

    void highContrastIsReadable() {
        // WCAG 2: 7:1 for text is level AAA; the disabled text 4.5:1 (AA).
        MainWindow window(false);
        const QPalette before = QApplication::palette();
        window.setHighContrast(true);
        QVERIFY(window.highContrast());
        const QPalette p = QApplication::palette();
        for (auto [fg, bg] : {std::pair{QPalette::WindowText, QPalette::Window}, {QPalette::Text, QPalette::Base},
                              {QPalette::ButtonText, QPalette::Button}, {QPalette::HighlightedText, QPalette::Highlight},
                              {QPalette::ToolTipText, QPalette::ToolTipBase}})
            QVERIFY2(contrastRatio(p.color(QPalette::Active, fg), p.color(QPalette::Active, bg)) >= 7.0,
                     qPrintable(QString::number(contrastRatio(p.color(fg), p.color(bg)))));
        QVERIFY(contrastRatio(p.color(QPalette::Disabled, QPalette::Text), p.color(QPalette::Disabled, QPalette::Base)) >= 4.5);
        QVERIFY(contrastRatio(p.color(QPalette::Link), p.color(QPalette::Base)) >= 7.0);
        // The ratio itself: black on white is 21:1.
        QCOMPARE(qRound(contrastRatio(Qt::black, Qt::white) * 100), 2100);
        window.setHighContrast(false);
        QCOMPARE(QApplication::palette().color(QPalette::Window), before.color(QPalette::Window));
    }

    void everyControlOfEveryDialogIsNamed() {
        MainWindow window(false);
        const simcore::ParameterSet params(simcore::SceneKind::Ring2d);
        std::vector<std::unique_ptr<QDialog>> dialogs;
        dialogs.emplace_back(new HelpDialog(&window));
        dialogs.emplace_back(new LessonsDialog(&window));
        dialogs.emplace_back(new CompareDialog({QStringLiteral("euler"), QStringLiteral("rk4")}, 0.003, &window));
        dialogs.emplace_back(new WorkPrecisionDialog(params, &window));
        dialogs.emplace_back(new RefinementDialog(params, &window));
        dialogs.emplace_back(new StabilityDialog(params, &window));
        QStringList missing;
        for (const auto& dialog : dialogs) {
            dialog->show();
            QVERIFY(QTest::qWaitForWindowExposed(dialog.get()));
            missing += unnamedControls(dialog.get());
            dialog->hide();
        }
        QVERIFY2(missing.isEmpty(), qPrintable(missing.join('\n')));
    }
};

QTEST_MAIN(TestAccessibility)
#include "test_accessibility.moc"
