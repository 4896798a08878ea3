#include "ui/studies_dialog.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include "qcustomplot.h"
#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "simcore/scenes.h"
#include "simlab/output.h"
#include "simlab/refinement.h"
#include "simlab/request.h"
#include "ui/export.h"
#include "ui/language.h"
#include "ui/mailbox.h"
#include "ui/parameter_dock.h"
#include "ui/plot_series.h"
#include "ui/plot_ticks.h"

namespace elui {

namespace {
// The study diagrams' colour (a shade of the integrator's family, simlab/study.h): the same in
// the dialogs, the CLI's SVG and the Python example.
QColor integratorColor(const QString& name) { return QColor(QString::fromLatin1(simlab::studyColour(name.toStdString()))); }

QString number(double v) { return QString::number(v, 'g', 4); }

void setupLogAxis(QCPAxis* axis, const QString& label) {
    setLogTicks(axis);
    axis->setLabel(label);
}

// Two log-log panels side by side, the legend inside the right one.
std::pair<QCPAxisRect*, QCPAxisRect*> twoLogPanels(QCustomPlot* plot, const QString& leftX, const QString& leftY,
                                                   const QString& rightX, const QString& rightY) {
    plot->plotLayout()->clear();
    auto* left = new QCPAxisRect(plot);
    auto* right = new QCPAxisRect(plot);
    plot->plotLayout()->addElement(0, 0, left);
    plot->plotLayout()->addElement(0, 1, right);
    setupLogAxis(left->axis(QCPAxis::atBottom), leftX);
    setupLogAxis(left->axis(QCPAxis::atLeft), leftY);
    setupLogAxis(right->axis(QCPAxis::atBottom), rightX);
    setupLogAxis(right->axis(QCPAxis::atLeft), rightY);
    plot->legend = new QCPLegend;
    right->insetLayout()->addElement(plot->legend, Qt::AlignBottom | Qt::AlignRight);
    plot->legend->setLayer(QStringLiteral("legend"));
    plot->legend->setVisible(true);
    return {left, right};
}

// Each panel's axes fitted to its graphs, with a factor 2 of room on every side.
void rescaleLogPanels(QCustomPlot* plot) {
    for (QCPAxisRect* rect : plot->axisRects()) {
        bool any = false;
        for (QCPGraph* graph : rect->graphs()) {
            graph->rescaleAxes(any);
            any = true;
        }
        for (QCPAxis* axis : {rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft)})
            axis->setRange(axis->range().lower / 2, axis->range().upper * 2);
    }
    plot->replot();
}

}  // namespace

StudyDialogBase::StudyDialogBase(const QString& title, const simcore::ParameterSet& params, QWidget* parent,
                                 std::optional<simcore::WorldSpec> world)
    : QDialog(parent), m_params(params), m_world(std::move(world)) {
    setWindowTitle(title);
    resize(1000, 720);
    auto* layout = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    layout->addWidget(makeSceneLabel());
    auto* integrators = new QWidget(this);
    auto* grid = new QGridLayout(integrators);
    grid->setContentsMargins(0, 0, 0, 0);
    int i = 0;
    for (const simcore::IntegratorInfo& info : simcore::integratorTable()) {
        auto* box = new QCheckBox(toQString(info.name), integrators);
        const QString name = toQString(info.name);
        box->setChecked(name == "euler" || name == "midpoint" || name == "rk4" || name == "verlet");
        box->setToolTip(tr("Include %1 (order %2) in the study: %3")
                            .arg(name)
                            .arg(info.order)
                            .arg(simcoreText(info.description)));
        grid->addWidget(box, i / 4, i % 4);
        m_integrators.push_back(box);
        ++i;
    }
    top->addWidget(integrators, 2);
    m_options = new QWidget(this);
    new QFormLayout(m_options);
    m_options->layout()->setContentsMargins(0, 0, 0, 0);
    top->addWidget(m_options, 1);
    layout->addLayout(top);

    auto* controls = new QHBoxLayout;
    m_run = new QPushButton(tr("Run"), this);
    m_run->setToolTip(tr("Run the study on a worker thread; the window stays usable"));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setToolTip(tr("Stop the study; the rows finished so far stay"));
    m_cancel->setEnabled(false);
    m_export = new QPushButton(tr("Export..."), this);
    m_export->setToolTip(tr("Write the table as CSV, or the plot as SVG, PNG or PDF"));
    m_export->setEnabled(false);
    m_progress = new QProgressBar(this);
    m_status = new QLabel(this);
    controls->addWidget(m_run);
    controls->addWidget(m_cancel);
    controls->addWidget(m_progress, 1);
    controls->addWidget(m_status, 1);
    controls->addWidget(m_export);
    layout->addLayout(controls);

    auto* split = new QSplitter(Qt::Vertical, this);
    m_plot = new QCustomPlot(split);
    m_plot->setAccessibleName(tr("Study plot"));
    m_plot->setAccessibleDescription(tr("The study's results drawn; the same numbers are in the table"));
    m_plot->setMinimumHeight(260);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_table = new QTableWidget(split);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setAccessibleName(tr("Results"));
    m_table->setAccessibleDescription(tr("One row per run of the study; the arrow keys move between the cells"));
    split->addWidget(m_plot);
    split->addWidget(m_table);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    layout->addWidget(split, 1);
    m_summary = new QLabel(this);
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);

    connect(m_run, &QPushButton::clicked, this, &StudyDialogBase::start);
    connect(m_cancel, &QPushButton::clicked, this, &StudyDialogBase::cancel);
    connect(m_export, &QPushButton::clicked, this, &StudyDialogBase::exportResults);
    m_fromWorker = new Mailbox(this);
}

