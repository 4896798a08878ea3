// The parameter and scene docks against simcore's parameter table: every key, unit, range and
// default; edits validated by the same table; values round-trip.
#include <QComboBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>

#include <QFileInfo>
#include <QUrl>

#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "simcore/scenes.h"
#include "ui/help_dialog.h"
#include "ui/parameter_dock.h"
#include "ui/presets.h"
#include "ui/scene_dock.h"

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
