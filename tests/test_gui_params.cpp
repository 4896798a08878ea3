// The parameter and scene docks against simcore's parameter table: every key, unit, range and
// default; edits validated by the same table; values round-trip.
#include <QComboBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QToolButton>
#include <QTest>

#include <QFileInfo>
#include <QUrl>

#include <QApplication>
#include <QLabel>
#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "simcore/scenes.h"
#include "test_support.h"
#include "ui/compare_dialog.h"
#include "ui/help_dialog.h"
#include "ui/main_window.h"
#include "ui/parameter_dock.h"
#include "ui/presets.h"
#include "ui/run_dock.h"
#include "ui/scene_dock.h"
#include "ui/simulation_controller.h"

using namespace elui;
using simcore::ParamGroup;
using simcore::SceneKind;

Q_DECLARE_METATYPE(simcore::SceneKind)

class TestGuiParams : public QObject {
    Q_OBJECT
private slots:
    void fieldsComeFromTheTable_data() {
        QTest::addColumn<SceneKind>("kind");
        for (const simcore::SceneInfo& s : simcore::sceneTable())
            QTest::newRow(std::string(s.name).c_str()) << s.kind;
    }
    void fieldsComeFromTheTable() {
        QFETCH(SceneKind, kind);
        ParameterDock dock;
        dock.showParameters(simcore::ParameterSet(kind));
        QStringList expected;
        for (const simcore::ParamSpec* spec : simcore::parametersFor(kind))
            if (!spec->isShape()) expected << toQString(spec->key);
        QCOMPARE(dock.form()->keys(), expected);
        for (const simcore::ParamSpec* spec : simcore::parametersFor(kind)) {
            if (spec->isShape()) continue;
            if (!spec->choices.empty()) {
                // A choice is a combo box of the table's names, showing the default.
                QComboBox* box = dock.form()->choice(toQString(spec->key));
                QVERIFY(box);
                QVERIFY(!dock.form()->field(toQString(spec->key)));
                QCOMPARE(box->currentIndex(), int(simcore::ParameterSet(kind).get(spec->id)));
                QCOMPARE(box->itemText(1), QString::fromStdString(spec->choiceName(1)));
                QVERIFY(box->toolTip().contains(toQString(spec->meaning).toHtmlEscaped()));
                continue;
            }
            QLineEdit* edit = dock.form()->field(toQString(spec->key));
            QVERIFY(edit);
            QCOMPARE(edit->text().toDouble(), simcore::ParameterSet(kind).get(spec->id));
            const QString tip = edit->toolTip();
            QVERIFY2(tip.contains(toQString(spec->meaning).toHtmlEscaped()), qPrintable(tip));
            QVERIFY(tip.contains(QString::fromStdString(spec->rangeText())));
            if (!spec->unit.empty()) QVERIFY(tip.contains(toQString(spec->unit)));
        }
        // Keys a scene does not have are not shown: no gas for the 1D spring.
        QCOMPARE(dock.form()->field("pressure") != nullptr, kind != SceneKind::Spring1d);
        QCOMPARE(dock.form()->field("rks") != nullptr, kind != SceneKind::Spring1d);
    }

    void gasKeysAreShownAsNrt() {
        // pressure, pressure_inner, pressure_outer hold nRT (J), not a pressure: named for it,
        // the key in the tooltip (and in files, the CLI, Python) unchanged.
        ParameterDock dock;
        dock.showParameters(simcore::ParameterSet(SceneKind::Sphere3d));
        const std::map<QString, QString> names = {
            {"pressure", "gas nRT"}, {"pressure_inner", "gas nRT inner"}, {"pressure_outer", "gas nRT outer"}, {"ks", "ks"}};
        for (const auto& [key, name] : names) {
            auto* label = dock.findChild<QLabel*>("label_" + key);
            QVERIFY2(label, qPrintable(key));
            QCOMPARE(label->text(), name);
            QVERIFY(dock.form()->field(key));
        }
        QVERIFY(dock.form()->field("pressure_inner")->toolTip().contains("key: pressure_inner"));
        QVERIFY(dock.form()->field("pressure_inner")->toolTip().contains("[J]"));
        QVERIFY(!dock.findChild<QLabel*>("label_ks")->toolTip().contains("key:"));
    }