StudyDialogBase::~StudyDialogBase() { stopAndWait(); }

void StudyDialogBase::computationEnded() {
    // The worker's last message: it has returned from compute() and touches nothing more.
    if (m_worker.joinable()) m_worker.join();
    m_busy = false;
    m_run->setEnabled(true);
    m_cancel->setEnabled(false);
    const bool cancelled = m_cancelFlag && m_cancelFlag->load();
    m_status->setText(cancelled ? tr("Cancelled: partial results") : tr("Done"));
    present();
    m_export->setEnabled(true);
    emit finished();
}

void StudyDialogBase::stopAndWait() {
    // Never leave a computation running against a destroyed dialog. Its last messages stay
    // in the mailbox, which is deleted with the dialog without running them.
    if (m_cancelFlag) m_cancelFlag->store(true);
    if (m_worker.joinable()) m_worker.join();
}

void StudyDialogBase::fillTable(const QStringList& headers, const QList<QStringList>& cells) {
    m_table->clear();
    m_table->setColumnCount(int(headers.size()));
    m_table->setHorizontalHeaderLabels(headers);
    m_table->setRowCount(int(cells.size()));
    for (int r = 0; r < int(cells.size()); ++r)
        for (int c = 0; c < int(cells[r].size()); ++c) m_table->setItem(r, c, new QTableWidgetItem(cells[r][c]));
    m_table->resizeColumnsToContents();
}

void StudyDialogBase::setChosenIntegrators(const QStringList& names) {
    for (QCheckBox* box : m_integrators) box->setChecked(names.contains(box->text()));
}

QStringList StudyDialogBase::chosenIntegrators() const {
    QStringList out;
    for (QCheckBox* box : m_integrators)
        if (box->isChecked()) out << box->text();
    return out;
}

void StudyDialogBase::setProgress(int done, int total, const QString& what) {
    m_fromWorker->post([this, done, total, what] {
        m_progress->setMaximum(std::max(1, total));
        m_progress->setValue(done);
        m_status->setText(what);
    });
}

void StudyDialogBase::start() {
    if (m_busy) return;
    if (chosenIntegrators().isEmpty()) {
        m_status->setText(tr("Choose at least one integrator"));
        return;
    }
    if (const QString problem = validate(); !problem.isEmpty()) {
        m_status->setText(problem);
        return;
    }
    m_busy = true;
    m_run->setEnabled(false);
    m_cancel->setEnabled(true);
    m_export->setEnabled(false);
    m_progress->setValue(0);
    m_cancelFlag = std::make_shared<std::atomic<bool>>(false);
    auto flag = m_cancelFlag;
    prepare();
    if (m_worker.joinable()) m_worker.join();  // the last run ended (its end was delivered)
    m_worker = std::thread([this, flag] {
        compute(flag.get());
        m_fromWorker->post([this] { computationEnded(); });
    });
}

void StudyDialogBase::cancel() {
    if (m_cancelFlag) m_cancelFlag->store(true);
    m_status->setText(tr("Cancelling..."));
}

void StudyDialogBase::exportResults() {
    const QString svgText = svg();
    const QString filter = svgText.isEmpty() ? tr("CSV table (*.csv);;PNG plot (*.png);;PDF plot (*.pdf)")
                                             : tr("CSV table (*.csv);;SVG plot (*.svg);;PNG plot (*.png);;PDF plot (*.pdf)");
    const QString path = QFileDialog::getSaveFileName(this, tr("Export results"), QStringLiteral("study.csv"), filter);
    if (path.isEmpty()) return;
    QString error;
    if (path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive)) error = writeFile(path, csv().toUtf8());
    else if (path.endsWith(QLatin1String(".svg"), Qt::CaseInsensitive)) error = writeFile(path, svgText.toUtf8());
    else if (path.endsWith(QLatin1String(".pdf"), Qt::CaseInsensitive)) error = writePlots(path, {m_plot}, {PlotSpec{"study", windowTitle(), {}, {}}});
    else error = writeImage(path, m_plot->toPixmap(1000, 600).toImage());
    if (!error.isEmpty()) QMessageBox::warning(this, tr("Export"), error);
    else m_status->setText(tr("Wrote %1").arg(path));
}

// ---------------------------------------------------------------- work-precision

QLabel* StudyDialogBase::makeSceneLabel() {
    auto* scene = new QLabel(m_world ? tr("Scene: <b>%1</b>, %2 bodies, with the current parameters (the whole world: "
                                          "every run moves every body)")
                                           .arg(QString::fromStdString(m_world->name).toHtmlEscaped())
                                           .arg(m_world->bodies.size())
                                     : tr("Scene: <b>%1</b> with the current parameters")
                                           .arg(toQString(simcore::sceneInfo(m_params.kind()).name)),
                             this);
    scene->setObjectName(QStringLiteral("studyScene"));
    scene->setWordWrap(true);
    return scene;
}

