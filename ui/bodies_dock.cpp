#include "ui/bodies_dock.h"

#include <cmath>
#include <limits>

#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include "qcustomplot.h"
#include "simcore/scenes.h"
#include "simlab/output.h"
#include "ui/language.h"
#include "ui/parameter_dock.h"
#include "ui/plot_series.h"
#include "ui/plot_ticks.h"

namespace elui {

namespace {

const char* const kPlotIds[] = {"momentum", "gap", "volume", "pressure"};

// The level key of a body kind: what "finer" means for it.
simcore::Param levelParam(simcore::SceneKind kind) {
    switch (kind) {
        case simcore::SceneKind::Ring2d: return simcore::Param::Particles;
        case simcore::SceneKind::Sphere3dLatLong: return simcore::Param::Slices;
        default: return simcore::Param::Subdivisions;
    }
}

// In the window's language (a decimal comma in German, French and Spanish), as every dock.
QString number(double v) { return num(v, 'g', 5); }

}  // namespace

BodiesDock::BodiesDock(QWidget* parent) : QDockWidget(tr("Bodies"), parent) {
    setObjectName(QStringLiteral("BodiesDock"));
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setAccessibleName(tr("Bodies"));
    scroll->setAccessibleDescription(tr("The bodies of the scene, total momentum and the smallest gap, with their "
                                        "curves against simulated time"));
    auto* host = new QWidget(scroll);
    auto* layout = new QVBoxLayout(host);
    layout->setContentsMargins(4, 4, 4, 4);
    m_note = new QLabel(tr("This dock is for scenes of several bodies: Presets > Several bodies, or a scene file of "
                           "several bodies."),
                        host);
    m_note->setWordWrap(true);
    layout->addWidget(m_note);
    m_content = new QWidget(host);
    auto* content = new QVBoxLayout(m_content);
    content->setContentsMargins(0, 0, 0, 0);
    m_readout = new QLabel(m_content);
    m_readout->setObjectName(QStringLiteral("bodiesReadout"));
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_readout->setWordWrap(true);
    content->addWidget(m_readout);
    m_table = new QTableWidget(0, 6, m_content);
    m_table->setObjectName(QStringLiteral("bodiesTable"));
    m_table->setHorizontalHeaderLabels({tr("body"), tr("mass [kg]"), tr("centre [m]"), tr("velocity [m/s]"),
                                        tr("volume in/out"), tr("pressure in/out")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->setMinimumHeight(90);
    content->addWidget(m_table);

    createPlots(host);
    content->addWidget(createAddBox());

    layout->addWidget(m_content);
    for (QCustomPlot* p : m_plots) layout->addWidget(p);
    layout->addStretch(1);
    m_content->hide();
    scroll->setWidget(host);
    setWidget(scroll);
    // The points a hidden dock took (a run before it was shown, or behind the Plots tab) are
    // put in view when it is shown: before, its plots kept their empty axes until the next
    // frame, and a screenshot after a run showed none of its curves.
    connect(this, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible) refreshPlots();
    });
}

void BodiesDock::createPlots(QWidget* host) {
    const QString titles[] = {tr("Total momentum"), tr("min_gap"), tr("Volume per body and layer"),
                              tr("Pressure per body and layer")};
    // Short axis labels: the title says what is plotted, and a long label ("quantité de
    // mouvement [kg m/s]") did not fit the plot's height.
    const QString labels[] = {tr("p [kg m/s]"), tr("gap [m]"), tr("volume"), tr("pressure")};
    // The plots directly in the scrolled widget (as the Plots dock's), shown with the content.
    for (int k = 0; k < 4; ++k) {
        auto* p = new QCustomPlot(host);
        p->setObjectName(QStringLiteral("bodies_") + QLatin1String(kPlotIds[k]));
        p->setMinimumHeight(130);
        p->plotLayout()->insertRow(0);
        p->plotLayout()->addElement(0, 0, new QCPTextElement(p, titles[k], QFont(font().family(), font().pointSize(), QFont::Bold)));
        p->xAxis->setLabel(tr("t [s]"));
        p->yAxis->setLabel(labels[k]);
        p->legend->setVisible(k != 1);
        p->legend->setFont(QFont(font().family(), font().pointSize() - 1));
        keepTickLabelsApart(p->xAxis);
        keepTickLabelsApart(p->yAxis);
        p->hide();
        m_plots.push_back(p);
    }
}

QWidget* BodiesDock::createAddBox() {
    // Add a body: kind, level, where and how fast.
    auto* addBox = new QWidget(m_content);
    auto* grid = new QGridLayout(addBox);
    grid->setContentsMargins(0, 4, 0, 0);
    m_kind = new QComboBox(addBox);
    m_kind->setObjectName(QStringLiteral("addBodyKind"));
    m_level = new QSpinBox(addBox);
    m_level->setObjectName(QStringLiteral("addBodyLevel"));
    m_level->setToolTip(tr("ring2d: particles per layer; sphere3d: subdivisions; sphere3d-latlong: slices"));
    grid->addWidget(new QLabel(tr("kind, level"), addBox), 0, 0);
    grid->addWidget(m_kind, 0, 1, 1, 2);
    grid->addWidget(m_level, 0, 3);
    const QString names[] = {QStringLiteral("position_x"), QStringLiteral("position_y"), QStringLiteral("position_z"),
                             QStringLiteral("velocity_x"), QStringLiteral("velocity_y"), QStringLiteral("velocity_z")};
    for (int k = 0; k < 6; ++k) {
        auto* edit = new QLineEdit(QStringLiteral("0"), addBox);
        edit->setObjectName(QStringLiteral("addBody_") + names[k]);
        edit->setToolTip(names[k] + (k < 3 ? QStringLiteral(" [m]") : QStringLiteral(" [m/s]")));
        m_start.push_back(edit);
        if (k % 3 == 0) grid->addWidget(new QLabel(k < 3 ? tr("where [m]") : tr("how fast [m/s]"), addBox), 1 + k / 3, 0);
        grid->addWidget(edit, 1 + k / 3, 1 + k % 3);
    }
    m_add = new QPushButton(tr("Add body"), addBox);
    m_add->setObjectName(QStringLiteral("addBody"));
    m_remove = new QPushButton(tr("Remove selected"), addBox);
    m_remove->setObjectName(QStringLiteral("removeBody"));
    // The buttons in a row of their own under the fields, not beside the labels' column: in
    // French the labels and the two buttons side by side needed 378 px, wider than the dock's
    // 334 px beside two views at 1280 px (the content was cut at the window's edge).
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_add);
    buttons->addWidget(m_remove);
    grid->addLayout(buttons, 3, 0, 1, 4);
    connect(m_add, &QPushButton::clicked, this, &BodiesDock::addBody);
    connect(m_remove, &QPushButton::clicked, this, &BodiesDock::removeBody);
    connect(m_kind, &QComboBox::currentIndexChanged, this, [this] {
        const auto kind = simcore::SceneKind(m_kind->currentData().toInt());
        const simcore::ParamSpec& level = simcore::paramSpec(levelParam(kind));
        m_level->setRange(int(level.minValue), int(std::min(level.maxValue, 64.0)));
        m_level->setValue(int(level.defaultFor(kind)));
    });
    return addBox;
}

