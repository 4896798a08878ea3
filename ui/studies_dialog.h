#pragma once
// Study dialogs: the work-precision study, the refinement study and the stability scan of
// simcore (study.h, refinement.h, stability.h — the same code as `elastic-lab-cli study`,
// `study --refine` and `stability`), run on a worker thread with a progress bar and Cancel,
// their results plotted and exportable.
//
// The worker is a std::thread; its progress and its end come back through a Mailbox
// (mailbox.h), so ThreadSanitizer sees every hand-over (no QtConcurrent, QFutureWatcher or
// queued call: those cross the threads through Qt's uninstrumented post-event list).

#include <atomic>
#include <memory>
#include <optional>
#include <thread>

#include <QDialog>

#include "simcore/params.h"
#include "simlab/conservation.h"
#include "simlab/refinement.h"
#include "simlab/stability.h"
#include "simlab/study.h"

class QCheckBox;
class QCustomPlot;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QComboBox;
class QSpinBox;

namespace elui {

class Mailbox;

// Common frame: integrator choice, run/cancel, progress, table, plot, export.
class StudyDialogBase : public QDialog {
    Q_OBJECT
public:
    // With `world`, the study is of that scene of several bodies (params: body 1's values), as
    // the CLI's study and stability take it.
    StudyDialogBase(const QString& title, const simcore::ParameterSet& params, QWidget* parent,
                    std::optional<simcore::WorldSpec> world = std::nullopt);
    ~StudyDialogBase() override;
    bool busy() const { return m_busy; }
    QTableWidget* table() const { return m_table; }
    QCustomPlot* plot() const { return m_plot; }
    QPushButton* runButton() const { return m_run; }
    void setChosenIntegrators(const QStringList& names);  // checks exactly these

public slots:
    void start();
    void cancel();

signals:
    void finished();

protected:
    // Cancels a running computation and waits for it. Every subclass calls it in its
    // destructor: the computation writes the subclass's members, which die before the base.
    void stopAndWait();
    QStringList chosenIntegrators() const;
    void fillTable(const QStringList& headers, const QList<QStringList>& cells);  // one QStringList per row
    void setProgress(int done, int total, const QString& what);  // thread-safe
    // On the GUI thread, before the run: read the widgets into the spec.
    virtual void prepare() = 0;
    // Runs on the worker thread: uses only what prepare() stored (never a widget).
    virtual void compute(const std::atomic<bool>* cancel) = 0;
    // Back on the GUI thread: fill table and plot.
    virtual void present() = 0;
    virtual QString csv() const = 0;
    virtual QString svg() const { return {}; }
    virtual QString validate() const { return {}; }