std::string StudyDialogBase::sceneName() const {
    return m_world ? m_world->name : std::string(simcore::sceneInfo(m_params.kind()).name);
}

WorkPrecisionDialog::WorkPrecisionDialog(const simcore::ParameterSet& params, QWidget* parent,
                                         std::optional<simcore::WorldSpec> world)
    : StudyDialogBase(tr("Work-precision study"), params, parent, std::move(world)) {
    auto* form = static_cast<QFormLayout*>(m_options->layout());
    m_dts = new QLineEdit(QStringLiteral("0.01 0.005 0.0025 0.00125"), m_options);
    m_dts->setToolTip(tr("Fixed steps DT [s], separated by spaces; T must be a multiple of each"));
    m_duration = new QLineEdit(QStringLiteral("1"), m_options);
    m_duration->setToolTip(tr("Simulated time of every run [s]"));
    m_reference = new QComboBox(m_options);
    m_reference->addItems({"auto", "exact", "rk4", "rk45"});
    m_reference->setToolTip(tr("What the errors are measured against: the closed form where there is one (exact), "
                               "or a run of rk4 or rk45 with a much smaller step; auto chooses"));
    m_reference->setAccessibleName(tr("Reference"));
    m_repeats = new QSpinBox(m_options);
    m_repeats->setRange(1, 100);
    m_repeats->setValue(3);
    m_repeats->setToolTip(tr("Each point is timed this many times; the plot shows the median run time with a band "
                             "from the first to the third quartile (the same binary runs at two speeds on a shared "
                             "machine)"));
    m_budget = new QLineEdit(m_options);
    m_budget->setPlaceholderText(tr("none"));
    m_budget->setToolTip(tr("A run that takes longer [s] is recorded as not reached (no error), and so is every "
                            "costlier point of its integrator: the curve stops there"));
    form->addRow(tr("DT values [s]"), m_dts);
    form->addRow(tr("Duration T [s]"), m_duration);
    form->addRow(tr("Reference"), m_reference);
    form->addRow(tr("Timed runs per point"), m_repeats);
    form->addRow(tr("Time budget per run [s]"), m_budget);
    m_cost = new QComboBox(m_options);
    m_cost->setObjectName(QStringLiteral("costAxis"));
    m_cost->addItem(tr("force evaluations"), int(Cost::ForceEvaluations));
    m_cost->addItem(tr("run time (median, band q1–q3)"), int(Cost::WallTime));
    m_cost->setToolTip(tr("The cost of a run on the left panel: the force evaluations it took (a count: the same on "
                          "every machine and every run), or its run time, the median over the timed runs with a band "
                          "from q1 to q3 (on a busy machine a curve can zigzag backwards)"));
    form->addRow(tr("Cost axis"), m_cost);
    twoLogPanels(m_plot, tr("force evaluations"), tr("max position error [m]"), tr("DT [s]"), tr("max position error [m]"));
    connect(m_cost, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_result.rows.empty()) {
            plotResult();
        } else {
            m_plot->axisRect(0)->axis(QCPAxis::atBottom)->setLabel(cost() == Cost::WallTime
                                                                      ? tr("run time [s] (median, band q1–q3)")
                                                                      : tr("force evaluations"));
            m_plot->replot();
        }
    });
}

void WorkPrecisionDialog::setCost(Cost cost) { m_cost->setCurrentIndex(m_cost->findData(int(cost))); }
WorkPrecisionDialog::Cost WorkPrecisionDialog::cost() const { return Cost(m_cost->currentData().toInt()); }

void WorkPrecisionDialog::setSteps(const QString& dts) { m_dts->setText(dts); }
void WorkPrecisionDialog::setDuration(double seconds) { m_duration->setText(QString::number(seconds)); }
void WorkPrecisionDialog::setRepeats(int repeats) { m_repeats->setValue(repeats); }
void WorkPrecisionDialog::setTimeBudget(const QString& seconds) { m_budget->setText(seconds); }

simlab::StudySpec WorkPrecisionDialog::spec() const {
    simlab::StudySpec s;
    s.params = m_params;
    s.world = m_world;
    for (const QString& name : chosenIntegrators()) s.integrators.push_back(name.toStdString());
    for (const QString& t : m_dts->text().split(QLatin1Char(' '), Qt::SkipEmptyParts)) s.dts.push_back(t.toDouble());
    s.duration = m_duration->text().toDouble();
    s.reference = m_reference->currentText().toStdString();
    s.repeat = m_repeats->value();
    s.timeBudget = m_budget->text().trimmed().isEmpty() ? 0.0 : m_budget->text().toDouble();
    return s;
}