    void sideBySideProposesDistinctIntegrators() {
        for (const QString& single : {QString("rk4"), QString("euler"), QString("midpoint"), QString("verlet")}) {
            const QStringList proposal = CompareDialog::proposal({single});
            QCOMPARE(proposal.size(), 3);
            QCOMPARE(proposal.front(), single);
            QCOMPARE(QSet<QString>(proposal.begin(), proposal.end()).size(), 3);
        }
        QCOMPARE(CompareDialog::proposal({"rk4"}), (QStringList{"rk4", "euler", "midpoint"}));
        QCOMPARE(CompareDialog::proposal({}), (QStringList{"euler", "midpoint", "rk4"}));
        QCOMPARE(CompareDialog::proposal({"verlet", "rk45"}), (QStringList{"verlet", "rk45"}));  // the views running
    }

    void enterAndEscapeLeaveTheField() {
        // After typing into a field, Enter (a valid value) or Escape (the value in use back,
        // unmarked) leave it; then Space runs and S steps instead of typing into it.
        MainWindow w(false);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        w.startScene(simcore::ParameterSet(SceneKind::Ring2d), {"rk4"});
        SimulationController* c = w.controller();
        QVERIFY(testsupport::waitUntil([&] { return c->latest() && w.parameterDock()->form(); }));
        w.parameterDock()->show();
        w.parameterDock()->raise();
        // Keys as the keyboard sends them: to the focused widget, or to the window.
        auto press = [&](int key, const QString& text = {}) {
            QWidget* target = QApplication::focusWidget() ? QApplication::focusWidget() : &w;
            if (text.isEmpty()) QTest::keyClick(target, Qt::Key(key));
            else QTest::keyClicks(target, text);
        };
        for (QLineEdit* field : {w.parameterDock()->form()->field("ks"), w.runDock()->dtEdit()}) {
            const QString inUse = field->text();
            field->setFocus();
            QVERIFY(testsupport::waitUntil([&] { return field->hasFocus(); }));
            field->selectAll();
            press(0, "-3");
            press(Qt::Key_Return);
            QVERIFY2(field->property("refused").toBool(), "a refused value is marked red");
            QVERIFY2(field->hasFocus(), "and stays to be corrected");
            press(Qt::Key_Escape);
            QCOMPARE(field->text(), inUse);
            QVERIFY2(!field->property("refused").toBool() && field->styleSheet().isEmpty(),
                     "Escape shows the value in use: no red mark");
            QVERIFY(!field->hasFocus());
            // Space runs and pauses, S steps: nothing is typed into the field.
            press(Qt::Key_Space);
            QVERIFY(testsupport::waitUntil([&] { return c->latest()->running; }));
            press(Qt::Key_Space);
            QVERIFY(testsupport::waitUntil([&] { return !c->latest()->running; }));
            const long steps = c->latest()->lanes.front().diagnostics.step;
            press(Qt::Key_S);
            QVERIFY(testsupport::waitUntil([&] { return c->latest()->lanes.front().diagnostics.step == steps + 1; }));
            QCOMPARE(field->text(), inUse);
            // Enter with a valid value applies it and leaves the field.
            field->setFocus();
            QVERIFY(testsupport::waitUntil([&] { return field->hasFocus(); }));
            field->selectAll();
            const bool isDt = field == w.runDock()->dtEdit();
            press(0, isDt ? "0.002" : "2500");
            press(Qt::Key_Return);
            QVERIFY(!field->hasFocus());
            QVERIFY(!field->property("refused").toBool());
            const simcore::Param id = isDt ? simcore::Param::Dt : simcore::Param::Ks;
            QVERIFY(testsupport::waitUntil([&] { return c->latest()->parameters.get(id) == (isDt ? 0.002 : 2500.0); }));
            press(Qt::Key_S);
            QVERIFY(testsupport::waitUntil([&] { return c->latest()->lanes.front().diagnostics.step == steps + 2; }));
        }
    }