QLineEdit* BodiesDock::addField(const QString& name) const {
    for (QLineEdit* e : m_start)
        if (e->objectName() == QStringLiteral("addBody_") + name) return e;
    return nullptr;
}

QCustomPlot* BodiesDock::plot(const QString& id) const {
    for (std::size_t k = 0; k < m_plots.size(); ++k)
        if (id == QLatin1String(kPlotIds[k])) return m_plots[k];
    return nullptr;
}

void BodiesDock::clearPlots() {
    for (QCustomPlot* p : m_plots)
        for (int g = 0; g < p->graphCount(); ++g) p->graph(g)->data()->clear();
    m_lastTime = -1.0;
}

void BodiesDock::rebuildSeries(const simcore::WorldSpec& spec) {
    for (QCustomPlot* p : m_plots) p->clearGraphs();
    const QString axes[] = {QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("z")};
    for (int a = 0; a < m_dimension; ++a) {
        QCPGraph* g = plot(QStringLiteral("momentum"))->addGraph();
        g->setName(QStringLiteral("p_") + axes[a]);
        g->setPen(QPen(QColor::fromHsv(a * 110, 200, 180), 1.6));
    }
    QCPGraph* gap = plot(QStringLiteral("gap"))->addGraph();
    gap->setName(QStringLiteral("min_gap"));
    gap->setPen(QPen(QColor(40, 40, 40), 1.6));
    for (std::size_t k = 0; k < spec.bodies.size(); ++k)
        for (const QString& id : {QStringLiteral("volume"), QStringLiteral("pressure")})
            for (int layer = 0; layer < 2; ++layer) {
                QCPGraph* g = plot(id)->addGraph();
                g->setName(QStringLiteral("body%1 %2").arg(k + 1).arg(layer == 0 ? tr("inner") : tr("outer")));
                g->setPen(QPen(bodyColor(int(k)), 1.6, layer == 0 ? Qt::DashLine : Qt::SolidLine));
            }
    for (QCustomPlot* p : m_plots) p->replot();
    m_lastTime = -1.0;
}