QString WorkPrecisionDialog::validate() const {
    try {
        simlab::checkStudy(spec());  // the front door: the CLI's and Python's checks and bounds
    } catch (const simlab::RequestError& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

void WorkPrecisionDialog::prepare() { m_spec = spec(); }

void WorkPrecisionDialog::compute(const std::atomic<bool>* cancel) {
    m_result = simlab::runStudy(
        m_spec, [this](const simlab::StudyProgress& p) { setProgress(p.done, p.total, QString::fromStdString(p.what)); },
        cancel);
}

void WorkPrecisionDialog::present() {
    const auto& rows = m_result.rows;
    const QStringList headers = {tr("integrator"),      tr("family"),          tr("DT [s]"),
                                 tr("steps"),           tr("force evals"),     tr("run time q1 [s]"),
                                 tr("median [s]"),      tr("q3 [s]"),          tr("error at T [m]"),
                                 tr("max error [m]"),   tr("RMS error [m]"),   tr("energy error [J]"),
                                 tr("status")};
    QList<QStringList> cells;
    for (const simlab::StudyRow& row : rows) {
        const bool timed = !row.walls.empty();
        cells.append({QString::fromStdString(row.item.integrator),
                      QString::fromStdString(std::string(simcore::integratorFamily(row.item.integrator))),
                      number(row.dt), QString::number(row.steps), QString::number(row.forceEvaluations),
                      timed ? number(row.wallQ1) : QString(), timed ? number(row.wallSeconds) : QString(),
                      timed ? number(row.wallQ3) : QString(), row.ok ? number(row.errorFinal) : QString(),
                      row.ok ? number(row.errorMax) : QString(), row.ok ? number(row.errorRms) : QString(),
                      row.ok ? number(row.errorEnergy) : QString(), QString::fromStdString(row.status())});
    }
    fillTable(headers, cells);
    plotResult();

    QString summary = tr("Reference: %1 (its own error about %2 m). Run time: median of %3 timed runs per point, "
                         "band q1–q3.")
                          .arg(QString::fromStdString(m_result.reference.description))
                          .arg(number(m_result.reference.estimatedError))
                          .arg(m_spec.repeat);
    for (const simlab::OrderFit& fit : simlab::fitOrders(rows, m_result.reference.estimatedError))
        if (fit.points >= 2)
            summary += tr(" %1: order %2 (RMS %3).")
                           .arg(QString::fromStdString(fit.integrator))
                           .arg(num(fit.order, 'f', 2))
                           .arg(num(fit.orderRms, 'f', 2));
    m_summary->setText(summary);
}

void WorkPrecisionDialog::plotResult() {
    const auto& rows = m_result.rows;
    // The left panel's cost: force evaluations (a count) or the run time (median, band q1-q3).
    const bool wallTime = cost() == Cost::WallTime;
    auto costOf = [wallTime](const simlab::StudyRow& r) {
        return wallTime ? r.wallSeconds : static_cast<double>(r.forceEvaluations);
    };
    m_plot->clearPlottables();
    QCPAxisRect* left = m_plot->axisRect(0);
    left->axis(QCPAxis::atBottom)->setLabel(wallTime ? tr("run time [s] (median, band q1–q3)") : tr("force evaluations"));
    QCPAxisRect* right = m_plot->axisRect(1);
    struct Curve {
        std::vector<const simlab::StudyRow*> points;
    };
    std::map<QString, Curve> curves;
    QStringList order;
    for (const simlab::StudyRow& row : rows) {
        if (!row.ok || !(row.errorMax > 0) || !(costOf(row) > 0)) continue;
        const QString name = QString::fromStdString(row.item.integrator);
        if (!curves.count(name)) order << name;
        curves[name].points.push_back(&row);
    }
    for (const QString& name : order) {
        auto& points = curves[name].points;
        std::sort(points.begin(), points.end(), [](auto* a, auto* b) { return a->dt < b->dt; });
        const QColor colour = integratorColor(name);
        int k = 0;
        if (wallTime) {
            // The band: from q1 to q3 of the timed runs at each point's error, a filled polygon.
            auto* band = new QCPCurve(left->axis(QCPAxis::atBottom), left->axis(QCPAxis::atLeft));
            for (const auto* r : points) band->addData(k++, r->wallQ1, r->errorMax);
            for (auto it = points.rbegin(); it != points.rend(); ++it) band->addData(k++, (*it)->wallQ3, (*it)->errorMax);
            QColor fill = colour;
            fill.setAlpha(50);
            band->setBrush(fill);
            band->setPen(QPen(fill, 0.8));
            band->setName(name + tr(" q1–q3"));
            band->removeFromLegend();
        }
        QCPGraph* wall = m_plot->addGraph(left->axis(QCPAxis::atBottom), left->axis(QCPAxis::atLeft));
        QCPGraph* step = m_plot->addGraph(right->axis(QCPAxis::atBottom), right->axis(QCPAxis::atLeft));
        for (QCPGraph* graph : {wall, step}) {
            graph->setPen(QPen(colour, 1.6));
            graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 6));
            graph->setName(QStringLiteral("%1 [%2]").arg(name, QString::fromStdString(std::string(
                                                                    simcore::integratorFamily(name.toStdString())))));
            graph->setLineStyle(QCPGraph::lsNone);  // the connecting line follows DT, drawn below
        }
        wall->removeFromLegend();
        // Joined in order of DT (a QCPGraph sorts by x; run times need not be ordered).
        auto* line = new QCPCurve(left->axis(QCPAxis::atBottom), left->axis(QCPAxis::atLeft));
        line->setPen(QPen(colour, 1.6));
        line->removeFromLegend();
        k = 0;
        for (const auto* r : points) {
            wall->addData(costOf(*r), r->errorMax);
            step->addData(r->dt, r->errorMax);
            line->addData(k++, costOf(*r), r->errorMax);
        }
        step->setLineStyle(QCPGraph::lsLine);
    }
    // The fastest method of each family at each decade of error: ringed on the run-time panel.
    const std::vector<simlab::FamilyBest> best = wallTime ? simlab::fastestByFamily(rows) : std::vector<simlab::FamilyBest>{};
    if (!best.empty()) {
        QCPGraph* rings = m_plot->addGraph(left->axis(QCPAxis::atBottom), left->axis(QCPAxis::atLeft));
        rings->setName(tr("fastest of its family"));
        rings->setLineStyle(QCPGraph::lsNone);
        rings->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(Qt::black, 1.5), Qt::NoBrush, 13));
        for (const simlab::FamilyBest& b : best) rings->addData(b.wallSeconds, b.error);
    }
    rescaleLogPanels(m_plot);
}

