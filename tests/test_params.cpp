// The parameter table: defaults, ranges, per-scene keys, inheritance, parsing.
#include <QtTest>

#include <cmath>
#include <limits>

#include "simcore/params.h"
#include "simcore/scenes.h"

using namespace simcore;

class TestParams : public QObject {
    Q_OBJECT
private slots:
    void thesisDefaults() {
        // Thesis §7.2.1: KS 800, KD 15, RKS 700, RKD 50, MKS 150, MKD 25, PRESSURE 20, MASS 1, DT 0.003.
        ParameterSet p(SceneKind::Ring2d);
        QCOMPARE(p.get(simcore::Param::Ks), 800.0);
        QCOMPARE(p.get(simcore::Param::Kd), 15.0);
        QCOMPARE(p.get(simcore::Param::Rks), 700.0);
        QCOMPARE(p.get(simcore::Param::Rkd), 50.0);
        QCOMPARE(p.get(simcore::Param::Mks), 150.0);
        QCOMPARE(p.get(simcore::Param::Mkd), 25.0);
        QCOMPARE(p.get(simcore::Param::Pressure), 20.0);
        QCOMPARE(p.get(simcore::Param::Mass), 1.0);
        QCOMPARE(p.get(simcore::Param::Dt), 0.003);
        QCOMPARE(p.get(simcore::Param::Gravity), 9.81);
    }
    void everyRequiredKeyExists() {
        for (const char* key : {"ks", "kd", "rks", "rkd", "mks", "mkd", "pressure", "mass", "mass_inner",
                                "mass_outer", "gravity", "restitution", "box", "dt", "particles",
                                "subdivisions", "slices", "stacks", "radius_inner", "radius_outer",
                                "length", "initial_length", "fixed_end"})
            QVERIFY2(findParam(key) != nullptr, key);
    }
    void sceneKeysAreScoped() {
        // A 1D spring has no gas, no radius/shear springs and no layers.
        ParameterSet p(SceneKind::Spring1d);
        for (const char* key : {"pressure", "rks", "rkd", "mass_inner", "particles", "radius_inner"})
            QVERIFY2(p.set(key, 1.0).has_value(), key);
        QVERIFY(!p.set(simcore::Param::Ks, 10.0).has_value());
        ParameterSet ring(SceneKind::Ring2d);
        QVERIFY(ring.set(simcore::Param::Length, 1.0).has_value());
        QVERIFY(ring.set(simcore::Param::Subdivisions, 1.0).has_value());
        QVERIFY(!ring.set(simcore::Param::Particles, 20.0).has_value());
    }
    void layerValuesInheritUntilSet() {
        ParameterSet p(SceneKind::Sphere3d);
        QVERIFY(!p.set(simcore::Param::Mass, 2.0));
        QCOMPARE(p.get(simcore::Param::MassInner), 2.0);
        QCOMPARE(p.get(simcore::Param::MassOuter), 2.0);
        QVERIFY(!p.set(simcore::Param::MassInner, 100.0));
        QVERIFY(!p.set(simcore::Param::Mass, 3.0));
        QCOMPARE(p.get(simcore::Param::MassInner), 100.0);  // explicit wins whatever the order
        QCOMPARE(p.get(simcore::Param::MassOuter), 3.0);
        QVERIFY(!p.set(simcore::Param::Pressure, 50.0));
        QCOMPARE(p.get(simcore::Param::PressureInner), 50.0);
    }
    void refusesBadValues_data() {
        QTest::addColumn<QString>("assignment");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("zero mass") << "mass=0" << "mass";
        QTest::newRow("negative mass") << "mass=-1" << "mass";
        QTest::newRow("zero dt") << "dt=0" << "dt";
        QTest::newRow("nan") << "ks=nan" << "ks";
        QTest::newRow("inf") << "kd=inf" << "kd";
        QTest::newRow("restitution above 1") << "restitution=1.5" << "restitution";
        QTest::newRow("restitution below 0") << "restitution=-0.1" << "restitution";
        QTest::newRow("text") << "ks=abc" << "ks";
        QTest::newRow("trailing junk") << "ks=12x" << "ks";
        QTest::newRow("fractional count") << "particles=12.5" << "particles";
        QTest::newRow("too few particles") << "particles=2" << "particles";
        QTest::newRow("level too high") << "subdivisions=8" << "subdivisions";
        QTest::newRow("unknown key") << "stiffness=3" << "stiffness";
        QTest::newRow("no equals") << "ks" << "key=value";
    }
    void refusesBadValues() {
        QFETCH(QString, assignment);
        QFETCH(QString, mentions);
        const SceneKind kind = assignment.startsWith("subdivisions") ? SceneKind::Sphere3d : SceneKind::Ring2d;
        ParameterSet p(kind);
        const ParameterSet before = p;
        const auto error = p.assign(assignment.toStdString());
        QVERIFY2(error.has_value(), qPrintable(assignment));
        QVERIFY2(QString::fromStdString(*error).contains(mentions), error->c_str());
        QVERIFY(p == before);  // nothing applied
    }
    void messagesSayWhatIsAllowed() {
        ParameterSet p(SceneKind::Ring2d);
        const auto error = p.set(simcore::Param::Restitution, 2.0);
        QVERIFY(error);
        QVERIFY2(QString::fromStdString(*error).contains("[0, 1]"), error->c_str());
    }
    void parseNumberIsStrict() {
        QCOMPARE(parseNumber("1e-3").value(), 1e-3);
        QCOMPARE(parseNumber("-2.5").value(), -2.5);
        QVERIFY(!parseNumber(""));
        QVERIFY(!parseNumber(" 1"));
        QVERIFY(!parseNumber("1 "));
        QVERIFY(!parseNumber("nan"));
        QVERIFY(!parseNumber("inf"));
        QVERIFY(!parseNumber("1e999"));
    }
    void tableIsConsistent() {
        for (const ParamSpec& spec : parameterTable()) {
            QVERIFY2(!spec.meaning.empty(), spec.key.data());
            QVERIFY2(spec.scenes != 0, spec.key.data());
            for (const SceneInfo& scene : sceneTable())
                if (spec.scenes & sceneBit(scene.kind))
                    QVERIFY2(!validateValue(spec, spec.defaultFor(scene.kind)), spec.key.data());
        }
    }
};

QTEST_GUILESS_MAIN(TestParams)
#include "test_params.moc"