    void tolerancesAreSetInTheRunDock() {
        // rk45's rtol and atol (the CLI's --rtol, --atol) from the Run dock reach every lane;
        // a tighter tolerance takes more, smaller steps over the same time (at 1e-6 the ring's
        // steps are mostly held by the speed cap, a tenth of the box per step).
        MainWindow w(false);
        w.startScene(simcore::ParameterSet(SceneKind::Ring2d), {"rk45"});
        SimulationController* c = w.controller();
        QVERIFY(testsupport::waitUntil([&] { return c->latest() != nullptr; }));
        auto* rtol = w.runDock()->findChild<QLineEdit*>("rtolEdit");
        auto* atol = w.runDock()->findChild<QLineEdit*>("atolEdit");
        QVERIFY(rtol && atol);
        QVERIFY(rtol->isEnabled());
        QCOMPARE(rtol->text().toDouble(), 1e-6);
        auto stepsTo = [&](double t) {
            c->reset();
            testsupport::waitUntil([&] { return c->latest()->lanes.front().diagnostics.time == 0.0; });
            c->runUntil(t);
            testsupport::waitUntil([&] {
                return !c->latest()->running && c->latest()->lanes.front().diagnostics.time >= t - 1e-12;
            });
            return c->latest()->lanes.front().diagnostics.step;
        };
        const long standard = stepsTo(1.2);  // through the impact on the floor (t ≈ 1 s)
        rtol->setText("1e-10");
        atol->setText("1e-10");
        emit atol->editingFinished();
        QVERIFY(testsupport::waitUntil([&] { return c->latest()->rtol == 1e-10 && c->latest()->atol == 1e-10; }));
        const long tight = stepsTo(1.2);
        QVERIFY2(tight > standard, qPrintable(QString("%1 steps at 1e-6, %2 at 1e-10").arg(standard).arg(tight)));
        // Out of range: refused and marked, nothing sent.
        rtol->setText("0");
        emit rtol->editingFinished();
        QVERIFY(rtol->property("refused").toBool());
        QCOMPARE(c->latest()->rtol, 1e-10);
        // A fixed-step method has no tolerance: the fields are greyed out.
        c->setIntegrator("rk4");
        QVERIFY(testsupport::waitUntil([&] { return c->latest()->lanes.front().integrator == "rk4"; }));
        QCoreApplication::processEvents();
        QVERIFY(!rtol->isEnabled());
    }

    void precisionSwitch() {
        // Precision float from the Run dock reaches the worker: the view steps on the float
        // path and the readout gives its distance from the shadow double run. The front door
        // refuses float for a method without a float build, with its words.
        MainWindow w(false);
        simcore::ParameterSet ring(SceneKind::Ring2d);
        ring.set(simcore::Param::Gravity, 0.0);  // free flight: the float path has no walls
        ring.set(simcore::Param::Perturb, 0.02);
        w.startScene(ring, {"rk4"});
        SimulationController* c = w.controller();
        QVERIFY(testsupport::waitUntil([&] { return c->latest() != nullptr; }));
        auto* precision = w.runDock()->findChild<QComboBox*>("precisionCombo");
        QVERIFY(precision);
        QCOMPARE(precision->currentIndex(), 0);
        QSignalSpy messages(w.runDock(), &RunDock::message);
        precision->setCurrentIndex(1);
        QVERIFY(testsupport::waitUntil([&] { return c->latest()->floatWanted; }));
        for (int i = 0; i < 5; ++i) c->step();
        QVERIFY(testsupport::waitUntil([&] { return c->latest()->lanes.front().diagnostics.step == 5; }));
        QVERIFY(c->latest()->floatActive);
        QVERIFY(c->latest()->floatDistance > 0.0 && c->latest()->floatDistance < 1e-5);
        QCoreApplication::processEvents();
        const QString readout = w.runDock()->readout()->text();
        QVERIFY2(readout.contains(QStringLiteral("float − double")), qPrintable(readout));
        QVERIFY(messages.isEmpty());
        // A method without a float build: the integrator changes, the run goes on in double.
        const QString refusal = QStringLiteral("precision float is built for the explicit integrators euler, midpoint, "
                                               "rk4, symplectic-euler, verlet, not 'rk45'");
        w.runDock()->integratorCombo()->setCurrentText("rk45");
        QVERIFY(testsupport::waitUntil([&] { return !c->latest()->floatWanted; }));
        QCOMPARE(precision->currentIndex(), 0);
        QCOMPARE(messages.size(), 1);
        QCOMPARE(messages.takeFirst().at(0).toString(), refusal);
        // ... and float is refused while it is chosen.
        QVERIFY(testsupport::waitUntil([&] { return c->latest()->lanes.front().integrator == "rk45"; }));
        QCoreApplication::processEvents();
        precision->setCurrentIndex(1);
        QCOMPARE(precision->currentIndex(), 0);
        QCOMPARE(messages.size(), 1);
        QCOMPARE(messages.takeFirst().at(0).toString(), refusal);
        c->step();
        QVERIFY(testsupport::waitUntil([&] { return c->latest()->lanes.front().diagnostics.step == 6; }));
        QVERIFY(!c->latest()->floatWanted && !c->latest()->floatActive);
    }