QString WorkPrecisionDialog::csv() const {
    std::string text = simlab::studyCsvHeader();
    for (const simlab::StudyRow& row : m_result.rows) text += simlab::studyCsvRow(row);
    return QString::fromStdString(text);
}

QString WorkPrecisionDialog::svg() const {
    return QString::fromStdString(simlab::studySvg(m_result.rows,
                                                    "work-precision: " + sceneName(),
                                                    simlab::referenceScale(m_result.reference), m_spec.duration));
}

// ---------------------------------------------------------------- long-time energy

ConservationDialog::ConservationDialog(const simcore::ParameterSet& params, QWidget* parent)
    : StudyDialogBase(tr("Long-time energy"), params, parent) {
    setChosenIntegrators({QStringLiteral("verlet"), QStringLiteral("yoshida4"), QStringLiteral("rk4")});
    auto* form = static_cast<QFormLayout*>(m_options->layout());
    m_periods = new QLineEdit(QStringLiteral("1000"), m_options);
    m_periods->setToolTip(tr("Run length in periods of the body's fastest mode (damping switched off)"));
    m_dt = new QLineEdit(QString::number(params.get(simcore::Param::Dt)), m_options);
    m_dt->setToolTip(tr("The fixed step of every run [s]"));
    m_precision = new QComboBox(m_options);
    m_precision->addItems({QStringLiteral("double"), QStringLiteral("float")});
    m_precision->setToolTip(tr("float: the float build of the 1D spring, where round-off shows as a random walk"));
    form->addRow(tr("Periods"), m_periods);
    form->addRow(tr("DT [s]"), m_dt);
    form->addRow(tr("Precision"), m_precision);
    auto* rect = m_plot->axisRect();
    setupLogAxis(rect->axis(QCPAxis::atBottom), tr("t [s]"));
    setupLogAxis(rect->axis(QCPAxis::atLeft), tr("|energy error| envelope [J]"));
    m_plot->legend->setVisible(true);
    rect->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
}

void ConservationDialog::setPeriods(double periods) { m_periods->setText(QString::number(periods)); }
void ConservationDialog::setStep(double dt) { m_dt->setText(QString::number(dt)); }
void ConservationDialog::setPrecision(const QString& precision) { m_precision->setCurrentText(precision); }

simlab::ConservationSpec ConservationDialog::spec() const {
    simlab::ConservationSpec s;
    s.params = m_params;
    s.integrators.clear();
    for (const QString& name : chosenIntegrators()) s.integrators.push_back(name.toStdString());
    s.periods = m_periods->text().toDouble();
    s.dt = m_dt->text().toDouble();
    s.precision = m_precision->currentText().toStdString();
    return s;
}

