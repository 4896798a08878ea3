#pragma once
// SceneDock: choose the scene and its shape (particles, subdivisions, slices/stacks, radii),
// then rebuild. The shape fields come from the parameter table's Shape group (with `scaling`,
// what the per-particle values mean when the mesh is refined); below them, what the built
// body actually uses per particle and per spring.

#include <QDockWidget>

#include "simcore/params.h"

class QComboBox;
class QLabel;
class QVBoxLayout;

namespace elui {

class ParameterForm;

class SceneDock : public QDockWidget {
    Q_OBJECT
public:
    explicit SceneDock(QWidget* parent = nullptr);
    // The scene and shape to build (shape keys from the form, nothing else set).
    simcore::ParameterSet requestedShape() const;
    QComboBox* sceneCombo() const { return m_scene; }
    QString bodyValuesText() const;

public slots:
    void showParameters(const simcore::ParameterSet& params);
    // The per-particle and per-spring values of the body that runs (simcore::bodyValuesText).
    void showBodyValues(const QString& text);

signals:
    void rebuildRequested(const simcore::ParameterSet& shape);
    void shapeRejected(const QString& key, const QString& message);

private:
    void rebuildForm(simcore::SceneKind kind);

    QComboBox* m_scene = nullptr;
    QLabel* m_description = nullptr;
    QVBoxLayout* m_formHost = nullptr;
    QLabel* m_bodyValues = nullptr;
    ParameterForm* m_form = nullptr;
    bool m_updating = false;
};

}  // namespace elui
