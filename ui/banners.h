#pragma once
// Banners: one part of the main window (docs/architecture.md, "The main window"): the two
// banners above the views. The failure banner (failure_banner.h) says why a run failed and
// offers its remedies; the stability banner warns, before the run goes on, that a rebuild made
// DT unstable for the chosen explicit method, with one-click remedies. Their buttons act on the
// controller directly.

#include <functional>

#include <QCoreApplication>
#include <QString>

class QFrame;
class QLabel;
class QPushButton;
class QVBoxLayout;
class QWidget;

namespace elui {

class FailureBanner;
class SimulationController;
struct Frame;
struct SceneData;

class Banners {
    Q_DECLARE_TR_FUNCTIONS(elui::MainWindow)  // the texts stay the window's (translations/*.ts)

public:
    // Both banners added to `column` (the failure banner first), children of `parent`, hidden;
    // `status` shows a line in the window's status bar.
    Banners(QWidget* parent, QVBoxLayout* column, SimulationController* controller,
            std::function<void(const QString&)> status);

    FailureBanner* failure() const { return m_failure; }
    void showFrame(const Frame& frame);
    // After a rebuild: the warning and its suggested DT, or hidden when the DT is stable.
    void showStabilityAdvice(const SceneData& scene);
    // The stability warning shown (empty when none is), and its button that sets the suggested DT.
    QString stabilityText() const;
    QPushButton* useSuggestedDt() const { return m_useSuggestedDt; }
    // Light tints in the normal theme; black with a coloured border in high contrast.
    void setHighContrast(bool on);

private:
    FailureBanner* m_failure = nullptr;
    QFrame* m_stability = nullptr;
    QLabel* m_stabilityText = nullptr;
    QPushButton* m_useSuggestedDt = nullptr;
    double m_suggestedDt = 0.0;
};

}  // namespace elui