    void valuesRoundTrip() {
        simcore::ParameterSet params(SceneKind::Sphere3d);
        QVERIFY(!params.set(simcore::Param::Ks, 1234.5));
        QVERIFY(!params.set(simcore::Param::PressureInner, 7.25));
        QVERIFY(!params.set(simcore::Param::MassOuter, 0.125));
        QVERIFY(!params.set(simcore::Param::Seed, 42));
        ParameterDock dock;
        dock.showParameters(params);
        const simcore::ParameterSet shown = dock.form()->values();
        for (const QString& key : dock.form()->keys())
            QCOMPARE(shown.get(simcore::findParam(key.toStdString())->id), params.get(simcore::findParam(key.toStdString())->id));
        // pressure_outer still inherits pressure (20), pressure_inner is its own.
        QCOMPARE(dock.form()->field("pressure_outer")->text(), QString("20"));
        QCOMPARE(dock.form()->field("pressure_inner")->text(), QString("7.25"));
    }

    void validEditEmitsOnce() {
        ParameterDock dock;
        dock.showParameters(simcore::ParameterSet(SceneKind::Ring2d));
        QSignalSpy edited(&dock, &ParameterDock::parameterEdited);
        QLineEdit* ks = dock.form()->field("ks");
        ks->setText("999.5");
        emit ks->editingFinished();
        QCOMPARE(edited.count(), 1);
        QCOMPARE(edited.at(0).at(0).value<simcore::Param>(), simcore::Param::Ks);
        QCOMPARE(edited.at(0).at(1).toDouble(), 999.5);
        emit ks->editingFinished();  // unchanged: no second edit
        QCOMPARE(edited.count(), 1);
        // Showing new values from the model does not echo back as an edit.
        simcore::ParameterSet p(SceneKind::Ring2d);
        p.set(simcore::Param::Ks, 10.0);
        dock.showParameters(p);
        QCOMPARE(edited.count(), 1);
        QCOMPARE(ks->text(), QString("10"));
    }

    void invalidEditIsRefusedWithTheTablesMessage_data() {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("text");
        QTest::newRow("negative stiffness") << "ks" << "-5";
        QTest::newRow("not a number") << "kd" << "abc";
        QTest::newRow("restitution above 1") << "restitution" << "1.5";
        QTest::newRow("zero mass (exclusive)") << "mass" << "0";
        QTest::newRow("fractional seed") << "seed" << "1.5";
        QTest::newRow("trailing junk") << "gravity" << "9.81x";
    }
    void invalidEditIsRefusedWithTheTablesMessage() {
        QFETCH(QString, key);
        QFETCH(QString, text);
        ParameterDock dock;
        dock.showParameters(simcore::ParameterSet(SceneKind::Ring2d));
        QSignalSpy edited(&dock, &ParameterDock::parameterEdited);
        QSignalSpy rejected(&dock, &ParameterDock::parameterRejected);
        QLineEdit* field = dock.form()->field(key);
        field->setText(text);
        emit field->editingFinished();
        QCOMPARE(edited.count(), 0);
        QCOMPARE(rejected.count(), 1);
        const QString message = rejected.at(0).at(1).toString();
        QVERIFY(message.startsWith(key));
        const simcore::ParamSpec* spec = simcore::findParam(key.toStdString());
        if (auto v = simcore::parseNumber(text.toStdString()))
            QCOMPARE(message, QString::fromStdString(*simcore::validateValue(*spec, *v)));
        QVERIFY(!field->styleSheet().isEmpty());  // marked
    }