QString ConservationDialog::validate() const {
    try {
        simlab::checkConservation(spec());  // the front door, as the CLI's and Python's
    } catch (const simlab::RequestError& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

void ConservationDialog::prepare() {
    m_spec = spec();
    m_error.clear();
}

void ConservationDialog::compute(const std::atomic<bool>* cancel) {
    try {
        m_result = simlab::runConservation(
            m_spec, [this](int done, int total, const std::string& what) { setProgress(done, total, QString::fromStdString(what)); },
            cancel);
    } catch (const std::exception& e) {
        m_result = simlab::ConservationResult{};
        m_error = QString::fromStdString(e.what());
    }
}

void ConservationDialog::present() {
    const QStringList headers = {tr("integrator"), tr("α"),       tr("95 % interval"), tr("class"),
                                 tr("final |ΔE| [J]"), tr("relative"), tr("steps"),        tr("status")};
    QList<QStringList> cells;
    for (const simlab::ConservationRow& row : m_result.rows)
        cells.append({QString::fromStdString(row.integrator), row.ok ? QString::number(row.alpha, 'f', 3) : QString(),
                      row.ok ? QStringLiteral("[%1, %2]").arg(num(row.alphaLo, 'f', 3)).arg(num(row.alphaHi, 'f', 3)) : QString(),
                      QString::fromStdString(row.growth), row.ok ? number(row.finalError) : QString(),
                      row.ok ? number(row.relativeError) : QString(), QString::number(row.steps),
                      QString::fromStdString(row.status())});
    fillTable(headers, cells);
    m_plot->clearPlottables();
    for (const simlab::ConservationRow& row : m_result.rows) {
        QCPGraph* graph = m_plot->addGraph();
        const QString name = QString::fromStdString(row.integrator);
        graph->setPen(QPen(integratorColor(name), 1.8));
        graph->setName(row.ok ? tr("%1: %2, α = %3").arg(name, QString::fromStdString(row.growth)).arg(num(row.alpha, 'f', 2))
                              : tr("%1: failed").arg(name));
        for (auto [t, e] : row.curve)
            if (t > 0 && e > 0) graph->addData(t, e);
    }
    // Reference slopes 1/2 (random walk) and 1 (drift) from the middle curve's first point.
    if (!m_result.rows.empty()) {
        const simlab::ConservationRow& mid = m_result.rows[m_result.rows.size() / 2];
        for (auto [t0, e0] : mid.curve) {
            if (!(e0 > 0) || !(t0 > 0)) continue;
            const double t1 = m_result.duration;
            for (double slope : {0.5, 1.0}) {
                QCPGraph* ref = m_plot->addGraph();
                ref->setPen(QPen(Qt::gray, 1.0, slope == 0.5 ? Qt::DotLine : Qt::DashLine));
                ref->setName(slope == 0.5 ? tr("slope 1/2 (random walk)") : tr("slope 1 (drift)"));
                ref->addData(t0, e0);
                ref->addData(t1, e0 * std::pow(t1 / t0, slope));
            }
            break;
        }
    }
    rescaleLogPanels(m_plot);
    if (!m_error.isEmpty()) {
        m_summary->setText(tr("The study did not run: %1").arg(m_error));
        return;
    }
    m_summary->setText(tr("Undamped (%1). Fastest mode ω = %2 rad/s, period %3 s; DT = %4 s (h·ω = %5); %6 periods = "
                          "%7 s. α: slope of log |ΔE| against log t from 10 periods on; bounded < 0.25 ≤ random walk "
                          "< 0.75 ≤ drift.")
                           .arg(QString::fromStdString(m_result.undamped), number(m_result.omegaMax),
                                number(m_result.period), number(m_spec.dt), number(m_spec.dt * m_result.omegaMax))
                           .arg(m_spec.periods)
                           .arg(number(m_result.duration)));
}

QString ConservationDialog::csv() const {
    std::string text = simlab::conservationCsvHeader();
    for (const simlab::ConservationRow& row : m_result.rows) text += simlab::conservationCsvRow(row);
    return QString::fromStdString(text);
}

QString ConservationDialog::svg() const {
    return QString::fromStdString(simlab::conservationSvg(
        m_result, "long-time energy: " + sceneName()));
}

// ---------------------------------------------------------------- refinement study

RefinementDialog::RefinementDialog(const simcore::ParameterSet& params, QWidget* parent,
                                   std::optional<simcore::WorldSpec> world)
    : StudyDialogBase(tr("Refinement study"), params, parent, std::move(world)) {
    setChosenIntegrators({QStringLiteral("rk4")});
    auto* form = static_cast<QFormLayout*>(m_options->layout());
    const std::string key = simlab::refinementKey(params.kind());
    // The scene's current resolution and two finer ones (the sphere: one coarser, one finer,
    // each level 4x the particles).
    QString levels;
    if (!key.empty()) {
        const int v = params.getInt(simcore::findParam(key)->id);
        levels = params.kind() == simcore::SceneKind::Sphere3d ? QStringLiteral("%1 %2 %3").arg(std::max(0, v - 1)).arg(v).arg(v + 1)
                                                               : QStringLiteral("%1 %2 %3").arg(v).arg(2 * v).arg(4 * v);
    }
    m_levels = new QLineEdit(levels, m_options);
    m_levels->setToolTip(tr("Values of the scene's resolution, separated by spaces; the finest is the reference"));
    m_dt = new QLineEdit(m_options);
    m_dt->setPlaceholderText(tr("automatic"));
    m_dt->setToolTip(tr("Fixed step DT [s] for every level; it must divide 0.01 s and be stable at the finest "
                        "level. Empty: a quarter of the smaller of the scene's DT and the finest level's stable step"));
    m_duration = new QLineEdit(QStringLiteral("0.5"), m_options);
    m_duration->setToolTip(tr("Simulated time of every run [s]"));
    form->addRow(key.empty() ? tr("Levels") : tr("Levels (%1)").arg(QString::fromStdString(key)), m_levels);
    form->addRow(tr("DT [s]"), m_dt);
    form->addRow(tr("Duration T [s]"), m_duration);
    twoLogPanels(m_plot, tr("run time [s]"), tr("max relative volume error"), tr("run time [s]"),
                 tr("max centre-of-mass error [m]"));
}

void RefinementDialog::setLevels(const QString& values) { m_levels->setText(values); }
void RefinementDialog::setStep(const QString& dt) { m_dt->setText(dt); }
void RefinementDialog::setDuration(double seconds) { m_duration->setText(QString::number(seconds)); }

simlab::RefinementSpec RefinementDialog::spec() const {
    simlab::RefinementSpec s;
    s.params = m_params;
    s.world = m_world;
    s.key = simlab::refinementKey(m_params.kind());
    for (const QString& t : m_levels->text().split(QLatin1Char(' '), Qt::SkipEmptyParts)) s.values.push_back(t.toInt());
    const QStringList names = chosenIntegrators();
    if (!names.isEmpty()) s.integrator = names.front().toStdString();
    s.dt = m_dt->text().trimmed().isEmpty() ? 0.0 : m_dt->text().toDouble();
    s.duration = m_duration->text().toDouble();
    return s;
}

QString RefinementDialog::validate() const {
    if (chosenIntegrators().size() != 1) return tr("Choose exactly one integrator");
    bool ok = true;
    if (!m_dt->text().trimmed().isEmpty()) m_dt->text().toDouble(&ok);
    if (!ok) return tr("DT must be a number in seconds, or empty for the automatic step");
    for (const QString& t : m_levels->text().split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        t.toInt(&ok);
        if (!ok) return tr("Levels are whole numbers separated by spaces, got '%1'").arg(t);
    }
    try {
        simlab::checkRefinement(spec());
    } catch (const simlab::RequestError& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

void RefinementDialog::prepare() {
    m_spec = spec();
    m_error.clear();
}

void RefinementDialog::compute(const std::atomic<bool>* cancel) {
    try {
        m_result = simlab::runRefinement(
            m_spec, [this](const simlab::StudyProgress& p) { setProgress(p.done, p.total, QString::fromStdString(p.what)); },
            cancel);
    } catch (const std::exception& e) {
        m_result = simlab::RefinementResult{};
        m_error = QString::fromStdString(e.what());
    }
}

void RefinementDialog::present() {
    const auto& rows = m_result.rows;
    const QString key = QString::fromStdString(m_spec.key);
    const QStringList headers = {tr("level (%1)").arg(key), tr("particles"), tr("springs"), tr("h [m]"), tr("DT [s]"), tr("steps"),
                                 tr("run time [s]"), tr("volume error"), tr("centre-of-mass error [m]"), tr("status")};
    QList<QStringList> cells;
    for (const simlab::RefinementRow& row : rows)
        cells.append({QString::number(row.value), QString::number(row.particles), QString::number(row.springs), number(row.h),
                      number(row.dt), QString::number(row.steps), number(row.wallSeconds),
                      row.ok ? number(row.errorVolume) : QString(), row.ok ? number(row.errorCom) : QString(),
                      row.reference ? tr("reference") : QString::fromStdString(row.status())});
    fillTable(headers, cells);

    // Per panel: the mesh levels at the study's step, and the step curve (one level, coarser steps).
    m_plot->clearPlottables();
    for (int panel = 0; panel < 2; ++panel) {
        QCPAxisRect* rect = m_plot->axisRect(panel);
        auto value = [panel](double volume, double com) { return panel == 0 ? volume : com; };
        QCPGraph* mesh = m_plot->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        mesh->setName(tr("mesh (%1)").arg(key));
        mesh->setPen(QPen(QColor(30, 120, 200), 1.6));
        mesh->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 6));
        for (const simlab::RefinementRow& row : rows)
            if (row.ok && !row.reference && value(row.errorVolume, row.errorCom) > 0 && row.wallSeconds > 0)
                mesh->addData(row.wallSeconds, value(row.errorVolume, row.errorCom));
        QCPGraph* step = m_plot->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        step->setName(tr("step (%1=%2, coarser DT)").arg(key).arg(m_result.temporalValue));
        step->setPen(QPen(QColor(200, 30, 30), 1.6, Qt::DashLine));
        step->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssSquare, 6));
        for (const simlab::TemporalPoint& p : m_result.temporal)
            if (p.ok && value(p.errorVolume, p.errorCom) > 0 && p.wallSeconds > 0)
                step->addData(p.wallSeconds, value(p.errorVolume, p.errorCom));
        if (panel == 0) {
            mesh->removeFromLegend();
            step->removeFromLegend();
        }
    }
    rescaleLogPanels(m_plot);

    if (!m_error.isEmpty()) {
        m_summary->setText(tr("Failed: %1").arg(m_error));
        return;
    }
    QString summary = QString::fromStdString(m_result.stepRule) + QStringLiteral(". ");
    if (std::isfinite(m_result.timeErrorVolume))
        summary += tr("Time error of that step (measured at %1=%2): volume %3, centre of mass %4 m. ")
                       .arg(key)
                       .arg(m_result.temporalValue)
                       .arg(number(m_result.timeErrorVolume), number(m_result.timeErrorCom));
    for (const simlab::SpatialOrder& fit : simlab::fitSpatialOrders(m_result))
        summary += fit.points >= 2 ? tr("Spatial order (%1): %2. ").arg(QString::fromStdString(fit.observable)).arg(num(fit.order, 'f', 2))
                                   : tr("Spatial order (%1): not resolved. ").arg(QString::fromStdString(fit.observable));
    m_summary->setText(summary);
}

