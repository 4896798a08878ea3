#pragma once
// StabilityMapDock: the chosen integrator's stability region in the complex hλ plane, with the
// current body's linearised eigenvalues times DT on it (simcore/stability_region.h).
//
//   Im(hλ) ┌──────────────────────┐   light fill: the region (|R(hλ)| ≤ 1, or the oscillator's
//          │     ╭────╮           │               spectral radius ≤ 1), on a grid
//          │    ╱  ··  ╲          │   line:       its exact boundary (|R| = 1)
//          │───┤ ·  ● · ├─── Re   │   dots:       DT·λ of every mode; the ring marks the
//          │    ╲  ··  ╱          │               one that leaves first when DT grows
//          │     ╰────╯      ✕    │   ✕:          "Try it": the measured stable limit
//          └──────────────────────┘
//   "DT can grow 2.3× before the fastest mode leaves the region."
//
// Inputs arrive with every frame (setState: parameters and lane 0's integrator); the dock
// works only while visible. The linearisation (simlab::linearModes: up to ~1 s for a large
// body) and the margin run on a worker std::thread, one job at a time; a change during a job
// queues one more (the newest wins). A DT change alone reuses the modes. "Try it" runs the
// stability scan's bisection (simlab::scanIntegrator) for the current integrator on another
// std::thread, with Cancel. Results come back through a Mailbox (mailbox.h: no Qt hand-over
// across threads, so ThreadSanitizer sees it).

#include <atomic>
#include <complex>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include <QDockWidget>

#include "simcore/params.h"
#include "simlab/stability.h"
#include "simlab/stability_region.h"

class QCustomPlot;
class QCPColorMap;
class QCPCurve;
class QCPGraph;
class QLabel;
class QPushButton;

namespace elui {

class Mailbox;

class StabilityMapDock : public QDockWidget {
    Q_OBJECT
public:
    explicit StabilityMapDock(QWidget* parent = nullptr);
    ~StabilityMapDock() override;  // cancels and joins its threads

    // The body and the method to map; cheap to call with every frame (nothing happens when
    // neither changed).
    void setState(const simcore::ParameterSet& params, const QString& integrator);

    // What is shown (for tests and the screenshot).
    QString integrator() const { return m_integrator; }
    double dt() const { return m_shownDt; }
    int pointCount() const;                 // eigenvalue dots drawn
    int boundaryPointCount() const;         // points of the boundary curves
    std::complex<double> point(int i) const;  // the i-th dot (h·lambda)
    QString marginText() const;
    QString methodText() const;
    QString measuredText() const;
    double marginFactor() const { return m_margin.factor; }
    bool computing() const { return m_jobRunning; }
    bool scanning() const { return m_scanRunning; }
    // The measured limit's mark (h·lambda at the measured stable DT), when "Try it" has run.
    std::optional<std::complex<double>> measuredMark() const { return m_measuredMark; }
    quint64 resultSerial() const { return m_resultSerial; }  // increases with each result shown
    QPushButton* tryButton() const { return m_try; }
    QCustomPlot* plot() const { return m_plot; }

public slots:
    void tryIt();  // starts the scan, or cancels the one running

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    struct Job {
        simcore::ParameterSet params;
        std::string integrator;
        std::shared_ptr<const simlab::LinearModes> modes;  // reused when only DT changed
    };
    struct Result {
        simcore::ParameterSet params;
        std::string integrator;
        std::shared_ptr<const simlab::LinearModes> modes;
        simlab::SpectrumPoints points;
        simlab::StepMargin margin;
        std::vector<std::vector<std::complex<double>>> boundary;
    };
    void request();
    void startJob(Job job);
    void present(const Result& result);
    void fitView();
    void drawRegion();
    void showMeasured();

    QCustomPlot* m_plot = nullptr;
    QCPColorMap* m_fill = nullptr;
    std::vector<QCPCurve*> m_boundary;
    QCPGraph* m_points = nullptr;
    QCPGraph* m_limiting = nullptr;
    QCPGraph* m_measured = nullptr;
    QLabel* m_methodLabel = nullptr;
    QLabel* m_marginLabel = nullptr;
    QLabel* m_measuredLabel = nullptr;
    QPushButton* m_try = nullptr;

    // The wanted state (from setState) and what is shown.
    simcore::ParameterSet m_params;
    QString m_integrator;
    bool m_hasState = false;
    simcore::ParameterSet m_shownParams;
    std::string m_shownIntegrator;
    double m_shownDt = 0.0;
    std::shared_ptr<const simlab::LinearModes> m_modes;
    simlab::SpectrumPoints m_spectrum;
    simlab::StepMargin m_margin;
    std::vector<std::vector<std::complex<double>>> m_curves;
    quint64 m_resultSerial = 0;

    // The worker of the region jobs.
    Mailbox* m_fromWorker = nullptr;
    std::thread m_jobThread;
    bool m_jobRunning = false;
    bool m_jobPending = false;

    // "Try it": the scan of the current integrator, on its own thread.
    std::thread m_scanThread;
    std::shared_ptr<std::atomic<bool>> m_scanCancel;
    bool m_scanRunning = false;
    simcore::ParameterSet m_scanParams;
    std::string m_scanIntegrator;
    std::optional<simlab::StabilityRow> m_scanRow;
    std::optional<std::complex<double>> m_measuredMark;
    QString m_measuredText;
};

}  // namespace elui
