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
// Inputs arrive with every frame (setState: parameters and every view's integrator); the dock
// works only while visible. Side by side every view is mapped on the same picture (one body,
// one DT: the same points hλ): the view with the smallest margin - the one that turns red
// first - is the primary one (its region filled, its limiting mode ringed, "Try it" measures
// it); each other view's edge is drawn dashed in its own colour, and the words give every
// view's margin, one line each. The linearisation (simlab::stabilityModes: up to ~1 s for a large
// body) and the margin run on a worker std::thread, one job at a time; a change during a job
// queues one more (the newest wins). A DT change alone reuses the modes. "Try it" runs the
// stability scan's bisection (simlab::scanIntegrator) for the current integrator on another
// std::thread, with Cancel. Results come back through a Mailbox (mailbox.h: no Qt hand-over
// across threads, so ThreadSanitizer sees it).
//
// A scene of several bodies (setWorld) is mapped the same way with the whole world's
// eigenvalues (simlab::stabilityModes of the WorldSpec: every body's modes and, where two
// bodies are within the contact skin, their contact's) and "Try it" scans the whole world.

#include <atomic>
#include <complex>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include <QDockWidget>

#include "simcore/params.h"
#include "simcore/world.h"
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

// simlab's words on the map in the window's language (in English, simlab's own text, which the
// tests check and the docs quote): composed from their parts with tr() and the language's number
// format (num()), as failure_text.h does for a run's failure.
//   the margin     "DT can grow 5.30× (to 0.0159 s) before the fastest mode (hλ = -0.525, a
//                  pure decay) leaves the region." (every case of simlab::StepMargin::Case)
//   the spectrum   how the eigenvalues were found: exact, modal or iterative (Arnoldi)
//   the region     what the picture shows for the integrator (one paragraph per family)
QString marginSentence(const simlab::StepMargin& margin);
QString spectrumSentence(const simlab::SpectrumPoints& points);
QString regionNoteSentence(const std::string& integrator);

class StabilityMapDock : public QDockWidget {
    Q_OBJECT
public:
    explicit StabilityMapDock(QWidget* parent = nullptr);
    ~StabilityMapDock() override;  // cancels and joins its threads

    // The body and the method to map; cheap to call with every frame (nothing happens when
    // neither changed).
    void setState(const simcore::ParameterSet& params, const QString& integrator);
    void setState(const simcore::ParameterSet& params, const QStringList& integrators);
    // A scene of several bodies and its method: the whole world's map (its DT is body 1's, the
    // world's shared step); cheap to call with every frame.
    void setWorld(const simcore::WorldSpec& world, const QStringList& integrators);
    // Whether the map shown is a world's, and of how many bodies (0: one body).
    int shownBodies() const { return m_shownWorld ? int(m_shownWorld->bodies.size()) : 0; }
    // The spectrum shown (for tests).
    const simlab::LinearModes* modes() const { return m_modes.get(); }

    // What is shown (for tests and the screenshot).
    QString integrator() const { return m_integrator; }  // the first view's (as asked)
    // The integrator shown as the primary one (the smallest margin), and the others overlaid.
    QString primaryIntegrator() const { return QString::fromStdString(m_shownIntegrator); }
    QStringList overlaidIntegrators() const;
    int overlayCurveCount() const { return int(m_overlay.size()); }
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
    // The map: the stable region, every mode's DT·λ, the one that leaves first, the measured limit.
    void createPlot(QWidget* host);
    struct Job {
        simcore::ParameterSet params;
        std::optional<simcore::WorldSpec> world;            // a scene of several bodies
        std::vector<std::string> integrators;               // every view's
        std::shared_ptr<const simlab::LinearModes> modes;  // reused when only DT changed
    };
    // One view's margin and edge.
    struct View {
        std::string integrator;
        simlab::StepMargin margin;
        std::vector<std::vector<std::complex<double>>> boundary;
    };
    struct Result {
        simcore::ParameterSet params;
        std::optional<simcore::WorldSpec> world;
        std::vector<std::string> integrators;  // as asked
        std::string integrator;                // the primary view's
        std::shared_ptr<const simlab::LinearModes> modes;
        simlab::SpectrumPoints points;
        simlab::StepMargin margin;
        std::vector<std::vector<std::complex<double>>> boundary;
        std::vector<View> views;               // every view, in order
    };
    void request();
    void startJob(Job job);
    void present(const Result& result);
    void drawEdges(const Result& r, bool hasRegion);
    void drawEigenvalues(bool hasRegion);
    void describe(const Result& r);
    void fitView();
    void drawRegion();
    void keepEqualAspect();
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
    std::optional<simcore::WorldSpec> m_world, m_shownWorld, m_scanWorld;
    QString m_integrator;
    QStringList m_integrators;
    bool m_hasState = false;
    std::vector<std::string> m_shownIntegrators;
    std::vector<QCPCurve*> m_overlay;      // the other views' edges
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
