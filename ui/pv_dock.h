#pragma once
// PvDock: the P–V diagram of each gas layer (inner, outer), a trail over the run.
//
//   P │ ·.                 the isotherm P = c / V, c = nRT of the layer: the parameter
//     │   ·.                 pressure_inner / pressure_outer [J] (docs/model.md: P = nRT / V,
//     │     ══●               n R T constant; the engine computes P = c / V from the same c)
//     │         ··..       ══ the trail: (V, P) of every recorded step of lane 0
//     └──────────── V      ●  the newest point
//
// The trail must lie on the isotherm: the gas is isothermal by the model, so the diagram shows
// a student where on it the layer is and how far it swings, not a cycle with an area. A change
// of c (a pressure edit) moves the isotherm: the trail restarts on the new one. The trail is
// cleared on reset and scene change; scenes without gas (spring1d) show a note instead.
// Rows arrive as they are recorded; the replot is queued at most 10 times a second.

#include <array>
#include <vector>

#include <QDockWidget>
#include <QPointF>

#include "ui/frame.h"

class QCustomPlot;
class QCPCurve;
class QCPGraph;
class QCheckBox;
class QLabel;
class QTimer;

namespace elui {

class PvDock : public QDockWidget {
    Q_OBJECT
public:
    explicit PvDock(QWidget* parent = nullptr);

    void setScene(simcore::SceneKind kind);
    // The isotherms' constants c = nRT from the parameters; a change restarts the trails.
    void setParameters(const simcore::ParameterSet& params);

    bool hasGas() const { return m_gas; }
    double isothermConstant(int layer) const { return m_c[std::size_t(layer)]; }
    int trailSize(int layer) const;
    QPointF trailPoint(int layer, int index) const;  // (V, P)
    // The isotherm as drawn: its sampled points (V, P).
    std::vector<QPointF> isothermPoints(int layer) const;
    std::vector<QCustomPlot*> plots() const { return {m_plots[0], m_plots[1]}; }

public slots:
    void clear();
    void appendRows(const std::vector<simcore::Diagnostics>& history, int first, int count);
    void replotNow();

private:
    void scheduleReplot();
    void fit(int layer);

    simcore::SceneKind m_kind = simcore::SceneKind::Ring2d;
    bool m_gas = true;
    bool m_created = false;
    std::array<double, 2> m_c{};               // nRT per layer [J]
    std::array<double, 2> m_restVolume{};      // [m^2 or m^3], from the rows
    std::array<QCustomPlot*, 2> m_plots{};
    std::array<QCPCurve*, 2> m_trails{};
    std::array<QCPGraph*, 2> m_isotherms{};
    std::array<QCPGraph*, 2> m_now{};
    // The trail's extent, kept as rows arrive (the axes fit it without a pass over the trail).
    std::array<double, 2> m_vMin{}, m_vMax{};
    QCheckBox* m_wide = nullptr;
    QLabel* m_note = nullptr;
    QWidget* m_plotHost = nullptr;
    QTimer* m_replotTimer = nullptr;
    bool m_dirty = false;
};

}  // namespace elui
