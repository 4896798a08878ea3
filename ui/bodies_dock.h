#pragma once
// BodiesDock: a scene of several bodies (simcore::World) at a glance and by the hand.
//
//   the readout   total momentum and angular momentum, min_gap (the smallest distance between
//                 two bodies' outer layers, or two non-adjacent elements of one, and which),
//                 the contact energy between bodies
//   the list      each body in its hue: kind, mass, centre of mass, its velocity, volumes
//   the plots     total momentum and min_gap against time; volume and pressure per body and
//                 layer (named lines "body2 outer"); the world's energy is in the Plots dock
//   add, remove   a body of a kind and level, where and how fast (a new world, from its start)
//
// The curves take one point per frame the GUI shows (tens per second of wall time), not one
// per step: they are for watching, the CLI's CSV is for numbers. A one-body scene shows only
// a line that says this dock is for scenes of several bodies.

#include <vector>

#include <QDockWidget>

#include "ui/frame.h"

class QCustomPlot;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace elui {

class BodiesDock : public QDockWidget {
    Q_OBJECT
public:
    explicit BodiesDock(QWidget* parent = nullptr);

    void showFrame(const Frame& frame);
    QString readoutText() const;
    int plottedPoints() const;                           // points of the momentum curve
    QStringList seriesNames(const QString& plotId) const;  // "momentum", "gap", "volume", "pressure"
    double lastValue(const QString& plotId, int series) const;
    double shownTimeEnd(const QString& plotId) const;    // the right end of its time axis [s]
    QTableWidget* table() const { return m_table; }
    QPushButton* addButton() const { return m_add; }
    QPushButton* removeButton() const { return m_remove; }
    QComboBox* addKind() const { return m_kind; }
    QLineEdit* addField(const QString& name) const;      // position_x, ..., velocity_z

signals:
    // A new world to build (a body added or removed), from its start.
    void worldRequested(const simcore::WorldSpec& spec);
    void message(const QString& text);

private:
    // The four plots (momentum, gap, volume, pressure), hidden until a world runs.
    void createPlots(QWidget* host);
    // The row that adds a body (kind, level, where, how fast) and removes the selected one.
    QWidget* createAddBox();
    void clearPlots();
    void rebuildSeries(const simcore::WorldSpec& spec);
    void showNumbers(const simcore::WorldDiagnostics& d);
    void addPoints(const simcore::WorldDiagnostics& d);
    // Every curve in view, drawn again (only while the dock is seen: a hidden or tabbed-away
    // dock catches up when it is shown).
    void refreshPlots();
    QString vector(const Eigen::Vector3d& v) const;
    void addBody();
    void removeBody();
    QCustomPlot* plot(const QString& id) const;

    QLabel* m_note = nullptr;
    QWidget* m_content = nullptr;
    QLabel* m_readout = nullptr;
    QTableWidget* m_table = nullptr;
    std::vector<QCustomPlot*> m_plots;  // momentum, gap, volume, pressure
    QComboBox* m_kind = nullptr;
    QSpinBox* m_level = nullptr;
    std::vector<QLineEdit*> m_start;    // position x y z, velocity x y z
    QPushButton* m_add = nullptr;
    QPushButton* m_remove = nullptr;
    std::shared_ptr<const simcore::WorldSpec> m_spec;
    std::shared_ptr<const SceneData> m_scene;
    double m_lastTime = -1.0;
    int m_dimension = 3;
};

}  // namespace elui