QString RefinementDialog::csv() const {
    std::string text = simlab::refinementCsvHeader();
    for (const simlab::RefinementRow& row : m_result.rows) text += simlab::refinementCsvRow(m_spec.key, row);
    return QString::fromStdString(text);
}

QString RefinementDialog::svg() const {
    return QString::fromStdString(simlab::refinementSvg(
        m_spec, m_result, "refinement: " + sceneName()));
}

// ---------------------------------------------------------------- stability scan

StabilityDialog::StabilityDialog(const simcore::ParameterSet& params, QWidget* parent,
                                 std::optional<simcore::WorldSpec> world)
    : StudyDialogBase(tr("Stability scan"), params, parent, std::move(world)) {
    auto* form = static_cast<QFormLayout*>(m_options->layout());
    m_duration = new QLineEdit(QStringLiteral("2"), m_options);
    m_duration->setToolTip(tr("Each trial runs this long; a run that does not blow up and whose energy stays "
                              "bounded is stable"));
    form->addRow(tr("Duration T [s]"), m_duration);
    auto* rect = m_plot->axisRect();
    setupLogAxis(rect->axis(QCPAxis::atLeft), tr("largest stable DT [s]"));
    m_plot->xAxis->setLabel(tr("integrator"));
    m_plot->legend->setVisible(true);
}