    // The scene's name in titles and file names: the world's or the body's.
    std::string sceneName() const;
    QLabel* makeSceneLabel();  // "Scene: ... with the current parameters" (the first line)
    simcore::ParameterSet m_params;
    std::optional<simcore::WorldSpec> m_world;  // a scene of several bodies, or none
    QWidget* m_options = nullptr;  // subclasses add their fields here (a QFormLayout)
    QTableWidget* m_table = nullptr;
    QCustomPlot* m_plot = nullptr;
    QLabel* m_summary = nullptr;

private:
    void exportResults();
    void computationEnded();  // GUI thread, posted by the worker as its last act
    std::vector<QCheckBox*> m_integrators;
    QPushButton* m_run = nullptr;
    QPushButton* m_cancel = nullptr;
    QPushButton* m_export = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    std::shared_ptr<std::atomic<bool>> m_cancelFlag;
    Mailbox* m_fromWorker = nullptr;  // progress and the end, run on the GUI thread
    std::thread m_worker;
    bool m_busy = false;
};

class WorkPrecisionDialog : public StudyDialogBase {
    Q_OBJECT
public:
    WorkPrecisionDialog(const simcore::ParameterSet& params, QWidget* parent = nullptr,
                        std::optional<simcore::WorldSpec> world = std::nullopt);
    ~WorkPrecisionDialog() override { stopAndWait(); }
    const simlab::StudyResult& result() const { return m_result; }
    void setSteps(const QString& dts);
    void setDuration(double seconds);
    void setRepeats(int repeats);              // timed runs of each point (the band: q1 to q3)
    void setTimeBudget(const QString& seconds);  // "" = none
    // The left panel's cost axis: force evaluations (the default: a count, the same on every
    // machine and every run) or the run time, the median over the repeats with its q1-q3 band
    // (noisy on a shared machine, where one curve can run backwards).
    enum class Cost { ForceEvaluations, WallTime };
    void setCost(Cost cost);
    Cost cost() const;

protected:
    void prepare() override;
    void compute(const std::atomic<bool>* cancel) override;
    void present() override;
    QString csv() const override;
    QString svg() const override;
    QString validate() const override;

private:
    simlab::StudySpec spec() const;
    QLineEdit* m_dts = nullptr;
    QLineEdit* m_duration = nullptr;
    QComboBox* m_reference = nullptr;
    void plotResult();
    QSpinBox* m_repeats = nullptr;
    QLineEdit* m_budget = nullptr;
    QComboBox* m_cost = nullptr;
    simlab::StudySpec m_spec;
    simlab::StudyResult m_result;
};

// Long-time energy (simlab/conservation.h, the CLI's `conservation`): the undamped scene for P
// periods of its fastest mode at DT, |energy error| against t on log-log axes, the fitted growth
// exponent and its class per integrator.
class ConservationDialog : public StudyDialogBase {
    Q_OBJECT
public:
    ConservationDialog(const simcore::ParameterSet& params, QWidget* parent = nullptr);
    ~ConservationDialog() override { stopAndWait(); }
    const simlab::ConservationResult& result() const { return m_result; }
    void setPeriods(double periods);
    void setStep(double dt);
    void setPrecision(const QString& precision);  // double | float

protected:
    void prepare() override;
    void compute(const std::atomic<bool>* cancel) override;
    void present() override;
    QString csv() const override;
    QString svg() const override;
    QString validate() const override;

private:
    simlab::ConservationSpec spec() const;
    QLineEdit* m_periods = nullptr;
    QLineEdit* m_dt = nullptr;
    QComboBox* m_precision = nullptr;
    simlab::ConservationSpec m_spec;
    simlab::ConservationResult m_result;
    QString m_error;
};

// The refinement study: one integrator (rk4 checked at first), the levels of the scene's
// resolution key, an optional fixed step. Plots volume and centre-of-mass error against run
// time for the mesh levels beside the same level's error at coarser steps.
class RefinementDialog : public StudyDialogBase {
    Q_OBJECT
public:
    RefinementDialog(const simcore::ParameterSet& params, QWidget* parent = nullptr,
                     std::optional<simcore::WorldSpec> world = std::nullopt);
    ~RefinementDialog() override { stopAndWait(); }
    const simlab::RefinementResult& result() const { return m_result; }
    void setLevels(const QString& values);  // e.g. "12 24 48"
    void setStep(const QString& dt);        // "" = chosen automatically
    void setDuration(double seconds);

protected:
    void prepare() override;
    void compute(const std::atomic<bool>* cancel) override;
    void present() override;
    QString csv() const override;
    QString svg() const override;
    QString validate() const override;

private:
    simlab::RefinementSpec spec() const;
    QLineEdit* m_levels = nullptr;
    QLineEdit* m_dt = nullptr;
    QLineEdit* m_duration = nullptr;
    simlab::RefinementSpec m_spec;
    simlab::RefinementResult m_result;
    QString m_error;  // the reference failed: why (no rows then)
};

class StabilityDialog : public StudyDialogBase {
    Q_OBJECT
public:
    StabilityDialog(const simcore::ParameterSet& params, QWidget* parent = nullptr,
                    std::optional<simcore::WorldSpec> world = std::nullopt);
    ~StabilityDialog() override { stopAndWait(); }
    const std::vector<simlab::StabilityRow>& rows() const { return m_rows; }
    void setDuration(double seconds);

protected:
    QString validate() const override;
    void prepare() override;
    void compute(const std::atomic<bool>* cancel) override;
    void present() override;
    QString csv() const override;

private:
    simlab::StabilitySpec spec() const;
    QLineEdit* m_duration = nullptr;
    simlab::StabilitySpec m_spec;
    simlab::LinearModes m_modes;
    std::vector<simlab::StabilityRow> m_rows;
};

}  // namespace elui
