#include "ui/scene_dock.h"

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

#include "simcore/scenes.h"
#include "ui/parameter_dock.h"

namespace elui {

SceneDock::SceneDock(QWidget* parent) : QDockWidget(tr("Scene"), parent) {
    setObjectName(QStringLiteral("SceneDock"));
    auto* host = new QWidget(this);
    auto* layout = new QVBoxLayout(host);
    layout->setContentsMargins(4, 4, 4, 4);
    m_scene = new QComboBox(host);
    m_scene->setObjectName(QStringLiteral("sceneCombo"));
    for (const simcore::SceneInfo& s : simcore::sceneTable())
        m_scene->addItem(toQString(s.name), int(s.kind));
    layout->addWidget(m_scene);
    m_description = new QLabel(host);
    m_description->setWordWrap(true);
    layout->addWidget(m_description);
    m_formHost = new QVBoxLayout;
    layout->addLayout(m_formHost);
    auto* rebuild = new QPushButton(tr("Rebuild body"), host);
    rebuild->setObjectName(QStringLiteral("rebuildButton"));
    rebuild->setToolTip(tr("Build the chosen scene with this shape and start again from rest"));
    layout->addWidget(rebuild);
    m_bodyValues = new QLabel(host);
    m_bodyValues->setObjectName(QStringLiteral("bodyValues"));
    m_bodyValues->setWordWrap(true);
    m_bodyValues->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_bodyValues->setToolTip(tr("What the parameters mean for the body that runs: under scaling=physical the "
                                "values hold at the scene's default resolution and a finer mesh keeps the "
                                "body's totals; under scaling=thesis they are per particle and per spring"));
    layout->addWidget(m_bodyValues);
    layout->addStretch(1);
    // Scrolls when the screen is short (a projector, presentation mode) instead of holding the
    // window taller than the screen; the Parameters dock beside it does the same.
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(host);
    setWidget(scroll);

    connect(m_scene, &QComboBox::currentIndexChanged, this, [this] {
        if (m_updating) return;
        rebuildForm(simcore::SceneKind(m_scene->currentData().toInt()));
    });
    connect(rebuild, &QPushButton::clicked, this, [this] { emit rebuildRequested(requestedShape()); });
    rebuildForm(simcore::SceneKind::Ring2d);
}

void SceneDock::rebuildForm(simcore::SceneKind kind) {
    delete m_form;
    m_form = new ParameterForm(kind, {simcore::ParamGroup::Shape}, widget());
    m_formHost->addWidget(m_form);
    connect(m_form, &ParameterForm::rejected, this, &SceneDock::shapeRejected);
    m_description->setText(toQString(simcore::sceneInfo(kind).description));
}

simcore::ParameterSet SceneDock::requestedShape() const { return m_form->values(); }

QString SceneDock::bodyValuesText() const { return m_bodyValues->text(); }

void SceneDock::showBodyValues(const QString& text) {
    m_bodyValues->setText(tr("This body uses: %1").arg(text));
}

void SceneDock::showParameters(const simcore::ParameterSet& params) {
    m_updating = true;
    const int index = m_scene->findData(int(params.kind()));
    if (index != m_scene->currentIndex()) m_scene->setCurrentIndex(index);
    m_updating = false;
    if (m_form->kind() != params.kind()) rebuildForm(params.kind());
    m_form->setValues(params);
}

}  // namespace elui