void StabilityDialog::setDuration(double seconds) { m_duration->setText(QString::number(seconds)); }

simlab::StabilitySpec StabilityDialog::spec() const {
    simlab::StabilitySpec s;
    s.params = m_params;
    s.world = m_world;
    for (const QString& name : chosenIntegrators()) s.integrators.push_back(name.toStdString());
    s.duration = simcore::parseNumber(m_duration->text().trimmed().toStdString()).value_or(0.0);
    return s;
}

QString StabilityDialog::validate() const {
    if (!(spec().duration > 0.0)) return tr("Duration must be a positive number of seconds");
    try {
        simlab::checkStability(spec());
    } catch (const simlab::RequestError& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

void StabilityDialog::prepare() { m_spec = spec(); }

void StabilityDialog::compute(const std::atomic<bool>* cancel) {
    setProgress(0, int(m_spec.integrators.size()), tr("linearising"));
    m_rows.clear();
    if (cancel->load()) return;
    m_modes = simlab::stabilityModes(m_spec);  // the world's when it is one
    m_rows = simlab::runStability(
        m_spec, m_modes,
        [this](const simlab::StabilityProgress& p) { setProgress(p.done, p.total, QString::fromStdString(p.what)); },
        cancel);
}

void StabilityDialog::present() {
    const QStringList headers = {tr("integrator"), tr("stable DT [s]"), tr("unstable DT [s]"), tr("predicted DT [s]"),
                                 tr("h·ω at stable"), tr("why it failed above")};
    auto dt = [](double v) {
        if (std::isinf(v)) return QObject::tr("unlimited");
        if (v <= 0) return QObject::tr("none");
        return number(v);
    };
    QList<QStringList> cells;
    for (const simlab::StabilityRow& row : m_rows)
        cells.append({QString::fromStdString(row.integrator), dt(row.stable), dt(row.unstable), dt(row.predicted),
                      number(row.stable * m_modes.omegaMax), QString::fromStdString(row.reasonAbove)});
    fillTable(headers, cells);
    m_table->horizontalHeader()->setStretchLastSection(true);

    m_plot->clearPlottables();
    QSharedPointer<QCPAxisTickerText> ticker(new QCPAxisTickerText);
    QCPGraph* measured = m_plot->addGraph();
    measured->setName(tr("measured"));
    measured->setLineStyle(QCPGraph::lsNone);
    measured->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(200, 30, 30), 10));
    QCPGraph* predicted = m_plot->addGraph();
    predicted->setName(tr("linearised prediction"));
    predicted->setLineStyle(QCPGraph::lsNone);
    predicted->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCross, QColor(30, 90, 200), 12));
    double lo = 1.0, hi = 1e-5;
    for (int r = 0; r < int(m_rows.size()); ++r) {
        const simlab::StabilityRow& row = m_rows[std::size_t(r)];
        ticker->addTick(r, QString::fromStdString(row.integrator));
        const double shownMax = m_spec.hMax;
        const double s = std::isinf(row.stable) ? shownMax : row.stable;
        const double p = std::isinf(row.predicted) ? shownMax : row.predicted;
        if (s > 0) {
            measured->addData(r, s);
            lo = std::min(lo, s);
            hi = std::max(hi, s);
        }
        if (p > 0) {
            predicted->addData(r, p);
            lo = std::min(lo, p);
            hi = std::max(hi, p);
        }
    }
    m_plot->xAxis->setTicker(ticker);
    m_plot->xAxis->setRange(-0.5, double(m_rows.size()) - 0.5);
    m_plot->yAxis->setRange(lo / 2, hi * 2);
    m_plot->replot();
    m_summary->setText(tr("Highest mode of the linearised body: ω = %1 rad/s (damping %2 1/s), %3 free coordinates. "
                          "A method is stable at DT when no mode grows; measured by bisection over %4 s runs.")
                           .arg(number(m_modes.omegaMax), number(m_modes.dampingAtMax))
                           .arg(m_modes.freeCoordinates)
                           .arg(m_spec.duration));
}

QString StabilityDialog::csv() const {
    std::string text = simlab::stabilityCsvHeader();
    for (const simlab::StabilityRow& row : m_rows) text += simlab::stabilityCsvRow(row, m_modes);
    return QString::fromStdString(text);
}

}  // namespace elui