void BodiesDock::showFrame(const Frame& frame) {
    const bool world = frame.world && frame.scene && frame.scene->isWorld();
    m_note->setVisible(!world);
    m_content->setVisible(world);
    for (QCustomPlot* p : m_plots) p->setVisible(world);
    if (!world) {
        m_spec.reset();
        m_scene.reset();
        return;
    }
    const simcore::WorldDiagnostics& d = *frame.world;
    if (m_kind->count() == 0 || frame.scene != m_scene) {
        m_dimension = frame.scene->topology.dimension;
        m_kind->blockSignals(true);
        m_kind->clear();
        for (const simcore::SceneInfo& s : simcore::sceneTable()) {
            const int dim = s.kind == simcore::SceneKind::Ring2d ? 2 : s.kind == simcore::SceneKind::Spring1d ? 1 : 3;
            if (dim == m_dimension) m_kind->addItem(toQString(s.name), int(s.kind));
        }
        m_kind->blockSignals(false);
        emit m_kind->currentIndexChanged(0);
        m_start[2]->setEnabled(m_dimension == 3);
        m_start[5]->setEnabled(m_dimension == 3);
    }
    // New series with a new scene (bodies added or removed, a new world); a live edit or a
    // scrubbed moment before it changes the spec only, and the curves go on.
    m_spec = frame.worldSpec;
    if (frame.scene != m_scene) {
        m_scene = frame.scene;
        rebuildSeries(*m_spec);
    }
    // Back in time. A moment scrubbed on the timeline: the curves stay (the run is still all
    // there). Running on from an earlier time (a branch, a reset): the curves end there.
    const bool scrubbed = frame.timeline.moment < frame.timeline.last;
    if (d.time < m_lastTime && !scrubbed) {
        for (QCustomPlot* p : m_plots)
            for (int g = 0; g < p->graphCount(); ++g) p->graph(g)->data()->removeAfter(d.time);
        m_lastTime = d.time;
    }
    showNumbers(d);
    addPoints(d);
}

// A vector as (x, y) in 2D, (x, y, z) in 3D, in the window's language.
QString BodiesDock::vector(const Eigen::Vector3d& v) const {
    return m_dimension == 2 ? QStringLiteral("(%1, %2)").arg(number(v.x()), number(v.y()))
                            : QStringLiteral("(%1, %2, %3)").arg(number(v.x()), number(v.y()), number(v.z()));
}

// The readout (momentum, angular momentum, min_gap and its pair, contact) and the list of bodies.
void BodiesDock::showNumbers(const simcore::WorldDiagnostics& d) {
    // The readout.
    const auto vec = [this](const Eigen::Vector3d& v) { return vector(v); };
    QString gapText = number(d.minGap) + QStringLiteral(" m");
    if (d.minGapBodies[0] >= 0)
        gapText += d.minGapBodies[0] == d.minGapBodies[1]
                       ? tr(" (body%1 with itself)").arg(d.minGapBodies[0] + 1)
                       : tr(" (body%1 and body%2)").arg(d.minGapBodies[0] + 1).arg(d.minGapBodies[1] + 1);
    else
        gapText = tr("beyond %1 m (nothing that close)").arg(number(d.minGap));
    m_readout->setText(tr("<b>momentum</b> %1 kg m/s<br><b>angular momentum</b> %2 kg m²/s<br><b>min_gap</b> %3<br>"
                          "<b>contact between bodies</b> %4 J, %5 pairs in the skin")
                           .arg(vec(d.momentum), vec(d.angularMomentum), gapText, number(d.contactPairs))
                           .arg(d.contactPairsActive));
    // The list.
    m_table->setRowCount(int(d.bodies.size()));
    for (std::size_t k = 0; k < d.bodies.size(); ++k) {
        const simcore::BodyDiagnostics& b = d.bodies[k];
        const QString kind = toQString(simcore::sceneInfo(m_spec->bodies[k].params.kind()).name);
        const QStringList cells = {QStringLiteral("body%1 %2").arg(k + 1).arg(kind), number(b.mass), vec(b.com),
                                   vec(b.velocity), number(b.volume[0]) + QStringLiteral(" / ") + number(b.volume[1]),
                                   number(b.pressure[0]) + QStringLiteral(" / ") + number(b.pressure[1])};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = m_table->item(int(k), c);
            if (!item) m_table->setItem(int(k), c, item = new QTableWidgetItem);
            item->setText(cells[c]);
            if (c == 0) item->setForeground(bodyColor(int(k)));
        }
    }
}