    void sceneDockOffersTheShapeKeys_data() { fieldsComeFromTheTable_data(); }
    void sceneDockOffersTheShapeKeys() {
        QFETCH(SceneKind, kind);
        SceneDock dock;
        dock.showParameters(simcore::ParameterSet(kind));
        const simcore::ParameterSet shape = dock.requestedShape();
        QCOMPARE(shape.kind(), kind);
        int count = 0;
        for (const simcore::ParamSpec* spec : simcore::parametersFor(kind)) {
            QCOMPARE(shape.isExplicit(spec->id), spec->isShape());
            count += spec->isShape();
        }
        QVERIFY(count >= 1);
        QSignalSpy rebuild(&dock, &SceneDock::rebuildRequested);
        dock.findChild<QWidget*>("rebuildButton")->metaObject()->invokeMethod(dock.findChild<QWidget*>("rebuildButton"), "click");
        QCOMPARE(rebuild.count(), 1);
    }
    void slidersBesideTheMainParameters() {
        ParameterDock dock;
        dock.showParameters(simcore::ParameterSet(SceneKind::Ring2d));
        ParameterForm* form = dock.form();
        // The main parameters have one, inside the table's range; the others only the field.
        for (const QString key : {"ks", "kd", "rks", "rkd", "pressure", "mass_inner", "gravity", "restitution", "friction"}) {
            QSlider* slider = form->slider(key);
            QVERIFY2(slider, qPrintable(key));
            const simcore::ParamSpec* spec = simcore::findParam(key.toStdString());
            const double lo = form->sliderValue(key, slider->minimum()), hi = form->sliderValue(key, slider->maximum());
            QVERIFY2(lo >= spec->minValue && hi <= spec->maxValue && lo < hi, qPrintable(key));
            QVERIFY2(!simcore::validateValue(*spec, lo) && !simcore::validateValue(*spec, hi), qPrintable(key));
            // Its range and unit are shown beside it and in its tooltip.
            QVERIFY2(slider->toolTip().contains(toQString(spec->unit)), qPrintable(slider->toolTip()));
            QVERIFY(slider->toolTip().contains(QString::fromStdString(spec->rangeText())));
            // It shows the value in use.
            QCOMPARE(slider->value(), form->sliderPosition(key, simcore::ParameterSet(SceneKind::Ring2d).get(spec->id)));
        }
        QVERIFY(!form->slider("seed"));
        QVERIFY(!form->slider("dt"));  // DT: the Run dock's field
        // Dragging it edits the parameter live, and the field follows; a slider on a log scale
        // covers the stiffness by factors.
        QSignalSpy edited(&dock, &ParameterDock::parameterEdited);
        QSlider* ks = form->slider("ks");
        ks->setValue(ks->maximum());
        QCOMPARE(edited.count(), 1);
        QCOMPARE(edited.at(0).at(0).value<simcore::Param>(), simcore::Param::Ks);
        QCOMPARE(edited.at(0).at(1).toDouble(), 1e5);
        QCOMPARE(form->field("ks")->text(), QString("100000"));
        ks->setValue(ks->maximum() / 2);
        QCOMPARE(edited.at(1).at(1).toDouble(), 1000.0);  // sqrt(10 * 1e5)
        // Typing a value moves the slider without a second edit.
        form->field("ks")->setText("316");
        emit form->field("ks")->editingFinished();
        QCOMPARE(edited.count(), 3);
        QCOMPARE(ks->value(), form->sliderPosition("ks", 316));
        // Showing the model's values does not echo as an edit.
        simcore::ParameterSet p(SceneKind::Ring2d);
        p.set(simcore::Param::Ks, 2000.0);
        dock.showParameters(p);
        QCOMPARE(edited.count(), 3);
        QCOMPARE(ks->value(), form->sliderPosition("ks", 2000));
    }