// The curves: one point per frame whose time moved on.
void BodiesDock::addPoints(const simcore::WorldDiagnostics& d) {
    if (d.time > m_lastTime) {
        m_lastTime = d.time;
        QCustomPlot* momentum = plot(QStringLiteral("momentum"));
        for (int a = 0; a < momentum->graphCount(); ++a) momentum->graph(a)->addData(d.time, d.momentum[a]);
        plot(QStringLiteral("gap"))->graph(0)->addData(d.time, d.minGap);
        for (std::size_t k = 0; k < d.bodies.size(); ++k)
            for (int layer = 0; layer < 2; ++layer) {
                plot(QStringLiteral("volume"))->graph(int(2 * k) + layer)->addData(d.time, d.bodies[k].volume[std::size_t(layer)]);
                plot(QStringLiteral("pressure"))->graph(int(2 * k) + layer)->addData(d.time, d.bodies[k].pressure[std::size_t(layer)]);
            }
        if (isVisible()) refreshPlots();
    }
}

void BodiesDock::refreshPlots() {
    for (QCustomPlot* p : m_plots) {
        p->rescaleAxes();
        p->replot(QCustomPlot::rpQueuedReplot);
    }
}

double BodiesDock::shownTimeEnd(const QString& plotId) const { return plot(plotId)->xAxis->range().upper; }

QString BodiesDock::readoutText() const { return m_readout->text(); }

int BodiesDock::plottedPoints() const {
    QCustomPlot* p = plot(QStringLiteral("momentum"));
    return p->graphCount() ? p->graph(0)->dataCount() : 0;
}

QStringList BodiesDock::seriesNames(const QString& plotId) const {
    QStringList names;
    if (QCustomPlot* p = plot(plotId))
        for (int g = 0; g < p->graphCount(); ++g) names << p->graph(g)->name();
    return names;
}

double BodiesDock::lastValue(const QString& plotId, int series) const {
    QCustomPlot* p = plot(plotId);
    if (!p || series >= p->graphCount() || p->graph(series)->dataCount() == 0)
        return std::numeric_limits<double>::quiet_NaN();
    return (p->graph(series)->data()->constEnd() - 1)->value;
}

void BodiesDock::addBody() {
    if (!m_spec) return;
    simcore::WorldSpec spec = *m_spec;
    simcore::WorldBodySpec body;
    const auto kind = simcore::SceneKind(m_kind->currentData().toInt());
    body.params = simcore::ParameterSet(kind);
    // The world's values (gravity, box, dt, contact ...) are every body's.
    for (const simcore::ParamSpec* p : simcore::parametersFor(kind))
        if (simcore::isWorldParameter(p->id) && spec.bodies.front().params.has(p->id))
            (void)body.params.set(p->id, spec.bodies.front().params.get(p->id));
    if (auto error = body.params.set(levelParam(kind), m_level->value())) {
        emit message(QString::fromStdString(*error));
        return;
    }
    for (int k = 0; k < 6; ++k) {
        bool ok = false;
        const double v = toCNumber(m_start[std::size_t(k)]->text()).toDouble(&ok);  // "0,5" in German as "0.5"
        if (!ok || !std::isfinite(v)) {
            emit message(tr("%1: not a number").arg(m_start[std::size_t(k)]->toolTip()));
            return;
        }
        (k < 3 ? body.position : body.velocity)[k % 3] = v;
    }
    spec.bodies.push_back(std::move(body));
    if (auto error = simcore::validateWorld(spec)) {
        emit message(QString::fromStdString(*error));
        return;
    }
    emit worldRequested(spec);
}

void BodiesDock::removeBody() {
    if (!m_spec) return;
    const int row = m_table->currentRow();
    if (row < 0 || row >= int(m_spec->bodies.size())) {
        emit message(tr("Choose a body in the list first."));
        return;
    }
    if (m_spec->bodies.size() == 1) {
        emit message(tr("A world keeps at least one body."));
        return;
    }
    simcore::WorldSpec spec = *m_spec;
    spec.bodies.erase(spec.bodies.begin() + row);
    emit worldRequested(spec);
}

}  // namespace elui