    void defaultButtonsAndResetAll() {
        ParameterDock dock;
        simcore::ParameterSet p(SceneKind::Ring2d);
        p.set(simcore::Param::Ks, 2000.0);
        p.set(simcore::Param::Gravity, 3.0);
        p.set(simcore::Param::Contact, 1.0);  // a choice
        p.set(simcore::Param::Dt, 0.001);
        dock.showParameters(p);
        ParameterForm* form = dock.form();
        QVERIFY(form->defaultButton("ks")->isEnabled());
        QVERIFY(!form->defaultButton("kd")->isEnabled());  // at its default already
        QVERIFY(form->defaultButton("contact")->isEnabled());
        QSignalSpy edited(&dock, &ParameterDock::parameterEdited);
        form->defaultButton("ks")->click();
        QCOMPARE(edited.count(), 1);
        QCOMPARE(edited.at(0).at(0).value<simcore::Param>(), simcore::Param::Ks);
        QCOMPARE(edited.at(0).at(1).toDouble(), 800.0);
        // Reset all: one edit for each value off the scene's default (DT too), none for the rest.
        p.set(simcore::Param::Ks, 800.0);
        dock.showParameters(p);
        edited.clear();
        dock.resetAllButton()->click();
        QMap<simcore::Param, double> got;
        for (const auto& args : edited) got[args.at(0).value<simcore::Param>()] = args.at(1).toDouble();
        const simcore::ParameterSet defaults(SceneKind::Ring2d);
        QCOMPARE(got.size(), 3);
        QCOMPARE(got.value(simcore::Param::Gravity), defaults.get(simcore::Param::Gravity));
        QCOMPARE(got.value(simcore::Param::Contact), defaults.get(simcore::Param::Contact));
        QCOMPARE(got.value(simcore::Param::Dt), defaults.get(simcore::Param::Dt));
    }

    void helpPageCoversEveryIntegratorAndLinksExist() {
        const QString html = HelpDialog::html();
        for (const simcore::IntegratorInfo& info : simcore::integratorTable()) {
            QVERIFY2(html.contains("<b>" + toQString(info.name) + "</b>"), std::string(info.name).c_str());
            QVERIFY(html.contains(toQString(info.description).toHtmlEscaped()));
        }
        for (const Preset& p : teachingPresets() + stabilityPresets()) QVERIFY(html.contains(p.title.toHtmlEscaped()));
        // Every link points at a file that exists (docs/gui.md, docs/architecture.md, README.md).
        int links = 0;
        for (qsizetype at = html.indexOf("href='"); at >= 0; at = html.indexOf("href='", at + 1)) {
            const qsizetype end = html.indexOf('\'', at + 6);
            const QString url = html.mid(at + 6, end - at - 6);
            QVERIFY2(QFileInfo::exists(QUrl(url).toLocalFile()), qPrintable(url));
            ++links;
        }
        QVERIFY(links >= 3);
        if (qEnvironmentVariableIsSet("ELASTIC_LAB_SHOT_DIR")) {
            HelpDialog d;
            d.resize(760, 900);
            d.grab().save(qEnvironmentVariable("ELASTIC_LAB_SHOT_DIR") + "/help.png");
        }
    }

    void presetsAreValid() {
        // Every preset's values pass the table for its scene, and its integrators exist.
        for (const Preset& p : teachingPresets() + stabilityPresets()) {
            const simcore::SceneInfo* scene = simcore::findScene(p.scene.toStdString());
            QVERIFY2(scene, qPrintable(p.id));
            simcore::ParameterSet params(scene->kind);
            for (const auto& [id, value] : p.values)
                QVERIFY2(!params.set(id, value), qPrintable(p.id + ": " + QString::fromUtf8(simcore::paramSpec(id).key.data())));
            QVERIFY(!p.integrators.isEmpty() && p.integrators.size() <= 3);
            for (const QString& name : p.integrators) QVERIFY(simcore::makeIntegrator(name.toStdString()) != nullptr);
            QCOMPARE(findPreset(p.id), findPreset(p.id));
            QVERIFY(findPreset(p.id) != nullptr);
        }
    }
};

QTEST_MAIN(TestGuiParams)
#include "test_gui_params.moc"
